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
#include <sepax/small_vector.hpp>

#include "contact_choice.hpp"
#include "face_refresh.hpp"
#include "posed_view.hpp"

namespace sepax::bullet {

/// choose_contact on the posed SAT result r of (a at pose_a, b at x relative to a).
inline SatResult<float> chosen_contact(const PreparedShape<float>& a, const RigidTransform<float>& pose_a,
                                       const PreparedShape<float>& b, const RigidTransform<float>& x,
                                       const SatResult<float>& r) {
  return choose_contact(a.polyhedron(), b.posed_scratch(x), pose_a, r);
}

/// The kept face `last` re-evaluated with b at x relative to a
/// (kept_contact), and its manifold, on a partial image of B': B's posed
/// vertices with only the planes the face and the manifold read (the face
/// of B; or, for a face of A, B's faces around the support vertex, among
/// which the manifold picks the incident face): the same contact and
/// manifold as on the full B'.  The image is `view` (posed_view.hpp) and the
/// manifold is refreshed (face_refresh.hpp; `face`: the kept face's side
/// planes); where either declines, B' is posed by PreparedShape::
/// posed_part_scratch and the manifold refreshed on it or, where the refresh
/// declines, built by posed_manifold_on.  `rigid`: check_rigid(x) is known
/// to pass (PosedView::pose); `world_a`: of a refreshed manifold's points
/// only point_a (else point_b) is in world (refresh_face_manifold).
/// Returns the contact; `refreshed` says which path built the points.
inline SatResult<float> kept_manifold(const PreparedShape<float>& a, const RigidTransform<float>& pose_a,
                                      const PreparedShape<float>& b, const RigidTransform<float>& x,
                                      bool rigid, const SatResult<float>& last, double margin,
                                      const KeptFace& face, bool world_a, PosedView& view,
                                      ContactManifold<float>& out, bool& refreshed) {
  const bool face_b = last.feature.type == FeatureType::FaceB;
  if (view.pose(b.polyhedron(), x, rigid) && (!face_b || view.derive(last.feature.b))) {
    const SatResult<float> r = kept_contact(a.polyhedron(), view, pose_a, last);
    bool planes = true;
    if (r.feature.type == FeatureType::FaceA) {
      for (const int h : view.vertex_half_edges(r.feature.b))
        planes = planes && view.derive(view.half_edge(h).face);
    }
    if (planes && refresh_face_manifold(a.polyhedron(), pose_a, view, r, margin, face, world_a, out)) {
      refreshed = true;
      return r;
    }
  }
  const ConvexPolyhedron<float>* bp = nullptr;
  if (face_b) {
    const int g = last.feature.b;
    bp = &b.posed_part_scratch(x, std::span<const int>(&g, 1), std::span<const int>());
  } else {
    bp = &b.posed_part_scratch(x, std::span<const int>(), std::span<const int>());
  }
  const SatResult<float> r = kept_contact(a.polyhedron(), *bp, pose_a, last);
  if (r.feature.type == FeatureType::FaceA) {
    SmallVector<int, 16> faces;
    for (const int h : bp->vertex_half_edges(r.feature.b)) faces.push_back(bp->half_edge(h).face);
    bp = &b.posed_part_scratch(x, std::span<const int>(faces.data(), faces.size()), std::span<const int>());
  }
  refreshed = refresh_face_manifold(a.polyhedron(), pose_a, *bp, r, margin, face, world_a, out);
  if (refreshed) return r;
  SatOptions opt;
  opt.margin = margin;
  out = sepax::detail::posed_manifold_on(a.polyhedron(), pose_a, *bp, r, opt);
  return r;
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
