// The peers' rows: Bullet, libccd and FCL, those found at configure time.
//
// Pre-posed rows get B's pre-posed float vertices and identity transforms;
// posed rows get the local shapes and the pair's float world poses as the
// peer's own transforms (its native use).  Every peer shape has margin 0.
#include <cmath>
#include <memory>

#include "rows.hpp"

#if SEPAX_BENCH_BULLET
#include <btBulletCollisionCommon.h>
#include <BulletCollision/CollisionDispatch/btBoxBoxDetector.h>
#include <BulletCollision/CollisionShapes/btConvexPolyhedron.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btPolyhedralContactClipping.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#endif
#if SEPAX_BENCH_CCD
#include <ccd/ccd.h>
#endif
#if SEPAX_BENCH_FCL
#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#endif

namespace bench {

namespace {

#if SEPAX_BENCH_BULLET
std::unique_ptr<btConvexHullShape> bullet_hull(const std::vector<V3f>& v) {
  auto hull = std::make_unique<btConvexHullShape>();
  for (const auto& p : v) hull->addPoint(btVector3(btScalar(p[0]), btScalar(p[1]), btScalar(p[2])), false);
  hull->recalcLocalAabb();
  hull->setMargin(0);  // sepax has no margin; Bullet's default 0.04 would inflate both shapes
  hull->initializePolyhedralFeatures();  // for findSeparatingAxis (setup, not timed)
  return hull;
}

btTransform bullet_transform(const sepax::RigidTransform<float>& x) {
  const auto& r = x.rotation;
  return btTransform(
      btMatrix3x3(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2)),
      btVector3(x.translation[0], x.translation[1], x.translation[2]));
}

struct BulletCell {
  std::vector<std::unique_ptr<btConvexHullShape>> local;    // per pool shape
  std::vector<std::unique_ptr<btBoxShape>> boxes;           // per pool shape (boxes)
  std::vector<std::unique_ptr<btConvexHullShape>> posed_b;  // per pair, pre-posed B
  std::vector<btTransform> pose_a, pose_b;                  // per pair
  // The shape a posed row gives Bullet: btBoxShape for boxes, else the hull.
  const btConvexShape* shape(int i) const {
    if (!boxes.empty()) return boxes[static_cast<std::size_t>(i)].get();
    return local[static_cast<std::size_t>(i)].get();
  }
};

Out gjk_epa(const btConvexShape* a, const btConvexShape* b, const btTransform& ta, const btTransform& tb,
            btScalar max_distance2) {
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver epa;
  btGjkPairDetector det(a, b, &simplex, &epa);
  btGjkPairDetector::ClosestPointInput in;
  in.m_transformA = ta;
  in.m_transformB = tb;
  in.m_maximumDistanceSquared = max_distance2;
  btPointCollector out;
  det.getClosestPoints(in, out, nullptr);
  if (!out.m_hasResult) {
    // with a maximum distance: proven farther apart than it (a separated
    // verdict); without one: no answer
    if (max_distance2 < btScalar(BT_LARGE_FLOAT)) return Out{false, std::nan(""), false};
    return Out{true, std::nan(""), true};
  }
  return Out{out.m_distance <= 0, double(out.m_distance), false};
}

void add_bullet_rows(Cell& c, std::vector<Row>& rows) {
  auto bc = std::make_shared<BulletCell>();
  for (const auto& s : c.pool->shapes) {
    bc->local.push_back(bullet_hull(s.f.vertices()));
    if (c.pool->kind == "box") {
      const auto& h = s.half_extents;
      auto box = std::make_unique<btBoxShape>(btVector3(btScalar(h[0]), btScalar(h[1]), btScalar(h[2])));
      box->setMargin(0);  // keeps the extents (btBoxShape::setMargin)
      bc->boxes.push_back(std::move(box));
    }
  }
  for (const auto& p : c.pairs) {
    bc->pose_a.push_back(bullet_transform(p.pose_a));
    bc->pose_b.push_back(bullet_transform(p.pose_b));
    if (c.frames == 0) bc->posed_b.push_back(bullet_hull(p.bverts));
  }
  const Cell* cp = &c;
  auto addp = [&](std::string name, std::function<Out(std::size_t)> f) {
    rows.push_back(Row{std::move(name), "peer", std::move(f)});
  };
  if (c.frames == 0) {
    addp("bullet gjk+epa (float)", [cp, bc](std::size_t i) {
      btTransform id;
      id.setIdentity();
      return gjk_epa(bc->local[static_cast<std::size_t>(cp->pairs[i].a)].get(), bc->posed_b[i].get(), id, id,
                     btScalar(BT_LARGE_FLOAT));
    });
    addp("bullet sat (float)", [cp, bc](std::size_t i) {
      const auto& a = *bc->local[static_cast<std::size_t>(cp->pairs[i].a)];
      const auto& b = *bc->posed_b[i];
      btTransform id;
      id.setIdentity();
      btVector3 sep;
      btPointCollector res;
      const bool ov = btPolyhedralContactClipping::findSeparatingAxis(
          *a.getConvexPolyhedron(), *b.getConvexPolyhedron(), id, id, sep, res);
      if (!ov) return Out{false, std::nan(""), false};
      // depth along Bullet's axis: overlap of the two projections (reporting only)
      const V3d ax = V3d(double(sep.x()), double(sep.y()), double(sep.z())).normalized();
      double amin = HUGE_VAL, amax = -HUGE_VAL, bmin = HUGE_VAL, bmax = -HUGE_VAL;
      for (const auto& v : local_a(*cp, i).vertices()) {
        const double d = ax.dot(to_d(v));
        amin = std::min(amin, d);
        amax = std::max(amax, d);
      }
      for (const auto& v : cp->pairs[i].bverts) {
        const double d = ax.dot(to_d(v));
        bmin = std::min(bmin, d);
        bmax = std::max(bmax, d);
      }
      return Out{true, -std::min(amax - bmin, bmax - amin), false};
    });
  }
  addp("bullet gjk+epa posed (float)", [cp, bc](std::size_t i) {
    const PairData& p = cp->pairs[i];
    return gjk_epa(bc->shape(p.a), bc->shape(p.b), bc->pose_a[i], bc->pose_b[i], btScalar(BT_LARGE_FLOAT));
  });
  addp("bullet gjk+epa posed margin (float)", [cp, bc](std::size_t i) {
    const PairData& p = cp->pairs[i];
    const btScalar m = p.margin;
    return gjk_epa(bc->shape(p.a), bc->shape(p.b), bc->pose_a[i], bc->pose_b[i], m * m);
  });
  if (c.pool->kind == "box") {
    addp("bullet boxbox posed (float)", [cp, bc](std::size_t i) {
      const PairData& p = cp->pairs[i];
      btBoxBoxDetector det(bc->boxes[static_cast<std::size_t>(p.a)].get(),
                           bc->boxes[static_cast<std::size_t>(p.b)].get());
      btDiscreteCollisionDetectorInterface::ClosestPointInput in;
      in.m_transformA = bc->pose_a[i];
      in.m_transformB = bc->pose_b[i];
      btPointCollector out;
      det.getClosestPoints(in, out, nullptr);
      // contacts only for penetrating boxes; the deepest point's distance
      if (!out.m_hasResult) return Out{false, std::nan(""), false};
      return Out{true, double(out.m_distance), false};
    });
  }
}
#endif

#if SEPAX_BENCH_CCD
struct CcdShape {
  std::vector<double> xyz;  // float-valued doubles
  ccd_vec3_t centre;
};
CcdShape make_ccd(const std::vector<V3f>& v) {
  CcdShape s;
  V3d c = V3d::Zero();
  for (const auto& p : v) {
    s.xyz.insert(s.xyz.end(), {double(p[0]), double(p[1]), double(p[2])});
    c += to_d(p);
  }
  c /= double(v.size());
  ccdVec3Set(&s.centre, c[0], c[1], c[2]);
  return s;
}
void ccd_support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto* s = static_cast<const CcdShape*>(obj);
  const double* p = s->xyz.data();
  const std::size_t n = s->xyz.size() / 3;
  std::size_t best = 0;
  double bd = -HUGE_VAL;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = p[3 * i] * dir->v[0] + p[3 * i + 1] * dir->v[1] + p[3 * i + 2] * dir->v[2];
    if (d > bd) {
      bd = d;
      best = i;
    }
  }
  ccdVec3Set(out, p[3 * best], p[3 * best + 1], p[3 * best + 2]);
}
void ccd_center(const void* obj, ccd_vec3_t* c) {
  ccdVec3Copy(c, &static_cast<const CcdShape*>(obj)->centre);
}

struct CcdCell {
  std::vector<CcdShape> a;  // per pool shape
  std::vector<CcdShape> b;  // per pair, pre-posed
};

void add_ccd_rows(Cell& c, std::vector<Row>& rows) {
  auto cc = std::make_shared<CcdCell>();
  for (const auto& s : c.pool->shapes) cc->a.push_back(make_ccd(s.f.vertices()));
  for (const auto& p : c.pairs) cc->b.push_back(make_ccd(p.bverts));
  const Cell* cp = &c;
  auto init = [](ccd_t& ccd) {
    CCD_INIT(&ccd);
    ccd.support1 = ccd_support;
    ccd.support2 = ccd_support;
    ccd.center1 = ccd_center;
    ccd.center2 = ccd_center;
  };
  // ccdGJKPenetration and ccdMPRPenetration: 0 penetrating, -1 separated,
  // -2 memory failure (GJK only)
  using Penetration = int (*)(const void*, const void*, const ccd_t*, ccd_real_t*, ccd_vec3_t*, ccd_vec3_t*);
  auto add = [&](std::string name, Penetration penetration) {
    rows.push_back(Row{std::move(name), "peer", [cp, cc, init, penetration](std::size_t i) {
                         ccd_t ccd;
                         init(ccd);
                         ccd_real_t depth;
                         ccd_vec3_t dir, pos;
                         const int r = penetration(&cc->a[static_cast<std::size_t>(cp->pairs[i].a)],
                                                   &cc->b[i], &ccd, &depth, &dir, &pos);
                         if (r == 0) return Out{true, -double(depth), false};
                         if (r == -2) return Out{true, std::nan(""), true};
                         return Out{false, std::nan(""), false};
                       }});
  };
  add("ccd gjk+epa (double)", ccdGJKPenetration);
  add("ccd mpr (double)", ccdMPRPenetration);
}
#endif

#if SEPAX_BENCH_FCL
struct FclShape {
  std::shared_ptr<fcl::Convexd> cvx;
  std::unique_ptr<fcl::CollisionObjectd> obj;
  FclShape(const std::vector<V3f>& v, const std::vector<std::vector<int>>& faces) {
    auto verts = std::make_shared<std::vector<fcl::Vector3d>>();
    for (const auto& p : v) verts->emplace_back(double(p[0]), double(p[1]), double(p[2]));
    auto fl = std::make_shared<std::vector<int>>();
    for (const auto& f : faces) {
      fl->push_back(static_cast<int>(f.size()));
      fl->insert(fl->end(), f.begin(), f.end());
    }
    cvx = std::make_shared<fcl::Convexd>(verts, static_cast<int>(faces.size()), fl);
    obj = std::make_unique<fcl::CollisionObjectd>(cvx);
  }
};

struct FclCell {
  std::vector<std::unique_ptr<FclShape>> a;  // per pool shape
  std::vector<std::unique_ptr<FclShape>> b;  // per pair, pre-posed
};

void add_fcl_rows(Cell& c, std::vector<Row>& rows) {
  auto fc = std::make_shared<FclCell>();
  for (const auto& s : c.pool->shapes) fc->a.push_back(std::make_unique<FclShape>(s.f.vertices(), s.faces));
  for (const auto& p : c.pairs)
    fc->b.push_back(
        std::make_unique<FclShape>(p.bverts, c.pool->shapes[static_cast<std::size_t>(p.b)].faces));
  const Cell* cp = &c;
  rows.push_back(Row{"fcl collide+contact (double)", "peer", [cp, fc](std::size_t i) {
                       fcl::CollisionRequestd req(1, true);
                       fcl::CollisionResultd res;
                       fcl::collide(fc->a[static_cast<std::size_t>(cp->pairs[i].a)]->obj.get(),
                                    fc->b[i]->obj.get(), req, res);
                       if (!res.isCollision()) return Out{false, std::nan(""), false};
                       return Out{true, -res.getContact(0).penetration_depth, false};
                     }});
}
#endif

}  // namespace

std::vector<Row> peer_rows(Cell& c) {
  std::vector<Row> rows;
#if SEPAX_BENCH_BULLET
  add_bullet_rows(c, rows);
#endif
  if (c.frames > 0) return rows;  // trajectories: Bullet only
#if SEPAX_BENCH_CCD
  add_ccd_rows(c, rows);
#endif
#if SEPAX_BENCH_FCL
  add_fcl_rows(c, rows);
#endif
  return rows;
}

}  // namespace bench
