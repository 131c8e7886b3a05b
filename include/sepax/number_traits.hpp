// sepax/number_traits.hpp
//
// The one place that says what sepax needs of a number type T.  Every
// algorithm in sepax is a template over T; what it may do with a T is exactly
// what this header lists:
//   * field operations  + - * /  and unary minus, on T values;
//   * comparison        <  <=  >  >=  ==  != ;
//   * construction from small integers: T(0), T(1), T(2), ...;
//   * number_traits<T>::from_double(d): the value of the double d as a T.
//     For exact types this conversion is exact (every double is a rational);
//   * number_traits<T>::to_double(x): a double near x, for *reporting only*.
//     No algorithm converts an exact T to double and back on its way to a
//     decision ("exact types never go through double");
//   * optionally number_traits<T>::sqrt(x) when has_sqrt is true.
//
// number_traits<T> (its members are described on floating_traits) is
// specialised here for float and double; GMP and CGAL number types are in
// robust/ (sepax/robust/number_types.hpp), so the float core needs only Eigen.
// The concepts Number, ExactNumber, FloatingNumber and SqrtNumber state it.
#pragma once

#include <cmath>
#include <concepts>
#include <limits>
#include <string_view>

namespace sepax {

/// Primary template: deliberately undefined.  A type is a sepax number type
/// exactly when number_traits<T> is specialised for it.
template <class T>
struct number_traits;

namespace detail {
/// The traits of a rounding floating-point type; every number_traits<T> has
/// these members (and `name`, a short human-readable name: "float", "mpq", ...).
template <class F>
struct floating_traits {
  /// Every field operation is exact (no rounding).
  static constexpr bool is_exact = false;
  /// sqrt(x) is available (and exact when is_exact).
  static constexpr bool has_sqrt = true;
  /// The SATs normalise axes to unit length with sqrt.  True for float/double
  /// and for exact types with an exact sqrt (CORE::Expr); false for rationals,
  /// which keep unnormalised axes and compare separations in squared form.
  static constexpr bool normalizes = true;
  /// u = 2^-p, the bound on the relative error of one correctly rounded
  /// operation; 0 for exact types.
  static constexpr double unit_roundoff = std::numeric_limits<F>::epsilon() / 2;
  /// The value of d as an F (exact for exact types: every double is a rational).
  static F from_double(double d) { return static_cast<F>(d); }
  /// A double near x, for reporting only.
  static double to_double(F x) { return static_cast<double>(x); }
  /// The square root (rounded for float/double).
  static F sqrt(F x) { return std::sqrt(x); }
  /// Neither NaN nor infinite.
  static bool is_finite(F x) { return std::isfinite(x); }
};
}  // namespace detail

template <>
struct number_traits<float> : detail::floating_traits<float> {
  static constexpr std::string_view name = "float";
};

template <>
struct number_traits<double> : detail::floating_traits<double> {
  static constexpr std::string_view name = "double";
};

/// The requirements every algorithm may rely on (see the header comment).
template <class T>
concept Number = std::copyable<T> && requires(const T a, const T b, double d) {
  { number_traits<T>::is_exact } -> std::convertible_to<bool>;
  { number_traits<T>::has_sqrt } -> std::convertible_to<bool>;
  { number_traits<T>::normalizes } -> std::convertible_to<bool>;
  { number_traits<T>::unit_roundoff } -> std::convertible_to<double>;
  { number_traits<T>::name } -> std::convertible_to<std::string_view>;
  { number_traits<T>::from_double(d) } -> std::convertible_to<T>;
  { number_traits<T>::to_double(a) } -> std::convertible_to<double>;
  { number_traits<T>::is_finite(a) } -> std::convertible_to<bool>;
  T(0);
  T(1);
  { a + b } -> std::convertible_to<T>;
  { a - b } -> std::convertible_to<T>;
  { a* b } -> std::convertible_to<T>;
  { a / b } -> std::convertible_to<T>;
  { -a } -> std::convertible_to<T>;
  { a < b } -> std::convertible_to<bool>;
  { a <= b } -> std::convertible_to<bool>;
  { a > b } -> std::convertible_to<bool>;
  { a >= b } -> std::convertible_to<bool>;
  { a == b } -> std::convertible_to<bool>;
  { a != b } -> std::convertible_to<bool>;
};

/// A number type whose field operations are exact (rationals, CGAL's Epeck::FT).
template <class T>
concept ExactNumber = Number<T> && number_traits<T>::is_exact;

/// A rounding floating-point type (float, double).
template <class T>
concept FloatingNumber = Number<T> && !number_traits<T>::is_exact;

/// A number type with sqrt (float, double, CORE::Expr).
template <class T>
concept SqrtNumber = Number<T> && number_traits<T>::has_sqrt && requires(const T a) {
  { number_traits<T>::sqrt(a) } -> std::convertible_to<T>;
};

/// γ_k = k u / (1 - k u), u a unit roundoff (number_traits<F>::unit_roundoff):
/// the relative error bound of k successive roundings (Higham, Lemma 3.1).
/// The one definition the error bounds of the core and of robust/ use.
constexpr double rounding_gamma(int k, double u) { return k * u / (1.0 - k * u); }

/// Sign of x as -1, 0 or +1, computed by comparison only (exact for exact T).
template <Number T>
inline int sign_of(const T& x) {
  const T zero(0);
  return (x > zero) - (x < zero);
}

template <Number T>
inline T abs_of(const T& x) {
  return x < T(0) ? T(-x) : x;
}

template <Number T>
inline double to_double(const T& x) {
  return number_traits<T>::to_double(x);
}

template <Number T>
inline T from_double(double d) {
  return number_traits<T>::from_double(d);
}

}  // namespace sepax
