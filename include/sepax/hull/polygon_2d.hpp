// sepax/hull/polygon_2d.hpp
//
// Convex polygons in a plane, in double, for the flat hull and the float fallbacks:
//   1. plane_basis: an orthonormal basis of a plane given its unit normal.
//   2. monotone_chain: Andrew's monotone chain over sorted points, with the turn test as a parameter.
//   3. hull_2d: the counter-clockwise 2D hull of points, corners within a tolerance of their neighbours' line
//      dropped.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

#include "../vec3.hpp"

namespace sepax::hull::detail {

// An orthonormal basis of the plane with unit normal n.
inline std::pair<Vec3<double>, Vec3<double>> plane_basis(const Vec3<double>& n) {
  int k = 0;
  for (int c = 1; c < 3; ++c)
    if (std::abs(n[c]) < std::abs(n[k])) k = c;
  Vec3<double> ax(0, 0, 0);
  ax[k] = 1;
  ax = Vec3<double>(ax - dot(ax, n) * n);
  ax = Vec3<double>(ax / std::sqrt(squared_norm(ax)));
  return {ax, cross(n, ax)};
}

// Andrew's monotone chain: the counter-clockwise loop of the points that
// `order` lists, sorted (lower chain forwards, upper chain backwards); a
// corner stays only while left(previous, corner, next) holds.  Shared by
// the flat builder (polygon) and the slab fallback (hull_2d).
template <class I, class Left>
inline std::vector<I> monotone_chain(const std::vector<I>& order, Left left) {
  const std::size_t n = order.size();
  std::vector<I> loop;
  for (int pass = 0; pass < 2 && n > 0; ++pass) {
    const std::size_t base = loop.size();
    for (std::size_t idx = 0; idx < n; ++idx) {
      const I q = pass == 0 ? order[idx] : order[n - 1 - idx];
      while (loop.size() >= base + 2 && !left(loop[loop.size() - 2], loop.back(), q)) loop.pop_back();
      loop.push_back(q);
    }
    loop.pop_back();  // the last point of each chain is the first of the next
  }
  return loop;
}

// Counter-clockwise 2D hull (Andrew's monotone chain) of p, indices into
// p; a corner whose neighbours' line passes within tol of it (either end
// point within tol of the other edge's line) is dropped.
inline std::vector<std::size_t> hull_2d(const std::vector<std::array<double, 2>>& p, double tol) {
  const std::size_t n = p.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return p[i] < p[j]; });
  auto left = [&](std::size_t i0, std::size_t i1, std::size_t i2) {
    const double ex = p[i1][0] - p[i0][0], ey = p[i1][1] - p[i0][1];
    const double fx = p[i2][0] - p[i1][0], fy = p[i2][1] - p[i1][1];
    const double len = std::max(std::hypot(ex, ey), std::hypot(fx, fy));
    return ex * fy - ey * fx > tol * len;
  };
  return monotone_chain(order, left);
}

}  // namespace sepax::hull::detail
