// sepax/edge_contact.hpp
//
// The edge and side contacts of contact_manifold:
//   * edge contact (the axis comes from edges eA x eB): one point, the
//     midpoint of the closest points of the two edge segments
//     (closest_segment_points), with the SAT separation;
//   * side contact (SideA/SideB: two coplanar flat polygons, feature.hpp):
//     always separated, so only within a speculative margin; the 2D face
//     contact.  The reference segment is the side's edge, the incident segment
//     the edge of the other polygon at its support vertex most parallel to it;
//     the incident segment is clipped to the slab between the planes through
//     the reference edge's ends (normal to it), and the clipped ends within
//     the margin are the points, with their separation along the side normal.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "manifold_result.hpp"

namespace sepax::detail {

/// Closest points of segments p1 + s d1 and p2 + t d2, s, t in [0, 1]
/// (Ericson, Real-Time Collision Detection, 5.1.9): field operations only.
/// s and t do not change when d1, d2 and p1 - p2 are scaled together, so for
/// float and double they are first scaled by the power of two that brings
/// their largest component into [1, 2): a e - b^2 is of degree 4 in the
/// coordinates and overflowed (NaN) from about 1e9 (float) / 1e77 (double)
/// and underflowed to 0 below the inverse.  The scaling is exact (up to
/// components that become subnormal, far below the largest), so at ordinary
/// scales the results are bit for bit those of the unscaled formula.
template <Number T>
void closest_segment_points(const Vec3<T>& p1, const Vec3<T>& d1, const Vec3<T>& p2, const Vec3<T>& d2, T& s,
                            T& t) {
  const T zero(0), one(1);
  auto clamp01 = [&](const T& x) { return x < zero ? zero : (x > one ? one : x); };
  Vec3<T> r(p1 - p2), u = d1, w = d2;
  if constexpr (std::is_floating_point_v<T>) {
    const T m = std::max(detail::max_abs2(u, w), detail::max_abs2(r, r));
    if (m > T(0) && m <= std::numeric_limits<T>::max()) {
      const int k = detail::pow2_exponent(m);
      u = detail::scale_pow2(u, k);
      w = detail::scale_pow2(w, k);
      r = detail::scale_pow2(r, k);
    }
  }
  const T a = dot(u, u), e = dot(w, w), f = dot(w, r), c = dot(u, r), b = dot(u, w);
  if (!(a > zero) || !(e > zero)) {  // a segment of length 0 (or below the scaled range) is its tail
    s = a > zero ? clamp01(T(-c / a)) : zero;
    t = e > zero && !(a > zero) ? clamp01(T(f / e)) : zero;
    return;
  }
  const T denom = a * e - b * b;
  s = denom > zero ? clamp01(T((b * f - c * e) / denom)) : zero;
  t = (b * s + f) / e;
  if (t < zero) {
    t = zero;
    s = clamp01(T(-c / a));
  } else if (t > one) {
    t = one;
    s = clamp01(T((b - c) / a));
  }
}

template <Number T>
void edge_contact(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b, int ea, int eb,
                  ContactManifold<T>& m) {
  m.kind = ContactKind::Edge;
  const Vec3<T>& pa = a.vertex(a.edge_tail(ea));
  const Vec3<T>& pb = b.vertex(b.edge_tail(eb));
  const Vec3<T> da = a.edge_direction(ea), db = b.edge_direction(eb);
  T s, t;
  closest_segment_points(pa, da, pb, db, s, t);
  ContactPoint<T> c;
  c.point_a = Vec3<T>(pa[0] + s * da[0], pa[1] + s * da[1], pa[2] + s * da[2]);
  c.point_b = Vec3<T>(pb[0] + t * db[0], pb[1] + t * db[1], pb[2] + t * db[2]);
  const T half = T(1) / T(2);
  c.position = Vec3<T>((c.point_a[0] + c.point_b[0]) * half, (c.point_a[1] + c.point_b[1]) * half,
                       (c.point_a[2] + c.point_b[2]) * half);
  c.separation = m.separation;
  c.id = ContactFeatureId{ShapeFeature::edge(ea), ShapeFeature::edge(eb)};
  m.candidate_points = 1;
  m.points.push_back(c);
}

/// Side contact (the header's second item).  R's edge ref_edge with in-plane
/// outward normal u = (head - tail) x normal(edge_face(ref_edge, 0)) (unit
/// when T normalises); `support` is the deepest vertex of I along -u.
template <Number T>
void side_contact(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b, bool ref_is_a, int ref_edge,
                  int support, const T& margin, ContactManifold<T>& m) {
  const ConvexPolyhedron<T>& R = ref_is_a ? a : b;
  const ConvexPolyhedron<T>& I = ref_is_a ? b : a;
  m.kind = ContactKind::Side;
  m.reference_shape = ref_is_a ? 0 : 1;
  const int rt = R.edge_tail(ref_edge), rh = R.edge_head(ref_edge);
  const Vec3<T>& t = R.vertex(rt);
  const Vec3<T> d = R.edge_direction(ref_edge);
  Vec3<T> u = scaled_cross(d, R.plane(R.edge_face(ref_edge, 0)).normal);  // == cross for exact T
  if constexpr (number_traits<T>::normalizes) {
    const T len = number_traits<T>::sqrt(squared_norm(u));
    u = Vec3<T>(u[0] / len, u[1] / len, u[2] / len);
  }
  const T n2 = norm2_of(u);
  // Incident edge: of the two edges of I at `support`, the one most
  // perpendicular to u, i.e. least (w.u)^2 / |w|^2 (exact in squared form for
  // rationals; ties to the lower edge index).
  int inc = -1, other = -1;
  T best_num(0), best_den(1);
  for (int h : I.vertex_half_edges(support)) {
    const int e = h / 2;
    const int o = I.half_edge(h ^ 1).origin;
    const Vec3<T> w(I.vertex(o) - I.vertex(support));
    const T wu = dot(w, u);
    const T num = wu * wu, den = squared_norm(w);
    if (inc < 0 || num * best_den < best_num * den || (num * best_den == best_num * den && e < inc)) {
      inc = e;
      other = o;
      best_num = num;
      best_den = den;
    }
  }
  // Clip the segment p -> q to 0 <= d.(x - t) <= d.d.
  const Vec3<T>& p = I.vertex(support);
  const Vec3<T>& q = I.vertex(other);
  const T gp = dot(d, Vec3<T>(p - t)), gq = dot(d, Vec3<T>(q - t)), dd = dot(d, d);
  struct End {
    Vec3<T> point;
    ContactFeatureId id;  // R's feature first
  };
  SmallVector<End, 2> ends;
  auto at = [&](const T& g) {  // the point of p -> q where d.(x - t) == g
    const T lambda = T(g - gp) / T(gq - gp);
    return Vec3<T>(p[0] + lambda * (q[0] - p[0]), p[1] + lambda * (q[1] - p[1]),
                   p[2] + lambda * (q[2] - p[2]));
  };
  auto clip_end = [&](const Vec3<T>& x, const T& gx, int vx) {
    if (gx < T(0)) {
      if (!(T(0) < gp || T(0) < gq)) return;  // the whole segment is before the tail plane
      ends.push_back({at(T(0)), {ShapeFeature::vertex(rt), ShapeFeature::edge(inc)}});
    } else if (gx > dd) {
      if (!(gp < dd || gq < dd)) return;  // beyond the head plane
      ends.push_back({at(dd), {ShapeFeature::vertex(rh), ShapeFeature::edge(inc)}});
    } else {
      ends.push_back({x, {ShapeFeature::edge(ref_edge), ShapeFeature::vertex(vx)}});
    }
  };
  clip_end(p, gp, support);
  clip_end(q, gq, other);
  if (ends.size() == 2 && ends[0].point == ends[1].point) ends.pop_back();
  auto add = [&](const End& x, bool fallback) {
    const Separation<T> s = fallback ? m.separation : Separation<T>{T(dot(u, Vec3<T>(x.point - t))), n2};
    if (!fallback && !within_margin(s, margin)) return;
    const T k = s.num / n2;
    const Vec3<T> proj(x.point[0] - u[0] * k, x.point[1] - u[1] * k, x.point[2] - u[2] * k);
    ContactPoint<T> c;
    c.separation = s;
    c.point_a = ref_is_a ? proj : x.point;
    c.point_b = ref_is_a ? x.point : proj;
    c.id = ref_is_a ? x.id : x.id.swapped();
    const T half = T(1) / T(2);
    c.position = Vec3<T>((c.point_a[0] + c.point_b[0]) * half, (c.point_a[1] + c.point_b[1]) * half,
                         (c.point_a[2] + c.point_b[2]) * half);
    m.points.push_back(c);
  };
  for (const auto& x : ends) add(x, false);
  if (m.points.empty()) {
    // The incident segment misses the slab (corner against corner), or no
    // clipped end is within the margin: the support vertex alone, with the
    // SAT's separation (which is within the margin).
    m.support_fallback = true;
    add(End{p, {ShapeFeature::edge(ref_edge), ShapeFeature::vertex(support)}}, true);
  }
  m.candidate_points = static_cast<int>(m.points.size());
}

}  // namespace sepax::detail
