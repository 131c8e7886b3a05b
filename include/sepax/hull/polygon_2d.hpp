// sepax/hull/polygon_2d.hpp
//
// Convex polygons in a plane, in double, for the flat hull and the float fallbacks:
//   1. plane_basis: an orthonormal basis of a plane given its unit normal.
//   2. monotone_chain: Andrew's monotone chain over sorted points, with the turn test as a parameter.
//   3. tolerant_loop: a convex loop with the corners dropped that a tolerance allows, every dropped corner
//      checked against the edge that replaces it.
//   4. hull_2d: the counter-clockwise 2D hull of points, corners within a tolerance of their neighbours' line
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

// The counter-clockwise convex loop with corners dropped, for a tolerant
// hull: within(a, c, q) says that corner q is within the tolerance of the
// segment a c (of the segment, not of its line: a corner beyond c near the
// line's extension is not within the polygon's tolerance, and a chord
// from the tip of a needle would otherwise reach around the other tip);
// left(p, q, r) that corner q turns left by more than it.
//   1. From loop[0] (an extreme point of the sort, kept), the farthest
//      next corner c whose chord every skipped corner is within, found by
//      galloping and bisection: each chord tried is checked against every
//      corner it skips, O(n log n) over the loop.
//   2. A corner left refuses is dropped when the chord of its neighbours
//      still passes within the tolerance of every corner it skips (a stack
//      pass around the loop, repeated until none is); one that cannot be
//      dropped stays, a strictly convex corner.
// (A chain that drops corners one at a time against their current
// neighbours lets the error add up along a dense arc: on 10^5 points of a
// circle in float it keeps 8 corners, with points 3 800 eps outside.)
template <class I, class Within, class Left>
inline std::vector<I> tolerant_loop(const std::vector<I>& loop, Within within, Left left) {
  const std::size_t m = loop.size();
  if (m < 3) return loop;
  auto at = [&](std::size_t i) { return loop[i % m]; };
  auto chord = [&](std::size_t a, std::size_t c) {
    for (std::size_t b = a + 1; b < c; ++b)
      if (!within(at(a), at(c), at(b))) return false;
    return true;
  };
  std::vector<std::size_t> kept;  // positions in loop, increasing
  for (std::size_t a = 0; a < m;) {
    kept.push_back(a);
    // the farthest corner a chord may reach: back to loop[0] (position m), except from loop[0] itself,
    // whose chord to itself would skip every corner with no line to measure them against
    const std::size_t last = a == 0 ? m - 1 : m;
    std::size_t good = a + 1, bad = last + 1;  // chord(a, good) holds; chord(a, bad) fails (last + 1: none)
    for (std::size_t step = 2; good < last; step *= 2) {
      const std::size_t c = std::min(a + step, last);
      if (!chord(a, c)) {
        bad = c;
        break;
      }
      good = c;
    }
    while (bad <= last && bad - good > 1) {
      const std::size_t mid = good + (bad - good) / 2;
      (chord(a, mid) ? good : bad) = mid;
    }
    a = good;
  }
  // corner b between a and c (positions, c may be past the end: c - m) is dropped if left refuses it and
  // the chord a c is still within the tolerance of every corner it skips
  auto drop = [&](std::size_t pa, std::size_t pb, std::size_t pc) {
    return !left(at(pa), at(pb), at(pc)) && chord(pa, pc);
  };
  for (bool dropped = true; dropped && kept.size() >= 3;) {
    dropped = false;
    std::vector<std::size_t> next;
    for (const std::size_t q : kept) {
      while (next.size() >= 2 && drop(next[next.size() - 2], next.back(), q)) {
        next.pop_back();
        dropped = true;
      }
      next.push_back(q);
    }
    // the corners at the seam: the last one, then the first one
    while (next.size() >= 3 && drop(next[next.size() - 2], next.back(), next.front() + m)) {
      next.pop_back();
      dropped = true;
    }
    while (next.size() >= 3 && drop(next.back(), next.front() + m, next[1] + m)) {
      next.erase(next.begin());
      dropped = true;
    }
    kept = std::move(next);
  }
  std::vector<I> out;
  for (const std::size_t k : kept) out.push_back(loop[k]);
  return out;
}

// Counter-clockwise 2D hull (Andrew's monotone chain) of p, indices into
// p: the strict chain, then tolerant_loop drops a corner whose neighbours'
// line passes within tol of it (either end point within tol of the other
// edge's line) when every corner it skips is within tol of its chord.
inline std::vector<std::size_t> hull_2d(const std::vector<std::array<double, 2>>& p, double tol) {
  const std::size_t n = p.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return p[i] < p[j]; });
  auto turn = [&](std::size_t i0, std::size_t i1, std::size_t i2) {
    const double ex = p[i1][0] - p[i0][0], ey = p[i1][1] - p[i0][1];
    const double fx = p[i2][0] - p[i1][0], fy = p[i2][1] - p[i1][1];
    return ex * fy - ey * fx;
  };
  auto left = [&](std::size_t i0, std::size_t i1, std::size_t i2) {
    const double len = std::max(std::hypot(p[i1][0] - p[i0][0], p[i1][1] - p[i0][1]),
                                std::hypot(p[i2][0] - p[i1][0], p[i2][1] - p[i1][1]));
    return turn(i0, i1, i2) > tol * len;
  };
  // q within tol of the segment a c: of an end point if q lies beyond it, else of the line, whose
  // distance outside it is turn(a, q, c) / |c - a|
  auto within = [&](std::size_t a, std::size_t c, std::size_t q) {
    const double ex = p[c][0] - p[a][0], ey = p[c][1] - p[a][1];
    if ((p[q][0] - p[a][0]) * ex + (p[q][1] - p[a][1]) * ey < 0)
      return std::hypot(p[q][0] - p[a][0], p[q][1] - p[a][1]) <= tol;
    if ((p[q][0] - p[c][0]) * ex + (p[q][1] - p[c][1]) * ey > 0)
      return std::hypot(p[q][0] - p[c][0], p[q][1] - p[c][1]) <= tol;
    return turn(a, q, c) <= tol * std::hypot(ex, ey);
  };
  const std::vector<std::size_t> strict = monotone_chain(
      order, [&](std::size_t i0, std::size_t i1, std::size_t i2) { return turn(i0, i1, i2) > 0; });
  return tolerant_loop(strict, within, left);
}

}  // namespace sepax::hull::detail
