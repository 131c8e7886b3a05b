// sepax/robust/exact_float.hpp
//
// ExactFloat: the exact number type the robust predicates fall back to.
//
// Every exact fallback in sepax/robust evaluates a *polynomial* (sums,
// differences and products, never a quotient) of input coordinates, which are
// floats or doubles.  The sign of such a polynomial only needs exact
// multi-precision binary floating point, not rationals: CGAL::Mpzf (a GMP
// mantissa with a binary exponent, stack storage for small values, no gcd
// normalisation) is several times faster than mpq_class for this and is what
// CGAL's own Epick predicates use.  When CGAL was built without Mpzf support
// (CGAL_HAS_MPZF undefined) ExactFloat is mpq_class, which is exact too.
//
// Both conversions from float and double are exact (a float is a double, a
// double is a dyadic rational).  Nothing here converts back to double except
// approx_double and approx_scaled, for reporting values, never for a decision.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include <gmpxx.h>

#include <CGAL/Mpzf.h>

#include <sepax/vec3.hpp>

/// Marks the exact (rare) paths so that they stay out of the inlined fast paths.
#if defined(__GNUC__) || defined(__clang__)
#define SEPAX_ROBUST_COLD [[gnu::noinline, gnu::cold]]
#else
#define SEPAX_ROBUST_COLD
#endif

namespace sepax::robust {

#if defined(CGAL_HAS_MPZF)
using ExactFloat = CGAL::Mpzf;
inline int exact_sign(const ExactFloat& x) { return x.sign(); }
/// A double near x, for reporting only (never fed back into a decision).
inline double approx_double(const ExactFloat& x) { return CGAL::to_double(x); }
#else
using ExactFloat = mpq_class;
inline int exact_sign(const ExactFloat& x) { return sgn(x); }
inline double approx_double(const ExactFloat& x) { return x.get_d(); }
#endif

/// The exact value of a float or double.
inline ExactFloat exact(double d) { return ExactFloat(d); }

/// For reporting only: doubles proportional to the exact values xs, xs 2^-scale for one power of two, the
/// largest magnitude in [2^-960, 2^960] unless every value is exactly 0.  approx_double alone overflows to
/// infinity or underflows to 0 where the exact value leaves double's range (an edge pair's cross product of
/// double edges beyond about 1e154, its squared norm beyond about 1e77); the scaling is exact.
template <std::size_t N>
inline std::array<double, N> approx_scaled(std::array<ExactFloat, N> xs, int& scale) {
  constexpr int kStep = 960;  // a power of two that keeps every double in range once applied
  std::array<double, N> d{};
  scale = 0;
  for (int step = 0; step < 8; ++step) {  // (double inputs: products of at most 2^2100 or 2^-2200)
    double m = 0;
    bool nonzero = false;
    for (std::size_t i = 0; i < N; ++i) {
      d[i] = approx_double(xs[i]);
      m = std::max(m, std::fabs(d[i]));
      nonzero = nonzero || exact_sign(xs[i]) != 0;
    }
    int dir = 0;
    if (!(m <= 0x1p960)) dir = 1;  // (infinity included)
    if (m < 0x1p-960 && nonzero) dir = -1;
    if (dir == 0) break;
    const ExactFloat f = exact(dir > 0 ? 0x1p-960 : 0x1p960);
    for (auto& x : xs) x = x * f;
    scale += dir * kStep;
  }
  return d;
}

/// Exact b - a for float/double points.
/// b - a with coordinates converted to N (exactly: float and double values are
/// ExactFloat and CGAL::Interval_nt values) before the subtraction.
template <class N, class F>
inline std::array<N, 3> diff_as(const Vec3<F>& b, const Vec3<F>& a) {
  return {N(static_cast<double>(b[0])) - N(static_cast<double>(a[0])),
          N(static_cast<double>(b[1])) - N(static_cast<double>(a[1])),
          N(static_cast<double>(b[2])) - N(static_cast<double>(a[2]))};
}

template <class F>
inline std::array<ExactFloat, 3> exact_diff(const Vec3<F>& b, const Vec3<F>& a) {
  return diff_as<ExactFloat>(b, a);
}

// Cross and dot products of coordinate arrays: exact for ExactFloat, outward
// enclosures for intervals (separation_compare.hpp's stage 2).
template <class N>
inline std::array<N, 3> exact_cross(const std::array<N, 3>& a, const std::array<N, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <class N>
inline N exact_dot(const std::array<N, 3>& a, const std::array<N, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

}  // namespace sepax::robust
