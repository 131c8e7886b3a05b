// The contact manifold of a posed pair in world coordinates, from the posed
// SAT result r of the same pair.  The one place the adapter builds a
// manifold: core sepax's contact_manifold on (A, B') in A's frame, B' the
// posed copy the posed SAT query has just left in this thread's scratch
// (PreparedShape::posed_scratch returns it without posing again at the same
// relative pose), the points then mapped to world by pose_a.  The SAT's
// features index the prepared shapes, which B' shares; r's axis is already in
// world coordinates and is the manifold's normal.  The manifold is built from
// the contact type contact_choice.hpp prefers.
#pragma once

#include <sepax/contact_manifold.hpp>
#include <sepax/prepared_shape.hpp>

#include "contact_choice.hpp"

namespace sepax::bullet {

inline void posed_manifold(const PreparedShape<float>& a, const RigidTransform<float>& pose_a,
                           const PreparedShape<float>& b, const RigidTransform<float>& pose_b,
                           const SatResult<float>& r, double margin, ContactManifold<float>& out) {
  const ConvexPolyhedron<float>& bp = b.posed_scratch(relative_pose(pose_a, pose_b));
  ManifoldOptions mo;
  mo.margin = margin;
  out = contact_manifold(a.polyhedron(), bp, choose_contact(a.polyhedron(), bp, pose_a, r), mo);
  for (auto& c : out.points) {
    c.point_a = pose_a.apply(c.point_a);
    c.point_b = pose_a.apply(c.point_b);
    c.position = pose_a.apply(c.position);
  }
}

}  // namespace sepax::bullet
