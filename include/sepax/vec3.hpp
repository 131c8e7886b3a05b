// sepax/vec3.hpp
//
// Vectors are Eigen::Matrix<T,3,1>.  Eigen is used for storage and for the
// element-wise + and -; the products that decide signs (dot, cross, triple) are
// written out here with a fixed evaluation order, so that
//   * the forward error bounds in robust/ can be derived for exactly these
//     operation sequences, and
//   * exact number types never meet an Eigen reduction they were not written for.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>
#include <type_traits>

#include <Eigen/Core>

#include "number_traits.hpp"

namespace sepax {

template <class T>
using Vec3 = Eigen::Matrix<T, 3, 1>;

template <class T>
using Vec2 = Eigen::Matrix<T, 2, 1>;

/// An exact number type may supply number_traits<T>::exact_dot(out, a, b): out = a . b, the value T's
/// operations give, by a faster route where the route applies (returning true), and false with out
/// untouched where it does not.  The GMP rationals do, for dyadic rationals (robust/number_types.hpp).
/// (number_traits<T> must be complete wherever dot<T> is first used: the concept is decided there.)
template <class T>
concept HasExactDot = number_traits<T>::is_exact && requires(T& out, const Vec3<T>& a) {
  { number_traits<T>::exact_dot(out, a, a) } -> std::same_as<bool>;
};

/// a.x*b.x + a.y*b.y + a.z*b.z, evaluated left to right (or T's exact_dot: the same value).
template <class T>
inline T dot(const Vec3<T>& a, const Vec3<T>& b) {
  if constexpr (HasExactDot<T>) {
    T out;
    if (number_traits<T>::exact_dot(out, a, b)) return out;
  }
  T s = a[0] * b[0];
  s = s + a[1] * b[1];
  s = s + a[2] * b[2];
  return s;
}

// Always inlined: in the fuzzer's large translation units GCC left it out
// of line in the brute force's edge-pair loop (1 % of a campaign's instructions).
template <class T>
[[gnu::always_inline]] inline Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  T x = a[1] * b[2] - a[2] * b[1];
  T y = a[2] * b[0] - a[0] * b[2];
  T z = a[0] * b[1] - a[1] * b[0];
  return Vec3<T>(x, y, z);
}

/// a . (b x c) = det[a, b, c].
template <class T>
inline T triple(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  return dot(a, cross(b, c));
}

/// An exact number type may supply number_traits<T>::dot_sign(a, b): the sign of a . b (-1, 0 or +1), the
/// sign of dot(a, b), by a cheaper route (a filter, or integer arithmetic without T's normalisation).
/// The GMP rationals and CGAL's Lazy_exact_nt do (robust/number_types.hpp).
template <class T>
concept HasDotSign = number_traits<T>::is_exact && requires(const Vec3<T>& a) {
  { number_traits<T>::dot_sign(a, a) } -> std::same_as<int>;
};

/// sign_of(dot(a, b)): through T's dot_sign where T has one (the same sign).
template <class T>
inline int sign_of_dot(const Vec3<T>& a, const Vec3<T>& b) {
  if constexpr (HasDotSign<T>) {
    return number_traits<T>::dot_sign(a, b);
  } else {
    return sign_of(dot(a, b));
  }
}

/// An exact number type may supply number_traits<T>::difference_dot_sign(a, p, q): the sign of a.(p - q),
/// the side of p against q along a (-1, 0 or +1), the sign of dot(a, p - q), by a cheaper route (without
/// building p - q).  CGAL's Lazy_exact_nt does (robust/number_types.hpp).
template <class T>
concept HasDifferenceDotSign = number_traits<T>::is_exact && requires(const Vec3<T>& a) {
  { number_traits<T>::difference_dot_sign(a, a, a) } -> std::same_as<int>;
};

/// sign_of(dot(a, p - q)): through T's difference_dot_sign where T has one (the same sign).
template <class T>
inline int sign_of_difference_dot(const Vec3<T>& a, const Vec3<T>& p, const Vec3<T>& q) {
  if constexpr (HasDifferenceDotSign<T>) {
    return number_traits<T>::difference_dot_sign(a, p, q);
  } else {
    return sign_of_dot(a, Vec3<T>(T(p[0] - q[0]), T(p[1] - q[1]), T(p[2] - q[2])));
  }
}

/// An exact number type may supply number_traits<T>::height_sign(a, b, p, q): the sign of (a x b).(p - q),
/// the side of p against q along a x b (-1, 0 or +1), the sign of dot(cross(a, b), p - q), by a cheaper
/// route.  The GMP rationals and CGAL's Lazy_exact_nt do (robust/number_types.hpp).
template <class T>
concept HasHeightSign = number_traits<T>::is_exact && requires(const Vec3<T>& a) {
  { number_traits<T>::height_sign(a, a, a, a) } -> std::same_as<int>;
};

/// sign_of(dot(cross(a, b), p - q)): through T's height_sign where T has one (the same sign).
template <class T>
inline int sign_of_height(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& p, const Vec3<T>& q) {
  if constexpr (HasHeightSign<T>) {
    return number_traits<T>::height_sign(a, b, p, q);
  } else {
    const Vec3<T> d(T(p[0] - q[0]), T(p[1] - q[1]), T(p[2] - q[2]));
    return sign_of(dot(cross(a, b), d));
  }
}

/// An exact number type may supply number_traits<T>::exact_difference(out, a, b): out = a - b, the value
/// T's subtraction gives, by a faster route where the route applies (returning true), and false with out
/// untouched where it does not.  mpq_class does, for dyadic rationals (robust/number_types.hpp).
template <class T>
concept HasExactDifference = number_traits<T>::is_exact && requires(T& out, const T& x) {
  { number_traits<T>::exact_difference(out, x, x) } -> std::same_as<bool>;
};

/// out = a - b, coordinate by coordinate: T's subtraction, or its exact_difference (the same values).
template <class T>
inline void assign_difference(Vec3<T>& out, const Vec3<T>& a, const Vec3<T>& b) {
  for (int c = 0; c < 3; ++c) {
    if constexpr (HasExactDifference<T>) {
      if (number_traits<T>::exact_difference(out[c], a[c], b[c])) continue;
    }
    out[c] = a[c] - b[c];
  }
}

template <class T>
inline T squared_norm(const Vec3<T>& a) {
  return dot(a, a);
}

template <class T>
inline bool is_zero(const Vec3<T>& a) {
  const T z(0);
  return a[0] == z && a[1] == z && a[2] == z;
}

// ---- scale-safe products for float and double --------------------------------
// |u x w|^2 is of the order of |u|^2 |w|^2: for double it overflows or
// underflows once coordinates pass about 1e+-77 (float: 1e+-9), long before
// the coordinates themselves do.  The helpers below rescale by a power of two
// when (and only when) that happens.  Multiplying by a power of two is exact
// and commutes with rounding (outside the subnormal range), so wherever the
// unscaled formula stays in range their results are bit for bit its results.
namespace detail {

/// max |component| over two vectors.
template <class T>
inline T max_abs2(const Vec3<T>& u, const Vec3<T>& w) {
  using std::fabs;
  return std::max({fabs(u[0]), fabs(u[1]), fabs(u[2]), fabs(w[0]), fabs(w[1]), fabs(w[2])});
}

/// The bits of float or double as an unsigned integer of the same width, and the layout of its exponent.
template <class T>
struct FloatBits {
  static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>);
  using Uint = std::conditional_t<std::is_same_v<T, float>, std::uint32_t, std::uint64_t>;
  static constexpr int kMantissaBits = std::numeric_limits<T>::digits - 1;  ///< stored fraction bits
  static constexpr int kBias = std::numeric_limits<T>::max_exponent - 1;    ///< exponent field of 2^0
};

/// 2^e for e in T's normal range (min_exponent - 1 <= e <= max_exponent - 1), built from its bits: the
/// value of std::ldexp(T(1), e), without a library call.  (Outside that range 2^e is subnormal or
/// overflows; callers take std::ldexp there.)
template <class T>
inline T normal_pow2(int e) {
  using B = FloatBits<T>;
  return std::bit_cast<T>(
      static_cast<typename B::Uint>(static_cast<typename B::Uint>(e + B::kBias) << B::kMantissaBits));
}

/// Binary exponent e of m (finite, > 0): m * 2^-e is in [1, 2).  std::ilogb(m); for a normal m read from
/// its exponent field.
template <class T>
inline int pow2_exponent(T m) {
  using B = FloatBits<T>;
  if (m >= std::numeric_limits<T>::min() && m <= std::numeric_limits<T>::max())
    return static_cast<int>(std::bit_cast<typename B::Uint>(m) >> B::kMantissaBits) - B::kBias;
  return std::ilogb(m);
}

/// x * 2^-e (std::ldexp(x, -e): exact unless the result is subnormal or overflows; e may exceed the
/// exponent range of a T factor).  When 2^-e is a normal T, a product by normal_pow2(-e): one rounding of
/// the same exact value, so bit for bit std::ldexp's result (subnormal results and overflow to infinity
/// included).
template <class T>
inline T scale_value_pow2(T x, int e) {
  if (e > -std::numeric_limits<T>::max_exponent && e < std::numeric_limits<T>::max_exponent - 1)
    return x * normal_pow2<T>(-e);
  return std::ldexp(x, -e);
}

/// v * 2^-e, component by component: scale_value_pow2 of each component (bit for bit std::ldexp's).
template <class T>
inline Vec3<T> scale_pow2(const Vec3<T>& v, int e) {
  if (e > -std::numeric_limits<T>::max_exponent && e < std::numeric_limits<T>::max_exponent - 1) {
    const T s = normal_pow2<T>(-e);
    return Vec3<T>(v[0] * s, v[1] * s, v[2] * s);
  }
  return Vec3<T>(std::ldexp(v[0], -e), std::ldexp(v[1], -e), std::ldexp(v[2], -e));
}

/// A squared norm (or product of squared norms) that is finite and far enough
/// above the subnormal range that squaring lost no relevant bits.
template <class T>
inline bool safe_squared_norm(T n2) {
  return n2 <= std::numeric_limits<T>::max() && n2 > std::numeric_limits<T>::min() * T(0x1p40);
}

}  // namespace detail

/// A positive multiple of u x w: u x w itself for exact T, and for float and
/// double whenever |u x w|^2 is in range; otherwise (u 2^-eu) x (w 2^-ew) for
/// the eu that puts the largest |component| of u in [1, 2) and the ew that
/// does so for w (each vector scaled by its own power of two, so that a long
/// vector against a short one still gives a cross product in range).  Its
/// direction is that of u x w at any scale; normalise it, never use its length.
template <class T>
inline Vec3<T> scaled_cross(const Vec3<T>& u, const Vec3<T>& w, Vec3<T> n);
template <class T>
inline Vec3<T> scaled_cross(const Vec3<T>& u, const Vec3<T>& w) {
  return scaled_cross(u, w, Vec3<T>(cross(u, w)));
}
/// scaled_cross(u, w) given n = cross(u, w), computed by the caller.
template <class T>
inline Vec3<T> scaled_cross(const Vec3<T>& u, const Vec3<T>& w, Vec3<T> n) {
  if constexpr (std::is_floating_point_v<T>) {
    if (!detail::safe_squared_norm(squared_norm(n))) {
      const T mu = detail::max_abs2(u, u), mw = detail::max_abs2(w, w);
      if (mu > T(0) && mu <= std::numeric_limits<T>::max() && mw > T(0) &&
          mw <= std::numeric_limits<T>::max()) {
        n = cross(detail::scale_pow2(u, detail::pow2_exponent(mu)),
                  detail::scale_pow2(w, detail::pow2_exponent(mw)));
      }
    }
  }
  return n;
}

/// Float and double: |u x w| <= tol |u| |w| (the sine of their angle is at
/// most tol), as !(|u x w|^2 > tol^2 |u|^2 |w|^2); when the right-hand side
/// leaves the range, u and w are first scaled by powers of two of their own.
template <class T>
inline bool nearly_parallel(const Vec3<T>& u, const Vec3<T>& w, T tol) {
  static_assert(std::is_floating_point_v<T>);
  const T rhs = tol * tol * squared_norm(u) * squared_norm(w);
  if (detail::safe_squared_norm(rhs)) return !(squared_norm(cross(u, w)) > rhs);
  const T mu = detail::max_abs2(u, u), mw = detail::max_abs2(w, w);
  if (!(mu > T(0) && mu <= std::numeric_limits<T>::max() && mw > T(0) &&
        mw <= std::numeric_limits<T>::max())) {
    return true;  // a zero or non-finite edge: no usable axis
  }
  const Vec3<T> us = detail::scale_pow2(u, detail::pow2_exponent(mu));
  const Vec3<T> ws = detail::scale_pow2(w, detail::pow2_exponent(mw));
  return !(squared_norm(cross(us, ws)) > tol * tol * squared_norm(us) * squared_norm(ws));
}

/// Convert a vector of doubles to T element by element (exact for exact T).
template <Number T>
inline Vec3<T> vec_from_double(const Vec3<double>& v) {
  return Vec3<T>(from_double<T>(v[0]), from_double<T>(v[1]), from_double<T>(v[2]));
}

/// For reporting only: the nearest doubles.
template <Number T>
inline Vec3<double> vec_to_double(const Vec3<T>& v) {
  return Vec3<double>(to_double(v[0]), to_double(v[1]), to_double(v[2]));
}

/// For reporting only: the direction of v as a unit vector of doubles, the zero vector for v = 0.  Types
/// that do not normalise (exact rationals) are first scaled by powers of two, exactly, until their nearest
/// doubles are in range, so that axes of very large or very small shapes (an edge pair's cross product
/// beyond about 1e154) come out unit too.  Float and double axes are unit already: returned as computed.
template <Number T>
inline Vec3<double> unit_as_double(Vec3<T> v) {
  Vec3<double> d = vec_to_double(v);
  if constexpr (!number_traits<T>::normalizes) {
    const bool nonzero = !(v[0] == T(0) && v[1] == T(0) && v[2] == T(0));
    for (int step = 0; step < 8 && nonzero; ++step) {  // (exact products of doubles: at most 8 steps)
      const double m = std::max({std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])});
      int dir = 0;
      if (!(m <= 0x1p960)) dir = 1;  // (infinity included)
      if (m < 0x1p-960) dir = -1;
      if (dir == 0) break;
      const T f = from_double<T>(dir > 0 ? 0x1p-960 : 0x1p960);
      v = Vec3<T>(T(v[0] * f), T(v[1] * f), T(v[2] * f));
      d = vec_to_double(v);
    }
    const double m = std::max({std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])});
    if (m > 0 && std::isfinite(m)) d /= m;
    const double len = d.norm();
    if (len > 0 && std::isfinite(len)) d /= len;
  }
  return d;
}

/// Convert from a floating type U (float or double) to any T.  float -> double
/// and double -> rational are exact; double -> float rounds to nearest.
/// Conversions out of an exact type are not offered: they would round.
template <Number T, Number U>
inline Vec3<T> vec_cast(const Vec3<U>& v) {
  if constexpr (std::is_same_v<T, U>) {
    return v;
  } else {
    static_assert(!number_traits<U>::is_exact,
                  "vec_cast from an exact type would go through double: use vec_to_double "
                  "for reporting");
    return Vec3<T>(from_double<T>(to_double(v[0])), from_double<T>(to_double(v[1])),
                   from_double<T>(to_double(v[2])));
  }
}

}  // namespace sepax
