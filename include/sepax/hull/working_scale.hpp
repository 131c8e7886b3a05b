// sepax/hull/working_scale.hpp
//
// Float and double hulls at every scale ConvexPolyhedron<T> accepts.  The builder's predicates multiply up
// to four coordinate differences and compare them with squared tolerances, so far below unit size they
// fall into T's subnormal range (a ball 1e-12 wide in float would be "collinear") and far above it they
// overflow.  A point set whose bounding box's largest width is outside [kHullExtentLow, kHullExtentHigh]
// (Tolerances<T>) is built at a power of two times its coordinates instead:
//   1. working_scale: the exponent k that brings that width into [1, 2), or 0 when it is in the range,
//      not finite (the builder names the coordinate), or some coordinate would overflow;
//   2. scaled_points: the points x 2^k;
//   3. scaled_back: the hull built on them, its vertices x 2^-k (a vertex that is a scaled point whose
//      coordinates lost bits: that input point) and its faces, validated by ConvexPolyhedron::from_faces at
//      the input's scale (BadScale there names what does not fit).
// Multiplying by a power of two is exact, and rounding commutes with it while nothing over- or underflows:
// the scaled build takes the decisions the same build would take on the input with an unbounded exponent
// range, and its vertices scaled back are the input points, as for every hull.  Scaling down, a coordinate
// far below the width (an interior point at 1e-30 of a float set 1e20 wide) can fall below T's normal
// range and lose bits: rounded to nearest, it moves by at most half of T's smallest subnormal times 2^-k,
// at most 2^-150 (float) or 2^-1075 (double) times the width, far below every tolerance; the build decides
// on the rounded point and the output holds the input point.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
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
/// (the builder's own checks name the problem), or when some coordinate x would overflow in 2^k x (a set
/// far from the origin relative to its width): the builder then works at the input's scale and reports
/// BadScale or what it finds there.  (Bits lost below T's normal range scaling down are allowed: see the
/// header.)
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
      if (!std::isfinite(std::ldexp(p[c], k))) return 0;
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

/// The hull h of scaled (points x 2^k) at the points' scale: its vertices x 2^-k (the input points again;
/// a vertex that is a scaled point whose coordinates lost bits below T's normal range is that input point)
/// and its faces, validated as from_faces validates every face list; BadScale when the input's scale is
/// outside what ConvexPolyhedron<T> accepts (tolerances.hpp, "Scale range").
template <Number T>
ConvexPolyhedron<T> scaled_back(const ConvexPolyhedron<T>& h, int k, std::span<const Vec3<T>> points,
                                const std::vector<Vec3<T>>& scaled) {
  auto back = [k](const Vec3<T>& v) {
    return Vec3<T>(std::ldexp(v[0], -k), std::ldexp(v[1], -k), std::ldexp(v[2], -k));
  };
  std::map<std::array<T, 3>, std::size_t> lost;  // scaled point -> its input point, where bits were lost
  for (std::size_t i = 0; i < points.size(); ++i)
    if (back(scaled[i]) != points[i])
      lost.emplace(std::array<T, 3>{scaled[i][0], scaled[i][1], scaled[i][2]}, i);
  std::vector<Vec3<T>> vertices;
  vertices.reserve(as_index(h.vertex_count()));
  for (const auto& v : h.vertices()) {
    const auto it = lost.empty() ? lost.end() : lost.find(std::array<T, 3>{v[0], v[1], v[2]});
    vertices.push_back(it != lost.end() ? points[it->second] : back(v));
  }
  std::vector<std::vector<int>> faces;
  faces.reserve(as_index(h.face_count()));
  for (int f = 0; f < h.face_count(); ++f) faces.push_back(h.face_vertices(f));
  return ConvexPolyhedron<T>::from_faces(std::move(vertices), faces);
}

}  // namespace sepax::hull::detail
