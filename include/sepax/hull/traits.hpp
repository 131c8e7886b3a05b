// sepax/hull/traits.hpp
//
// The number-type-dependent decisions of the hull builder, one traits type per kind of number type
// (the model: CGAL's Convex_hull_traits_3), selected through number_traits<T>::is_exact:
//   ExactHullTraits<T>  every decision exact; tolerances zero; no repair passes.
//   FloatHullTraits<T>  decisions within eps = Tolerances<T>::coplanar x extent; repair passes.
#pragma once

#include <type_traits>

#include "../number_traits.hpp"

namespace sepax::hull::detail {

/// Exact T: every decision exact.
template <Number T>
struct ExactHullTraits {
  /// The exact hull holds every point: no repair passes, no fallbacks.
  static constexpr bool kRepairs = false;
};

/// float / double: decisions within eps.
template <Number T>
struct FloatHullTraits {
  /// Points left outside by rounding are measured, pinned and the hull rebuilt (repair.hpp).
  static constexpr bool kRepairs = true;
};

/// The hull traits of T.
template <Number T>
using HullTraits = std::conditional_t<number_traits<T>::is_exact, ExactHullTraits<T>, FloatHullTraits<T>>;

}  // namespace sepax::hull::detail
