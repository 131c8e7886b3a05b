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
#include <limits>

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

namespace detail {

/// The nearest double to sqrt(sq) for an exact sq > 0 whose double rounding
/// is a normal double: sqrt of that rounding is within about one ulp, and
/// the nearest double is the v whose two rounding midpoints m- < m+ (exact
/// in T) have m-^2 <= sq <= m+^2, so step to a neighbour while sq lies
/// beyond one of them (exact comparisons; a tie keeps v).
template <Number T>
double nearest_sqrt(const T& sq) {
  double v = std::sqrt(number_traits<T>::to_double(sq));
  for (int i = 0; i < 8; ++i) {
    const T tv = number_traits<T>::from_double(v);
    const double up = std::nextafter(v, std::numeric_limits<double>::infinity());
    const T m_up = T((tv + number_traits<T>::from_double(up)) / 2);
    if (sq > T(m_up * m_up)) {
      v = up;
      continue;
    }
    const double down = std::nextafter(v, 0.0);
    const T m_down = T((tv + number_traits<T>::from_double(down)) / 2);
    if (sq < T(m_down * m_down)) {
      v = down;
      continue;
    }
    break;
  }
  return v;
}

}  // namespace detail

/// The separation as a double, for reporting (never fed back into a decision).
///
/// Normalising T: num itself.  Otherwise value = num / sqrt(norm2) with
/// norm2 > 0, and num and norm2 can be far beyond double's range when the
/// value is not (an edge axis of coordinates 1e200 has norm2 ~ 1e800), so
/// the square value^2 = num^2 / norm2, exact in T, is rounded to the nearest
/// double's square root by exact comparisons (detail::nearest_sqrt).  When
/// value^2 is outside double's normal range (|value| above ~1e154 or below
/// ~1e-154) it is first scaled by 4^-k, exactly, into [1, 4): the nearest
/// double to value 2^-k times 2^k is the nearest double to value while that
/// is a normal double (a subnormal result, below ~2.2e-308, is rounded
/// twice; beyond ~1.8e308 it is infinity).
template <Number T>
inline double to_double(const Separation<T>& s) {
  if constexpr (number_traits<T>::normalizes) {
    return to_double(s.num);
  } else {
    if (!(sign_of(s.norm2) > 0)) return std::numeric_limits<double>::quiet_NaN();
    const int sg = sign_of(s.num);
    if (sg == 0) return 0.0;
    T sq = T(s.num * s.num / s.norm2);
    auto normal = [](double x) {
      return x >= std::numeric_limits<double>::min() && x <= std::numeric_limits<double>::max();
    };
    if (normal(to_double(sq))) return sg * detail::nearest_sqrt(sq);
    // steps of 4^256, 4^32 and 4 (at most 80 of each: value^2 within
    // 2^(+-40000), far beyond any separation of shapes sepax accepts)
    int k = 0;
    for (const int step : {256, 32, 1}) {
      const T down = number_traits<T>::from_double(std::ldexp(1.0, -2 * step));
      const T up = number_traits<T>::from_double(std::ldexp(1.0, 2 * step));
      const double hi = step == 1 ? 4.0 : std::ldexp(1.0, 2 * step + 2);
      const double lo = step == 1 ? 1.0 : std::ldexp(1.0, -2 * step - 2);
      for (int i = 0; i < 80 && !(to_double(sq) < hi); ++i) {
        sq = T(sq * down);
        k += step;
      }
      for (int i = 0; i < 80 && !(to_double(sq) >= lo); ++i) {
        sq = T(sq * up);
        k -= step;
      }
    }
    const double r = normal(to_double(sq)) ? detail::nearest_sqrt(sq) : std::sqrt(to_double(sq));
    return sg * std::ldexp(r, k);
  }
}

}  // namespace sepax
