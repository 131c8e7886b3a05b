// sepax/hull/welded_points.hpp
//
// The builder's first steps, before any hull:
//   1. check_input: NaN/Inf (NonFinite, naming the point), fewer than 3 points (TooFewPoints), an extent
//      that overflows plane computations (BadScale); the tolerances eps, flat and weld of the extent.
//   2. local: float T decides on coordinates relative to the bounding-box centre (exact T: as given).
//   3. weld: one representative of the points closer than weld * extent (exact T: of exact duplicates);
//      fewer than 3 left is TooFewPoints.
//   4. make_shadow: exact T whose coordinates are all exactly doubles gets a double copy, so that the
//      quickhull predicates are filtered (orientation_filter.hpp) before they are decided in T.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "../error.hpp"
#include "../number_traits.hpp"
#include "../tolerances.hpp"
#include "builder.hpp"

namespace sepax::hull::detail {

template <Number T>
inline void Builder<T>::check_input() {
  for (std::size_t i = 0; i < in_.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      if (!number_traits<T>::is_finite(in_[i][c])) {
        std::ostringstream s;
        s << "convex_hull: point " << i << " has a non-finite coordinate (NaN or infinity)";
        throw InvalidInput(ErrorCode::NonFinite, s.str());
      }
    }
  }
  if (in_.size() < 3) {
    throw InvalidInput(ErrorCode::TooFewPoints,
                       "convex_hull: needs at least 3 distinct points, got " +
                           std::to_string(in_.size()) + " points");
  }
  Vec3<T> lo = in_[0], hi = in_[0];
  for (const auto& p : in_) {
    for (int c = 0; c < 3; ++c) {
      if (p[c] < lo[c]) lo[c] = p[c];
      if (p[c] > hi[c]) hi[c] = p[c];
    }
  }
  double d2 = 0;
  for (int c = 0; c < 3; ++c) {
    const double w = to_double(T(hi[c] - lo[c]));
    d2 += w * w;
  }
  extent_ = std::sqrt(d2);
  if constexpr (!exact) {
    if (!std::isfinite(extent_) || !std::isfinite(extent_ * extent_ * extent_ * 8.0) ||
        !number_traits<T>::is_finite(static_cast<T>(extent_ * extent_ * 4.0))) {
      throw InvalidInput(ErrorCode::BadScale,
                         "convex_hull: the point set's extent " + format_number(extent_) +
                             " overflows " + std::string(number_traits<T>::name) +
                             " in plane computations");
    }
    // Decisions are made on coordinates relative to the box centre.
    const T two(2);
    centre_ = Vec3<T>((lo[0] + hi[0]) / two, (lo[1] + hi[1]) / two, (lo[2] + hi[2]) / two);
    eps_ = static_cast<T>(Tolerances<T>::coplanar * extent_);
    flat_ = static_cast<T>(Tolerances<T>::flat * extent_);
    weld_ = static_cast<T>(Tolerances<T>::weld * extent_);
  } else {
    centre_ = Vec3<T>(T(0), T(0), T(0));
    eps_ = flat_ = weld_ = T(0);
  }
}

// A point in local coordinates.
template <Number T>
inline Vec3<T> Builder<T>::local(const Vec3<T>& p) const {
  if constexpr (exact) {
    return p;
  } else {
    return Vec3<T>(p - centre_);
  }
}

// Welds the input into the welded points (q_, pts_).
template <Number T>
inline void Builder<T>::weld() {
  std::vector<Vec3<T>> loc;
  loc.reserve(in_.size());
  for (const auto& p : in_) loc.push_back(local(p));
  std::vector<int> order(in_.size());
  std::iota(order.begin(), order.end(), 0);
  auto lex = [&](int i, int j) {
    const auto& a = loc[as_index(i)];
    const auto& b = loc[as_index(j)];
    if (a[0] != b[0]) return a[0] < b[0];
    if (a[1] != b[1]) return a[1] < b[1];
    if (a[2] != b[2]) return a[2] < b[2];
    return i < j;
  };
  std::sort(order.begin(), order.end(), lex);
  if constexpr (exact) {
    for (std::size_t k = 0; k < order.size(); ++k) {
      if (k > 0 && loc[as_index(order[k])] == loc[as_index(order[k - 1])]) continue;
      add_point(order[k], loc[as_index(order[k])]);
    }
  } else {
    // Sweep in x: a point is welded to an earlier representative within weld.
    const T w2 = weld_ * weld_;
    std::size_t window = 0;  // first representative with x >= current x - weld
    for (int i : order) {
      const Vec3<T>& p = loc[as_index(i)];
      while (window < q_.size() && q_[window][0] < p[0] - weld_) ++window;
      bool dup = false;
      for (std::size_t r = window; r < q_.size() && !dup; ++r) {
        const Vec3<T> d(q_[r] - p);
        dup = squared_norm(d) <= w2;
      }
      if (!dup) add_point(i, p);
    }
  }
  if constexpr (exact) make_shadow();
  if (pts_.size() < 3) {
    throw InvalidInput(ErrorCode::TooFewPoints,
                       "convex_hull: needs at least 3 distinct points, got " +
                           std::to_string(pts_.size()) + " after merging duplicates" +
                           (exact ? "" : " (points closer than the weld tolerance)"));
  }
  removed_.assign(pts_.size(), 0);
  pinned_.assign(pts_.size(), 0);
}

// Exact T: the welded points as doubles, used when every coordinate is
// exactly a double (checked exactly): the quickhull predicates are then
// decided by orientation_filter, and in T only when it cannot decide.
template <Number T>
inline void Builder<T>::make_shadow() {
  shadow_ = true;
  qd_.resize(q_.size());
  for (std::size_t i = 0; i < q_.size() && shadow_; ++i)
    for (int c = 0; c < 3 && shadow_; ++c) {
      qd_[i][c] = to_double(q_[i][c]);
      shadow_ = std::isfinite(qd_[i][c]) && from_double<T>(qd_[i][c]) == q_[i][c];
    }
  if (!shadow_) qd_.clear();
}

template <Number T>
inline void Builder<T>::add_point(int input_index, const Vec3<T>& loc) {
  pts_.push_back(input_index);
  q_.push_back(loc);
}

}  // namespace sepax::hull::detail
