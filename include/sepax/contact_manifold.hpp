// sepax/contact_manifold.hpp
//
// contact_manifold: contact points of two overlapping (or nearly touching)
// convex polyhedra, from the result of any SAT (sat::brute_force,
// sat::gauss_map, sat::traversal; any policy).
//
// Face contact (the SAT axis is a face normal of A or of B):
//   * reference face: the face that realises the axis (A's face for FaceA,
//     B's face for FaceB);
//   * incident face: the face of the other shape most anti-parallel to the
//     reference normal among the faces around the SAT's support vertex (the
//     deepest vertex): a few faces, not all of them, and the deepest vertex
//     is always a vertex of the incident face;
//   * the incident face is clipped against the side planes of the reference
//     face (Sutherland-Hodgman, clip_polygon.hpp), never against the reference
//     face itself; the points below the reference face (separation <= margin)
//     are kept, each with its separation from the reference plane;
//   * at most four of them are kept (manifold_reduction.hpp) unless
//     ManifoldOptions::reduce is false.
// Edge contact (the axis comes from edges eA x eB): one point, the midpoint of
// the closest points of the two edge segments, with the SAT separation.
// Side contact (SideA/SideB: two coplanar flat polygons, feature.hpp): always
// separated, so only within a speculative margin; the 2D face contact.  The
// reference segment is the side's edge, the incident segment the edge of the
// other polygon at its support vertex most parallel to it; the incident
// segment is clipped to the slab between the planes through the reference
// edge's ends (normal to it), and the clipped ends within the margin are the
// points, with their separation along the side normal.
//
// Conventions (see docs/contacts.md):
//   normal      from A to B: the SAT axis.  Unit when T normalises; for
//               rationals the exact unnormalised axis, whose squared length is
//               `norm2` (no sqrt anywhere).
//   separation  of each point: Separation{num, norm2}, value num/sqrt(norm2)
//               along the unit normal; < 0 penetration (depth = -value),
//               > 0 only within a speculative margin.  For a face contact it is
//               the height of the incident point above the reference plane;
//               for an edge contact the SAT separation.
//   point_a/b   the contact point on A / on B: for a face contact one of them is
//               the clipped incident point, the other its projection onto the
//               reference plane; for an edge contact, the closest points of the
//               two segments.  position = (point_a + point_b) / 2.
//   id          the features of A and B that made the point (contact_feature.hpp).
// For exact T and rational inputs everything above is exact.
//
// Speculative margin: an absolute user distance (same units as the shapes).
// Shapes separated by at most the margin get a manifold with the points whose
// separation is <= margin.  Every internal tolerance is relative to the shapes'
// extent and named in tolerances.hpp (contact_weld, contact_area); exact types
// use none.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "clip_polygon.hpp"
#include "contact_feature.hpp"
#include "convex_polyhedron.hpp"
#include "error.hpp"
#include "manifold_reduction.hpp"
#include "sat_gauss_map.hpp"
#include "sat_result.hpp"
#include "separation.hpp"
#include "small_vector.hpp"
#include "tolerances.hpp"

namespace sepax {

enum class ContactKind : std::uint8_t { None = 0, Face = 1, Edge = 2, Side = 3 };

inline const char* to_string(ContactKind k) {
  switch (k) {
    case ContactKind::None:
      return "none";
    case ContactKind::Face:
      return "face";
    case ContactKind::Edge:
      return "edge";
    case ContactKind::Side:
      return "side";
  }
  return "?";
}

struct ManifoldOptions {
  /// Keep at most 4 points (deepest + largest area).  false keeps all.
  bool reduce = true;
  /// Speculative margin: an absolute distance >= 0 in the shapes' units.
  double margin = 0;
  /// Record the clip steps (ContactManifold::clip_steps), for audits.
  bool record_steps = false;
};

template <class T>
struct ContactPoint {
  Vec3<T> position;  // (point_a + point_b) / 2
  Vec3<T> point_a;   // on A
  Vec3<T> point_b;   // on B
  Separation<T> separation;
  ContactFeatureId id;

  /// Penetration depth as a double (reporting only): -separation.
  double depth() const { return -sepax::to_double(separation); }
};

/// One Sutherland-Hodgman step: the incident polygon clipped by the side plane
/// of reference edge `side_edge`.
struct ClipStep {
  int side_edge = -1;
  int vertices_in = 0;
  int vertices_out = 0;
};

/// Inline capacities (small_vector.hpp): a manifold keeps up to
/// kManifoldInlinePoints points without allocating (with ManifoldOptions::
/// reduce, the default, it keeps at most 4); the clipped incident polygon
/// and its candidate points use up to kManifoldInlineClip vertices on the
/// stack (the reduction's tables: manifold_reduction.hpp).  Beyond these
/// sizes they spill to the heap.
inline constexpr std::size_t kManifoldInlinePoints = 8;
inline constexpr std::size_t kManifoldInlineClip = kReductionInlinePoints;

template <class T>
struct ContactManifold {
  ContactKind kind = ContactKind::None;
  /// The SAT feature the manifold was built from.
  Feature feature;
  /// From A to B; unit iff number_traits<T>::normalizes, else |normal|^2 == norm2.
  Vec3<T> normal = Vec3<T>(T(0), T(0), T(0));
  T norm2 = T(1);
  /// The SAT separation along `normal` (<= 0 overlapping).
  Separation<T> separation;
  /// Face contacts: 0 when the reference face is on A, 1 when on B.
  int reference_shape = -1;
  int reference_face = -1;
  int incident_face = -1;
  /// Faces the incident-face search evaluated.
  int incident_faces_visited = 0;
  /// Points below the reference face before the reduction.
  int candidate_points = 0;
  /// Face contact whose clipped incident face was empty: the manifold is the
  /// support vertex alone (a safety net; see docs/contacts.md).
  bool support_fallback = false;
  SmallVector<ContactPoint<T>, kManifoldInlinePoints> points;
  /// Filled when ManifoldOptions::record_steps is set.
  std::vector<ClipStep> clip_steps;

  bool empty() const { return points.empty(); }
  int size() const { return static_cast<int>(points.size()); }

  /// The translation of B, along `normal`, that brings the shapes exactly to
  /// touching (the SAT separation becomes 0): normal * (-num / norm2).  Exact
  /// for exact T (no sqrt).
  Vec3<T> resolving_translation() const {
    const T s = T(-separation.num) / separation.norm2;
    return Vec3<T>(normal[0] * s, normal[1] * s, normal[2] * s);
  }
};

namespace detail {

template <Number T>
T norm2_of(const Vec3<T>& n) {
  if constexpr (number_traits<T>::normalizes) {
    (void)n;
    return T(1);
  } else {
    return squared_norm(n);
  }
}

/// s <= margin, exactly for exact T (squared form, no sqrt).
template <Number T>
bool within_margin(const Separation<T>& s, const T& margin) {
  if (!(s.num > T(0))) return true;
  if constexpr (number_traits<T>::normalizes) {
    return s.num <= margin;
  } else {
    return s.num * s.num <= margin * margin * s.norm2;
  }
}

[[noreturn]] inline void bad_feature(const std::string& what) {
  throw InvalidInput(ErrorCode::BadIndex,
                     "contact_manifold: the SAT result does not fit the shapes: " + what);
}

inline void check_index(int i, int count, const char* what) {
  if (i < 0 || i >= count) {
    bad_feature(std::string(what) + " " + std::to_string(i) + " out of range [0, " + std::to_string(count) +
                ")");
  }
}

/// The face of p around `start_vertex` (the support vertex) most anti-parallel
/// to n: maximum of -n.m/|m| over those faces' normals m (exact comparison in
/// squared form for rationals; ties to the lower face index).  Restricting the
/// choice to the faces of the deepest vertex keeps that vertex on the incident
/// face; the globally most anti-parallel face can lie elsewhere and miss the
/// overlap region entirely.
template <Number T>
int most_antiparallel_face(const ConvexPolyhedron<T>& p, const Vec3<T>& n, int start_vertex, int& visited) {
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

template <Number T>
T extent_tolerance(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b, double rel, int power) {
  if constexpr (number_traits<T>::is_exact) {
    (void)a, (void)b, (void)rel, (void)power;
    return T(0);
  } else {
    // power 1: a length rel*ext; 2: its square; 3: an area rel*ext^2.
    const double ext = std::min(a.extent(), b.extent());
    return static_cast<T>(power == 1 ? rel * ext : (power == 2 ? rel * ext * rel * ext : rel * ext * ext));
  }
}

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
    int h = I.face(inc).edge;
    for (int i = 0; i < I.face(inc).count; ++i, h = I.half_edge(h).next) {
      ClipVertex<T> v;
      const int o = I.half_edge(h).origin;
      v.point = I.vertex(o);
      v.id.a = ShapeFeature::face(ref_face);
      v.id.b = ShapeFeature::vertex(o);
      v.next_edge = h / 2;
      poly.push_back(v);
    }
  }
  // Clip against the side planes of the reference face, in loop order.  A
  // plane that keeps every vertex leaves the polygon as it is
  // (clip_polygon_if_cut), and welding an already welded polygon changes
  // nothing (every consecutive pair, the last and the first included, is
  // farther apart than the weld tolerance), so once the polygon has been
  // welded such a step is skipped: the same points and ids (a large
  // reference face, such as a ramp under a box, has many such planes).
  const T weld2 = extent_tolerance(a, b, Tolerances<T>::contact_weld, 2);
  {
    bool welded = number_traits<T>::is_exact;  // exact T: no welding at all
    int h = R.face(ref_face).edge;
    for (int i = 0; i < R.face(ref_face).count && !pp->empty(); ++i, h = R.half_edge(h).next) {
      Poly& poly = *pp;
      Poly& tmp = *tp;
      const int tail = R.half_edge(h).origin;
      const int head = R.half_edge(R.half_edge(h).next).origin;
      ClipPlane<T> cp;
      cp.normal = cross(Vec3<T>(R.vertex(head) - R.vertex(tail)), nr);
      cp.offset = dot(cp.normal, R.vertex(tail));
      cp.edge = h / 2;
      cp.tail = tail;
      cp.head = head;
      if (welded && !clip_polygon_if_cut(poly, cp, inc, tmp)) {
        if (opt.record_steps) {
          m.clip_steps.push_back(
              ClipStep{cp.edge, static_cast<int>(poly.size()), static_cast<int>(poly.size())});
        }
        continue;
      }
      if (!welded) clip_polygon(poly, cp, inc, tmp);
      if constexpr (!number_traits<T>::is_exact) {
        weld_polygon(tmp, weld2);
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
    for (const auto& v : poly) {
      const Separation<T> s{T(dot(nr, v.point) - rp.offset), n2};
      if (!within_margin(s, margin)) continue;
      const T k = s.num / n2;
      const Vec3<T> proj(v.point[0] - nr[0] * k, v.point[1] - nr[1] * k, v.point[2] - nr[2] * k);
      ContactPoint<T> c;
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
      pts.push_back(c);
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
    pos.push_back(c.position);
    keys.push_back(c.separation.num);
  }
  const T area_tol = extent_tolerance(a, b, Tolerances<T>::contact_area, 3);
  const T key_tol = extent_tolerance(a, b, Tolerances<T>::contact_weld, 1);
  SmallVector<int, 4> keep;
  reduce_contact_points_into(pos, keys, nr, key_tol, area_tol, keep);
  for (int i : keep) m.points.push_back(pts[static_cast<std::size_t>(i)]);
}

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

/// Side contact (see the header comment).  R's edge ref_edge with in-plane
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

}  // namespace detail

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
