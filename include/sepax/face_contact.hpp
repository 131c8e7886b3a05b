// sepax/face_contact.hpp
//
// The face contact of contact_manifold (the SAT axis is a face normal of A or
// of B), in steps:
//   1. reference face: the face that realises the axis (A's face for FaceA,
//      B's face for FaceB);
//   2. incident face: the face of the other shape most anti-parallel to the
//      reference normal among the faces around the SAT's support vertex
//      (most_antiparallel_face), so the deepest vertex is on it;
//   3. the incident face clipped against the side planes of the reference face
//      that cut it (Sutherland-Hodgman, clip_polygon.hpp), never against the
//      reference face itself; the points below the reference face (separation
//      <= margin) are kept, each with its height over the reference plane;
//   4. at most four of them kept (manifold_reduction.hpp) unless
//      ManifoldOptions::reduce is false.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

#include "clip_polygon.hpp"
#include "manifold_reduction.hpp"
#include "manifold_result.hpp"
#include "tolerances.hpp"

namespace sepax::detail {

/// The face of p around `start_vertex` (the support vertex) most anti-parallel
/// to n: maximum of -n.m/|m| over those faces' normals m (exact comparison in
/// squared form for rationals; ties to the lower face index).  Restricting the
/// choice to the faces of the deepest vertex keeps that vertex on the incident
/// face; the globally most anti-parallel face can lie elsewhere and miss the
/// overlap region entirely.  P: a ConvexPolyhedron, or a partial view of a
/// posed one with its accessors (vertex_half_edges, half_edge, plane).
template <class P>
int most_antiparallel_face(const P& p, const Vec3<typename P::Scalar>& n, int start_vertex, int& visited) {
  using T = typename P::Scalar;
  auto score = [&](int f) {
    const Vec3<T>& m = p.plane(f).normal;
    return Separation<T>{T(-dot(n, m)), norm2_of(m)};
  };
  auto better = [&](int f, const Separation<T>& sf, int g, const Separation<T>& sg) {
    const int c = compare(sf, sg);
    return c > 0 || (c == 0 && f < g);
  };
  int best = -1;
  Separation<T> best_s;
  for (int h : p.vertex_half_edges(start_vertex)) {
    const int f = p.half_edge(h).face;
    const auto s = score(f);
    ++visited;
    if (best < 0 || better(f, s, best, best_s)) {
      best = f;
      best_s = s;
    }
  }
  return best;
}

/// The lowest-index vertex of p deepest along -n (a support vertex), for SAT
/// results that carry none.
template <Number T>
int support_vertex(const ConvexPolyhedron<T>& p, const Vec3<T>& n) {
  int best = 0;
  T best_h = dot(n, p.vertex(0));
  for (int i = 1; i < p.vertex_count(); ++i) {
    const T h = dot(n, p.vertex(i));
    if (h < best_h) {
      best_h = h;
      best = i;
    }
  }
  return best;
}

/// Step 3's input: incident face `inc` of I as a clip polygon, each vertex
/// with its features (reference face ref_face, incident vertex) and the
/// incident edge to the next vertex; appended to poly.
template <class P, class Poly>
void incident_polygon(const P& I, int inc, int ref_face, Poly& poly) {
  int h = I.face(inc).edge;
  for (int i = 0; i < I.face(inc).count; ++i, h = I.half_edge(h).next) {
    ClipVertex<typename P::Scalar> v;
    const int o = I.half_edge(h).origin;
    v.point = I.vertex(o);
    v.id.a = ShapeFeature::face(ref_face);
    v.id.b = ShapeFeature::vertex(o);
    v.next_edge = h / 2;
    poly.push_back(v);
  }
}

/// The side plane of the reference face's half-edge h (tail -> head), nr the
/// face's normal: normal (v_head - v_tail) x nr, unnormalised, through the
/// tail; the points with dot(normal, x) - offset <= 0 are kept.  Float and
/// double: the normal is scaled by the power of two that puts its largest
/// |component| in [1, 2), so that the offset and every height, at most
/// 2 sqrt(3) |x| for coordinates |x| <= max/16, stay in range at every scale
/// the shapes accept (unscaled, |edge| |tail| overflows double beyond
/// coordinates of about 1e154 and float beyond 1e19).  The scaling is exact
/// wherever nothing under- or overflows, and clipping reads only the heights'
/// signs and ratios, so the clipped points are those of the unscaled plane
/// there, bit for bit.
template <class P, class T = typename P::Scalar>
[[gnu::always_inline]] inline ClipPlane<T> side_plane(const P& R, int h, const Vec3<T>& nr) {
  const int tail = R.half_edge(h).origin;
  const int head = R.half_edge(R.half_edge(h).next).origin;
  ClipPlane<T> cp;
  cp.normal = cross(Vec3<T>(R.vertex(head) - R.vertex(tail)), nr);
  if constexpr (std::is_floating_point_v<T>) {
    const T m = std::max(std::max(std::abs(cp.normal[0]), std::abs(cp.normal[1])), std::abs(cp.normal[2]));
    if (!(m >= T(1) && m < T(2)) && m > T(0) && m <= std::numeric_limits<T>::max())
      cp.normal = detail::scale_pow2(cp.normal, detail::pow2_exponent(m));
  }
  cp.offset = dot(cp.normal, R.vertex(tail));
  cp.edge = h / 2;
  cp.tail = tail;
  cp.head = head;
  return cp;
}

/// Step 3's point of clipped vertex v when it is within `margin` of the
/// reference plane rp (n2 = |rp.normal|^2): its separation, its projection
/// onto rp, the points on A and B and their midpoint; false otherwise.
template <Number T>
bool face_point(const ClipVertex<T>& v, const Plane<T>& rp, const T& n2, bool ref_is_a, const T& margin,
                ContactPoint<T>& c) {
  const Vec3<T>& nr = rp.normal;
  const Separation<T> s{T(dot(nr, v.point) - rp.offset), n2};
  if (!within_margin(s, margin)) return false;
  const T k = s.num / n2;
  const Vec3<T> proj(v.point[0] - nr[0] * k, v.point[1] - nr[1] * k, v.point[2] - nr[2] * k);
  c.separation = s;
  if (ref_is_a) {
    c.point_a = proj;
    c.point_b = v.point;
    c.id = v.id;
  } else {
    c.point_a = v.point;
    c.point_b = proj;
    c.id = v.id.swapped();
  }
  const T half = T(1) / T(2);
  c.position = Vec3<T>((c.point_a[0] + c.point_b[0]) * half, (c.point_a[1] + c.point_b[1]) * half,
                       (c.point_a[2] + c.point_b[2]) * half);
  return true;
}

/// The face contact of the header's steps, appended to m: reference face
/// ref_face of A (ref_is_a) or of B, support vertex `support` of the other
/// shape, points within `margin`.
template <Number T>
void face_contact(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b, bool ref_is_a, int ref_face,
                  int support, const T& margin, const ManifoldOptions& opt, ContactManifold<T>& m) {
  const ConvexPolyhedron<T>& R = ref_is_a ? a : b;
  const ConvexPolyhedron<T>& I = ref_is_a ? b : a;
  const Plane<T>& rp = R.plane(ref_face);
  const Vec3<T>& nr = rp.normal;
  m.kind = ContactKind::Face;
  m.reference_shape = ref_is_a ? 0 : 1;
  m.reference_face = ref_face;
  const int inc = most_antiparallel_face(I, nr, support, m.incident_faces_visited);
  m.incident_face = inc;

  // The incident polygon, with its features.
  // Two buffers, swapped by pointer after each clip step.
  using Poly = SmallVector<ClipVertex<T>, kManifoldInlineClip>;
  Poly buf0, buf1;
  Poly* pp = &buf0;
  Poly* tp = &buf1;
  pp->reserve(static_cast<std::size_t>(I.face(inc).count) + 8);
  tp->reserve(pp->capacity());
  {
    Poly& poly = *pp;
    incident_polygon(I, inc, ref_face, poly);
  }
  // Clip against the side planes of the reference face, in loop order.  A
  // plane that keeps every vertex leaves the polygon as it is
  // (clip_polygon_if_cut), and welding an already welded polygon changes
  // nothing (every consecutive pair, the last and the first included, is
  // farther apart than the weld tolerance), so once the polygon has been
  // welded such a step is skipped: the same points and ids (a large
  // reference face, such as a ramp under a box, has many such planes).
  const int unit = manifold_scale_exponent(a, b);  // (lengths compared in units of 2^unit)
  const T weld2 = extent_tolerance(a, b, Tolerances<T>::kContactWeld, 2, unit);
  {
    bool welded = number_traits<T>::is_exact;  // exact T: no welding at all
    int h = R.face(ref_face).edge;
    for (int i = 0; i < R.face(ref_face).count && !pp->empty(); ++i, h = R.half_edge(h).next) {
      Poly& poly = *pp;
      Poly& tmp = *tp;
      const ClipPlane<T> cp = side_plane(R, h, nr);
      if (welded && !clip_polygon_if_cut(poly, cp, inc, tmp)) {
        if (opt.record_steps) {
          m.clip_steps.push_back(
              ClipStep{cp.edge, static_cast<int>(poly.size()), static_cast<int>(poly.size())});
        }
        continue;
      }
      if (!welded) clip_polygon(poly, cp, inc, tmp);
      if constexpr (!number_traits<T>::is_exact) {
        weld_polygon(tmp, weld2, unit);
        welded = true;
      }
      if (opt.record_steps) {
        m.clip_steps.push_back(
            ClipStep{cp.edge, static_cast<int>(poly.size()), static_cast<int>(tmp.size())});
      }
      std::swap(pp, tp);
    }
  }
  Poly& poly = *pp;
  // Keep the points below the reference face (within the margin).
  const T n2 = norm2_of(nr);
  SmallVector<ContactPoint<T>, kManifoldInlineClip> pts;
  pts.reserve(poly.size());
  auto keep_points = [&] {
    ContactPoint<T> c;
    for (const auto& v : poly) {
      if (face_point(v, rp, n2, ref_is_a, margin, c)) pts.push_back(c);
    }
  };
  keep_points();
  if (pts.empty()) {
    // Safety net (not seen in tests): no point of the clipped incident face is
    // within the margin.  Report the support vertex itself, whose separation
    // is the SAT's.
    ClipVertex<T> v;
    v.point = I.vertex(support);
    v.id = ContactFeatureId{ShapeFeature::face(ref_face), ShapeFeature::vertex(support)};
    poly.assign(1, v);
    m.support_fallback = true;
    keep_points();
  }
  m.candidate_points = static_cast<int>(pts.size());
  if (!opt.reduce || pts.size() <= 4) {
    m.points.clear();
    m.points.append(pts.begin(), pts.end());
    return;
  }
  SmallVector<Vec3<T>, kManifoldInlineClip> pos;
  SmallVector<T, kManifoldInlineClip> keys;
  pos.reserve(pts.size());
  keys.reserve(pts.size());
  for (const auto& c : pts) {
    pos.push_back(in_manifold_units(c.position, unit));
    keys.push_back(in_manifold_units(c.separation.num, unit));
  }
  const T area_tol = extent_tolerance(a, b, Tolerances<T>::kContactArea, 3, unit);
  const T key_tol = extent_tolerance(a, b, Tolerances<T>::kContactWeld, 1, unit);
  SmallVector<int, 4> keep;
  reduce_contact_points_into(pos, keys, nr, key_tol, area_tol, keep);
  for (int i : keep) m.points.push_back(pts[static_cast<std::size_t>(i)]);
}

}  // namespace sepax::detail
