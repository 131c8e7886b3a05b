// python/src/query_core.hpp
//
// The C++ side of the Python module that runs without the GIL: posed queries
// on prepared shapes in one number type, their results flattened to doubles
// and indices (QueryOut), and the batch loop writing into caller-owned
// arrays.  No pybind11 here: module.cpp converts to and from Python objects
// while holding the GIL, exact.cpp instantiates the same templates for the
// GMP rationals.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <sepax/contact_manifold.hpp>
#include <sepax/prepared_shape.hpp>
#include <sepax/robust/robust_kernel.hpp>

namespace sepax::python {

/// A pose as the module receives it: world = R local + t, R row-major.
struct PoseD {
  std::array<double, 9> r{1, 0, 0, 0, 1, 0, 0, 0, 1};
  std::array<double, 3> t{0, 0, 0};
};

/// The pose in T: every entry converted with from_double (exact for exact
/// T).  Rigidity is checked by the posed query (posing.hpp).
template <Number T>
RigidTransform<T> to_transform(const PoseD& p) {
  RigidTransform<T> x;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) x.rotation(i, j) = from_double<T>(p.r[static_cast<std::size_t>(3 * i + j)]);
    x.translation[i] = from_double<T>(p.t[static_cast<std::size_t>(i)]);
  }
  return x;
}

struct QueryOptions {
  SatAlgorithm algorithm = SatAlgorithm::traversal;
  bool robust = true;  // float/double only: policy::Robust
  bool early_out = false;
  double margin = 0.0;
  bool manifold = true;
};

struct PointOut {
  std::array<double, 3> position{}, point_a{}, point_b{};
  double separation = 0;
  ContactFeatureId id;
};

/// One query's answer in doubles (reporting values; every decision was made
/// in the query's number type and policy).
struct QueryOut {
  bool overlap = false;
  bool early_out = false;
  double separation = 0;
  std::array<double, 3> axis{};  // unit, world (exact T: the exact axis normalised in double)
  Feature feature;
  SatStats stats;
  // exact T only: the exact separation num / sqrt(norm2) as "p/q" strings
  std::string separation_num, separation_norm2;
  bool has_manifold = false;
  ContactKind kind = ContactKind::None;
  std::array<double, 3> normal{};
  int reference_shape = -1, reference_face = -1, incident_face = -1;
  std::vector<PointOut> points;
};

template <Number T>
std::array<double, 3> to_array(const Vec3<T>& v) {
  return {to_double(v[0]), to_double(v[1]), to_double(v[2])};
}

/// v normalised in double (exact T keep unnormalised axes; float/double
/// axes are unit already and are returned as computed).
template <Number T>
std::array<double, 3> unit_array(const Vec3<T>& v) {
  const Vec3<double> u = unit_as_double(v);
  return {u[0], u[1], u[2]};
}

/// How exact numbers are written into QueryOut (exact.cpp: mpq's "p/q").
template <Number T>
std::string exact_string(const T&) {
  return {};
}

template <class Policy, Number T>
SatResult<T> posed_sat(const QueryOptions& o, const PreparedShape<T>& a, const RigidTransform<T>& pa,
                       const PreparedShape<T>& b, const RigidTransform<T>& pb, SatCache<T>* cache) {
  SatOptions so;
  so.early_out = o.early_out;
  so.margin = o.margin;
  return sat::run<Policy>(o.algorithm, a, pa, b, pb, so, cache);
}

/// One posed query (and its manifold when asked and not stopped early).
template <Number T>
void run_query(const QueryOptions& o, const PreparedShape<T>& a, const PoseD& pose_a,
               const PreparedShape<T>& b, const PoseD& pose_b, SatCache<T>* cache, QueryOut& out) {
  const RigidTransform<T> pa = to_transform<T>(pose_a), pb = to_transform<T>(pose_b);
  SatResult<T> r;
  if constexpr (number_traits<T>::is_exact) {
    r = posed_sat<policy::Plain>(o, a, pa, b, pb, cache);
  } else {
    r = o.robust ? posed_sat<policy::Robust>(o, a, pa, b, pb, cache)
                 : posed_sat<policy::Plain>(o, a, pa, b, pb, cache);
  }
  out.overlap = r.overlap;
  out.early_out = r.early_out;
  out.separation = r.separation_as_double();
  out.axis = unit_array(r.axis);
  out.feature = r.feature;
  out.stats = r.stats;
  if constexpr (number_traits<T>::is_exact) {
    out.separation_num = exact_string(r.separation.num);
    out.separation_norm2 = exact_string(r.separation.norm2);
  }
  out.has_manifold = false;
  out.points.clear();
  if (!o.manifold || r.early_out) return;
  SatOptions so;
  so.margin = o.margin;
  const ContactManifold<T> m = contact_manifold(a, pa, b, pb, r, so);
  out.has_manifold = true;
  out.kind = m.kind;
  out.normal = unit_array(m.normal);
  out.reference_shape = m.reference_shape;
  out.reference_face = m.reference_face;
  out.incident_face = m.incident_face;
  for (const auto& p : m.points) {
    PointOut q;
    q.position = to_array(p.position);
    q.point_a = to_array(p.point_a);
    q.point_b = to_array(p.point_b);
    q.separation = to_double(p.separation);
    q.id = p.id;
    out.points.push_back(q);
  }
}

/// The batch's output columns (caller-owned, K rows each; contact columns
/// only when the manifold is asked for: kBatchPoints points per row, unused
/// slots NaN / -1).
inline constexpr int kBatchPoints = 4;  // ContactManifold keeps at most 4 (reduce)

struct BatchColumns {
  bool* overlap = nullptr;
  bool* early_out = nullptr;
  double* separation = nullptr;
  double* axis = nullptr;  // K x 3
  std::int8_t* feature_type = nullptr;
  std::int32_t* feature = nullptr;  // K x 2 (a, b)
  std::int64_t* exact_fallbacks = nullptr;
  std::int32_t* contact_count = nullptr;  // K
  double* contact_points = nullptr;       // K x 4 x 3
  double* contact_separations = nullptr;  // K x 4
  std::int32_t* contact_ids = nullptr;    // K x 4 x 4 (kind A, index A, kind B, index B)
};

/// Poses of a batch: K rows of PoseD for each side, or one broadcast.
struct BatchPoses {
  const PoseD* a = nullptr;
  std::size_t a_count = 0;
  const PoseD* b = nullptr;
  std::size_t b_count = 0;
  std::size_t k = 0;
};

/// The batch: row i is run_query on (poses.a[i or 0], poses.b[i or 0]),
/// with one cache carried from row to row when `cache` is given.
template <Number T>
void run_batch(const QueryOptions& o, const PreparedShape<T>& a, const PreparedShape<T>& b,
               const BatchPoses& poses, SatCache<T>* cache, const BatchColumns& c) {
  QueryOut q;
  const double nan = std::nan("");
  for (std::size_t i = 0; i < poses.k; ++i) {
    run_query(o, a, poses.a[poses.a_count == 1 ? 0 : i], b, poses.b[poses.b_count == 1 ? 0 : i], cache, q);
    c.overlap[i] = q.overlap;
    c.early_out[i] = q.early_out;
    c.separation[i] = q.separation;
    for (std::size_t j = 0; j < 3; ++j) c.axis[3 * i + j] = q.axis[j];
    c.feature_type[i] = static_cast<std::int8_t>(q.feature.type);
    c.feature[2 * i] = q.feature.a;
    c.feature[2 * i + 1] = q.feature.b;
    c.exact_fallbacks[i] = q.stats.exact_fallbacks;
    if (!c.contact_count) continue;
    const std::size_t n = std::min<std::size_t>(q.points.size(), kBatchPoints);
    c.contact_count[i] = static_cast<std::int32_t>(n);
    for (std::size_t p = 0; p < static_cast<std::size_t>(kBatchPoints); ++p) {
      const std::size_t row = i * kBatchPoints + p;
      const bool used = p < n;
      for (std::size_t j = 0; j < 3; ++j)
        c.contact_points[3 * row + j] = used ? q.points[p].position[j] : nan;
      c.contact_separations[row] = used ? q.points[p].separation : nan;
      const ContactFeatureId id = used ? q.points[p].id : ContactFeatureId{};
      c.contact_ids[4 * row + 0] = used ? static_cast<std::int32_t>(id.a.kind) : -1;
      c.contact_ids[4 * row + 1] = used ? id.a.index : -1;
      c.contact_ids[4 * row + 2] = used ? static_cast<std::int32_t>(id.b.kind) : -1;
      c.contact_ids[4 * row + 3] = used ? id.b.index : -1;
    }
  }
}

/// The per-edge-pair sign table of an audit: for every edge pair (ea, eb),
/// row ea * |E_B| + eb, the four triple-product signs of the Minkowski-face
/// test (ArcSigns: cba, dba, adc, bdc) and whether the edges are parallel,
/// as kernel K decides them.
struct SignTable {
  std::vector<std::int8_t> signs;      // rows x 4
  std::vector<std::uint8_t> parallel;  // rows
};

template <SatKernel K>
void fill_sign_table(K& k, int edges_a, int edges_b, SignTable& t) {
  const auto rows = static_cast<std::size_t>(edges_a) * static_cast<std::size_t>(edges_b);
  t.signs.assign(4 * rows, 0);
  t.parallel.assign(rows, 0);
  std::size_t r = 0;
  for (int ea = 0; ea < edges_a; ++ea) {
    for (int eb = 0; eb < edges_b; ++eb, ++r) {
      const ArcSigns s = k.arc_signs(ea, eb);
      t.signs[4 * r + 0] = static_cast<std::int8_t>(s.cba);
      t.signs[4 * r + 1] = static_cast<std::int8_t>(s.dba);
      t.signs[4 * r + 2] = static_cast<std::int8_t>(s.adc);
      t.signs[4 * r + 3] = static_cast<std::int8_t>(s.bdc);
      t.parallel[r] = k.edges_parallel(ea, eb) ? 1 : 0;
    }
  }
}

/// The sign table of A and B' = B posed into A's frame (the input every
/// posed query decides on) under Policy.
template <class Policy, Number T>
void sign_table(const PreparedShape<T>& a, const PoseD& pose_a, const PreparedShape<T>& b,
                const PoseD& pose_b, SignTable& t) {
  const ConvexPolyhedron<T>& bp =
      b.posed_scratch(relative_pose(to_transform<T>(pose_a), to_transform<T>(pose_b)));
  kernel_t<Policy, T> k(a.polyhedron(), bp);
  fill_sign_table(k, a.polyhedron().edge_count(), bp.edge_count(), t);
}

// ---- the exact number type (exact.cpp: mpq_class), behind opaque handles ----

struct ExactShape;  // PreparedShape<mpq_class>
struct ExactCache;  // SatCache<mpq_class>

/// The exact image of a double shape (same topology and plane triples).
std::shared_ptr<const ExactShape> make_exact_shape(const ConvexPolyhedron<double>& p);
std::unique_ptr<ExactCache, void (*)(ExactCache*)> make_exact_cache();
std::int64_t exact_cache_hits(const ExactCache& c);
std::int64_t exact_cache_misses(const ExactCache& c);
void reset_exact_cache(ExactCache& c);
void run_query_exact(const QueryOptions& o, const ExactShape& a, const PoseD& pose_a, const ExactShape& b,
                     const PoseD& pose_b, ExactCache* cache, QueryOut& out);
/// detail::check_rigid (posing.hpp) of the pose in mpq_class, as run_query_exact makes it.
void check_rigid_exact(const PoseD& p);
/// The exact sign table of the exact images of a and b (both in one frame):
/// what the robust policy's decisions on (a, b) must equal.
void exact_sign_table(const ConvexPolyhedron<double>& a, const ConvexPolyhedron<double>& b, SignTable& t);
void exact_sign_table(const ConvexPolyhedron<float>& a, const ConvexPolyhedron<float>& b, SignTable& t);
void run_batch_exact(const QueryOptions& o, const ExactShape& a, const ExactShape& b, const BatchPoses& poses,
                     ExactCache* cache, const BatchColumns& c);

}  // namespace sepax::python
