// sepax/manifold_reduction.hpp
//
// reduce_contact_points: choose at most four of a face contact's points so
// that the deepest point is kept and the kept points span a large area.
//
// Greedy, deterministic for a given input (every tie goes to the lowest index):
//   1. p0: the deepest point (smallest separation key);
//   2. p1: the point farthest from p0;
//   3. p2: the point that makes the triangle p0 p1 p2 of largest area;
//   4. p3: the point outside that triangle that adds the largest area to it
//          (the largest triangle it forms with an edge it lies outside of).
// A point is only taken when it adds more than `area_tol` (twice the area,
// measured along `normal`, in normal-length units; for the distance of step 2,
// squared length); for exact T pass 0 and nothing but exactly degenerate
// points is refused.  Areas are
// ((b - a) x (c - a)) . normal: products and sums only, so the choice is exact
// for exact T.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "vec3.hpp"

namespace sepax {

/// Indices (into `points`) of the kept points, in the order chosen.
/// `keys[i]` orders depth: smaller = deeper.  Float near-ties are ties: a
/// candidate within `key_tol` of the deepest key, or within `area_tol` (in
/// squared-length units) of the largest squared distance or doubled area,
/// counts as equal, and the lowest index among the equal ones wins; this keeps
/// the choice stable under rounding (e.g. when the same configuration is
/// scaled).  A point is only taken when it adds more than `area_tol`.  For
/// exact T pass 0 for both.
template <Number T>
std::vector<int> reduce_contact_points(const std::vector<Vec3<T>>& points, const std::vector<T>& keys,
                                       const Vec3<T>& normal, const T& key_tol, const T& area_tol) {
  const int n = static_cast<int>(points.size());
  std::vector<int> out;
  if (n == 0) return out;
  if (n <= 4) {
    for (int i = 0; i < n; ++i) out.push_back(i);
    return out;
  }
  auto P = [&](int i) -> const Vec3<T>& { return points[static_cast<std::size_t>(i)]; };
  auto area = [&](int a, int b, int c) {
    return dot(cross(Vec3<T>(P(b) - P(a)), Vec3<T>(P(c) - P(a))), normal);
  };
  // The lowest index whose value is within tol of the maximum of value(i) over
  // the admissible i with value(i) > floor; -1 if none.
  auto pick = [&](auto&& value, auto&& admissible, const T& floor, const T& tol) {
    bool any = false;
    T best(0);
    int best_i = -1;
    for (int i = 0; i < n; ++i) {
      if (!admissible(i)) continue;
      const T v = value(i);
      if (v > floor && (!any || v > best)) {
        best = v;
        best_i = i;
        any = true;
      }
    }
    if (!any) return -1;
    if (!(tol > T(0))) return best_i;  // exact: the first maximum
    // the lowest index within tol of the maximum (recomputed: no allocation)
    for (int i = 0; i < best_i; ++i) {
      if (!admissible(i)) continue;
      const T v = value(i);
      if (v > floor && v >= best - tol) return i;
    }
    return best_i;
  };
  // 1. deepest (largest -key)
  const T no_floor = [&] {
    T lo = keys[0];
    for (const T& k : keys)
      if (k < lo) lo = k;
    return T(-lo - T(1));
  }();
  const int i0 = pick([&](int i) { return T(-keys[static_cast<std::size_t>(i)]); }, [](int) { return true; }, no_floor,
                      key_tol);
  out.push_back(i0);
  // 2. farthest from p0
  const int i1 = pick([&](int i) { return squared_norm(Vec3<T>(P(i) - P(i0))); }, [&](int i) { return i != i0; },
                      area_tol, area_tol);
  if (i1 < 0) return out;
  out.push_back(i1);
  // 3. largest triangle (either orientation)
  const int i2 = pick([&](int i) { return abs_of(area(i0, i1, i)); }, [&](int i) { return i != i0 && i != i1; },
                      area_tol, area_tol);
  if (i2 < 0) return out;
  out.push_back(i2);
  // 4. the point adding the most area outside the triangle: the largest
  // triangle it forms with an edge it lies outside of.  Orient the triangle
  // counter-clockwise about the normal first.
  std::array<int, 3> tri{i0, i1, i2};
  if (area(i0, i1, i2) < T(0)) tri = {i0, i2, i1};
  auto added = [&](int i) {
    T add(0);
    for (int k = 0; k < 3; ++k) {
      // outside edge (tri[k], tri[k+1]) <=> negative area (tri[k], tri[k+1], i)
      const T s = T(-area(tri[static_cast<std::size_t>(k)], tri[static_cast<std::size_t>((k + 1) % 3)], i));
      if (s > add) add = s;
    }
    return add;
  };
  const int i3 = pick(added, [&](int i) { return i != i0 && i != i1 && i != i2; }, area_tol, area_tol);
  if (i3 >= 0) out.push_back(i3);
  return out;
}

}  // namespace sepax
