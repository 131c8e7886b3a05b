// sepax/convex_polyhedron_validation.hpp
//
// ConvexPolyhedron<T>'s validation (convex_polyhedron.hpp declares the class):
// every check throws InvalidInput naming the broken rule and the offending
// vertex, face or edge.
//   * check_coordinates(): finite coordinates, at least 3 vertices;
//   * check_range(), check_new_range(): float/double coordinates within the
//     range where planes and SAT values stay finite (BadScale);
//   * validate_geometry(): no sliver plane triangles, planar faces, outward
//     faces, convexity (every vertex below every face plane, or on large
//     shapes the local certificate: local_convexity_witnesses(),
//     vertex_windings_once()), no adjacent coplanar faces.
// Tolerances for float and double are in tolerances.hpp; exact T is exact.
#pragma once

#include <cmath>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "convex_polyhedron.hpp"

namespace sepax {

template <Number T>
inline void ConvexPolyhedron<T>::check_coordinates() {
  for (std::size_t i = 0; i < vertices_.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      if (!number_traits<T>::is_finite(vertices_[i][c])) {
        std::ostringstream s;
        s << "vertex " << i << " has a non-finite coordinate (NaN or infinity)";
        fail(ErrorCode::NonFinite, s.str());
      }
    }
  }
  if (vertices_.size() < 3) {
    fail(ErrorCode::TooFewPoints,
         "a polyhedron needs at least 3 vertices, got " + std::to_string(vertices_.size()));
  }
}

template <Number T>
inline std::string ConvexPolyhedron<T>::num_str(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

// Float and double work at any scale (planes, normals, extent and centroid
// are computed scale-safely, see plane_through and scaled_cross) within
//   |coordinate| <= max(T)/16   (so that sums and differences of a few
//                               coordinates -- edges, plane offsets, the
//                               SATs' projections and distances between two
//                               such shapes -- stay finite), and
//   coplanar/4 * extent >= min(T), the smallest normal number (so that the
//                               relative tolerances are not subnormal, where
//                               rounding is no longer small against them).
// Out of range is refused here with BadScale, naming the quantity that does
// not fit, before any geometric check can misreport it.
template <Number T>
[[gnu::always_inline]] inline bool ConvexPolyhedron<T>::coordinates_in_range() const {
  const double limit = static_cast<double>(std::numeric_limits<T>::max()) / 16;
  const double smallest_tol = Tolerances<T>::kCoplanar * kAdjacentCoplanarFraction * extent_;
  return max_abs_ <= limit && smallest_tol >= static_cast<double>(std::numeric_limits<T>::min());
}

template <Number T>
inline void ConvexPolyhedron<T>::check_range(bool planes) {
  const std::string_view tname = number_traits<T>::name;  // (a std::string only in a message)
  const double limit = static_cast<double>(std::numeric_limits<T>::max()) / 16;
  if (!(max_abs_ <= limit)) {
    fail(ErrorCode::BadScale, "coordinates up to " + num_str(max_abs_) + " are out of range for " +
                                  std::string(tname) + ": sepax needs |coordinate| <= " + num_str(limit) +
                                  " (max/16) so that edges, plane offsets and projections stay finite");
  }
  const double smallest_tol = Tolerances<T>::kCoplanar * kAdjacentCoplanarFraction * extent_;
  if (!(smallest_tol >= static_cast<double>(std::numeric_limits<T>::min()))) {
    fail(ErrorCode::BadScale, "extent " + num_str(extent_) + " is too small for " + std::string(tname) +
                                  ": the validation tolerances (relative to the extent) fall "
                                  "into its subnormal range");
  }
  if (!planes) return;
  // (cannot fail within the range above)  One pass without a branch per
  // value; the face is looked for only when some plane is not finite.
  bool all_finite = true;
  const T tmax = std::numeric_limits<T>::max();
  for (const auto& pl : planes_) {
    all_finite &= std::abs(pl.offset) <= tmax;  // false for NaN and infinities
    for (int c = 0; c < 3; ++c) all_finite &= std::abs(pl.normal[c]) <= tmax;
  }
  if (all_finite) [[likely]]
    return;
  for (int f = 0; f < face_count(); ++f) {
    const auto& pl = plane(f);
    bool finite = number_traits<T>::is_finite(pl.offset);
    for (int c = 0; c < 3; ++c) finite = finite && number_traits<T>::is_finite(pl.normal[c]);
    if (!finite) {
      fail(ErrorCode::BadScale, "face " + std::to_string(f) + ": its plane overflows " + std::string(tname) +
                                    "; coordinates reach " + num_str(max_abs_));
    }
  }
}

// Float and double: the plane triangle's height over its longest side
// (detail::triangle_aspect); not above Tolerances::sliver means zero area up
// to rounding.
template <Number T>
inline double ConvexPolyhedron<T>::triple_aspect(int f) const {
  const auto& t = face(f).plane_vertices;
  return detail::triangle_aspect(vertex(t[0]), vertex(t[1]), vertex(t[2]));
}

// convert_from and with_vertices: no geometric re-validation, but the new
// coordinates must be finite (check_coordinates, before the planes) and, for
// float/double, within check_range()'s range, or the planes and every SAT
// on them would be infinities and NaN.
template <Number T>
inline void ConvexPolyhedron<T>::check_new_range() {
  if constexpr (!number_traits<T>::is_exact) {
    if (!(extent_ > 0)) fail(ErrorCode::BadScale, "all vertices coincide: the shape has no extent");
    check_range();
  }
  check_plane_normals();
}

// convert_from, with_vertices and rigid images: the new coordinates need not
// keep a face's plane triple apart.  A small shape placed far from the origin
// of its frame (or converted to a narrower type) has its coordinates rounded
// to a spacing near its own size; when a triple rounds to three collinear
// points the face has no plane (normal 0, in every number type: exact T
// takes the coordinates as given), and every SAT value on it would be
// meaningless.  Refused here, naming the face, the extent and how far the
// coordinates reach.  (A validated shape never has such a face: validation
// refuses a plane triangle without area.)
template <Number T>
inline void ConvexPolyhedron<T>::check_plane_normals() const {
  for (int f = 0; f < face_count(); ++f) {
    const Vec3<T>& n = planes_[static_cast<std::size_t>(f)].normal;
    if (n[0] == T(0) && n[1] == T(0) && n[2] == T(0)) [[unlikely]] {
      const auto& t = face(f).plane_vertices;
      fail(ErrorCode::BadScale,
           "face " + std::to_string(f) + " has no plane at these coordinates: its plane vertices " +
               std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) +
               " are collinear in " + std::string(number_traits<T>::name) + " (extent " + num_str(extent_) +
               ", coordinates up to " + num_str(max_abs_) +
               "): the shape is too small for its distance from the origin in this type; place it "
               "nearer the origin of its frame or use a wider number type");
    }
  }
}

// The local convexity certificate of a large closed shape (validate_geometry
// uses it instead of every vertex against every face plane when
// faces x vertices > kConvexityScanPairs): face f's witnesses are, across
// each of its edges, the two vertices of the neighbouring face next to that
// edge.  Every edge convex (those witnesses below f's plane) and every vertex
// wound once (vertex_windings_once) on a closed, consistently oriented
// genus-0 surface make the surface convex (docs/hull.md, "Validation").
template <Number T>
inline void ConvexPolyhedron<T>::local_convexity_witnesses(int f, std::vector<int>& out) const {
  out.clear();
  int h = face(f).edge;
  for (int i = 0; i < face(f).count; ++i, h = half_edge(h).next) {
    const HalfEdge& t = half_edge(twin(h));
    out.push_back(half_edge(half_edge(t.next).next).origin);
    out.push_back(half_edge(t.prev).origin);
  }
}

// Every vertex of a large solid is wound once: its neighbours, projected on
// the plane normal to the sum of its faces' normals (inside the normal cone
// of a convex corner), turn once around it (a ray-crossing count; exact for
// exact T).  A star wound twice has convex edges but is not convex.
// Returns false at the first vertex that is not wound once.  For float and
// double the count is taken on rounded projections with no tolerance, while
// the edges are convex only within Tolerances::convexity: a corner whose
// faces are convex within that tolerance can count 0.  The certificate is
// sufficient, not necessary, so validate_geometry then decides by the full
// scan of every vertex against every face plane.
template <Number T>
inline bool ConvexPolyhedron<T>::vertex_windings_once() const {
  std::vector<std::array<T, 2>> ring;  // (one vertex's projected neighbours; one buffer for every vertex)
  for (int v = 0; v < vertex_count(); ++v) {
    const auto fan = vertex_half_edges(v);
    Vec3<T> m(T(0), T(0), T(0));
    for (int h : fan) m = Vec3<T>(m + plane(half_edge(h).face).normal);
    int k = 0;
    for (int c = 1; c < 3; ++c)
      if (abs_of(m[c]) < abs_of(m[k])) k = c;
    Vec3<T> axis(T(0), T(0), T(0));
    axis[k] = T(1);
    const Vec3<T> a = cross(m, axis), b = cross(m, a);
    // neighbours in order around v: the head of each outgoing half-edge h,
    // the next one twin(prev(h))
    ring.clear();
    int h = fan[0];
    do {
      const Vec3<T> d(vertex(half_edge(twin(h)).origin) - vertex(v));
      ring.push_back({dot(a, d), dot(b, d)});
      h = twin(half_edge(h).prev);
    } while (h != fan[0] && ring.size() <= fan.size());
    int wind = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const auto& p = ring[i];
      const auto& q = ring[(i + 1) % ring.size()];
      const T side = T(p[0] * q[1] - p[1] * q[0]);
      if (p[1] <= T(0) && q[1] > T(0) && side > T(0)) ++wind;
      if (q[1] <= T(0) && p[1] > T(0) && side < T(0)) --wind;
    }
    if (wind != 1 && wind != -1) return false;
  }
  return true;
}

template <Number T>
inline void ConvexPolyhedron<T>::validate_geometry(double scan_pairs) {
  if (!(extent_ > 0)) fail(ErrorCode::BadScale, "all vertices coincide: the shape has no extent");
  if constexpr (!number_traits<T>::is_exact) check_range();
  const T plan_tol = height_tolerance(Tolerances<T>::kPlanarity);
  const T conv_tol = height_tolerance(Tolerances<T>::kConvexity);
  // faces: non-zero area, planar, convex loops
  std::vector<int> loop;  // (face f's vertices; one buffer for every face)
  for (int f = 0; f < face_count(); ++f) {
    const auto& pl = plane(f);
    if constexpr (number_traits<T>::is_exact) {
      if (is_zero(pl.normal)) {
        fail(ErrorCode::DegenerateFace,
             "face " + std::to_string(f) + " has zero area (its vertices are collinear)");
      }
    } else {
      const double aspect = triple_aspect(f);
      if (!(aspect > Tolerances<T>::kSliver)) {
        const auto& t = face(f).plane_vertices;
        fail(ErrorCode::DegenerateFace,
             "face " + std::to_string(f) + " has zero area up to rounding: its widest triangle (vertices " +
                 std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) +
                 ") is only " + num_str(aspect) +
                 " times as high as its longest side (Tolerances::sliver = " +
                 num_str(Tolerances<T>::kSliver) + "); its normal would be rounding noise");
      }
    }
    face_vertices(f, loop);
    const int n = static_cast<int>(loop.size());
    const auto& triple = face(f).plane_vertices;
    for (int i = 0; i < n; ++i) {
      // (exact T: the plane triple's own heights are exactly 0 by the plane's construction)
      if constexpr (number_traits<T>::is_exact) {
        const int v = loop[static_cast<std::size_t>(i)];
        if (v == triple[0] || v == triple[1] || v == triple[2]) continue;
      }
      const T h = height(f, vertex(loop[static_cast<std::size_t>(i)]));
      if (abs_of(h) > plan_tol) {
        fail(ErrorCode::NonPlanarFace, "face " + std::to_string(f) + " is not planar: vertex " +
                                           std::to_string(loop[i]) + " is " + num_str(to_double(h)) +
                                           " off the face's plane (tolerance " +
                                           num_str(to_double(plan_tol)) + ")");
      }
    }
    for (int i = 0; i < n; ++i) {
      const Vec3<T>& a = vertex(loop[static_cast<std::size_t>((i + n - 1) % n)]);
      const Vec3<T>& b = vertex(loop[static_cast<std::size_t>(i)]);
      const Vec3<T>& c = vertex(loop[static_cast<std::size_t>((i + 1) % n)]);
      if (a == b) {
        fail(ErrorCode::DegenerateFace,
             "face " + std::to_string(f) + " has two consecutive corners at one point (vertices " +
                 std::to_string(loop[static_cast<std::size_t>((i + n - 1) % n)]) + " and " +
                 std::to_string(loop[static_cast<std::size_t>(i)]) + ")");
      }
      Vec3<T> ab(b - a);
      Vec3<T> bc(c - b);
      bool bad;
      if constexpr (number_traits<T>::is_exact) {
        // (a triangle, its own plane triple: the turn is |normal|^2, non-zero as tested above)
        bad = n != 3 && !(dot(pl.normal, cross(ab, bc)) > T(0));
      } else {
        // turn/|ab| is the distance of c from the line a-b (times |n| = 1).
        // ab, bc and the tolerance scaled by one power of two (largest
        // |component| in [1, 2)) so that the cross product and |ab|^2 stay
        // in range at any scale; exact, so the same decision as unscaled
        // wherever that stays in range.
        T tol = conv_tol;
        const T m = detail::max_abs2(ab, bc);
        if (m > T(0) && m <= std::numeric_limits<T>::max()) {
          const int e = detail::pow2_exponent(m);
          ab = detail::scale_pow2(ab, e);
          bc = detail::scale_pow2(bc, e);
          tol = detail::scale_value_pow2(tol, e);
        }
        const T turn = dot(pl.normal, cross(ab, bc));
        const T lab = number_traits<T>::sqrt(squared_norm(ab));
        bad = !(lab > T(0)) || turn < -(tol * lab);
      }
      if (bad) {
        fail(ErrorCode::NonConvexFace,
             "face " + std::to_string(f) + " is not convex at vertex " +
                 std::to_string(loop[static_cast<std::size_t>(i)]) +
                 (number_traits<T>::is_exact ? " (reflex or collinear corner)" : " (reflex corner)"));
      }
    }
  }
  if (is_flat()) {
    // (normals compared for exact opposition, not by a cross product: under
    // FMA contraction cross(n, -n) need not be exactly 0)
    if (!(plane(1).normal == Vec3<T>(-plane(0).normal)) || !(dot(plane(0).normal, plane(1).normal) < T(0))) {
      fail(ErrorCode::NotConvex, "a two-face shape must be a polygon and its reverse");
    }
    return;
  }
  // solids: every vertex has degree >= 3
  for (int v = 0; v < vertex_count(); ++v) {
    if (vertex_half_edges(v).size() < 3) {
      fail(ErrorCode::NotConvex,
           "vertex " + std::to_string(v) + " has only two edges (it lies in the middle of an edge)");
    }
  }
  // global convexity and orientation: every vertex against every face
  // plane, or on large shapes the local certificate (local_convexity_witnesses)
  const bool scan = static_cast<double>(face_count()) * static_cast<double>(vertex_count()) <= scan_pairs ||
                    !vertex_windings_once();
  int faces_all_above = 0;
  int first_bad_face = -1, first_bad_vertex = -1;
  double first_bad_height = 0;
  std::vector<int> witnesses;
  for (int f = 0; f < face_count(); ++f) {
    bool any_below = false, any_above = false;
    if (!scan) local_convexity_witnesses(f, witnesses);
    const int count = scan ? vertex_count() : static_cast<int>(witnesses.size());
    for (int i = 0; i < count; ++i) {
      const int v = scan ? i : witnesses[static_cast<std::size_t>(i)];
      const T h = height(f, vertex(v));
      if (h < -conv_tol) any_below = true;
      if (h > conv_tol) {
        any_above = true;
        if (first_bad_face < 0) {
          first_bad_face = f;
          first_bad_vertex = v;
          first_bad_height = to_double(h);
        }
      }
    }
    if (any_above && !any_below) ++faces_all_above;
  }
  if (faces_all_above == face_count()) {
    fail(ErrorCode::InwardFaces,
         "all faces point inward: list each face counter-clockwise seen from outside");
  }
  if (first_bad_face >= 0) {
    fail(ErrorCode::NotConvex, "not convex: vertex " + std::to_string(first_bad_vertex) + " is " +
                                   std::to_string(first_bad_height) + " above the plane of face " +
                                   std::to_string(first_bad_face));
  }
  // adjacent faces must not be coplanar (they must be merged)
  for (int e = 0; e < edge_count(); ++e) {
    const int f = edge_face(e, 0), g = edge_face(e, 1);
    bool coplanar;
    if constexpr (number_traits<T>::is_exact) {
      coplanar = is_zero(cross(plane(f).normal, plane(g).normal));
    } else {
      const T tol = height_tolerance(Tolerances<T>::kCoplanar * kAdjacentCoplanarFraction);
      coplanar = true;
      int h = face(g).edge;
      for (int i = 0; i < face(g).count && coplanar; ++i, h = half_edge(h).next)
        coplanar = !(abs_of(height(f, vertex(half_edge(h).origin))) > tol);
    }
    if (coplanar) {
      fail(ErrorCode::NotConvex, "faces " + std::to_string(f) + " and " + std::to_string(g) +
                                     " are adjacent and coplanar: merge them into one face");
    }
  }
}

}  // namespace sepax
