// sepax/clip_polygon.hpp
//
// Sutherland-Hodgman clipping of a convex polygon (the incident face) against
// one plane (a side plane of the reference face, contact_manifold.hpp), keeping
// the part on the inner side (dot(normal, x) - offset <= 0), with the features
// that made every output vertex (ClipVertex):
//   * a cut of an incident edge e by side plane s gives {Edge(s), Edge(e)};
//   * a cut of a segment lying on side plane s' by side plane s gives the
//     reference corner between s' and s: {Vertex(c), Face(G)}.
// For exact T every output point is exact (t = d_a / (d_a - d_b), a quotient of
// plane heights) and never duplicated (a vertex exactly on the plane is kept
// and makes no intersection point); float clipping can produce near-duplicates,
// which weld_polygon removes with a tolerance the caller scales by the shapes'
// extent.
#pragma once

#include "small_vector.hpp"

#include <cstddef>
#include <type_traits>
#include <vector>

#include "contact_feature.hpp"
#include "vec3.hpp"

namespace sepax {

/// A vertex of the clipped polygon with the features that made it:
///   * id.a:  its feature on the reference side (Face = not cut yet, Edge(s) =
///            on side plane s, Vertex(c) = the reference corner c),
///   * id.b:  its feature on the incident side (Vertex(v), Edge(e), Face(G)),
///   * the label of the segment from it to the next vertex: an incident edge,
///     or a side plane of the reference face (the segment a previous clip
///     created along that plane).
template <class T>
struct ClipVertex {
  /// The point, in the frame of the clipped polygon.
  Vec3<T> point;
  /// a: reference-side feature, b: incident-side feature.
  ContactFeatureId id;
  /// The segment to the next vertex lies on incident edge `next_edge`
  /// (next_on_side false) or on the side plane of reference edge `next_edge`
  /// whose vertices are side_tail/side_head (next_on_side true).
  int next_edge = -1;
  bool next_on_side = false;
  int side_tail = -1;
  int side_head = -1;
};

/// A side plane: points with dot(normal, x) - offset <= 0 are kept.
template <class T>
struct ClipPlane {
  Vec3<T> normal;
  T offset;
  int edge = -1;  // the reference edge (undirected index) this plane stands on
  int tail = -1;  // its two vertices, for the ids of reference corners
  int head = -1;
};

/// The reference corner shared by the side edges (t1,h1) and (t2,h2), or -1
/// when they share no vertex.
inline int shared_corner(int t1, int h1, int t2, int h2) {
  if (h1 == t2 || h1 == h2) return h1;
  if (t1 == t2 || t1 == h2) return t1;
  return -1;
}

namespace clip_detail {

/// clip_polygon's body, with height(i) the signed height of in[i] over the
/// plane (computed once per vertex).
template <Number T, class Poly, class Height>
void clip_with(const Poly& in, const ClipPlane<T>& plane, int incident_face, Poly& out, Height&& height) {
  out.clear();
  const std::size_t n = in.size();
  if (n == 0) return;
  const T zero(0);
  auto cut = [&](const ClipVertex<T>& a, const T& da, const ClipVertex<T>& b, const T& db) {
    // da and db have strictly opposite signs (one may be <= 0, the other > 0).
    const T t = da / T(da - db);
    ClipVertex<T> c;
    c.point =
        Vec3<T>(a.point[0] + t * T(b.point[0] - a.point[0]), a.point[1] + t * T(b.point[1] - a.point[1]),
                a.point[2] + t * T(b.point[2] - a.point[2]));
    if (a.next_on_side) {
      const int corner = shared_corner(a.side_tail, a.side_head, plane.tail, plane.head);
      c.id.a = corner >= 0 ? ShapeFeature::vertex(corner) : ShapeFeature::edge(plane.edge);
      c.id.b = ShapeFeature::face(incident_face);
    } else {
      c.id.a = ShapeFeature::edge(plane.edge);
      c.id.b = ShapeFeature::edge(a.next_edge);
    }
    return c;
  };
  auto on_side = [&](ClipVertex<T>& v) {
    v.next_edge = plane.edge;
    v.next_on_side = true;
    v.side_tail = plane.tail;
    v.side_head = plane.head;
  };
  T dcur = height(std::size_t{0});
  const T d0 = dcur;
  for (std::size_t i = 0; i < n; ++i) {
    const ClipVertex<T>& cur = in[i];
    const ClipVertex<T>& nxt = in[(i + 1) % n];
    const T dnxt = (i + 1 == n) ? d0 : height(i + 1);
    const bool cur_in = !(dcur > zero);
    const bool nxt_in = !(dnxt > zero);
    if (cur_in) {
      out.push_back(cur);
      // On the plane and the polygon leaves here: the segment from cur now
      // runs along the plane.
      if (!nxt_in && dcur == zero) on_side(out.back());
    }
    if (cur_in && !nxt_in && dcur < zero) {
      ClipVertex<T> c = cut(cur, dcur, nxt, dnxt);  // exit point
      on_side(c);
      out.push_back(c);
    } else if (!cur_in && nxt_in && dnxt < zero) {
      ClipVertex<T> c = cut(cur, dcur, nxt, dnxt);  // entry point, continues along cur's segment
      c.next_edge = cur.next_edge;
      c.next_on_side = cur.next_on_side;
      c.side_tail = cur.side_tail;
      c.side_head = cur.side_head;
      out.push_back(c);
    }
    dcur = dnxt;
  }
}

template <Number T>
T height_over(const ClipPlane<T>& plane, const Vec3<T>& p) {
  return T(dot(plane.normal, p) - plane.offset);
}

}  // namespace clip_detail

/// Clip `in` against `plane` into `out` (cleared first).  `incident_face` is
/// the incident face index (the incident feature of reference corners).
/// Poly: std::vector<ClipVertex<T>> or a SmallVector of them.
template <Number T, class Poly>
void clip_polygon(const Poly& in, const ClipPlane<T>& plane, int incident_face, Poly& out) {
  clip_detail::clip_with(in, plane, incident_face, out,
                         [&](std::size_t i) { return clip_detail::height_over(plane, in[i].point); });
}

/// clip_polygon, unless `plane` keeps every vertex of `in` (no height > 0):
/// then false and `out` untouched, for clip_polygon's output would be `in`
/// itself, labels included.  The test and the clip read the same heights,
/// each computed once (the same decision with FMA contraction on or off).
/// Heights are kept inline up to 64 vertices (no allocation below).
template <Number T, class Poly>
bool clip_polygon_if_cut(const Poly& in, const ClipPlane<T>& plane, int incident_face, Poly& out) {
  SmallVector<T, 64> heights;
  heights.reserve(in.size());
  bool all_in = true;
  for (const auto& v : in) {
    heights.push_back(clip_detail::height_over(plane, v.point));
    all_in = all_in && !(heights.back() > T(0));
  }
  if (all_in) return false;
  clip_detail::clip_with(in, plane, incident_face, out, [&](std::size_t i) { return heights[i]; });
  return true;
}

namespace clip_detail {

/// weld_polygon's body with close(x, y) its test of two vertices.
template <class Poly, class Close>
void weld_with(Poly& poly, Close&& close) {
  if (poly.size() < 2) return;
  auto take_label = [](auto& to, const auto& from) {
    to.next_edge = from.next_edge;
    to.next_on_side = from.next_on_side;
    to.side_tail = from.side_tail;
    to.side_head = from.side_head;
  };
  // In place (no allocation): w is the number of vertices kept so far.
  std::size_t w = 1;
  for (std::size_t i = 1; i < poly.size(); ++i) {
    if (close(poly[i], poly[w - 1])) {
      take_label(poly[w - 1], poly[i]);
      continue;
    }
    if (w != i) poly[w] = poly[i];
    ++w;
  }
  while (w > 1 && close(poly[0], poly[w - 1])) --w;
  poly.resize(w);
}

}  // namespace clip_detail

/// Remove consecutive vertices (cyclically) closer than sqrt(tol2) to the
/// vertex kept before them.  The first vertex of a run is kept, with the label
/// of the last one (the segment leaving the run).  tol2 = 0 removes exact
/// duplicates only (the exact-type case).  Float and double with
/// scale_exponent k != 0: differences are measured in units of 2^k, tol2
/// given in those units (manifold_scale_exponent: squares in range at every
/// scale).
template <Number T, class Poly>
void weld_polygon(Poly& poly, const T& tol2, int scale_exponent = 0) {
  if constexpr (std::is_floating_point_v<T>) {
    if (scale_exponent != 0) {
      clip_detail::weld_with(poly, [&](const ClipVertex<T>& x, const ClipVertex<T>& y) {
        return !(squared_norm(detail::scale_pow2(Vec3<T>(x.point - y.point), scale_exponent)) > tol2);
      });
      return;
    }
  }
  clip_detail::weld_with(poly, [&](const ClipVertex<T>& x, const ClipVertex<T>& y) {
    return !(squared_norm(Vec3<T>(x.point - y.point)) > tol2);
  });
}

}  // namespace sepax
