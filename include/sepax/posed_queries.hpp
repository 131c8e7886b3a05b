// sepax/posed_queries.hpp
//
// The SATs on prepared shapes at poses (included by prepared_shape.hpp):
//
//   sat::traversal<Policy>(a, pose_a, b, pose_b, opt = {}, cache = nullptr)
//   sat::gauss_map<Policy>(...), sat::brute_force<Policy>(...)  (same parameters)
//
// Each works in A's frame on (A, B'), B' = posed(B, relative_pose(pose_a,
// pose_b)) (posing.hpp: the exact definition of the input), and returns
// exactly what the same SAT returns on (a.polyhedron(), B') - feature,
// verdict, separation, stats - except that the axis is mapped to world
// coordinates: pose_a.rotate(axis) (separation is frame-invariant).
//
// Allocation: none per query for float/double (B' lives in per-thread
// scratch, prepared_shape.hpp; the traversal's walk data is the prepared
// shapes'; its per-face scratch is on the stack up to kTraversalInlineFaces
// faces in total).
//
// cache: optional per-pair SatCache (sat_cache.hpp); its guarantee is the
// one stated there, with the cached feature's indices being those of the
// prepared shapes (the same at every pose).
#pragma once

#include "prepared_shape.hpp"
#include "sat.hpp"
#include "contact_manifold.hpp"
#include "sat_cache.hpp"

namespace sepax::sat {

namespace detail {

/// The posed query: B moved into A's frame, the kernel built on (A, B'),
/// run(k) the SAT, the axis mapped to world.
template <class Policy, Number T, class Run>
SatResult<T> posed_query(const PreparedShape<T>& a, const RigidTransform<T>& pose_a, const PreparedShape<T>& b,
                         const RigidTransform<T>& pose_b, const SatOptions& opt, SatCache<T>* cache, Run&& run) {
  check_options(opt);
  if (a.polyhedron().empty()) throw InvalidInput(ErrorCode::TooFewPoints, "PreparedShape A is empty (moved from)");
  const ConvexPolyhedron<T>& bp = b.posed_scratch(relative_pose(pose_a, pose_b));
  kernel_t<Policy, T> k(a.polyhedron(), bp);
  SatResult<T> r = cache ? cached_with(k, *cache, opt, run) : run(k, opt);
  r.axis = pose_a.rotate(r.axis);
  return r;
}

}  // namespace detail

/// Posed traversal SAT (see the header comment).
template <class Policy = policy::Plain, Number T>
SatResult<T> traversal(const PreparedShape<T>& a, const RigidTransform<T>& pose_a, const PreparedShape<T>& b,
                       const RigidTransform<T>& pose_b, const SatOptions& opt = {}, SatCache<T>* cache = nullptr) {
  return detail::posed_query<Policy>(a, pose_a, b, pose_b, opt, cache, [&](auto& k, const SatOptions& o) {
    return traversal_with(k, a.walk(), b.walk(), o);
  });
}

/// Posed Gauss-map SAT (see the header comment).
template <class Policy = policy::Plain, Number T>
SatResult<T> gauss_map(const PreparedShape<T>& a, const RigidTransform<T>& pose_a, const PreparedShape<T>& b,
                       const RigidTransform<T>& pose_b, const SatOptions& opt = {}, SatCache<T>* cache = nullptr) {
  return detail::posed_query<Policy>(a, pose_a, b, pose_b, opt, cache,
                                     [](auto& k, const SatOptions& o) { return gauss_map_with(k, o); });
}

/// Posed brute-force SAT (see the header comment).
template <class Policy = policy::Plain, Number T>
SatResult<T> brute_force(const PreparedShape<T>& a, const RigidTransform<T>& pose_a, const PreparedShape<T>& b,
                         const RigidTransform<T>& pose_b, const SatOptions& opt = {}, SatCache<T>* cache = nullptr) {
  return detail::posed_query<Policy>(a, pose_a, b, pose_b, opt, cache,
                                     [](auto& k, const SatOptions& o) { return brute_force_with(k, o); });
}

/// All three behind one entry point (sat.hpp's run), posed.
template <class Policy = policy::Plain, Number T>
SatResult<T> run(SatAlgorithm algorithm, const PreparedShape<T>& a, const RigidTransform<T>& pose_a,
                 const PreparedShape<T>& b, const RigidTransform<T>& pose_b, const SatOptions& opt = {},
                 SatCache<T>* cache = nullptr) {
  switch (algorithm) {
    case SatAlgorithm::brute_force: return brute_force<Policy>(a, pose_a, b, pose_b, opt, cache);
    case SatAlgorithm::traversal: return traversal<Policy>(a, pose_a, b, pose_b, opt, cache);
    case SatAlgorithm::gauss_map: break;
  }
  return gauss_map<Policy>(a, pose_a, b, pose_b, opt, cache);
}

}  // namespace sepax::sat

namespace sepax {

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
  if (a.polyhedron().empty()) throw InvalidInput(ErrorCode::TooFewPoints, "PreparedShape A is empty (moved from)");
  const ConvexPolyhedron<T>& bp = b.posed_scratch(relative_pose(pose_a, pose_b));
  ManifoldOptions mo;
  mo.margin = opt.margin;
  ContactManifold<T> m = contact_manifold(a.polyhedron(), bp, r, mo);
  for (auto& p : m.points) {
    p.position = pose_a.apply(p.position);
    p.point_a = pose_a.apply(p.point_a);
    p.point_b = pose_a.apply(p.point_b);
  }
  m.normal = r.axis;
  return m;
}

}  // namespace sepax
