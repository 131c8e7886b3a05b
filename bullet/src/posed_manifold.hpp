// The adapter's contact of a posed pair and its manifold in world
// coordinates: the contact type contact_choice.hpp prefers, from the posed
// SAT result or from the face the adapter keeps between steps, and sepax's
// posed contact_manifold (posed_queries.hpp, no allocation) on it.  B' (B in
// A's frame) is the one the posed SAT query has just left in this thread's
// scratch (PreparedShape::posed_scratch returns it without posing again at
// the same relative pose x).
#pragma once

#include <sepax/contact_manifold.hpp>
#include <sepax/prepared_shape.hpp>

#include "contact_choice.hpp"

namespace sepax::bullet {

/// choose_contact on the posed SAT result r of (a at pose_a, b at x relative to a).
inline SatResult<float> chosen_contact(const PreparedShape<float>& a, const RigidTransform<float>& pose_a,
                                       const PreparedShape<float>& b, const RigidTransform<float>& x,
                                       const SatResult<float>& r) {
  return choose_contact(a.polyhedron(), b.posed_scratch(x), pose_a, r);
}

/// kept_contact: the kept face `last` re-evaluated with b at x relative to a.
inline SatResult<float> kept_contact(const PreparedShape<float>& a, const RigidTransform<float>& pose_a,
                                     const PreparedShape<float>& b, const RigidTransform<float>& x,
                                     const SatResult<float>& last) {
  return kept_contact(a.polyhedron(), b.posed_scratch(x), pose_a, last);
}

/// The manifold of contact r (world axis), points within the margin.
inline void posed_manifold(const PreparedShape<float>& a, const RigidTransform<float>& pose_a,
                           const PreparedShape<float>& b, const RigidTransform<float>& pose_b,
                           const SatResult<float>& r, double margin, ContactManifold<float>& out) {
  SatOptions opt;
  opt.margin = margin;
  out = contact_manifold(a, pose_a, b, pose_b, r, opt);
}

}  // namespace sepax::bullet
