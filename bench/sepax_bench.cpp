// sepax_bench: sepax's SATs against each other and against Bullet, libccd and
// FCL on the same shape pairs.  A plain harness (not Google Benchmark): the
// table needs per-row verdicts and depth errors against an exact reference,
// which is easier to compute when the harness owns the loop.
//
// Workloads: hulls of N random points on the unit sphere (N = 4 .. 256), boxes,
// a 32-sided cylinder; fixed-seed random poses in two sets, "overlapping"
// (centres within 1.0) and "separated" (centres 1 to 2.5 apart).
//
// Fairness:
//   * every row sees the same pairs in the same order;
//   * B is PRE-POSED for everybody: its pose is applied once, in double, and
//     the posed vertices are rounded to float.  Every row (sepax float,
//     double, exact; every peer) gets exactly these float-valued vertices and
//     identity transforms, so the exact reference is the exact answer for
//     every row's input.  One extra row ("... +pose") includes the cost of
//     posing B (transform + ConvexPolyhedron::with_vertices) in sepax's query;
//   * peers with a collision margin get margin 0;
//   * the time of a row is the minimum over several batches of passes over
//     the pairs (the machine is shared; the minimum is the least disturbed).
//
// Usage: sepax_bench [--quick] [--min-time S] [--max-pass S] [--pairs P] [--filter SUBSTR]
//                    [--workload W] [--json FILE]
//   --filter keeps the rows whose name contains SUBSTR (and the baseline);
//   --workload keeps one workload (sphere4 .. sphere256, box, cylinder32).
//        sepax_bench --callgrind --row NAME --workload W --poses P [--passes K]
//          runs one row only, K passes over the pairs, inside callgrind client
//          requests (use bench/callgrind_ratios.sh).
#include <sepax/robust/number_types.hpp>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/shapes.hpp>

#if __has_include(<sepax/sat_traversal.hpp>)
#include <sepax/sat_traversal.hpp>
#define SEPAX_BENCH_TRAVERSAL 1
#endif
#if __has_include(<sepax/sat_cache.hpp>) && SEPAX_BENCH_TRAVERSAL
#include <sepax/sat_cache.hpp>
#define SEPAX_BENCH_CACHE 1
#endif
#if __has_include(<sepax/convex_hull.hpp>)
#include <sepax/convex_hull.hpp>
#define SEPAX_BENCH_HULL 1
#endif
#if __has_include(<sepax/contact_manifold.hpp>)
#include <sepax/contact_manifold.hpp>
#define SEPAX_BENCH_CONTACTS 1
#endif
#if __has_include(<sepax/robust/robust_kernel.hpp>)
#include <sepax/robust/robust_kernel.hpp>
#define SEPAX_BENCH_ROBUST 1
#endif

#if !SEPAX_BENCH_HULL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#endif

#if SEPAX_BENCH_BULLET
#include <btBulletCollisionCommon.h>
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
#if SEPAX_BENCH_CALLGRIND
#include <valgrind/callgrind.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace sepax;
using V3d = Vec3<double>;
using V3f = Vec3<float>;
using Q = mpq_class;

// ---------------------------------------------------------------- random ----
// Fixed-seed, implementation-independent uniform doubles.
struct Rng {
  std::uint64_t s;
  explicit Rng(std::uint64_t seed) : s(seed) {}
  std::uint64_t next() {  // splitmix64
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  V3d unit() {  // uniform on the sphere, by rejection
    for (;;) {
      V3d p(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      const double n2 = p.squaredNorm();
      if (n2 > 1e-6 && n2 <= 1.0) return p / std::sqrt(n2);
    }
  }
};

struct Pose {
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  V3d t = V3d::Zero();
  V3d apply(const V3d& v) const { return r * v + t; }
};

Pose random_pose(Rng& rng, double dmin, double dmax) {
  Eigen::Quaterniond q(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1),
                       rng.uniform(-1, 1));
  while (q.squaredNorm() < 1e-3 || q.squaredNorm() > 1)
    q = Eigen::Quaterniond(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1),
                           rng.uniform(-1, 1));
  q.normalize();
  Pose p;
  p.r = q.toRotationMatrix();
  if (dmin <= 0) {  // uniform in the ball of radius dmax
    for (;;) {
      V3d t(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      if (t.squaredNorm() <= 1) {
        p.t = dmax * t;
        break;
      }
    }
  } else {
    p.t = rng.unit() * rng.uniform(dmin, dmax);
  }
  return p;
}

V3d to_d(const V3f& v) { return V3d(double(v[0]), double(v[1]), double(v[2])); }
V3f to_f(const V3d& v) {
  return V3f(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
}

// ----------------------------------------------------------------- shapes ----
// A local shape: float vertices (every row's input is float-valued) and faces.
struct Shape {
  ConvexPolyhedron<float> f;
  std::vector<std::vector<int>> faces;
};

std::vector<std::vector<int>> faces_of(const ConvexPolyhedron<float>& p) {
  std::vector<std::vector<int>> out;
  for (int i = 0; i < p.face_count(); ++i) out.push_back(p.face_vertices(i));
  return out;
}

// Hull of float-valued points with CGAL's exact-predicate convex_hull_3
// (triangulated; random points on a sphere have no four coplanar points, and
// the validation of from_faces would reject near-coplanar neighbours).
std::optional<Shape> sphere_hull(Rng& rng, int n) {
#if SEPAX_BENCH_HULL
  // sepax's own hull builder (exact decisions in double on float-valued points;
  // the output vertices are the input points), re-validated in float.
  std::vector<V3d> pts;
  for (int i = 0; i < n; ++i) pts.push_back(to_d(to_f(rng.unit())));
  try {
    const auto h = convex_hull<double>(pts);
    std::vector<V3f> verts;
    for (const auto& v : h.vertices()) verts.push_back(to_f(v));
    std::vector<std::vector<int>> faces;
    for (int f = 0; f < h.face_count(); ++f) faces.push_back(h.face_vertices(f));
    Shape s{ConvexPolyhedron<float>::from_faces(verts, faces), {}};
    s.faces = faces_of(s.f);
    return s;
  } catch (const InvalidInput&) {
    return std::nullopt;
  }
#else
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_3> pts;
  std::vector<V3f> fp;
  for (int i = 0; i < n; ++i) {
    const V3f p = to_f(rng.unit());
    fp.push_back(p);
    pts.emplace_back(double(p[0]), double(p[1]), double(p[2]));
  }
  CGAL::Surface_mesh<K::Point_3> sm;
  CGAL::convex_hull_3(pts.begin(), pts.end(), sm);
  std::map<std::tuple<double, double, double>, int> index;
  std::vector<V3f> verts;
  auto idx = [&](const K::Point_3& p) {
    auto key = std::make_tuple(p.x(), p.y(), p.z());
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    const int i = static_cast<int>(verts.size());
    verts.push_back(V3f(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())));
    index[key] = i;
    return i;
  };
  std::vector<std::vector<int>> faces;
  for (auto f : sm.faces()) {
    std::vector<int> loop;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) loop.push_back(idx(sm.point(v)));
    faces.push_back(loop);
  }
  try {
    Shape s{ConvexPolyhedron<float>::from_faces(verts, faces), {}};
    s.faces = faces_of(s.f);
    return s;
  } catch (const InvalidInput&) {
    return std::nullopt;  // resample (has not happened with the fixed seeds)
  }
#endif
}

// -------------------------------------------------------------- peers ----
#if SEPAX_BENCH_BULLET
struct BulletShape {
  std::unique_ptr<btConvexHullShape> hull;
  explicit BulletShape(const std::vector<V3f>& v) {
    hull = std::make_unique<btConvexHullShape>();
    for (const auto& p : v) hull->addPoint(btVector3(btScalar(p[0]), btScalar(p[1]), btScalar(p[2])), false);
    hull->recalcLocalAabb();
    hull->setMargin(0);  // sepax has no margin; Bullet's default 0.04 would bias depths
    hull->initializePolyhedralFeatures();  // for findSeparatingAxis (setup, not timed)
  }
};
#endif

#if SEPAX_BENCH_CCD
struct CcdShape {
  std::vector<double> xyz;  // float-valued doubles
  ccd_vec3_t centre;
};
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
void ccd_center(const void* obj, ccd_vec3_t* c) { ccdVec3Copy(c, &static_cast<const CcdShape*>(obj)->centre); }
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
#endif

// ----------------------------------------------------------------- cells ----
struct PairData {
  int a = 0;                    // index into the workload's pool (A is not moved)
  int b = 0;
  Pose pose;                    // B's pose
  std::vector<V3f> bverts;      // B's posed vertices (float-valued)
  ConvexPolyhedron<float> bf;   // B posed, float
  ConvexPolyhedron<double> bd;  // same vertices, double
  // exact reference (mpq SAT on the same float-valued vertices)
  bool ref_overlap = false;
  double ref_sep = 0;  // to_double of the exact separation (< 0: penetration depth)
#if SEPAX_BENCH_BULLET
  std::unique_ptr<BulletShape> bullet_b;
#endif
#if SEPAX_BENCH_CCD
  CcdShape ccd_b;
#endif
#if SEPAX_BENCH_FCL
  std::unique_ptr<FclShape> fcl_b;
#endif
};

struct Pool {
  std::vector<Shape> shapes;
  std::vector<ConvexPolyhedron<double>> d;
  std::vector<ConvexPolyhedron<Q>> q;
#if SEPAX_BENCH_TRAVERSAL
  std::vector<GaussMapWalk> walk;  // topology only: valid for posed and converted copies
#endif
#if SEPAX_BENCH_BULLET
  std::vector<std::unique_ptr<BulletShape>> bullet;
#endif
#if SEPAX_BENCH_CCD
  std::vector<CcdShape> ccd;
#endif
#if SEPAX_BENCH_FCL
  std::vector<std::unique_ptr<FclShape>> fcl;
#endif
};

struct Cell {
  std::string workload;  // "sphere16", "box", "cylinder32"
  int n = 0;             // points for sphere hulls; 0 otherwise
  std::string poses;     // "overlapping" / "separated"
  Pool* pool = nullptr;
  std::vector<PairData> pairs;
  std::vector<ConvexPolyhedron<Q>> bq;  // exact images of B (built on demand)
  int frames = 0;  // "moving": pairs are trajectories of `frames` consecutive poses
#if SEPAX_BENCH_CACHE
  std::vector<SatCache<float>> cache;  // one per trajectory
#endif
};

CcdShape make_ccd(const std::vector<V3f>& v) {
  CcdShape s;
  V3d c = V3d::Zero();
  for (const auto& p : v) {
    s.xyz.insert(s.xyz.end(), {double(p[0]), double(p[1]), double(p[2])});
    c += to_d(p);
  }
  c /= double(v.size());
#if SEPAX_BENCH_CCD
  ccdVec3Set(&s.centre, c[0], c[1], c[2]);
#endif
  return s;
}

void build_pool(Pool& pool, const std::string& kind, int n, Rng& rng, int count) {
  for (int i = 0; i < count; ++i) {
    if (kind == "sphere") {
      std::optional<Shape> s;
      while (!(s = sphere_hull(rng, n))) {
      }
      pool.shapes.push_back(std::move(*s));
    } else if (kind == "box") {
      auto b = shapes::box<float>(static_cast<float>(rng.uniform(0.3, 1.0)),
                                  static_cast<float>(rng.uniform(0.3, 1.0)),
                                  static_cast<float>(rng.uniform(0.3, 1.0)));
      pool.shapes.push_back(Shape{b, faces_of(b)});
    } else {
      auto c = shapes::prism<float>(32, 1.0, 0.5);
      pool.shapes.push_back(Shape{c, faces_of(c)});
    }
  }
  for (const auto& s : pool.shapes) {
    pool.d.push_back(ConvexPolyhedron<double>::convert_from(s.f));
    pool.q.push_back(ConvexPolyhedron<Q>::convert_from(s.f));
#if SEPAX_BENCH_TRAVERSAL
    pool.walk.emplace_back(s.f);
#endif
#if SEPAX_BENCH_BULLET
    pool.bullet.push_back(std::make_unique<BulletShape>(s.f.vertices()));
#endif
#if SEPAX_BENCH_CCD
    pool.ccd.push_back(make_ccd(s.f.vertices()));
#endif
#if SEPAX_BENCH_FCL
    pool.fcl.push_back(std::make_unique<FclShape>(s.f.vertices(), s.faces));
#endif
  }
}

std::vector<V3f> pose_vertices(const ConvexPolyhedron<float>& p, const Pose& pose) {
  std::vector<V3f> out;
  out.reserve(p.vertices().size());
  for (const auto& v : p.vertices()) out.push_back(to_f(pose.apply(to_d(v))));
  return out;
}

// Pose B of pair p (shape p.b at p.pose) once, in double rounded to float,
// build every row's copy of it from those same vertices (sepax float/double,
// Bullet, libccd, FCL), and append the pair to the cell.
void add_posed_pair(Cell& c, PairData p) {
  const auto& lb = c.pool->shapes[static_cast<std::size_t>(p.b)];
  p.bverts = pose_vertices(lb.f, p.pose);
  p.bf = lb.f.with_vertices(p.bverts);
  p.bd = ConvexPolyhedron<double>::convert_from(p.bf);
#if SEPAX_BENCH_BULLET
  p.bullet_b = std::make_unique<BulletShape>(p.bverts);
#endif
#if SEPAX_BENCH_CCD
  p.ccd_b = make_ccd(p.bverts);
#endif
#if SEPAX_BENCH_FCL
  p.fcl_b = std::make_unique<FclShape>(p.bverts, lb.faces);
#endif
  c.pairs.push_back(std::move(p));
}

void build_pairs(Cell& c, Rng& rng, int count) {
  const bool overlapping = c.poses == "overlapping";
  const int m = static_cast<int>(c.pool->shapes.size());
  for (int i = 0; i < count; ++i) {
    PairData p;
    p.a = static_cast<int>(rng.next() % static_cast<std::uint64_t>(m));
    p.b = static_cast<int>(rng.next() % static_cast<std::uint64_t>(m));
    p.pose = overlapping ? random_pose(rng, 0.0, 1.0) : random_pose(rng, 1.0, 2.5);
    add_posed_pair(c, std::move(p));
  }
}

// "moving": trajectories of slowly moving poses.  Each starts at a random pose
// with centres 1.0 to 2.5 apart and moves B, per frame, by 0.005 towards A and
// rotates it by 0.01 rad about a fixed random axis (so some trajectories end
// overlapping).  Frames are consecutive pairs; every row sees them in order.
void build_trajectories(Cell& c, Rng& rng, int count, int frames) {
  const int m = static_cast<int>(c.pool->shapes.size());
  c.frames = frames;
  for (int t = 0; t < count; ++t) {
    const int a = static_cast<int>(rng.next() % static_cast<std::uint64_t>(m));
    const int b = static_cast<int>(rng.next() % static_cast<std::uint64_t>(m));
    Pose pose = random_pose(rng, 1.0, 2.5);
    const V3d axis = rng.unit();
    const Eigen::Matrix3d step = Eigen::AngleAxisd(0.01, axis).toRotationMatrix();
    for (int f = 0; f < frames; ++f) {
      PairData p;
      p.a = a;
      p.b = b;
      p.pose = pose;
      add_posed_pair(c, std::move(p));
      pose.r = step * pose.r;
      const double d = pose.t.norm();
      if (d > 0.005) pose.t *= (d - 0.005) / d;
    }
  }
#if SEPAX_BENCH_CACHE
  c.cache.assign(static_cast<std::size_t>(count), SatCache<float>{});
#endif
}

void build_exact(Cell& c) {
  if (!c.bq.empty()) return;
  for (const auto& p : c.pairs) c.bq.push_back(ConvexPolyhedron<Q>::convert_from(p.bf));
}

// The exact reference: sepax's SAT in mpq_class on the same vertices.
void compute_reference(Cell& c) {
  build_exact(c);
  for (std::size_t i = 0; i < c.pairs.size(); ++i) {
    auto& p = c.pairs[i];
    const auto& a = c.pool->q[static_cast<std::size_t>(p.a)];
#if SEPAX_BENCH_TRAVERSAL
    const auto r = sat::traversal(a, c.pool->walk[static_cast<std::size_t>(p.a)], c.bq[i],
                                  c.pool->walk[static_cast<std::size_t>(p.b)]);
#else
    const auto r = sat::gauss_map(a, c.bq[i]);
#endif
    p.ref_overlap = r.overlap;
    p.ref_sep = r.separation_as_double();
  }
}

// ------------------------------------------------------------------- rows ----
struct Out {
  bool overlap = false;
  double sep = 0;     // signed separation (< 0: penetration depth); NaN if none
  bool failed = false;  // the method gave no answer (counted, not timed differently)
};

struct Row {
  std::string name;
  std::string group;  // "sepax" or "peer"
  std::function<Out(std::size_t)> run;
  std::size_t max_pairs = static_cast<std::size_t>(-1);  // slow rows run on a prefix of the pairs
};

template <class R>
Out from_sat(const R& r) {
  return Out{r.overlap, r.separation_as_double(), false};
}

const ConvexPolyhedron<float>& af(const Cell& c, std::size_t i) {
  return c.pool->shapes[static_cast<std::size_t>(c.pairs[i].a)].f;
}
const ConvexPolyhedron<double>& ad(const Cell& c, std::size_t i) {
  return c.pool->d[static_cast<std::size_t>(c.pairs[i].a)];
}
const ConvexPolyhedron<Q>& aq(const Cell& c, std::size_t i) {
  return c.pool->q[static_cast<std::size_t>(c.pairs[i].a)];
}
#if SEPAX_BENCH_TRAVERSAL
const GaussMapWalk& wa(const Cell& c, std::size_t i) {
  return c.pool->walk[static_cast<std::size_t>(c.pairs[i].a)];
}
const GaussMapWalk& wb(const Cell& c, std::size_t i) {
  return c.pool->walk[static_cast<std::size_t>(c.pairs[i].b)];
}
#endif

constexpr std::size_t kExactPairs = 16;
constexpr std::size_t kMinPairs = 16;
constexpr double kChunkTime = 0.001;
std::size_t g_contact_points = 0;

// Every row's closure holds only the Cell pointer (rows outlive make_rows).
std::vector<Row> make_rows(Cell& c) {
  std::vector<Row> rows;
  Cell* cp = &c;
  const int n = c.n;
  const bool small = n == 0 || n <= 64;  // brute force: O(E^2 (V+F)), skip beyond 64
  auto add = [&](std::string name, std::function<Out(std::size_t)> f) {
    rows.push_back(Row{std::move(name), "sepax", std::move(f)});
  };
  auto addp = [&](std::string name, std::function<Out(std::size_t)> f) {
    rows.push_back(Row{std::move(name), "peer", std::move(f)});
  };
  if (c.frames > 0) {  // moving poses: early-out and cached traversal (+ the rows kept below)
#if SEPAX_BENCH_TRAVERSAL
    add("traversal float early-out", [cp](std::size_t i) {
      SatOptions opt;
      opt.early_out = true;
      return from_sat(sat::traversal(af(*cp, i), wa(*cp, i), cp->pairs[i].bf, wb(*cp, i), opt));
    });
#if SEPAX_BENCH_CACHE
    // the cache of trajectory t is reset at its first frame, so every pass
    // replays the trajectories from a cold cache
    add("traversal float cached", [cp](std::size_t i) {
      auto& cache = cp->cache[i / static_cast<std::size_t>(cp->frames)];
      if (i % static_cast<std::size_t>(cp->frames) == 0) cache.reset();
      SatOptions opt;
      opt.early_out = true;
      const auto& A = af(*cp, i);
      const auto& B = cp->pairs[i].bf;
      const GaussMapWalk& WA = wa(*cp, i);
      const GaussMapWalk& WB = wb(*cp, i);
      return from_sat(sat::cached(cache, A, B, [&](auto& k, const SatOptions& o) {
        return sat::traversal_with(k, WA, WB, o);
      }, opt));
    });
#endif
#endif
  }
  // float plain
  if (small && c.frames == 0) add("brute float", [cp](std::size_t i) { return from_sat(sat::brute_force(af(*cp, i), cp->pairs[i].bf)); });
  add("gauss float", [cp](std::size_t i) { return from_sat(sat::gauss_map(af(*cp, i), cp->pairs[i].bf)); });
#if SEPAX_BENCH_TRAVERSAL
  add("traversal float", [cp](std::size_t i) {
    return from_sat(sat::traversal(af(*cp, i), wa(*cp, i), cp->pairs[i].bf, wb(*cp, i)));
  });
  // posing included: B's local shape, transformed and rebuilt inside the query
  add("traversal float +pose", [cp](std::size_t i) {
    const auto& lb = cp->pool->shapes[static_cast<std::size_t>(cp->pairs[i].b)].f;
    const auto posed = lb.with_vertices(pose_vertices(lb, cp->pairs[i].pose));
    return from_sat(sat::traversal(af(*cp, i), wa(*cp, i), posed, wb(*cp, i)));
  });
#if SEPAX_BENCH_CONTACTS
  add("traversal+manifold float", [cp](std::size_t i) {
    const auto& a = af(*cp, i);
    const auto& b = cp->pairs[i].bf;
    const auto r = sat::traversal(a, wa(*cp, i), b, wb(*cp, i));
    const auto m = contact_manifold(a, b, r);
    Out o = from_sat(r);
    g_contact_points += m.points.size();  // a global side effect: the manifold cannot be elided
    return o;
  });
#endif
#endif
#if SEPAX_BENCH_ROBUST
  if (small)
    add("brute float robust",
        [cp](std::size_t i) { return from_sat(sat::brute_force<policy::Robust>(af(*cp, i), cp->pairs[i].bf)); });
  add("gauss float robust",
      [cp](std::size_t i) { return from_sat(sat::gauss_map<policy::Robust>(af(*cp, i), cp->pairs[i].bf)); });
#if SEPAX_BENCH_TRAVERSAL
  add("traversal float robust",
      [cp](std::size_t i) {
        return from_sat(sat::traversal<policy::Robust>(af(*cp, i), wa(*cp, i), cp->pairs[i].bf, wb(*cp, i)));
      });
#endif
#endif
  // double plain
  if (small) add("brute double", [cp](std::size_t i) { return from_sat(sat::brute_force(ad(*cp, i), cp->pairs[i].bd)); });
  add("gauss double", [cp](std::size_t i) { return from_sat(sat::gauss_map(ad(*cp, i), cp->pairs[i].bd)); });
#if SEPAX_BENCH_TRAVERSAL
  add("traversal double", [cp](std::size_t i) {
    return from_sat(sat::traversal(ad(*cp, i), wa(*cp, i), cp->pairs[i].bd, wb(*cp, i)));
  });
#endif
  // exact (mpq_class): small shapes only and the first kExactPairs pairs; they are slow
  const bool cyl = c.workload.rfind("cylinder", 0) == 0;
  if ((n == 0 && !cyl) || (n > 0 && n <= 8)) {
    add("brute mpq", [cp](std::size_t i) { return from_sat(sat::brute_force(aq(*cp, i), cp->bq[i])); });
    rows.back().max_pairs = kExactPairs;
  }
  if (n == 0 || n <= 16) {
    add("gauss mpq", [cp](std::size_t i) { return from_sat(sat::gauss_map(aq(*cp, i), cp->bq[i])); });
    rows.back().max_pairs = kExactPairs;
  }
#if SEPAX_BENCH_TRAVERSAL
  if (n == 0 || n <= 64) {
    add("traversal mpq", [cp](std::size_t i) {
      return from_sat(sat::traversal(aq(*cp, i), wa(*cp, i), cp->bq[i], wb(*cp, i)));
    });
    rows.back().max_pairs = kExactPairs;
  }
#endif

  // ---- peers (pre-posed vertices, identity transforms) ----
#if SEPAX_BENCH_BULLET
  addp("bullet gjk+epa (float)", [cp](std::size_t i) {
    const auto& a = *cp->pool->bullet[static_cast<std::size_t>(cp->pairs[i].a)];
    const auto& b = *cp->pairs[i].bullet_b;
    btVoronoiSimplexSolver simplex;
    btGjkEpaPenetrationDepthSolver epa;
    btGjkPairDetector det(a.hull.get(), b.hull.get(), &simplex, &epa);
    btGjkPairDetector::ClosestPointInput in;
    in.m_transformA.setIdentity();
    in.m_transformB.setIdentity();
    btPointCollector out;
    det.getClosestPoints(in, out, nullptr);
    if (!out.m_hasResult) return Out{true, std::nan(""), true};
    return Out{out.m_distance <= 0, double(out.m_distance), false};
  });
  addp("bullet sat (float)", [cp](std::size_t i) {
    const auto& a = *cp->pool->bullet[static_cast<std::size_t>(cp->pairs[i].a)];
    const auto& b = *cp->pairs[i].bullet_b;
    btTransform id;
    id.setIdentity();
    btVector3 sep;
    btPointCollector res;
    const bool ov = btPolyhedralContactClipping::findSeparatingAxis(
        *a.hull->getConvexPolyhedron(), *b.hull->getConvexPolyhedron(), id, id, sep, res);
    if (!ov) return Out{false, std::nan(""), false};
    // depth along Bullet's axis: overlap of the two projections (reporting only)
    const V3d ax = V3d(double(sep.x()), double(sep.y()), double(sep.z())).normalized();
    double amin = HUGE_VAL, amax = -HUGE_VAL, bmin = HUGE_VAL, bmax = -HUGE_VAL;
    for (const auto& v : af(*cp, i).vertices()) {
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
#endif
#if SEPAX_BENCH_CCD
  auto ccd_init = [](ccd_t& ccd) {
    CCD_INIT(&ccd);
    ccd.support1 = ccd_support;
    ccd.support2 = ccd_support;
    ccd.center1 = ccd_center;
    ccd.center2 = ccd_center;
  };
  addp("ccd gjk+epa (double)", [cp, ccd_init](std::size_t i) {
    ccd_t ccd;
    ccd_init(ccd);
    ccd_real_t depth;
    ccd_vec3_t dir, pos;
    const int r = ccdGJKPenetration(&cp->pool->ccd[static_cast<std::size_t>(cp->pairs[i].a)], &cp->pairs[i].ccd_b, &ccd,
                                    &depth, &dir, &pos);
    if (r == 0) return Out{true, -double(depth), false};
    if (r == -2) return Out{true, std::nan(""), true};  // memory failure
    return Out{false, std::nan(""), false};
  });
  addp("ccd mpr (double)", [cp, ccd_init](std::size_t i) {
    ccd_t ccd;
    ccd_init(ccd);
    ccd_real_t depth;
    ccd_vec3_t dir, pos;
    const int r = ccdMPRPenetration(&cp->pool->ccd[static_cast<std::size_t>(cp->pairs[i].a)], &cp->pairs[i].ccd_b, &ccd,
                                    &depth, &dir, &pos);
    if (r == 0) return Out{true, -double(depth), false};
    return Out{false, std::nan(""), false};
  });
#endif
#if SEPAX_BENCH_FCL
  addp("fcl collide+contact (double)", [cp](std::size_t i) {
    fcl::CollisionRequestd req(1, true);
    fcl::CollisionResultd res;
    fcl::collide(cp->pool->fcl[static_cast<std::size_t>(cp->pairs[i].a)]->obj.get(), cp->pairs[i].fcl_b->obj.get(), req, res);
    if (!res.isCollision()) return Out{false, std::nan(""), false};
    return Out{true, -res.getContact(0).penetration_depth, false};
  });
#endif
  if (c.frames > 0) {  // moving poses: only these rows
    std::erase_if(rows, [](const Row& r) {
      return !(r.name.rfind("traversal float", 0) == 0 || r.name == "bullet gjk+epa (float)") ||
             r.name == "traversal float +pose";
    });
  }
  return rows;
}

bool needs_exact(const Row& r) { return r.name.find("mpq") != std::string::npos; }

// ----------------------------------------------------------------- timing ----
struct Measured {
  std::string workload, poses, row, group;
  int n = 0;
  double ns = 0;       // ns per query (min over batches)
  double ratio = 0;    // ns / baseline ns in the same cell
  int queries = 0;     // pairs per pass
  int disagree = 0;    // verdicts differing from the exact reference
  int failed = 0;      // no answer
  int depth_count = 0;  // overlapping pairs (both agree) with a depth
  double depth_med = 0, depth_max = 0;  // |depth - exact depth|
};

volatile double g_sink = 0;

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

Measured measure(Cell& c, Row& row, double min_time, double max_pass, std::vector<Out>& outs) {
  Measured m;
  m.workload = c.workload;
  m.poses = c.poses;
  m.row = row.name;
  m.group = row.group;
  m.n = c.n;
  std::size_t np = std::min(c.pairs.size(), row.max_pairs);
  outs.assign(np, Out{});
  // first pass: answers (also the warm-up).  A slow row stops after max_pass
  // seconds and at least kMinPairs pairs: it is then measured on that prefix
  // (its "verdict" column shows how many pairs it ran).
  double t0 = now_s();
  for (std::size_t i = 0; i < np; ++i) {
    outs[i] = row.run(i);
    if (i + 1 >= kMinPairs && now_s() - t0 > max_pass) {
      np = i + 1;
      outs.resize(np);
      break;
    }
  }
  m.queries = static_cast<int>(np);
  const double first = now_s() - t0;
  // Timing on a loaded machine: the pairs are cut into chunks of about
  // kChunkTime seconds (short enough to run within one scheduler slice); each
  // chunk is repeated and keeps its minimum time; ns/query is the sum of the
  // chunk minima over the pairs.  Rows whose first pass already took longer
  // than min_time get two more repetitions.
  const double per_pair = first / double(np);
  const std::size_t chunk =
      std::clamp<std::size_t>(static_cast<std::size_t>(kChunkTime / std::max(per_pair, 1e-12)), 1, np);
  std::vector<double> best_chunk;
  for (std::size_t b = 0; b < np; b += chunk) best_chunk.push_back(HUGE_VAL);
  const double start = now_s();
  for (int rep = 0; rep < 2 || (now_s() - start < min_time && rep < 1000); ++rep) {
    double sum = 0;
    for (std::size_t b = 0, k = 0; b < np; b += chunk, ++k) {
      const std::size_t e = std::min(np, b + chunk);
      t0 = now_s();
      for (std::size_t i = b; i < e; ++i) sum += row.run(i).sep;
      best_chunk[k] = std::min(best_chunk[k], now_s() - t0);
    }
    g_sink = g_sink + sum;
  }
  double best = 0;
  for (double t : best_chunk) best += t;
  m.ns = best * 1e9 / double(np);
  // verdicts and depth errors against the exact reference
  std::vector<double> err;
  for (std::size_t i = 0; i < np; ++i) {
    const auto& p = c.pairs[i];
    if (outs[i].failed) {
      ++m.failed;
      continue;
    }
    if (outs[i].overlap != p.ref_overlap) {
      ++m.disagree;
      std::fprintf(stderr, "[%s %s] %s: pair %zu says %s, exact says %s (exact separation %.17g)\n",
                   c.workload.c_str(), c.poses.c_str(), row.name.c_str(), i,
                   outs[i].overlap ? "overlap" : "separated", p.ref_overlap ? "overlap" : "separated",
                   p.ref_sep);
      continue;
    }
    if (p.ref_overlap && !std::isnan(outs[i].sep)) err.push_back(std::abs(outs[i].sep - p.ref_sep));
  }
  m.depth_count = static_cast<int>(err.size());
  if (!err.empty()) {
    std::sort(err.begin(), err.end());
    m.depth_med = err[err.size() / 2];
    m.depth_max = err.back();
  }
  return m;
}

#if SEPAX_BENCH_TRAVERSAL
// Mean walk counters of the float traversal over a cell's pairs (diagnostics).
std::string traversal_counters(const Cell& c) {
  sat::TraversalStats sum;
  std::int64_t edge_pairs = 0;
  for (std::size_t i = 0; i < c.pairs.size(); ++i) {
    sat::TraversalStats ts;
    kernel_t<policy::Plain, float> k(af(c, i), c.pairs[i].bf);
    const auto r = sat::traversal_with(k, wa(c, i), wb(c, i), SatOptions{}, &ts);
    edge_pairs += r.stats.edge_pairs;
    sum.support_scans += ts.support_scans;
    sum.climb_steps += ts.climb_steps;
    sum.height_evals += ts.height_evals;
    sum.arc_tests += ts.arc_tests;
    sum.corner_passes += ts.corner_passes;
    sum.fallback_arcs += ts.fallback_arcs;
    sum.pruned_faces += ts.pruned_faces;
    sum.probe_checks += ts.probe_checks;
    sum.probe_pruned += ts.probe_pruned;
    sum.pruned_arcs += ts.pruned_arcs;
    sum.late_certified += ts.late_certified;
  }
  const double np = double(c.pairs.size());
  const auto& a0 = af(c, 0);
  char buf[600];
  std::snprintf(buf, sizeof buf, "  %-11s %-11s E_A=%-4d arc tests %9.1f  (E_A*E_B %d)  height evals %8.1f  climb %7.1f  "
              "fallback arcs %6.2f  corner passes %5.2f  pruned faces %6.1f (of %d; by a probe %5.1f of %5.1f)  pruned arcs %6.1f  late climbs %5.1f\n",
              c.workload.c_str(), c.poses.c_str(), a0.edge_count(), double(sum.arc_tests) / np,
              a0.edge_count() * c.pairs[0].bf.edge_count(), double(sum.height_evals) / np,
              double(sum.climb_steps) / np, double(sum.fallback_arcs) / np,
              double(sum.corner_passes) / np, double(sum.pruned_faces) / np,
              a0.face_count() + c.pairs[0].bf.face_count(), double(sum.probe_pruned) / np,
              double(sum.probe_checks) / np, double(sum.pruned_arcs) / np,
              double(sum.late_certified) / np);
  (void)edge_pairs;
  return buf;
}
#endif

// ------------------------------------------------------------------ main ----
struct Options {
  bool quick = false;
  double min_time = 0.2;
  double max_pass = 1.0;
  int pairs = 64;
  std::string filter;
  std::string json;
  bool callgrind = false;
  std::string cg_row, cg_workload, cg_poses = "overlapping";
  int cg_passes = 10;
};

struct WorkloadSpec {
  std::string name, kind;
  int n;
};

std::vector<WorkloadSpec> workloads(const Options& o) {
  std::vector<WorkloadSpec> w;
  for (int n : {4, 8, 16, 32, 64, 128, 256}) {
    if (o.quick && n > 64) continue;
    w.push_back({"sphere" + std::to_string(n), "sphere", n});
  }
  w.push_back({"box", "box", 0});
  w.push_back({"cylinder32", "cylinder", 0});
  w.push_back({"moving16", "sphere", 16});
  w.push_back({"moving64", "sphere", 64});
  return w;
}

void print_header() {
  std::printf("%-11s %-11s %-30s %11s %9s %7s %5s %10s %10s\n", "workload", "poses", "row",
              "ns/query", "x trav", "verdict", "fail", "depth-err", "depth-err");
  std::printf("%-11s %-11s %-30s %11s %9s %7s %5s %10s %10s\n", "", "", "", "", "", "diff", "",
              "median", "max");
}

void print_row(const Measured& m) {
  std::printf("%-11s %-11s %-30s %11.1f %9.2f %4d/%-3d %4d %10.2e %10.2e\n", m.workload.c_str(),
              m.poses.c_str(), m.row.c_str(), m.ns, m.ratio, m.disagree, m.queries, m.failed,
              m.depth_med, m.depth_max);
  std::fflush(stdout);
}

// JSON has no NaN: a number or null.
std::string num(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream o;
  o.precision(6);
  o << v;
  return o.str();
}

void write_json(const std::string& path, const std::vector<Measured>& all) {
  std::ofstream f(path);
  f << "[\n";
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto& m = all[i];
    f << "  {\"workload\": \"" << m.workload << "\", \"n\": " << m.n << ", \"poses\": \"" << m.poses
      << "\", \"row\": \"" << m.row << "\", \"group\": \"" << m.group << "\", \"ns\": " << num(m.ns)
      << ", \"ratio_to_traversal\": " << num(m.ratio) << ", \"queries\": " << m.queries
      << ", \"verdict_disagreements\": " << m.disagree << ", \"failed\": " << m.failed
      << ", \"depth_pairs\": " << m.depth_count << ", \"depth_err_median\": " << num(m.depth_med)
      << ", \"depth_err_max\": " << num(m.depth_max) << "}" << (i + 1 < all.size() ? "," : "") << "\n";
  }
  f << "]\n";
}

const Measured* find(const std::vector<Measured>& all, const std::string& w, const std::string& poses,
                     const std::string& row) {
  for (const auto& m : all)
    if (m.workload == w && m.poses == poses && m.row == row) return &m;
  return nullptr;
}

void print_targets(const std::vector<Measured>& all) {
  std::printf("\nTargets (float, overlapping poses, ratios of ns/query in this run):\n");
  auto ratio = [&](const std::string& w, const std::string& slow, const std::string& fast) -> double {
    const auto* s = find(all, w, "overlapping", slow);
    const auto* f = find(all, w, "overlapping", fast);
    if (!s || !f || f->ns <= 0) return std::nan("");
    return s->ns / f->ns;
  };
  auto line = [](const std::string& what, double got, double need, bool at_least) {
    const bool ok = !std::isnan(got) && (at_least ? got >= need : got <= need);
    std::printf("  %-58s %8.2f  (%s %.2f)  %s\n", what.c_str(), got, at_least ? ">=" : "<=", need,
                std::isnan(got) ? "NOT MEASURED" : (ok ? "met" : "MISSED"));
  };
  const int ns[] = {4, 8, 16, 32};
  const double need[] = {3, 8, 25, 50};
  for (int i = 0; i < 4; ++i) {
    const std::string w = "sphere" + std::to_string(ns[i]);
    line("gauss over brute, " + w, ratio(w, "brute float", "gauss float"), need[i], true);
  }
  line("traversal over gauss, sphere32", ratio("sphere32", "gauss float", "traversal float"), 5, true);
  line("traversal over gauss, sphere128", ratio("sphere128", "gauss float", "traversal float"), 20, true);
  for (int n : {8, 16, 32, 64, 128, 256}) {
    const std::string w = "sphere" + std::to_string(n);
    line("bullet gjk+epa over robust traversal, " + w,
         ratio(w, "bullet gjk+epa (float)", "traversal float robust"), 3, true);
  }
  for (int n : {16, 32, 64}) {
    const std::string w = "sphere" + std::to_string(n);
    line("robust over plain traversal, " + w, ratio(w, "traversal float robust", "traversal float"),
         1.15, false);
    line("traversal+manifold over traversal, " + w,
         ratio(w, "traversal+manifold float", "traversal float"), 1.30, false);
  }
  std::printf("  robust traversal depth error (max over overlapping pairs, per workload):\n");
  for (const auto& m : all)
    if (m.row == "traversal float robust" && m.poses == "overlapping")
      std::printf("    %-11s max %.3g  (float unit roundoff 2^-24 = %.3g)\n", m.workload.c_str(),
                  m.depth_max, 0x1.0p-24);
}

void setup_cell(Cell& c, const WorkloadSpec& spec, const std::string& poses, Pool& pool, int pairs) {
  c.workload = spec.name;
  c.n = spec.n;
  c.poses = poses;
  c.pool = &pool;
  if (poses == "moving") {
    Rng prng(3003u);
    build_trajectories(c, prng, std::max(2, pairs / 16), 32);
  } else {
    Rng prng(poses == "overlapping" ? 1001u : 2002u);
    build_pairs(c, prng, pairs);
  }
}

int run_callgrind(const Options& o) {
#if SEPAX_BENCH_CALLGRIND
  for (const auto& spec : workloads(Options{})) {
    if (spec.name != o.cg_workload) continue;
    Rng rng(0x5e9a7 + static_cast<std::uint64_t>(spec.n) * 7919 + spec.kind.size());
    Pool pool;
    build_pool(pool, spec.kind, spec.n, rng, 8);
    Cell c;
    setup_cell(c, spec, spec.name.rfind("moving", 0) == 0 ? "moving" : o.cg_poses, pool, o.pairs);
    for (auto& row : make_rows(c)) {
      if (row.name != o.cg_row) continue;
      if (needs_exact(row)) build_exact(c);
      double s = 0;
      for (std::size_t i = 0; i < c.pairs.size(); ++i) s += row.run(i).sep;  // warm-up
      CALLGRIND_START_INSTRUMENTATION;
      for (int k = 0; k < o.cg_passes; ++k)
        for (std::size_t i = 0; i < c.pairs.size(); ++i) s += row.run(i).sep;
      CALLGRIND_STOP_INSTRUMENTATION;
      g_sink = g_sink + s;
      std::printf("queries %zu\n", c.pairs.size() * static_cast<std::size_t>(o.cg_passes));
      return 0;
    }
  }
  std::fprintf(stderr, "no such row/workload\n");
  return 2;
#else
  (void)o;
  std::fprintf(stderr, "built without valgrind/callgrind.h\n");
  return 2;
#endif
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto val = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--quick") o.quick = true;
    else if (a == "--min-time") o.min_time = std::stod(val());
    else if (a == "--max-pass") o.max_pass = std::stod(val());
    else if (a == "--pairs") o.pairs = std::stoi(val());
    else if (a == "--filter") o.filter = val();
    else if (a == "--json") o.json = val();
    else if (a == "--callgrind") o.callgrind = true;
    else if (a == "--row") o.cg_row = val();
    else if (a == "--workload") o.cg_workload = val();
    else if (a == "--poses") o.cg_poses = val();
    else if (a == "--passes") o.cg_passes = std::stoi(val());
    else {
      std::fprintf(stderr,
                   "usage: %s [--quick] [--min-time S] [--max-pass S] [--pairs P] [--filter SUBSTR] [--workload W] [--json FILE]\n"
                   "       %s --callgrind --row NAME --workload W [--poses P] [--passes K]\n",
                   argv[0], argv[0]);
      return 2;
    }
  }
  if (o.pairs < 1) {
    std::fprintf(stderr, "--pairs must be >= 1\n");
    return 2;
  }
  if (o.callgrind) return run_callgrind(o);

  std::printf("sepax_bench: %d pairs per pose set; B pre-posed for every row (see bench.md)\n",
              o.pairs);
#if SEPAX_BENCH_BULLET
  std::printf("Bullet btScalar: %s, margin 0\n", sizeof(btScalar) == 4 ? "float" : "double");
#endif
#if SEPAX_BENCH_TRAVERSAL
  const std::string baseline = "traversal float";
#else
  const std::string baseline = "gauss float";
  std::printf("(sat_traversal.hpp not available: ratios are to the Gauss-map SAT)\n");
#endif
  std::printf("reference: sepax %s SAT in mpq_class on the same float-valued vertices\n\n",
#if SEPAX_BENCH_TRAVERSAL
              "traversal"
#else
              "gauss-map"
#endif
  );
  print_header();
  std::vector<Measured> all;
  std::vector<std::string> counters;
  for (const auto& spec : workloads(o)) {
    if (!o.cg_workload.empty() && spec.name != o.cg_workload) continue;
    Rng rng(0x5e9a7 + static_cast<std::uint64_t>(spec.n) * 7919 + spec.kind.size());
    Pool pool;
    build_pool(pool, spec.kind, spec.n, rng, 8);
    const bool moving = spec.name.rfind("moving", 0) == 0;
    for (const std::string poses : {"overlapping", "separated", "moving"}) {
      if (moving != (poses == "moving")) continue;
      Cell c;
      setup_cell(c, spec, poses, pool, o.pairs);
      const double tr = now_s();
      compute_reference(c);
      std::fprintf(stderr, "[%s %s: exact reference %.1f s]\n", c.workload.c_str(), c.poses.c_str(),
                   now_s() - tr);
#if SEPAX_BENCH_TRAVERSAL
      counters.push_back(traversal_counters(c));
#endif
      std::vector<Measured> cell;
      std::vector<Out> outs;
      for (auto& row : make_rows(c)) {
        if (!o.filter.empty() && row.name.find(o.filter) == std::string::npos && row.name != baseline)
          continue;
        if (needs_exact(row)) build_exact(c);
        cell.push_back(measure(c, row, o.min_time, o.max_pass, outs));
      }
      if (c.frames > 0) {
        int ov = 0;
        for (const auto& p : c.pairs) ov += p.ref_overlap ? 1 : 0;
        char buf[300];
        std::int64_t hits = 0, misses = 0;
#if SEPAX_BENCH_CACHE
        // counters of the last pass (each trajectory's cache is reset at its first frame)
        for (const auto& k : c.cache) {
          hits += k.hits;
          misses += k.misses;
        }
#endif
        std::snprintf(buf, sizeof buf,
                      "  %-11s %-11s %zu frames, %d overlapping (exact); cache hits %lld, misses %lld\n",
                      c.workload.c_str(), c.poses.c_str(), c.pairs.size(), ov,
                      static_cast<long long>(hits), static_cast<long long>(misses));
        counters.push_back(buf);
      }
      double base = 0;
      for (const auto& m : cell)
        if (m.row == baseline) base = m.ns;
      for (auto& m : cell) {
        m.ratio = base > 0 ? m.ns / base : std::nan("");
        print_row(m);
        all.push_back(m);
      }
      std::printf("\n");
    }
  }
  print_targets(all);
  if (!counters.empty()) {
    std::printf("\nTraversal walk counters (float, plain; mean per query):\n");
    for (const auto& l : counters) std::printf("%s", l.c_str());
  }
  if (!o.json.empty()) write_json(o.json, all);
  return 0;
}
