#include "workloads.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <sepax/convex_hull.hpp>
#include <sepax/sat_traversal.hpp>
#include <sepax/shapes.hpp>

namespace bench {

using namespace sepax;

std::vector<WorkloadSpec> workloads(bool quick) {
  std::vector<WorkloadSpec> w;
  for (int n : {4, 8, 16, 32, 64, 128, 256}) {
    if (quick && n > 64) continue;
    w.push_back({"sphere" + std::to_string(n), "sphere", n});
  }
  w.push_back({"box", "box", 0});
  w.push_back({"cylinder32", "cylinder", 0});
  w.push_back({"moving16", "sphere", 16});
  w.push_back({"moving64", "sphere", 64});
  return w;
}

std::vector<std::string> pose_sets(const WorkloadSpec& w) {
  if (w.name.rfind("moving", 0) == 0) return {"moving"};
  std::vector<std::string> out{"overlapping", "separated"};
  if (w.kind == "box" || (w.kind == "sphere" && w.n >= 16)) {
    for (const char* s : {"resting", "sliding", "rolling", "hovering"}) out.emplace_back(s);
  }
  return out;
}

namespace {

std::vector<std::vector<int>> faces_of(const ConvexPolyhedron<float>& p) {
  std::vector<std::vector<int>> out;
  for (int i = 0; i < p.face_count(); ++i) out.push_back(p.face_vertices(i));
  return out;
}

double extent_of(const ConvexPolyhedron<float>& p) {
  V3d lo = V3d::Constant(HUGE_VAL), hi = V3d::Constant(-HUGE_VAL);
  for (const auto& v : p.vertices()) {
    lo = lo.cwiseMin(to_d(v));
    hi = hi.cwiseMax(to_d(v));
  }
  return (hi - lo).maxCoeff();
}

// Hull of N float-valued points on the unit sphere (sepax's hull builder: the
// output vertices are input points), re-validated in float; nullopt when float
// validation refuses it (the caller draws again).
std::optional<Shape> sphere_hull(Rng& rng, int n) {
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
}

// A rotation by angle about a unit axis.
Eigen::Matrix3d rotation_about(const V3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d(axis[0], axis[1], axis[2])).toRotationMatrix();
}

RigidTransform<float> to_float(const Pose& p) {
  RigidTransform<float> x;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) x.rotation(i, j) = static_cast<float>(p.r(i, j));
  x.translation = to_f(p.t);
  return x;
}

// Pose B by p.rel once (double, rounded to float), fill the pair's world poses
// and margin, and append the pair to the cell.
void add_pair(Cell& c, PairData p, Rng& world) {
  const Pool& pool = *c.pool;
  const Shape& la = pool.shapes[static_cast<std::size_t>(p.a)];
  const Shape& lb = pool.shapes[static_cast<std::size_t>(p.b)];
  p.bverts = pose_vertices(lb.f, p.rel);
  p.bf = lb.f.with_vertices(p.bverts);
  p.bd = ConvexPolyhedron<double>::convert_from(p.bf);
  if (c.frames == 0 || c.pairs.size() % static_cast<std::size_t>(c.frames) == 0) {
    p.world_a = random_pose(world, 0.0, 4.0);  // a new pair: A somewhere in the world
  } else {
    p.world_a = c.pairs.back().world_a;  // a trajectory: A stays put
  }
  p.pose_a = to_float(p.world_a);
  p.pose_b = to_float(p.world_a * p.rel);
  p.margin = static_cast<float>(0.02 * std::max(la.extent, lb.extent));
  c.pairs.push_back(std::move(p));
}

void build_pairs(Cell& c, Rng& rng, int count) {
  Rng world(rng.next());
  const bool overlapping = c.poses == "overlapping";
  const int m = static_cast<int>(c.pool->shapes.size());
  for (int i = 0; i < count; ++i) {
    PairData p;
    p.a = rng.below(m);
    p.b = rng.below(m);
    p.rel = overlapping ? random_pose(rng, 0.0, 1.0) : random_pose(rng, 1.0, 2.5);
    add_pair(c, std::move(p), world);
  }
}

// "moving": trajectories of slowly moving poses.  Each starts at a random pose
// with centres 1.0 to 2.5 apart and moves B, per frame, by 0.005 towards A and
// rotates it by 0.01 rad about a fixed random axis (so some trajectories end
// overlapping).
void build_moving(Cell& c, Rng& rng, int count, int frames) {
  Rng world(rng.next());
  const int m = static_cast<int>(c.pool->shapes.size());
  c.frames = frames;
  for (int t = 0; t < count; ++t) {
    const int a = rng.below(m);
    const int b = rng.below(m);
    Pose pose = random_pose(rng, 1.0, 2.5);
    const Eigen::Matrix3d step = rotation_about(rng.unit(), 0.01);
    for (int f = 0; f < frames; ++f) {
      PairData p;
      p.a = a;
      p.b = b;
      p.rel = pose;
      add_pair(c, std::move(p), world);
      pose.r = step * pose.r;
      const double d = pose.t.norm();
      if (d > 0.005) pose.t *= (d - 0.005) / d;
    }
  }
}

// The SAT separation (double, pre-posed) of A and B with B at rel.
double separation_at(const Pool& pool, int a, int b, const Pose& rel) {
  const auto& lb = pool.shapes[static_cast<std::size_t>(b)].f;
  std::vector<V3d> v;
  for (const auto& p : lb.vertices()) v.push_back(rel.apply(to_d(p)));
  const auto bd = ConvexPolyhedron<double>::convert_from(lb).with_vertices(std::move(v));
  const auto r = sat::traversal(pool.d[static_cast<std::size_t>(a)], pool.walk[static_cast<std::size_t>(a)],
                                bd, pool.walk[static_cast<std::size_t>(b)]);
  return r.separation_as_double();
}

// The offset s along d at which B (rotation r, centre s d + tangent) has SAT
// separation -depth from A: bisection on [0, 4 extent] (the separation is
// convex in s, negative at the centre, positive far out: one crossing).
Pose in_contact(const Pool& pool, int a, int b, const Eigen::Matrix3d& r, const V3d& d, const V3d& tangent,
                double depth) {
  const double far =
      4 * (pool.shapes[static_cast<std::size_t>(a)].extent + pool.shapes[static_cast<std::size_t>(b)].extent);
  double lo = 0, hi = far;
  for (int k = 0; k < 50; ++k) {
    const double mid = 0.5 * (lo + hi);
    const Pose p{r, V3d(mid * d + tangent)};
    (separation_at(pool, a, b, p) + depth > 0 ? hi : lo) = mid;
  }
  return Pose{r, V3d(0.5 * (lo + hi) * d + tangent)};
}

// resting / sliding / rolling / hovering: `count` trajectories of `frames`
// steps each.
void build_coherent(Cell& c, Rng& rng, int count, int frames) {
  Rng world(rng.next());
  const Pool& pool = *c.pool;
  const int m = static_cast<int>(pool.shapes.size());
  c.frames = frames;
  for (int t = 0; t < count; ++t) {
    const int a = rng.below(m);
    const int b = rng.below(m);
    const double extent = std::max(pool.shapes[static_cast<std::size_t>(a)].extent,
                                   pool.shapes[static_cast<std::size_t>(b)].extent);
    const double depth = 0.005 * extent;
    const V3d d = rng.unit();                        // contact direction, A towards B
    const V3d u = d.cross(rng.unit()).normalized();  // sliding / rolling direction
    const V3d w = d.cross(u);                        // rolling axis
    const Eigen::Matrix3d r0 = rng.rotation();
    const Pose rest = in_contact(pool, a, b, r0, d, V3d::Zero(), depth);
    for (int f = 0; f < frames; ++f) {
      PairData p;
      p.a = a;
      p.b = b;
      if (c.poses == "resting") {
        const Eigen::Matrix3d jitter = rotation_about(rng.unit(), 2e-4);
        p.rel = Pose{jitter * rest.r, V3d(rest.t + rng.in_ball(2e-4))};
      } else if (c.poses == "sliding") {
        p.rel = in_contact(pool, a, b, r0, d, V3d(0.004 * f * u), depth);
      } else if (c.poses == "rolling") {
        p.rel = in_contact(pool, a, b, rotation_about(w, 0.01 * f) * r0, d, V3d(0.01 * f * u), depth);
      } else {  // hovering: separated by a gap of 10% of the extent, turning and drifting
        p.rel =
            in_contact(pool, a, b, rotation_about(w, 0.01 * f) * r0, d, V3d(0.004 * f * u), -0.1 * extent);
      }
      add_pair(c, std::move(p), world);
    }
  }
}

}  // namespace

std::vector<V3f> pose_vertices(const ConvexPolyhedron<float>& p, const Pose& pose) {
  std::vector<V3f> out;
  out.reserve(p.vertices().size());
  for (const auto& v : p.vertices()) out.push_back(to_f(pose.apply(to_d(v))));
  return out;
}

void build_pool(Pool& pool, const WorkloadSpec& spec, Rng& rng, int count) {
  pool.kind = spec.kind;
  for (int i = 0; i < count; ++i) {
    if (spec.kind == "sphere") {
      std::optional<Shape> s;
      while (!(s = sphere_hull(rng, spec.n))) {
      }
      pool.shapes.push_back(std::move(*s));
    } else if (spec.kind == "box") {
      const V3d h(rng.uniform(0.3, 1.0), rng.uniform(0.3, 1.0), rng.uniform(0.3, 1.0));
      const V3f hf = to_f(h);  // every row gets the same float-valued half extents
      auto b = shapes::box<float>(double(hf[0]), double(hf[1]), double(hf[2]));
      pool.shapes.push_back(Shape{b, faces_of(b), to_d(hf)});
    } else {
      auto c = shapes::prism<float>(32, 1.0, 0.5);
      pool.shapes.push_back(Shape{c, faces_of(c)});
    }
  }
  for (auto& s : pool.shapes) {
    s.extent = extent_of(s.f);
    pool.d.push_back(ConvexPolyhedron<double>::convert_from(s.f));
    pool.walk.emplace_back(s.f);
#if SEPAX_BENCH_PREPARED
    pool.prepared.push_back(std::make_unique<PreparedShape<float>>(s.f));
#endif
  }
}

void setup_cell(Cell& c, const WorkloadSpec& spec, const std::string& poses, Pool& pool, int pairs) {
  c.workload = spec.name;
  c.n = spec.n;
  c.poses = poses;
  c.pool = &pool;
  if (poses == "moving") {
    Rng prng(3003u);
    build_moving(c, prng, std::max(2, pairs / 16), 32);
  } else if (poses == "resting" || poses == "sliding" || poses == "rolling" || poses == "hovering") {
    Rng prng(poses == "resting" ? 4004u : poses == "sliding" ? 5005u : poses == "rolling" ? 6006u : 7007u);
    build_coherent(c, prng, std::max(2, pairs / 32), 120);
  } else {
    Rng prng(poses == "overlapping" ? 1001u : 2002u);
    build_pairs(c, prng, pairs);
  }
}

}  // namespace bench
