// sepax/hull/flat_hull.hpp
//
// A point set within the flat tolerance of a plane (exact T: in one plane) is a flat double-sided polygon:
//   1. sort the points on the two coordinates other than the normal's largest component, along the one
//      they spread most on;
//   2. Andrew's monotone chain (polygon_2d.hpp) with the strict turn decided in 3D against the normal;
//      float T: tolerant_loop drops corners within eps of their neighbours' line where every corner a new
//      edge skips is within eps of it (of the edge, not only of its line);
//   3. float T: start the loop where validation accepts it (precheck.hpp), else reject the failing corner;
//   4. ConvexPolyhedron::polygon validates the result.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "../error.hpp"
#include "builder.hpp"
#include "polygon_2d.hpp"

namespace sepax::hull::detail {

// The flat hull of the active points, in the plane with normal n.
template <Number T>
inline std::optional<ConvexPolyhedron<T>> Builder<T>::polygon(const std::vector<int>& active,
                                                              const Vec3<T>& n, std::vector<int>& reject) {
  tris_state_ = TrisState::none;
  // Sort on the two coordinates other than n's largest component (exact
  // for exact T); decide turns in 3D against n.
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (abs_of(n[i]) > abs_of(n[k])) k = i;
  // Sort along the in-plane axis the points spread most on: the tolerant
  // turn test below only drops points between their neighbours in sort
  // order, so a needle sorted across its width (by its tiny coordinate
  // first) would lose one end (half the extent).
  int u = (k + 1) % 3, w = (k + 2) % 3;
  {
    auto spread = [&](int c) {
      T lo = local_point(active[0])[c], hi = lo;
      for (int i : active) {
        lo = std::min(lo, local_point(i)[c]);
        hi = std::max(hi, local_point(i)[c]);
      }
      return T(hi - lo);
    };
    if (spread(w) > spread(u)) std::swap(u, w);
  }
  std::vector<int> pts = active;
  std::sort(pts.begin(), pts.end(), [&](int i, int j) {
    if (local_point(i)[u] != local_point(j)[u]) return local_point(i)[u] < local_point(j)[u];
    return local_point(i)[w] < local_point(j)[w];
  });
  const bool flip = n[k] < T(0);
  const T nlen = length(n);
  auto turn = [&](int p0, int p1, int p2) {
    const T t =
        dot(n, cross(Vec3<T>(local_point(p1) - local_point(p0)), Vec3<T>(local_point(p2) - local_point(p1))));
    return flip ? T(-t) : t;
  };
  std::vector<int> hull =
      monotone_chain(pts, [&](int p0, int p1, int p2) { return turn(p0, p1, p2) > T(0); });
  if constexpr (Traits::kTolerantChain) {
    // the distance of p2 from the line p0 p1 (and of p0 from p1 p2) > eps
    auto left = [&](int p0, int p1, int p2) {
      return Traits::left_turn(turn(p0, p1, p2), [&] {
        const T len = std::max(length(Vec3<T>(local_point(p1) - local_point(p0))),
                               length(Vec3<T>(local_point(p2) - local_point(p1))));
        return T(eps_ * nlen * len);
      });
    };
    // q within eps of the segment a c: of an end point if q lies beyond it, else at most eps outside
    // the line a c, turn(a, q, c) / (|n| |c - a|) <= eps
    auto within = [&](int a, int c, int q) {
      const Vec3<T> e(local_point(c) - local_point(a));
      const Vec3<T> qa(local_point(q) - local_point(a)), qc(local_point(q) - local_point(c));
      if (dot(qa, e) < T(0)) return length(qa) <= eps_;
      if (dot(qc, e) > T(0)) return length(qc) <= eps_;
      return turn(a, q, c) <= T(eps_ * nlen * length(e));
    };
    hull = tolerant_loop(hull, within, left);
  }
  if (hull.size() < 3) {
    throw InvalidInput(ErrorCode::Collinear,
                       "convex_hull: all points lie on one line" + std::string(Traits::kLineNote));
  }
  if constexpr (Traits::kPrechecks) {
    // Start at the best-conditioned corner, or if validation would refuse
    // that (a slab up to flat*extent thick is off the plane triple by more
    // than the planarity tolerance from some starts), at the first corner
    // it accepts, rather than losing a vertex.
    start_at_best_apex(hull);
    for (std::size_t rot = 0; rot < hull.size(); ++rot) {
      std::vector<int> front = hull;
      std::rotate(front.begin(), front.begin() + static_cast<std::ptrdiff_t>(rot), front.end());
      std::vector<std::vector<int>> both{front, std::vector<int>(front.rbegin(), front.rend())};
      std::vector<int> r;
      prevalidate(both, r, true);
      if (rot == 0) reject = r;
      if (r.empty()) {
        reject.clear();
        hull = std::move(front);
        break;
      }
    }
    if (!reject.empty()) return std::nullopt;
  }
  std::vector<Vec3<T>> loop;
  out_vertex_.assign(pts_.size(), 0);
  for (int i : hull) {
    loop.push_back(in_[as_index(pts_[as_index(i)])]);
    out_vertex_[as_index(i)] = 1;
  }
  return finish([&] { return ConvexPolyhedron<T>::polygon(std::move(loop)); });
}

}  // namespace sepax::hull::detail
