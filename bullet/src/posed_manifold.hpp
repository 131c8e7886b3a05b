// The contact manifold of a posed pair in world coordinates, from the posed
// SAT result r of the same pair: sepax's posed contact_manifold
// (posed_queries.hpp, no allocation) on the contact type contact_choice.hpp
// prefers.  B' (B in A's frame) is the one the posed SAT query has just left
// in this thread's scratch (PreparedShape::posed_scratch returns it without
// posing again at the same relative pose).
#pragma once

#include <sepax/contact_manifold.hpp>
#include <sepax/prepared_shape.hpp>

#include "contact_choice.hpp"

namespace sepax::bullet {

inline void posed_manifold(const PreparedShape<float>& a, const RigidTransform<float>& pose_a,
                           const PreparedShape<float>& b, const RigidTransform<float>& pose_b,
                           const SatResult<float>& r, double margin, ContactManifold<float>& out) {
  const ConvexPolyhedron<float>& bp = b.posed_scratch(relative_pose(pose_a, pose_b));
  SatOptions opt;
  opt.margin = margin;
  out = contact_manifold(a, pose_a, b, pose_b, choose_contact(a.polyhedron(), bp, pose_a, r), opt);
}

}  // namespace sepax::bullet
