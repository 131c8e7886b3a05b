// sepax/posed_queries.hpp
//
// The SATs on prepared shapes at poses (included by prepared_shape.hpp):
//
//   sat::traversal<Policy>(a, pose_a, b, pose_b, opt = {}, cache = nullptr)
//   sat::gauss_map<Policy>(...), sat::brute_force<Policy>(...)  (same parameters)
//
// Each works in A's frame on (A, B'), B' = posed(B, relative_pose(pose_a,
// pose_b)) (posing.hpp: the exact definition of the input), and returns
// exactly what the same SAT returns on (a.polyhedron(), B'), the axis mapped
// to world coordinates.  Steps of a query (posed_query):
//   1. with opt.early_out: the cache's feature (warm_hit), then the margin
//      pre-check (margin_precheck), each on B's posed vertices and only the
//      plane or edge it reads;
//   2. otherwise the rest of B' derived into per-thread scratch and the SAT run.
// No allocation per query for float/double.  Each step in detail: on
// sat::traversal below.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <type_traits>

#include "prepared_shape.hpp"
#include "sat.hpp"
#include "contact_manifold.hpp"
#include "sat_cache.hpp"

namespace sepax::sat {

namespace detail {

/// The faces and edges of B' that re-evaluating feature f reads (reevaluate,
/// sat_cache.hpp); false when f's indices are out of range for (A, B) or a
/// side feature's shapes are not both flat (reevaluate answers nullopt then:
/// the query runs the SAT).
template <Number T>
bool feature_parts(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b, const Feature& f,
                   std::array<int, 2>& faces, int& nfaces, int& edge) {
  nfaces = 0;
  edge = -1;
  switch (f.type) {
    case FeatureType::FaceA:
      return f.a >= 0 && f.a < a.face_count();  // B's vertices only
    case FeatureType::FaceB:
      if (!(f.b >= 0 && f.b < b.face_count())) return false;
      faces[0] = f.b;
      nfaces = 1;
      return true;
    case FeatureType::EdgePair:
      if (!(f.a >= 0 && f.a < a.edge_count() && f.b >= 0 && f.b < b.edge_count())) return false;
      faces = {b.edge_face(f.b, 0), b.edge_face(f.b, 1)};
      nfaces = 2;
      edge = f.b;
      return true;
    case FeatureType::SideA:
      return f.a >= 0 && f.a < a.edge_count() && a.is_flat() && b.is_flat();
    case FeatureType::SideB:
      if (!(f.b >= 0 && f.b < b.edge_count() && a.is_flat() && b.is_flat())) return false;
      faces = {b.edge_face(f.b, 0), b.edge_face(f.b, 1)};
      nfaces = 2;
      edge = f.b;
      return true;
  }
  return false;
}

/// The warm early-out check of a posed query (the cache's hit, sat_cache.hpp):
/// the cached feature re-evaluated on the partial image of B' that holds
/// B's posed vertices and only the planes and edge that feature reads
/// (posing.hpp, "Staged posing"), with the kernel built on it.  The same
/// decision and the same values as cache_hit on the full B' (exact_fallbacks
/// may count fewer: the bound of a few planes is tighter); nullopt if the
/// feature does not separate beyond the margin (the query then derives the
/// rest of B' and runs the SAT).
template <class Policy, Number T>
std::optional<SatResult<T>> warm_hit(const PreparedShape<T>& a, const PreparedShape<T>& b,
                                     const RigidTransform<T>& x, SatCache<T>& cache, const SatOptions& opt) {
  std::array<int, 2> faces{};
  int nfaces = 0, edge = -1;
  if (!feature_parts(a.polyhedron(), b.polyhedron(), cache.feature, faces, nfaces, edge)) return std::nullopt;
  const ConvexPolyhedron<T>& bp =
      b.posed_part_scratch(x, std::span<const int>(faces.data(), static_cast<std::size_t>(nfaces)),
                           std::span<const int>(&edge, edge >= 0 ? 1u : 0u));
  kernel_t<Policy, T> k(a.polyhedron(), bp);
  return cache_hit(k, cache, opt);
}

/// The margin pre-check of a posed query with early_out (float/double; see
/// sat::traversal below).  With d = c(B') - c(A) (centroids, in A's frame):
/// the face of A whose normal is best aligned with d, then the face of B
/// whose normal is best aligned with -d (found among B's local normals with
/// R^T(-d), R = x.rotation), each evaluated by the kernel exactly as every
/// SAT evaluates a face (face_query_a / face_query_b) and returned when it
/// separates beyond the margin (stops_early).  Estimates skip the work that
/// cannot succeed (a choice, never a decision: a skipped pair runs the SAT):
/// a face's separation is at most its plane's height of the other shape's
/// centroid minus that shape's inner radius (PreparedShape::inner_radius),
/// and no axis separates by more than |d| - r_A - r_B.  part(faces) gives B'
/// with at least the planes of `faces` derived: the partial image of the
/// posed query, or the full pre-posed B' (the tests' reference).
template <class Policy, Number T, class Part>
std::optional<SatResult<T>> margin_precheck_with(const PreparedShape<T>& pa, const PreparedShape<T>& pb,
                                                 const RigidTransform<T>& x, const SatOptions& opt,
                                                 Part&& part) {
  const ConvexPolyhedron<T>& a = pa.polyhedron();
  const ConvexPolyhedron<T>& bv = part(std::span<const int>());
  const Vec3<T>& ca = a.centroid();
  const Vec3<T>& cb = bv.centroid();
  const Vec3<T> d(T(cb[0] - ca[0]), T(cb[1] - ca[1]), T(cb[2] - ca[2]));
  const double ra = pa.inner_radius(), rb = pb.inner_radius();
  const double dd = static_cast<double>(d[0]) * static_cast<double>(d[0]) +
                    static_cast<double>(d[1]) * static_cast<double>(d[1]) +
                    static_cast<double>(d[2]) * static_cast<double>(d[2]);
  const double reach = ra + rb + opt.margin;
  if (!(dd > reach * reach)) return std::nullopt;
  std::int64_t fallbacks = 0;
  const int fa = pa.most_aligned_face(d);
  const Plane<T>& pla = a.plane(fa);
  if (static_cast<double>(dot(pla.normal, cb)) - static_cast<double>(pla.offset) - rb > opt.margin) {
    kernel_t<Policy, T> k(a, bv);
    const auto q = k.face_query_a(fa);
    const Feature f = Feature::face_a(fa, q.support_vertex);
    if (stops_early(k, q.separation, f, opt)) return early_out_result(k, f, q.separation);
    fallbacks = k.exact_fallbacks();
  }
  // in B's local frame: e = R^T(-d), and A's centroid u = R^T(c(A) - t)
  const auto& r = x.rotation;
  const Vec3<T> ct(T(ca[0] - x.translation[0]), T(ca[1] - x.translation[1]), T(ca[2] - x.translation[2]));
  Vec3<T> e, u;
  for (int j = 0; j < 3; ++j) {
    e[j] = T(-(r(0, j) * d[0] + r(1, j) * d[1] + r(2, j) * d[2]));
    u[j] = T(r(0, j) * ct[0] + r(1, j) * ct[1] + r(2, j) * ct[2]);
  }
  const int gb = pb.most_aligned_face(e);
  const Plane<T>& plb = pb.polyhedron().plane(gb);
  if (!(static_cast<double>(dot(plb.normal, u)) - static_cast<double>(plb.offset) - ra > opt.margin))
    return std::nullopt;
  const ConvexPolyhedron<T>& bp = part(std::span<const int>(&gb, 1));
  kernel_t<Policy, T> k(a, bp);
  const auto q = k.face_query_b(gb);
  const Feature f = Feature::face_b(q.support_vertex, gb);
  if (!stops_early(k, q.separation, f, opt)) return std::nullopt;
  SatResult<T> res = early_out_result(k, f, q.separation);
  res.stats.face_axes = 2;
  res.stats.exact_fallbacks += fallbacks;
  return res;
}

/// A valid cache whose last answer was not beyond the margin (a pair in
/// contact or close; a coherent pair stays so): the query skips the margin
/// pre-check (a choice, never a decision: the SAT runs).
template <Number T>
bool cache_says_near(const SatCache<T>* cache, const SatOptions& opt) {
  return cache != nullptr && cache->valid && !(sepax::to_double(cache->separation) > opt.margin);
}

/// margin_precheck_with on the posed query's partial image of B'.
template <class Policy, Number T>
std::optional<SatResult<T>> margin_precheck(const PreparedShape<T>& a, const PreparedShape<T>& b,
                                            const RigidTransform<T>& x, const SatOptions& opt) {
  return margin_precheck_with<Policy>(a, b, x, opt,
                                      [&](std::span<const int> faces) -> const ConvexPolyhedron<T>& {
                                        return b.posed_part_scratch(x, faces, std::span<const int>());
                                      });
}

/// The posed query: B moved into A's frame, the kernel built on (A, B'),
/// run(k) the SAT, the axis mapped to world.  kEdgeLanes: run reads B's
/// edge lane arrays (sat::gauss_map's batched arc test); the others run on
/// B' without them (PreparedShape::posed_scratch).  With early_out and a valid
/// cache, the cached feature is checked first on a partial B' (warm_hit).
template <class Policy, bool kEdgeLanes, Number T, class Run>
SatResult<T> posed_query(const PreparedShape<T>& a, const RigidTransform<T>& pose_a,
                         const PreparedShape<T>& b, const RigidTransform<T>& pose_b, const SatOptions& opt,
                         SatCache<T>* cache, Run&& run) {
  check_options(opt);
  if (a.polyhedron().empty())
    throw InvalidInput(ErrorCode::TooFewPoints, "PreparedShape A is empty (moved from)");
  const RigidTransform<T> x = relative_pose(pose_a, pose_b);
  if (cache && opt.early_out && cache->valid) {
    if (auto hit = warm_hit<Policy>(a, b, x, *cache, opt)) {
      hit->axis = pose_a.rotate(hit->axis);
      return *hit;
    }
  }
  if constexpr (std::is_floating_point_v<T>) {
    if (opt.early_out && !cache_says_near(cache, opt)) {
      if (auto pre = margin_precheck<Policy>(a, b, x, opt)) {
        if (cache) cache->remember(pre->feature, pre->separation);
        pre->axis = pose_a.rotate(pre->axis);
        return *pre;
      }
    }
  }
  const ConvexPolyhedron<T>& bp = b.posed_scratch_from(x, pose_a, pose_b, kEdgeLanes);
  kernel_t<Policy, T> k(a.polyhedron(), bp);
  SatResult<T> r = cache ? cached_run(k, *cache, opt, run) : run(k, opt, nullptr);
  r.axis = pose_a.rotate(r.axis);
  return r;
}

}  // namespace detail

/// Posed traversal SAT.  It works in A's frame on (A, B'), B' = posed(B, relative_pose(pose_a,
/// pose_b)) (posing.hpp: the exact definition of the input), and returns
/// exactly what the same SAT returns on (a.polyhedron(), B') - feature,
/// verdict, separation, stats - except that the axis is mapped to world
/// coordinates: pose_a.rotate(axis) (separation is frame-invariant).
///
/// With opt.early_out two checks come first, each decided by the kernel on
/// B's posed vertices and only the plane or edge of B' it reads (posing.hpp,
/// "Staged posing"); only when both fail is the rest of B' derived and the
/// SAT run:
///   1. the cache's feature (cache valid): SatCache's early-out hit;
///   2. the margin pre-check (float/double): the face of A best aligned with
///      c(B') - c(A) and the face of B best aligned with c(A) - c(B')
///      (centroids), evaluated as every SAT evaluates a face
///      (face_query_a / face_query_b); the first that separates beyond the
///      margin (stops_early) is the answer (with a cache, the cache takes
///      it).  Inner-radius estimates skip it where it cannot succeed, and
///      so does a cache whose last answer was not beyond the margin.
/// Either answer is an early-out answer as SatOptions defines it: a feature
/// whose separation is greater than the margin (exactly so under
/// policy::Robust and for exact T), early_out set, not necessarily the
/// feature the SAT would meet first; the verdict is the SAT's.  Without
/// early_out nothing changes: the SAT's full result, bit for bit.
///
/// Allocation: none per query for float/double (B' lives in per-thread
/// scratch, prepared_shape.hpp; the traversal's walk data is the prepared
/// shapes'; its per-face scratch is on the stack up to kTraversalInlineFaces
/// faces in total).
///
/// cache: optional per-pair SatCache (sat_cache.hpp), warm start included;
/// its guarantee is the one stated there (a cached query returns the fresh
/// query's feature, separation and verdict; with early_out a re-checked
/// feature beyond the margin answers at once), the cached feature's indices
/// being those of the prepared shapes (the same at every pose).  A cache from
/// another pair or stale shapes only costs one re-evaluation.
template <class Policy = policy::Plain, Number T>
SatResult<T> traversal(const PreparedShape<T>& a, const RigidTransform<T>& pose_a, const PreparedShape<T>& b,
                       const RigidTransform<T>& pose_b, const SatOptions& opt = {},
                       SatCache<T>* cache = nullptr) {
  return detail::posed_query<Policy, false>(a, pose_a, b, pose_b, opt, cache,
                                            [&](auto& k, const SatOptions& o, const Feature* seed) {
                                              return traversal_with(k, a.walk(), b.walk(), o, nullptr, seed);
                                            });
}

/// Posed Gauss-map SAT: as the posed traversal above, with sat::gauss_map.
template <class Policy = policy::Plain, Number T>
SatResult<T> gauss_map(const PreparedShape<T>& a, const RigidTransform<T>& pose_a, const PreparedShape<T>& b,
                       const RigidTransform<T>& pose_b, const SatOptions& opt = {},
                       SatCache<T>* cache = nullptr) {
  return detail::posed_query<Policy, true>(
      a, pose_a, b, pose_b, opt, cache,
      [](auto& k, const SatOptions& o, const Feature* seed) { return gauss_map_with(k, o, seed); });
}

/// Posed brute-force SAT: as the posed traversal above, with sat::brute_force.
template <class Policy = policy::Plain, Number T>
SatResult<T> brute_force(const PreparedShape<T>& a, const RigidTransform<T>& pose_a,
                         const PreparedShape<T>& b, const RigidTransform<T>& pose_b,
                         const SatOptions& opt = {}, SatCache<T>* cache = nullptr) {
  return detail::posed_query<Policy, false>(
      a, pose_a, b, pose_b, opt, cache,
      [](auto& k, const SatOptions& o, const Feature* seed) { return brute_force_with(k, o, seed); });
}

/// All three behind one entry point (sat.hpp's run), posed.
template <class Policy = policy::Plain, Number T>
SatResult<T> run(SatAlgorithm algorithm, const PreparedShape<T>& a, const RigidTransform<T>& pose_a,
                 const PreparedShape<T>& b, const RigidTransform<T>& pose_b, const SatOptions& opt = {},
                 SatCache<T>* cache = nullptr) {
  switch (algorithm) {
    case SatAlgorithm::brute_force:
      return brute_force<Policy>(a, pose_a, b, pose_b, opt, cache);
    case SatAlgorithm::traversal:
      return traversal<Policy>(a, pose_a, b, pose_b, opt, cache);
    case SatAlgorithm::gauss_map:
      break;
  }
  return gauss_map<Policy>(a, pose_a, b, pose_b, opt, cache);
}

}  // namespace sepax::sat

namespace sepax {

namespace detail {

/// The posed contact_manifold below on a given image bp of B in A's frame:
/// built in A's frame as contact_manifold(a, bp, r_local), the points mapped
/// to world by pose_a and normal = r.axis.  bp is posed(B, X) or a partial
/// image of it (PreparedShape::posed_part_scratch) holding every plane the
/// manifold reads: for a face of A, the faces of B' around the support
/// vertex (the incident face's candidates); for a face of B, that face.
/// The same manifold, bit for bit, on either.
template <Number T>
ContactManifold<T> posed_manifold_on(const ConvexPolyhedron<T>& a, const RigidTransform<T>& pose_a,
                                     const ConvexPolyhedron<T>& bp, const SatResult<T>& r,
                                     const SatOptions& opt) {
  ManifoldOptions mo;
  mo.margin = opt.margin;
  ContactManifold<T> m = contact_manifold(a, bp, r, mo);
  const sepax::detail::PointMap<T> to_world(pose_a);  // pose_a.apply, bit for bit
  for (auto& p : m.points) {
    p.position = to_world(p.position);
    p.point_a = to_world(p.point_a);
    p.point_b = to_world(p.point_b);
  }
  m.normal = r.axis;
  return m;
}

}  // namespace detail

/// The contact manifold of a posed pair from a posed SAT result `r` of the
/// same pair and poses (sat::traversal / gauss_map / brute_force on prepared
/// shapes): built in A's frame on (A, B') exactly as contact_manifold(A, B',
/// r_local) builds it (r_local: r with its local axis), then the points mapped
/// to world by pose_a (pose_a.apply) and normal = r.axis (world).  Keeps the
/// points within opt.margin (ManifoldOptions::margin); at most 4 (reduce).
/// No allocation for float/double (inline capacities: contact_manifold.hpp;
/// B' is the posed query's, reused when the poses are the same).
template <Number T>
ContactManifold<T> contact_manifold(const PreparedShape<T>& a, const RigidTransform<T>& pose_a,
                                    const PreparedShape<T>& b, const RigidTransform<T>& pose_b,
                                    const SatResult<T>& r, const SatOptions& opt = {}) {
  check_options(opt);
  if (a.polyhedron().empty())
    throw InvalidInput(ErrorCode::TooFewPoints, "PreparedShape A is empty (moved from)");
  return detail::posed_manifold_on(a.polyhedron(), pose_a, b.posed_scratch_between(pose_a, pose_b, false), r,
                                   opt);
}

}  // namespace sepax
