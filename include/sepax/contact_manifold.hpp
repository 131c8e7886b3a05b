// sepax/contact_manifold.hpp
//
// contact_manifold: contact points of two overlapping (or nearly touching)
// convex polyhedra, from the result of any SAT (sat::brute_force,
// sat::gauss_map, sat::traversal; any policy), by the kind of its feature:
//   * a face normal of A or B: the face contact (face_contact.hpp): the
//     incident face clipped by the reference face's side planes, at most four
//     points;
//   * an edge pair: one point between the two edges (edge_contact.hpp);
//   * a side axis of two coplanar flat polygons: the 2D face contact within a
//     speculative margin (edge_contact.hpp).
// The result and options: manifold_result.hpp; conventions: docs/contacts.md.
// For exact T and rational inputs everything is exact.
#pragma once

#include <cmath>
#include <string>

#include "edge_contact.hpp"
#include "error.hpp"
#include "face_contact.hpp"
#include "manifold_result.hpp"
#include "sat_gauss_map.hpp"
#include "sat_result.hpp"

namespace sepax {

/// The contact manifold of A and B from a SAT result `sat` for the same pair
/// (both shapes in one frame).  Throws InvalidInput when the options are bad
/// (negative or non-finite margin) or the SAT result refers to features the
/// shapes do not have.
template <Number T>
ContactManifold<T> contact_manifold(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b,
                                    const SatResult<T>& sat, const ManifoldOptions& opt = {}) {
  if (!std::isfinite(opt.margin)) {
    throw InvalidInput(ErrorCode::NonFinite, "contact_manifold: the speculative margin is not finite");
  }
  if (opt.margin < 0) {
    throw InvalidInput(ErrorCode::BadScale, "contact_manifold: the speculative margin " +
                                                format_number(opt.margin) + " is negative");
  }
  ContactManifold<T> m;
  m.feature = sat.feature;
  m.normal = sat.axis;
  m.norm2 = sat.separation.norm2;
  m.separation = sat.separation;
  if (a.empty() || b.empty()) return m;
  const T margin = from_double<T>(opt.margin);
  if (!detail::within_margin(sat.separation, margin)) return m;
  using detail::check_index;
  switch (sat.feature.type) {
    case FeatureType::FaceA: {
      check_index(sat.feature.a, a.face_count(), "face of A");
      int v = sat.feature.b;
      if (v < 0) v = detail::support_vertex(b, a.plane(sat.feature.a).normal);
      check_index(v, b.vertex_count(), "support vertex of B");
      detail::face_contact(a, b, true, sat.feature.a, v, margin, opt, m);
      break;
    }
    case FeatureType::FaceB: {
      check_index(sat.feature.b, b.face_count(), "face of B");
      int v = sat.feature.a;
      if (v < 0) v = detail::support_vertex(a, b.plane(sat.feature.b).normal);
      check_index(v, a.vertex_count(), "support vertex of A");
      detail::face_contact(a, b, false, sat.feature.b, v, margin, opt, m);
      break;
    }
    case FeatureType::EdgePair: {
      check_index(sat.feature.a, a.edge_count(), "edge of A");
      check_index(sat.feature.b, b.edge_count(), "edge of B");
      detail::edge_contact(a, b, sat.feature.a, sat.feature.b, m);
      break;
    }
    case FeatureType::SideA: {
      check_index(sat.feature.a, a.edge_count(), "edge of A");
      check_index(sat.feature.b, b.vertex_count(), "support vertex of B");
      detail::side_contact(a, b, true, sat.feature.a, sat.feature.b, margin, m);
      break;
    }
    case FeatureType::SideB: {
      check_index(sat.feature.b, b.edge_count(), "edge of B");
      check_index(sat.feature.a, a.vertex_count(), "support vertex of A");
      detail::side_contact(a, b, false, sat.feature.b, sat.feature.a, margin, m);
      break;
    }
  }
  return m;
}

/// Convenience: run `sat_fn(a, b)` (any callable returning SatResult<T>) and
/// build the manifold from its result.
template <Number T, class SatFn>
ContactManifold<T> contact_manifold_with(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b,
                                         SatFn&& sat_fn, const ManifoldOptions& opt = {}) {
  const SatResult<T> r = sat_fn(a, b);
  return contact_manifold(a, b, r, opt);
}

/// Convenience: sat::gauss_map under `Policy`, then the manifold.
template <class Policy = policy::Plain, Number T>
ContactManifold<T> contact_manifold(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b,
                                    const ManifoldOptions& opt = {}) {
  return contact_manifold(a, b, sat::gauss_map<Policy>(a, b), opt);
}

}  // namespace sepax
