// The adapter's choice of contact type for a physics engine's solver: a face
// contact unless an edge pair separates clearly more, and the face of A unless
// a face of B separates clearly more (D. Gregorius, "Robust Contact Creation
// for Physics Simulations", GDC 2015; Box2D's and Bullet's polyhedral
// clipping do the same):
//
//   face of B over face of A  iff  sB > kRelFace sA + tol
//   edge pair over the face   iff  sE > kRelEdge sF + tol
//
// with tol = kAbsTolerance * min(extent A, extent B).  A contact policy on top
// of the exact SAT, not a change of its answer: the verdict and the early exit
// beyond the speculative margin stay sepax's.  Why: on kRelFace.
#pragma once

#include <limits>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/sat_result.hpp>
#include <sepax/transform.hpp>

namespace sepax::bullet {

/// sepax's SAT reports the axis of maximum separation; a face and an edge pair
/// (or a face of A and a face of B) can be within rounding of each other, as
/// in every resting stack of equal boxes, where the touching faces' edges
/// coincide.  Building the manifold from whichever wins by a hair gives a
/// single edge-edge point one step and four face points the next, and swaps
/// the reference face between the shapes, which changes every point's feature
/// ids: the solver loses its warm start and the stack wobbles.  Physics
/// engines therefore prefer a face contact unless an edge pair separates
/// clearly more, and the face of A unless a face of B separates clearly more
/// (the header's rule, with tol = kAbsTolerance x the smaller extent,
/// ConvexPolyhedron::extent).  The candidate face of each shape is its
/// face most aligned with the SAT axis (towards the other shape), its
/// separation computed over the other shape's vertices in double.  kRelFace: a
/// face of B must separate by more than this fraction of A's (plus tol),
/// dimensionless.
inline constexpr double kRelFace = 0.98;
/// An edge pair must separate by more than this fraction of the face's
/// separation (plus tol), dimensionless.
inline constexpr double kRelEdge = 0.90;
/// tol in units of the smaller shape extent, dimensionless.
inline constexpr double kAbsTolerance = 1e-3;

namespace detail {

struct FaceQuery {
  int face = -1;
  int support = -1;  // the other shape's deepest vertex
  double separation = -std::numeric_limits<double>::infinity();
};

/// The face of p whose normal is most aligned with d.
inline FaceQuery face_query(const ConvexPolyhedron<float>& p, const Vec3<float>& d) {
  FaceQuery r;
  double best = -std::numeric_limits<double>::infinity();
  for (int f = 0; f < p.face_count(); ++f) {
    const double a = static_cast<double>(dot(p.plane(f).normal, d));
    if (a > best) {
      best = a;
      r.face = f;
    }
  }
  return r;
}

/// r's face of p: its separation from q (min over q's vertices of n.v -
/// offset) and q's deepest vertex.  P, Q: ConvexPolyhedron<float> or a
/// PosedView (posed_view.hpp).
template <class P, class Q>
void face_separation(const P& p, const Q& q, FaceQuery& r) {
  const auto& pl = p.plane(r.face);
  const double nx = pl.normal[0], ny = pl.normal[1], nz = pl.normal[2], off = pl.offset;
  r.separation = std::numeric_limits<double>::infinity();
  for (int v = 0; v < q.vertex_count(); ++v) {
    const auto& x = q.vertex(v);
    const double s = nx * x[0] + ny * x[1] + nz * x[2] - off;
    if (s < r.separation) {
      r.separation = s;
      r.support = v;
    }
  }
}

/// r with its feature replaced by the face q of B (use_b) or of A: q's
/// separation (unit normals) and support vertex, the axis in world.
template <class BP>
SatResult<float> face_result(const ConvexPolyhedron<float>& a, const BP& bp,
                             const RigidTransform<float>& pose_a, const SatResult<float>& r, bool use_b,
                             const FaceQuery& q) {
  SatResult<float> out = r;
  out.separation = Separation<float>{static_cast<float>(q.separation), 1.0f};
  if (use_b) {
    out.feature = Feature::face_b(q.support, q.face);
    const Vec3<float>& n = bp.plane(q.face).normal;
    out.axis = pose_a.rotate(Vec3<float>(-n[0], -n[1], -n[2]));
  } else {
    out.feature = Feature::face_a(q.face, q.support);
    out.axis = pose_a.rotate(a.plane(q.face).normal);
  }
  return out;
}

}  // namespace detail

/// r (a posed SAT result of A and B, axis in world) with its feature replaced
/// by the preferred face when the rule above says so.  a and bp: A and B' in
/// A's frame; pose_a maps A's frame to world.
inline SatResult<float> choose_contact(const ConvexPolyhedron<float>& a, const ConvexPolyhedron<float>& bp,
                                       const RigidTransform<float>& pose_a, const SatResult<float>& r) {
  const FeatureType t = r.feature.type;
  if (t != FeatureType::FaceA && t != FeatureType::FaceB && t != FeatureType::EdgePair) return r;
  // the axis in A's frame (R^T axis)
  Vec3<float> axis;
  for (int i = 0; i < 3; ++i) axis[i] = dot(pose_a.column(i), r.axis);
  const Vec3<float> neg(-axis[0], -axis[1], -axis[2]);
  // Each shape's candidate face: the SAT's own when it is a face of that
  // shape, else the face most aligned with the axis (towards the other).
  auto candidate = [&](bool from_sat, int face, int support, const ConvexPolyhedron<float>& p,
                       const ConvexPolyhedron<float>& q, const Vec3<float>& d) {
    detail::FaceQuery fq;
    if (from_sat) {
      fq.face = face;
      fq.support = support;
      fq.separation = to_double(r.separation);
    } else {
      fq = detail::face_query(p, d);
      detail::face_separation(p, q, fq);
    }
    return fq;
  };
  const detail::FaceQuery qa = candidate(t == FeatureType::FaceA, r.feature.a, r.feature.b, a, bp, axis);
  const detail::FaceQuery qb = candidate(t == FeatureType::FaceB, r.feature.b, r.feature.a, bp, a, neg);
  const double tol = kAbsTolerance * std::min(a.extent(), bp.extent());
  const bool use_b = qb.separation > kRelFace * qa.separation + tol;
  const detail::FaceQuery& qf = use_b ? qb : qa;
  if (t == FeatureType::EdgePair && to_double(r.separation) > kRelEdge * qf.separation + tol) return r;
  if ((t == FeatureType::FaceA && !use_b) || (t == FeatureType::FaceB && use_b)) return r;
  return detail::face_result(a, bp, pose_a, r, use_b, qf);
}

/// The contact of a pair at a new pose from a face feature f (FaceA or
/// FaceB) the adapter keeps: f's face with its separation and the other
/// shape's deepest vertex re-evaluated on (a, bp), as choose_contact
/// evaluates a face; overlap and stats as in `last`.  BP: B' as a
/// ConvexPolyhedron<float> or a PosedView with the kept face's plane when it
/// is a face of B.
template <class BP>
SatResult<float> kept_contact(const ConvexPolyhedron<float>& a, const BP& bp,
                              const RigidTransform<float>& pose_a, const SatResult<float>& last) {
  const bool use_b = last.feature.type == FeatureType::FaceB;
  detail::FaceQuery q;
  q.face = use_b ? last.feature.b : last.feature.a;
  if (use_b) {
    detail::face_separation(bp, a, q);
  } else {
    detail::face_separation(a, bp, q);
  }
  return detail::face_result(a, bp, pose_a, last, use_b, q);
}

}  // namespace sepax::bullet
