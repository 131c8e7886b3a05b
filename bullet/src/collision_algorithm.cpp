// sepax::bullet: the btCollisionAlgorithm (see collision_algorithm.hpp).
#include "sepax/bullet/collision_algorithm.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <new>
#include <vector>

#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btConvexPointCloudShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include <sepax/contact_manifold.hpp>
#include <sepax/convex_hull.hpp>
#include <sepax/prepared_shape.hpp>
#include <sepax/robust/robust_kernel.hpp>

#include "coherence.hpp"
#include "posed_manifold.hpp"

namespace sepax::bullet {

struct Prepared {
  explicit Prepared(ConvexPolyhedron<float> local) : shape(std::move(local)) {
    const ConvexPolyhedron<float>& p = shape.polyhedron();
    for (int c = 0; c < 3; ++c) center[c] = static_cast<double>(p.centroid()[c]);
    for (int v = 0; v < p.vertex_count(); ++v) {
      double r2 = 0, d2 = 0;
      for (int c = 0; c < 3; ++c) {
        const double x = static_cast<double>(p.vertex(v)[c]);
        r2 += x * x;
        d2 += (x - center[c]) * (x - center[c]);
      }
      reach = std::max(reach, std::sqrt(r2));
      bound = std::max(bound, std::sqrt(d2));
    }
  }
  PreparedShape<float> shape;
  std::array<double, 3> center{};  // the bounding sphere: centroid and radius (local frame)
  double bound = 0;
  double reach = 0;  // max |v| over the vertices (local frame): the motion bound's lever arm
};

namespace {

constexpr int kSupported[] = {BOX_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE,
                              CONVEX_POINT_CLOUD_SHAPE_PROXYTYPE};

/// The hull sepax collides for a supported shape, in its local frame (the
/// polyhedral geometry, see the header): btPolyhedralConvexShape::getVertex
/// gives a box's corners at its half extents with margin and a hull's or
/// point cloud's scaled points.
ConvexPolyhedron<float> local_hull(const btCollisionShape& shape) {
  const auto& poly = static_cast<const btPolyhedralConvexShape&>(shape);
  std::vector<Vec3<float>> pts;
  const int n = poly.getNumVertices();
  pts.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    btVector3 v;
    poly.getVertex(i, v);
    pts.emplace_back(v.x(), v.y(), v.z());
  }
  return convex_hull<float>(pts);
}

/// Bullet's transform as sepax's, entry for entry (the rotation and the
/// translation built in place: RigidTransform's default members would be
/// written first and then overwritten).
RigidTransform<float> pose_of(const btTransform& t) {
  const btMatrix3x3& r = t.getBasis();
  const btVector3& o = t.getOrigin();
  RigidTransform<float>::Matrix3 m;
  m << r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0], r[2][1], r[2][2];
  return RigidTransform<float>{m, Vec3<float>(o[0], o[1], o[2])};
}

btVector3 bt(const Vec3<float>& v) { return btVector3(v[0], v[1], v[2]); }

/// btBoxShape::getHalfExtentsWithMargin's value (the half extents without
/// margin plus the margin, each a float sum) with one call of the virtual
/// getMargin where Bullet's makes three.
btVector3 half_extents_with_margin(const btBoxShape& box) {
  const btScalar m = box.getMargin();
  return box.getHalfExtentsWithoutMargin() + btVector3(m, m, m);
}

/// Whether shape_type is in kSupported, as a switch (is_supported runs per
/// pair and step); the static_assert below keeps it the same set.
constexpr bool supported_type(int shape_type) {
  switch (shape_type) {
    case BOX_SHAPE_PROXYTYPE:
    case CONVEX_HULL_SHAPE_PROXYTYPE:
    case CONVEX_POINT_CLOUD_SHAPE_PROXYTYPE:
      return true;
    default:
      return false;
  }
}

/// supported_type and kSupported agree on every Bullet shape type.
constexpr bool supported_type_is_the_list() {
  for (int t = 0; t <= MAX_BROADPHASE_COLLISION_TYPES; ++t) {
    bool listed = false;
    for (int s : kSupported) listed = listed || s == t;
    if (listed != supported_type(t)) return false;
  }
  return true;
}
static_assert(supported_type_is_the_list());

}  // namespace

bool is_supported(int shape_type) { return supported_type(shape_type); }

ShapeKey shape_key(const btCollisionShape& shape) {
  ShapeKey k;
  const int type = shape.getShapeType();
  if (!is_supported(type)) return k;
  k.type = type;
  const btVector3& s = shape.getLocalScaling();
  for (int i = 0; i < 3; ++i) k.scaling[i] = s[i];
  if (type == BOX_SHAPE_PROXYTYPE) {
    const btVector3 h = half_extents_with_margin(static_cast<const btBoxShape&>(shape));
    for (int i = 0; i < 3; ++i) k.size[i] = h[i];
  } else if (type == CONVEX_HULL_SHAPE_PROXYTYPE) {
    const auto& hull = static_cast<const btConvexHullShape&>(shape);
    k.points = hull.getUnscaledPoints();
    k.point_count = hull.getNumPoints();
  } else {
    const auto& cloud = static_cast<const btConvexPointCloudShape&>(shape);
    k.points = cloud.getUnscaledPoints();
    k.point_count = cloud.getNumPoints();
  }
  return k;
}

namespace {

/// shape_key(shape) == k, read in place with an early exit at the first
/// field that differs (no ShapeKey built): the same fields, the same
/// comparisons (float ==, as the defaulted operator== compares them).
bool key_matches(const btCollisionShape& shape, const ShapeKey& k) {
  const int type = shape.getShapeType();
  if (!is_supported(type)) return k == ShapeKey{};
  if (type != k.type) return false;
  const btVector3& s = shape.getLocalScaling();
  for (int i = 0; i < 3; ++i) {
    if (!(static_cast<float>(s[i]) == k.scaling[i])) return false;
  }
  if (type == BOX_SHAPE_PROXYTYPE) {
    const btVector3 h = half_extents_with_margin(static_cast<const btBoxShape&>(shape));
    for (int i = 0; i < 3; ++i) {
      if (!(static_cast<float>(h[i]) == k.size[i])) return false;
    }
    return k.points == nullptr && k.point_count == 0;
  }
  for (int i = 0; i < 3; ++i) {
    if (!(k.size[i] == 0.0f)) return false;
  }
  if (type == CONVEX_HULL_SHAPE_PROXYTYPE) {
    const auto& hull = static_cast<const btConvexHullShape&>(shape);
    return hull.getUnscaledPoints() == k.points && hull.getNumPoints() == k.point_count;
  }
  const auto& cloud = static_cast<const btConvexPointCloudShape&>(shape);
  return cloud.getUnscaledPoints() == k.points && cloud.getNumPoints() == k.point_count;
}

}  // namespace

// ---- ShapeCache ----------------------------------------------------------------

ShapeCache::ShapeCache() = default;
ShapeCache::~ShapeCache() = default;

std::shared_ptr<const Prepared> ShapeCache::get(const btCollisionShape& shape, const ShapeKey& key) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = entries_.find(&shape);
    if (it != entries_.end() && it->second.key == key) return it->second.prepared;
  }
  // Prepared outside the lock (a large hull takes a while); a racing thread
  // may prepare the same shape too, and the last one stored wins.
  auto p = std::make_shared<const Prepared>(local_hull(shape));
  std::lock_guard<std::mutex> lock(mutex_);
  entries_[&shape] = Entry{key, p};
  ++preparations_;
  return p;
}

void ShapeCache::forget(const btCollisionShape* shape) {
  std::lock_guard<std::mutex> lock(mutex_);
  entries_.erase(shape);
}

std::size_t ShapeCache::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return entries_.size();
}

std::int64_t ShapeCache::preparations() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return preparations_;
}

// ---- counters ------------------------------------------------------------------

struct CreateFunc::Live {
  std::atomic<std::int64_t> queries{0}, early_outs{0}, culled{0}, kept_apart{0}, kept{0}, refreshed{0},
      reduced{0}, manifolds{0}, points{0}, id_matches{0}, errors{0}, fallback_pairs{0};
  std::mutex error_mutex;
  std::string last_error;

  void error(const std::string& what) {
    errors.fetch_add(1, std::memory_order_relaxed);
    std::lock_guard<std::mutex> lock(error_mutex);
    last_error = what;
  }
};

Counters CreateFunc::counters() const {
  Counters c;
  c.queries = live_->queries.load();
  c.early_outs = live_->early_outs.load();
  c.culled = live_->culled.load();
  c.kept = live_->kept.load();
  c.refreshed = live_->refreshed.load();
  c.reduced = live_->reduced.load();
  c.kept_apart = live_->kept_apart.load();
  c.manifolds = live_->manifolds.load();
  c.points = live_->points.load();
  c.id_matches = live_->id_matches.load();
  c.errors = live_->errors.load();
  c.fallback_pairs = live_->fallback_pairs.load();
  std::lock_guard<std::mutex> lock(live_->error_mutex);
  c.last_error = live_->last_error;
  return c;
}

void CreateFunc::reset_counters() {
  live_->queries = 0;
  live_->early_outs = 0;
  live_->culled = 0;
  live_->kept = 0;
  live_->refreshed = 0;
  live_->reduced = 0;
  live_->kept_apart = 0;
  live_->manifolds = 0;
  live_->points = 0;
  live_->id_matches = 0;
  live_->errors = 0;
  live_->fallback_pairs = 0;
  std::lock_guard<std::mutex> lock(live_->error_mutex);
  live_->last_error.clear();
}

// ---- the algorithm ---------------------------------------------------------------

struct CollisionAlgorithm::State {
  const btCollisionShape* shape_a = nullptr;
  const btCollisionShape* shape_b = nullptr;
  ShapeKey key_a, key_b;
  std::shared_ptr<const Prepared> a, b;
  SatCache<float> cache;
  ContactManifold<float> manifold;  // reused between steps
  // the kept face (coherence.hpp): valid, the contact, the SAT's separation
  // and the relative pose of the query it came from
  bool kept = false;
  SatResult<float> contact;
  KeptFace face;   // its side planes when it is a face of A (face_refresh.hpp)
  PosedView view;  // B' in part for the kept face (posed_view.hpp), reused between steps
  double sat_separation = 0;
  RigidTransform<float> x0;
  double defect0 = 0;  // rotation_defect(x0) (coherence.hpp)
  // the last query's answer beyond the margin (coherence.hpp): valid, its
  // separation and the relative pose it was proven at
  bool apart = false;
  double apart_separation = 0;
  RigidTransform<float> x_apart;

  /// A shape was prepared anew (another shape or key): the warm cache, the
  /// kept face (its face index and side planes) and the kept separation
  /// belonged to the old one.
  void forget_shape_state() {
    cache = SatCache<float>{};
    kept = false;
    apart = false;
    face = KeptFace{};
  }
};

namespace {

/// A new point of write_points before it goes into the manifold: its points
/// in world and in the manifold bodies' frames, its depth and its feature
/// ids as Bullet's (partId0, index0, partId1, index1).
struct NewPoint {
  btVector3 world_a, world_b, local_a, local_b;
  btScalar depth;
  int part0, index0, part1, index1;
};

bool same_ids(const btManifoldPoint& x, const NewPoint& y) {
  // the four comparisons at once (no early exit: each is a load and a xor)
  return ((x.m_partId0 ^ y.part0) | (x.m_index0 ^ y.index0) | (x.m_partId1 ^ y.part1) |
          (x.m_index1 ^ y.index1)) == 0;
}

/// The pair's material and flags, as btManifoldResult::addContactPoint sets
/// them on each point.
struct Material {
  btScalar friction, restitution, rolling, spinning, damping, stiff;
  bool stiffness, anchor;
  /// btPlaneSpace1 of the pair's normal on body 1, which addContactPoint
  /// computes for each point (the same normal: the same directions).
  btVector3 lateral1, lateral2;
};

/// Every field of `p` that a point constructed by addContactPoint for `q`
/// takes from `q` and the material: all but the accumulated impulses, the
/// previous right-hand side, the user data and the lifetime, the fields
/// btPersistentManifold::replaceContactPoint keeps from the stored point.
/// On a point constructed from q's local points, normal and depth this is
/// addContactPoint's point; on a stored point it is replaceContactPoint's
/// result without the copy.
void fill(btManifoldPoint& p, const NewPoint& q, const btVector3& normal_on_b, const Material& mat) {
  p.m_localPointA = q.local_a;
  p.m_localPointB = q.local_b;
  p.m_positionWorldOnB = q.world_b;
  p.m_positionWorldOnA = q.world_a;
  p.m_normalWorldOnB = normal_on_b;
  p.m_distance1 = q.depth;
  p.m_combinedFriction = mat.friction;
  p.m_combinedRollingFriction = mat.rolling;
  p.m_combinedSpinningFriction = mat.spinning;
  p.m_combinedRestitution = mat.restitution;
  p.m_partId0 = q.part0;
  p.m_partId1 = q.part1;
  p.m_index0 = q.index0;
  p.m_index1 = q.index1;
  p.m_contactPointFlags = 0;
  p.m_contactMotion1 = 0;
  p.m_contactMotion2 = 0;
  p.m_contactCFM = 0;
  p.m_contactERP = 0;
  p.m_frictionCFM = 0;
  if (mat.stiffness) {
    p.m_combinedContactDamping1 = mat.damping;
    p.m_combinedContactStiffness1 = mat.stiff;
    p.m_contactPointFlags |= BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING;
  }
  if (mat.anchor) p.m_contactPointFlags |= BT_CONTACT_FLAG_FRICTION_ANCHOR;
  p.m_lateralFrictionDir1 = mat.lateral1;
  p.m_lateralFrictionDir2 = mat.lateral2;
}

/// Writes the world-space manifold m of (w0, w1) into `man` (see the header):
/// points as btManifoldResult::addContactPoint builds them, matched to the
/// manifold's points by their feature ids, else by position.  A matched
/// stored point is updated in place to what replaceContactPoint would leave
/// (fill), except with friction anchors, whose replacement depends on the
/// stored impulses: those go through replaceContactPoint.  Returns the id
/// matches.
int write_points(btPersistentManifold& man, const btCollisionObjectWrapper* w0,
                 const btCollisionObjectWrapper* w1, const ContactManifold<float>& m) {
  const btCollisionObject* o0 = w0->getCollisionObject();
  const btCollisionObject* o1 = w1->getCollisionObject();
  const bool swapped = man.getBody0() != o0;
  const btCollisionObject* ma = swapped ? o1 : o0;  // the manifold's body 0
  const btCollisionObject* mb = swapped ? o0 : o1;
  const btScalar threshold = man.getContactBreakingThreshold();
  const btVector3 n = bt(m.normal);  // from w0's shape to w1's
  // Bullet's convention: the normal on the manifold's body 1, pointing to
  // body 0; the point on body 1; the point on body 0 = that + normal depth.
  const btVector3 normal_on_b = swapped ? n : -n;

  // the pair's material, as addContactPoint computes it (once per pair here)
  Material mat;
  mat.friction = gCalculateCombinedFrictionCallback(o0, o1);
  mat.restitution = gCalculateCombinedRestitutionCallback(o0, o1);
  mat.rolling = gCalculateCombinedRollingFrictionCallback(o0, o1);
  mat.spinning = gCalculateCombinedSpinningFrictionCallback(o0, o1);
  const int flags = o0->getCollisionFlags() | o1->getCollisionFlags();
  mat.stiffness = flags & btCollisionObject::CF_HAS_CONTACT_STIFFNESS_DAMPING;
  mat.damping = mat.stiffness ? gCalculateCombinedContactDampingCallback(o0, o1) : btScalar(0);
  mat.stiff = mat.stiffness ? gCalculateCombinedContactStiffnessCallback(o0, o1) : btScalar(0);
  mat.anchor = flags & btCollisionObject::CF_HAS_FRICTION_ANCHOR;
  btPlaneSpace1(normal_on_b, mat.lateral1, mat.lateral2);

  NewPoint pts[MANIFOLD_CACHE_SIZE];
  int count = 0;
  for (const auto& c : m.points) {
    if (count == MANIFOLD_CACHE_SIZE) break;
    const btScalar depth = static_cast<btScalar>(to_double(c.separation));
    if (depth > threshold) continue;
    NewPoint& q = pts[count++];
    q.world_b = bt(swapped ? c.point_a : c.point_b);
    q.world_a = q.world_b + normal_on_b * depth;
    q.local_a = ma->getWorldTransform().invXform(q.world_a);
    q.local_b = mb->getWorldTransform().invXform(q.world_b);
    q.depth = depth;
    const ShapeFeature& f0 = swapped ? c.id.b : c.id.a;
    const ShapeFeature& f1 = swapped ? c.id.a : c.id.b;
    q.part0 = static_cast<int>(f0.kind);
    q.index0 = f0.index;
    q.part1 = static_cast<int>(f1.kind);
    q.index1 = f1.index;
  }

  const bool new_collision = man.getNumContacts() == 0;
  // Each new point takes the stored point with its ids (its warm start);
  // a new point whose ids no stored point has takes, as Bullet's
  // getCacheEntry does, the nearest remaining stored point within the
  // threshold (local point on body 1).  Ids change where a feature of the
  // clip changes at the same place (a vertex of B crossing a side plane of
  // A's face, for equal boxes exactly on it): the point, and the impulse
  // the solver has accumulated there, stays.
  const int stored = man.getNumContacts();
  int from[MANIFOLD_CACHE_SIZE] = {-1, -1, -1, -1};  // the stored point each new point replaces
  bool used[MANIFOLD_CACHE_SIZE] = {false, false, false, false};
  int matches = 0;
  for (int j = 0; j < count; ++j) {
    for (int i = 0; i < stored; ++i) {
      if (!used[i] && same_ids(man.getContactPoint(i), pts[j])) {
        from[j] = i;
        break;
      }
    }
    if (from[j] >= 0) {
      used[from[j]] = true;
      ++matches;
    }
  }
  for (int j = 0; j < count; ++j) {
    if (from[j] >= 0) continue;
    btScalar nearest = threshold * threshold;
    for (int i = 0; i < stored; ++i) {
      if (used[i]) continue;
      const btScalar d2 = (man.getContactPoint(i).m_localPointB - pts[j].local_b).length2();
      if (d2 < nearest) {
        nearest = d2;
        from[j] = i;
      }
    }
    if (from[j] >= 0) used[from[j]] = true;
  }
  auto constructed = [&](const NewPoint& q) {
    btManifoldPoint p(q.local_a, q.local_b, normal_on_b, q.depth);
    fill(p, q, normal_on_b, mat);
    return p;
  };
  for (int j = 0; j < count; ++j) {
    if (from[j] < 0) continue;
    if (mat.anchor) {
      man.replaceContactPoint(constructed(pts[j]), from[j]);
    } else {
      fill(man.getContactPoint(from[j]), pts[j], normal_on_b, mat);
    }
  }
  // Stored points no new point took go (backwards: removal moves the last
  // point into the hole, which has been looked at already).
  for (int i = stored - 1; i >= 0; --i) {
    if (!used[i]) man.removeContactPoint(i);
  }
  for (int j = 0; j < count; ++j) {
    if (from[j] < 0) man.addManifoldPoint(constructed(pts[j]));
  }
  const bool custom = flags & btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK;
  if (gContactAddedCallback && custom) {
    const btCollisionObjectWrapper* x0 = swapped ? w1 : w0;
    const btCollisionObjectWrapper* x1 = swapped ? w0 : w1;
    for (int i = 0; i < man.getNumContacts(); ++i) {
      btManifoldPoint& q = man.getContactPoint(i);
      (*gContactAddedCallback)(q, x0, q.m_partId0, q.m_index0, x1, q.m_partId1, q.m_index1);
    }
  }
  if (gContactStartedCallback && new_collision && man.getNumContacts() > 0) gContactStartedCallback(&man);
  return matches;
}

}  // namespace

CollisionAlgorithm::CollisionAlgorithm(const btCollisionAlgorithmConstructionInfo& ci,
                                       const btCollisionObjectWrapper* body0,
                                       const btCollisionObjectWrapper* body1, CreateFunc& owner)
    : btActivatingCollisionAlgorithm(ci, body0, body1), owner_(owner), state_(std::make_unique<State>()) {}

CollisionAlgorithm::~CollisionAlgorithm() {
  if (manifold_) m_dispatcher->releaseManifold(manifold_);
}

void CollisionAlgorithm::getAllContactManifolds(btManifoldArray& out) {
  if (manifold_) out.push_back(manifold_);
}

void CollisionAlgorithm::processCollision(const btCollisionObjectWrapper* body0,
                                          const btCollisionObjectWrapper* body1, const btDispatcherInfo&,
                                          btManifoldResult* result) {
  if (!manifold_)
    manifold_ = m_dispatcher->getNewManifold(body0->getCollisionObject(), body1->getCollisionObject());
  result->setPersistentManifold(manifold_);
  State& s = *state_;
  auto& live = *owner_.live_;
  try {
    // The prepared hulls: looked up again only when a shape or its key changed.
    const btCollisionShape* sa = body0->getCollisionShape();
    const btCollisionShape* sb = body1->getCollisionShape();
    if (sa != s.shape_a || !s.a || !key_matches(*sa, s.key_a)) {
      const ShapeKey ka = shape_key(*sa);
      s.a = owner_.shapes_.get(*sa, ka);
      s.shape_a = sa;
      s.key_a = ka;
      s.forget_shape_state();
    }
    if (sb != s.shape_b || !s.b || !key_matches(*sb, s.key_b)) {
      const ShapeKey kb = shape_key(*sb);
      s.b = owner_.shapes_.get(*sb, kb);
      s.shape_b = sb;
      s.key_b = kb;
      s.forget_shape_state();
    }
    const btTransform& wa = body0->getWorldTransform();
    const btTransform& wb = body1->getWorldTransform();
    const double margin = static_cast<double>(manifold_->getContactBreakingThreshold());
    if (spheres_beyond(wa.getBasis(), wa.getOrigin(), s.a->center, s.a->bound, wb.getBasis(), wb.getOrigin(),
                       s.b->center, s.b->bound, margin)) {
      live.culled.fetch_add(1, std::memory_order_relaxed);
      s.kept = false;
      s.apart = false;
      if (manifold_->getNumContacts() > 0) manifold_->clearManifold();
      return;
    }
    const RigidTransform<float> pa = pose_of(wa);
    const RigidTransform<float> pb = pose_of(wb);
    const RigidTransform<float> x = relative_pose(pa, pb);
    if (s.apart &&
        s.apart_separation - motion_bound(s.x_apart, x, s.b->reach) - motion_slack(s.x_apart, x, s.b->reach) >
            margin) {
      live.kept_apart.fetch_add(1, std::memory_order_relaxed);
      if (manifold_->getNumContacts() > 0) manifold_->clearManifold();
      return;
    }
    s.apart = false;
    bool keep = false;
    Motion moved;
    if (s.kept) {
      moved = motion_between(s.x0, x);
      const double delta = motion_bound(moved, s.b->reach);
      const double slack = motion_slack(s.x0, x, s.b->reach);
      const double budget = kKeepMotion * kAbsTolerance *
                            std::min(s.a->shape.polyhedron().extent(), s.b->shape.polyhedron().extent());
      keep = delta <= budget && s.sat_separation + delta + slack <= margin;
    }
    if (keep) {
      bool refreshed = false;
      const bool rigid = stays_rigid(s.defect0, moved);
      // write_points reads the point on the Bullet manifold's body 1: A's
      // when the manifold's bodies are in the other order
      const bool world_a = manifold_->getBody0() != body0->getCollisionObject();
      kept_manifold(s.a->shape, pa, s.b->shape, x, rigid, s.contact, margin, s.face, world_a, s.view,
                    s.manifold, refreshed);
      live.kept.fetch_add(1, std::memory_order_relaxed);
      if (refreshed) live.refreshed.fetch_add(1, std::memory_order_relaxed);
      if (refreshed && s.manifold.candidate_points > 4) live.reduced.fetch_add(1, std::memory_order_relaxed);
    } else {
      SatOptions opt;
      opt.early_out = true;
      opt.margin = margin;
      const SatResult<float> r =
          sat::traversal<policy::Robust>(s.a->shape, pa, s.b->shape, pb, opt, &s.cache);
      live.queries.fetch_add(1, std::memory_order_relaxed);
      s.kept = false;
      if (r.early_out) {
        live.early_outs.fetch_add(1, std::memory_order_relaxed);
        s.apart = true;
        s.apart_separation = to_double(r.separation);
        s.x_apart = x;
        if (manifold_->getNumContacts() > 0) manifold_->clearManifold();
        return;
      }
      const SatResult<float> contact = chosen_contact(s.a->shape, pa, s.b->shape, x, r);
      const FeatureType t = contact.feature.type;
      if (t == FeatureType::FaceA || t == FeatureType::FaceB) {
        s.kept = true;
        s.contact = contact;
        if (t == FeatureType::FaceA) {
          if (s.face.face != contact.feature.a) s.face.set(s.a->shape.polyhedron(), contact.feature.a);
        } else {
          s.face.face = -1;
          s.face.planes.clear();
        }
        s.sat_separation = to_double(r.separation);
        s.x0 = x;
        s.defect0 = rotation_defect(x);
      }
      posed_manifold(s.a->shape, pa, s.b->shape, pb, contact, margin, s.manifold);
    }
    live.manifolds.fetch_add(1, std::memory_order_relaxed);
    live.points.fetch_add(s.manifold.size(), std::memory_order_relaxed);
    live.id_matches.fetch_add(write_points(*manifold_, body0, body1, s.manifold), std::memory_order_relaxed);
  } catch (const InvalidInput& e) {
    // sepax refused the pair at this pose (for example a pose too far from
    // the origin for float to resolve): no contact from sepax; counted.
    live.error(std::string(to_string(e.code())) + ": " + e.what());
    s.kept = false;
    s.apart = false;
    if (manifold_->getNumContacts() > 0) manifold_->clearManifold();
  }
}

// ---- the create function -----------------------------------------------------------

CreateFunc::CreateFunc(btCollisionConfiguration& config) : config_(config), live_(std::make_shared<Live>()) {}

btCollisionAlgorithm* CreateFunc::CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                           const btCollisionObjectWrapper* body0,
                                                           const btCollisionObjectWrapper* body1) {
  const btCollisionShape* sa = body0->getCollisionShape();
  const btCollisionShape* sb = body1->getCollisionShape();
  bool ok = is_supported(sa->getShapeType()) && is_supported(sb->getShapeType());
  if (ok) {
    try {
      shapes_.get(*sa, shape_key(*sa));
      shapes_.get(*sb, shape_key(*sb));
    } catch (const InvalidInput& e) {
      live_->error(std::string("shape refused, Bullet's algorithm used: ") + to_string(e.code()) + ": " +
                   e.what());
      ok = false;
    }
  }
  if (!ok) {
    live_->fallback_pairs.fetch_add(1, std::memory_order_relaxed);
    btCollisionAlgorithmCreateFunc* f =
        config_.getCollisionAlgorithmCreateFunc(sa->getShapeType(), sb->getShapeType());
    return f->CreateCollisionAlgorithm(ci, body0, body1);
  }
  void* mem = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(CollisionAlgorithm));
  return new (mem) CollisionAlgorithm(ci, body0, body1, *this);
}

void register_algorithm(btCollisionDispatcher& dispatcher, CreateFunc& cf) {
  for (int a : kSupported) {
    for (int b : kSupported) dispatcher.registerCollisionCreateFunc(a, b, &cf);
  }
}

}  // namespace sepax::bullet
