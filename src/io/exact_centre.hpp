// src/io/exact_centre.hpp
//
// exact_centre<T>: a translation c, per axis, such that x - c is exact in T
// for every coordinate x of the given point sets.  The program builds its
// shapes at x - c and adds c back to the positions it reports, so a small
// shape far from the origin (a decomposition piece 0.4 wide at 150 units) is
// validated and queried near the origin: in float, validation cannot resolve
// a shape more than about 40 of its extents from the origin
// (sepax/tolerances.hpp), whatever the shape.
//
// Why the subtraction is exact (T a binary floating-point type): on an axis
// where every coordinate lies in [lo, hi] with 0 < lo and hi <= 2 lo, take
// c = fl(lo + (hi - lo) / 2).  hi - lo is exact (Sterbenz), so is the halving
// (barring underflow), and rounding to nearest is monotonic with lo and hi
// representable, so lo <= c <= hi.  Then for every x in [lo, hi]:
// x / 2 <= hi / 2 <= lo <= c and c <= hi <= 2 lo <= 2 x, and Sterbenz's lemma
// makes fl(x - c) = x - c.  The negative side is the mirror image.  On any
// other axis the coordinates span at least half their largest magnitude
// (hi > 2 lo > 0 gives hi - lo > hi / 2; a sign change gives |x| <= hi - lo),
// so the shapes are already within two extents of the origin there and c = 0.
// After the translation every coordinate is within one extent of the
// origin.  Exact types need no re-centring: c = 0.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include <sepax/number_traits.hpp>
#include <sepax/tolerances.hpp>
#include <sepax/vec3.hpp>

namespace sepax::cli::io {

template <Number T>
Vec3<T> exact_centre(std::span<const std::vector<Vec3<T>>> point_sets) {
  Vec3<T> c(T(0), T(0), T(0));
  if constexpr (!number_traits<T>::is_exact) {
    for (int axis = 0; axis < 3; ++axis) {
      bool any = false;
      T lo = T(0), hi = T(0);
      for (const auto& set : point_sets) {
        for (const auto& p : set) {
          if (!any || p[axis] < lo) lo = p[axis];
          if (!any || p[axis] > hi) hi = p[axis];
          any = true;
        }
      }
      if (!any) continue;
      if (lo > T(0) && hi / 2 <= lo) {
        c[axis] = lo + (hi - lo) / 2;
      } else if (hi < T(0) && lo / 2 >= hi) {
        c[axis] = hi + (lo - hi) / 2;
      }
    }
  }
  return c;
}

/// Whether points, moved by -c, are near enough to the origin for T to
/// resolve them as a shape: their largest |coordinate| at most half of
/// planarity * extent / (kHullFarRounding u), the bound beyond which the hull
/// builder (and validation) cannot resolve a shape's planes
/// (sepax/tolerances.hpp: about 40 extents for float, 2e5 for double); the
/// half leaves room for the coordinates' own rounding.  Always true for exact T.
template <Number T>
bool resolvable_around(const std::vector<Vec3<T>>& points, const Vec3<T>& c) {
  if constexpr (number_traits<T>::is_exact) {
    return true;
  } else {
    if (points.empty()) return true;
    Vec3<double> lo = vec_to_double(points[0]), hi = lo;
    double far = 0;
    for (const auto& p : points) {
      const Vec3<double> q = vec_to_double(p), d = vec_to_double(Vec3<T>(p - c));
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], q[k]);
        hi[k] = std::max(hi[k], q[k]);
        far = std::max(far, std::abs(d[k]));
      }
    }
    const double extent = std::sqrt(squared_norm(Vec3<double>(hi - lo)));
    return far <=
           Tolerances<T>::kPlanarity / (2 * kHullFarRounding * number_traits<T>::unit_roundoff) * extent;
  }
}

/// points - c, each subtraction exact when c = exact_centre of a family of
/// sets that includes points.
template <Number T>
std::vector<Vec3<T>> minus(std::vector<Vec3<T>> points, const Vec3<T>& c) {
  for (auto& p : points) p = p - c;
  return points;
}

}  // namespace sepax::cli::io
