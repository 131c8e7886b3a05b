// sepax/hull/welded_points.hpp
//
// The builder's first steps, before any hull:
//   1. check_input: NaN/Inf (NonFinite, naming the point), fewer than 3 points (TooFewPoints), an extent
//      that overflows plane computations (BadScale); the tolerances eps, flat and weld of the extent.
//   2. local_points: float T decides on coordinates relative to the bounding-box centre (exact T: on the
//      input as given, never copied: Traits::kLocalIsInput).
//   3. shadow: exact T whose coordinates are all exactly doubles gets a double copy, so that welding sorts
//      on doubles and the quickhull predicates are filtered (orientation_filter.hpp) before they are
//      decided in T.
//   4. weld: one representative of the points closer than weld * extent (exact T: of exact duplicates),
//      walking the points in lexicographic order (radix_sort.hpp); fewer than 3 left is TooFewPoints.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <span>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "../error.hpp"
#include "../number_traits.hpp"
#include "../tolerances.hpp"
#include "builder.hpp"
#include "radix_sort.hpp"

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
    throw InvalidInput(ErrorCode::TooFewPoints, "convex_hull: needs at least 3 distinct points, got " +
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
  Traits::scale(*this, lo, hi);
}

// Welds the input into the welded points (pts_, and their local coordinates q_ unless Traits::kLocalIsInput).
template <Number T>
inline void Builder<T>::weld() {
  const auto loc = Traits::local_points(*this);  // float: a vector of differences; exact T: in_ itself
  Traits::shadow(*this, loc);
  // lexicographic order, ties by index (float and double coordinates by lex_order, a radix sort; exact
  // T's doubles give its order: they are its values)
  std::vector<int> order;
  if (shadow_) {
    order = lex_order(std::span<const Vec3<double>>(qd_));
  } else if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
    order = lex_order(std::span<const Vec3<T>>(loc));
  } else {
    order.resize(in_.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int i, int j) {
      const auto& a = loc[as_index(i)];
      const auto& b = loc[as_index(j)];
      if (a[0] != b[0]) return a[0] < b[0];
      if (a[1] != b[1]) return a[1] < b[1];
      if (a[2] != b[2]) return a[2] < b[2];
      return i < j;
    });
  }
  pts_.reserve(in_.size());
  if constexpr (!Traits::kLocalIsInput) q_.reserve(in_.size());
  Traits::weld(*this, loc, order);
  if (shadow_) {  // keep the welded points' doubles, in welded order
    std::vector<Vec3<double>> welded(pts_.size());
    for (std::size_t k = 0; k < pts_.size(); ++k) welded[k] = qd_[as_index(pts_[k])];
    qd_ = std::move(welded);
  }
  if (pts_.size() < 3) {
    throw InvalidInput(ErrorCode::TooFewPoints, "convex_hull: needs at least 3 distinct points, got " +
                                                    std::to_string(pts_.size()) +
                                                    " after merging duplicates" + Traits::kWeldNote);
  }
  removed_.assign(pts_.size(), 0);
  pinned_.assign(pts_.size(), 0);
}

// Adds a welded point: its input index and its local coordinates.
template <Number T>
inline void Builder<T>::add_point(int input_index, const Vec3<T>& loc) {
  pts_.push_back(input_index);
  if constexpr (!Traits::kLocalIsInput) q_.push_back(loc);
}

}  // namespace sepax::hull::detail
