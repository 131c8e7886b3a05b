// sepax/separation.hpp
//
// Separation<T>: a signed separation along a candidate axis, kept in a form
// that can be compared exactly without sqrt.
//
//   value = num / sqrt(norm2)
//
// For number types that normalise axes (float, double, CORE::Expr) the axis is
// unit, norm2 == 1 and num is the separation itself.  For rationals the axis is
// left unnormalised (a face's cross-product normal, or eA x eB), num is the
// projection on it and norm2 its squared length.  Comparison then uses
//   num1 / sqrt(n1)  vs  num2 / sqrt(n2)
//   <=>  (signs first) then  num1^2 * n2  vs  num2^2 * n1   (reversed when both < 0)
// which is exact for exact T.  Positive separation: the shapes are separated
// along that axis; zero: touching; negative: overlapping, by -value.
#pragma once

#include <cmath>

#include "number_traits.hpp"

namespace sepax {

template <class T>
struct Separation {
  T num = T(0);
  T norm2 = T(1);
};

template <Number T>
inline int sign(const Separation<T>& s) {
  return sign_of(s.num);
}

/// -1, 0, +1 as a < b, a == b, a > b, exactly for exact T.
template <Number T>
inline int compare(const Separation<T>& a, const Separation<T>& b) {
  if constexpr (number_traits<T>::normalizes) {
    return (a.num > b.num) - (a.num < b.num);
  } else {
    const int sa = sign_of(a.num), sb = sign_of(b.num);
    if (sa != sb) return sa < sb ? -1 : 1;
    if (sa == 0) return 0;
    const T lhs = a.num * a.num * b.norm2;  // |a|^2 scaled
    const T rhs = b.num * b.num * a.norm2;
    const int mag = (lhs > rhs) - (lhs < rhs);
    return sa > 0 ? mag : -mag;
  }
}

/// The separation as a double, for reporting (never fed back into a decision).
template <Number T>
inline double to_double(const Separation<T>& s) {
  const double n2 = to_double(s.norm2);
  return n2 == 1.0 ? to_double(s.num) : to_double(s.num) / std::sqrt(n2);
}

}  // namespace sepax
