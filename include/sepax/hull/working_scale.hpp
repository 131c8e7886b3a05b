// sepax/hull/working_scale.hpp
//
// Float and double hulls at every scale ConvexPolyhedron<T> accepts.  The builder's predicates multiply up
// to four coordinate differences and compare them with squared tolerances, so far below unit size they
// fall into T's subnormal range (a ball 1e-12 wide in float would be "collinear") and far above it they
// overflow.  A point set whose bounding box's largest width is outside [kHullExtentLow, kHullExtentHigh]
// (Tolerances<T>) is built at a power of two times its coordinates instead:
//   1. working_scale: the exponent k that brings that width into [1, 2), or 0 when it is in the range,
//      not finite (the builder names the coordinate), or some coordinate does not scale exactly;
//   2. scaled_points: the points x 2^k;
//   3. scaled_back: the hull built on them, its vertices x 2^-k and its faces, validated by
//      ConvexPolyhedron::from_faces at the input's scale (BadScale there names what does not fit).
// Multiplying by a power of two is exact, and rounding commutes with it while nothing over- or underflows:
// the scaled build takes the decisions the same build would take on the input with an unbounded exponent
// range, and its vertices scaled back are the input points, as for every hull.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "../convex_polyhedron.hpp"
#include "../number_traits.hpp"
#include "../tolerances.hpp"
#include "../vec3.hpp"
#include "index.hpp"

namespace sepax::hull::detail {

/// The exponent k of 2^k that brings the largest width of the points' bounding box into [1, 2) when that
/// width is outside [kHullExtentLow, kHullExtentHigh]; 0 when it is within, when it is not finite or zero
/// (the builder's own checks name the problem), or when some coordinate x would not come back from
/// 2^k x unchanged (overflow, or bits lost below T's normal range): the builder then works at the input's
/// scale and reports BadScale or what it finds there.
template <Number T>
int working_scale(std::span<const Vec3<T>> points) {
  if (points.empty()) return 0;
  double width = 0;
  for (int c = 0; c < 3; ++c) {
    double lo = to_double(points[0][c]), hi = lo;
    for (const auto& p : points) {
      lo = std::min(lo, to_double(p[c]));
      hi = std::max(hi, to_double(p[c]));
    }
    width = std::max(width, hi - lo);
  }
  // (a NaN or an infinity may hide from the width; it fails the round trip below)
  if (!std::isfinite(width) || width == 0) return 0;
  if (width >= Tolerances<T>::kHullExtentLow && width <= Tolerances<T>::kHullExtentHigh) return 0;
  const int k = -std::ilogb(width);
  for (const auto& p : points)
    for (int c = 0; c < 3; ++c) {
      const T y = std::ldexp(p[c], k);
      if (!std::isfinite(y) || std::ldexp(y, -k) != p[c]) return 0;
    }
  return k;
}

/// The points x 2^k (exact: working_scale checked every coordinate).
template <Number T>
std::vector<Vec3<T>> scaled_points(std::span<const Vec3<T>> points, int k) {
  std::vector<Vec3<T>> out;
  out.reserve(points.size());
  for (const auto& p : points)
    out.emplace_back(std::ldexp(p[0], k), std::ldexp(p[1], k), std::ldexp(p[2], k));
  return out;
}

/// The hull h of the points x 2^k at the points' scale: its vertices x 2^-k (the input points again) and
/// its faces, validated as from_faces validates every face list; BadScale when the input's scale is
/// outside what ConvexPolyhedron<T> accepts (tolerances.hpp, "Scale range").
template <Number T>
ConvexPolyhedron<T> scaled_back(const ConvexPolyhedron<T>& h, int k) {
  std::vector<Vec3<T>> vertices;
  vertices.reserve(as_index(h.vertex_count()));
  for (const auto& v : h.vertices())
    vertices.emplace_back(std::ldexp(v[0], -k), std::ldexp(v[1], -k), std::ldexp(v[2], -k));
  std::vector<std::vector<int>> faces;
  faces.reserve(as_index(h.face_count()));
  for (int f = 0; f < h.face_count(); ++f) faces.push_back(h.face_vertices(f));
  return ConvexPolyhedron<T>::from_faces(std::move(vertices), faces);
}

}  // namespace sepax::hull::detail
