// sepax/hull/local_frame.hpp
//
// A hull in its own frame, for point sets far from the origin:
//   1. exact_origin: an origin near the points' bounding-box centre on a grid
//      coarse enough that p - origin is exact in T for every point (checked
//      with an error-free subtraction; exact T: the zero vector).
//   2. convex_hull_local: the hull of the translated points, and that origin;
//      the world hull is shape + origin, every vertex exactly an input point.
// float cannot validate a 0.4-unit shape 150 units from the origin (its planes
// are evaluated with u x 150 of rounding, more than the planarity tolerance of
// 0.4 x 4e-5), but it can in the shape's own frame.
#pragma once

#include <cmath>
#include <span>
#include <vector>

#include "../convex_polyhedron.hpp"
#include "../number_traits.hpp"
#include "../vec3.hpp"

namespace sepax {

template <Number T>
ConvexPolyhedron<T> convex_hull(std::span<const Vec3<T>> points);

/// A convex hull in its own frame: the world hull is shape translated by origin.
template <Number T>
struct LocalHull {
  ConvexPolyhedron<T> shape;
  Vec3<T> origin;
};

namespace hull {

/// Whether a - b is exact in T (TwoSum: the rounding error of the difference
/// is computed exactly; exact T: always).
template <Number T>
bool exact_difference(const T& a, const T& b) {
  if constexpr (number_traits<T>::is_exact) {
    (void)a;
    (void)b;
    return true;
  } else {
    const T nb = -b;
    const T s = a + nb;
    const T bb = s - a;
    const T err = (a - (s - bb)) + (nb - bb);
    return err == T(0) && std::isfinite(s);
  }
}

/// An origin for points such that p - origin is exact in T for every point:
/// per coordinate, the box centre rounded to a multiple of 2^k, starting with
/// the smallest 2^k >= 2 x the box width and doubling until every difference
/// is exact (at the latest when the rounded centre is 0).  The zero vector
/// for exact T and for points whose box contains the origin's neighbourhood.
template <Number T>
Vec3<T> exact_origin(std::span<const Vec3<T>> points) {
  Vec3<T> origin(T(0), T(0), T(0));
  if constexpr (!number_traits<T>::is_exact) {
    if (points.empty()) return origin;
    for (int c = 0; c < 3; ++c) {
      double lo = to_double(points[0][c]), hi = lo;
      for (const auto& p : points) {
        lo = std::min(lo, to_double(p[c]));
        hi = std::max(hi, to_double(p[c]));
      }
      if (!std::isfinite(lo) || !std::isfinite(hi)) return Vec3<T>(T(0), T(0), T(0));
      const double centre = lo / 2 + hi / 2;
      int k = std::ilogb(std::max(2 * (hi - lo), std::numeric_limits<double>::min())) + 1;
      for (;; ++k) {
        const double step = std::ldexp(1.0, k);
        const T o = static_cast<T>(std::round(centre / step) * step);
        bool exact = to_double(o) == std::round(centre / step) * step;
        for (std::size_t i = 0; i < points.size() && exact; ++i) exact = exact_difference(points[i][c], o);
        if (exact) {
          origin[c] = o;
          break;
        }
        if (o == T(0)) break;  // (unreachable: p - 0 is exact)
      }
    }
  }
  return origin;
}

}  // namespace hull

/// The convex hull of points in its own frame: shape is convex_hull of the
/// points minus origin (hull::exact_origin: every subtraction exact), so a
/// small shape far from the origin is built and validated at its own scale.
/// shape.vertex(v) + origin is exactly the input point it comes from.
template <Number T>
LocalHull<T> convex_hull_local(std::span<const Vec3<T>> points) {
  const Vec3<T> origin = hull::exact_origin<T>(points);
  std::vector<Vec3<T>> local;
  local.reserve(points.size());
  for (const auto& p : points) local.push_back(Vec3<T>(p - origin));
  return LocalHull<T>{convex_hull<T>(std::span<const Vec3<T>>(local.data(), local.size())), origin};
}

template <Number T>
LocalHull<T> convex_hull_local(const std::vector<Vec3<T>>& points) {
  return convex_hull_local<T>(std::span<const Vec3<T>>(points.data(), points.size()));
}

}  // namespace sepax
