// sepax/robust/orientation.hpp
//
// (P1) The exact sign of a 3x3 determinant of difference vectors
//
//     orient_sign(a0, a1, b0, b1, c0, c1) = sign det[a1 - a0, b1 - b0, c1 - c0]
//
// for float or double points (orient3d(p, q, r, s) is the case a0 = b0 = c0).
// Every sign the SATs decide reduces to this (face heights, arc signs, edge
// separation signs, projection comparisons).  Two stages:
//   1. a semi-static filter in double that decides almost every call with ~30
//      flops (its derivation: sepax/orientation_filter.hpp, core, double only,
//      shared with the hull's exact-type predicates);
//   2. when the filter cannot decide, an exact evaluation: for float
//      coordinates whose exponents lie within kIntegerExponentSpread of each
//      other, in 64- and 128-bit integers (orient_sign_integer: the aligned
//      and touching shapes whose exact ties reach this stage); otherwise with
//      ExactFloat (exact_float.hpp) from the coordinates.
// The result is exact for all finite inputs, with or without FMA contraction.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include <sepax/orientation_filter.hpp>
#include <sepax/robust/exact_float.hpp>
#include <sepax/vec3.hpp>

namespace sepax::robust {

/// Filter outcome: a sign (-1, 0, +1) or "cannot decide".
inline constexpr int kUncertain = 2;

/// Stage 1 only: sign of det[A, B, C] for the difference vectors given as
/// endpoints, or kUncertain.  Never wrong when it returns a sign.
inline int orient_filter(double a0x, double a0y, double a0z, double a1x, double a1y, double a1z, double b0x,
                         double b0y, double b0z, double b1x, double b1y, double b1z, double c0x, double c0y,
                         double c0z, double c1x, double c1y, double c1z) {
  const FilteredSign s = orientation_filter(a0x, a0y, a0z, a1x, a1y, a1z, b0x, b0y, b0z, b1x, b1y, b1z, c0x,
                                            c0y, c0z, c1x, c1y, c1z);
  if (!s.certain) return kUncertain;
  return s.det > 0 ? 1 : -1;
}

/// The largest difference between the exponent fields of the nonzero
/// coordinates that orient_sign_integer evaluates (its bound below).
inline constexpr int kIntegerExponentSpread = 16;

/// Stage 2a: the exact sign in integers for float coordinates, or kUncertain
/// when the coordinates are outside its range (a subnormal, an infinity or
/// NaN, exponents more than kIntegerExponentSpread apart, or no 128-bit
/// integer type).
///
/// A normal float x with exponent field e (1..254) and stored mantissa bits m
/// is +-(2^23 + m) 2^(e - 150).  With e0 the least exponent field among the
/// nonzero coordinates, every coordinate is the integer
/// X = +-(2^23 + m) 2^(e - e0) (0 for a zero) times the common factor
/// 2^(e0 - 150) > 0, and the determinant, a cubic form in the coordinates,
/// is the integer determinant of the X times 2^(3 (e0 - 150)): the same sign.
/// Bounds with e - e0 <= 16: |X| < 2^24 2^16 = 2^40 (int64); a difference
/// |X1 - X0| < 2^41; a cross product component, a difference of two products
/// of such differences, < 2 2^82 = 2^83; the dot product, three products of a
/// difference and a component, < 3 2^41 2^83 < 2^126: every value fits in a
/// signed 128-bit integer and every operation is exact.
inline int orient_sign_integer(const Vec3<float>& a0, const Vec3<float>& a1, const Vec3<float>& b0,
                               const Vec3<float>& b1, const Vec3<float>& c0, const Vec3<float>& c1) {
#if defined(__SIZEOF_INT128__)
  const Vec3<float>* const p[6] = {&a0, &a1, &b0, &b1, &c0, &c1};
  std::uint32_t bits[18];
  int emin = 255, emax = 0;
  for (int k = 0; k < 18; ++k) {
    bits[k] = std::bit_cast<std::uint32_t>((*p[k / 3])[k % 3]);
    if ((bits[k] & 0x7fffffffu) == 0) continue;  // +-0
    const int e = static_cast<int>((bits[k] >> 23) & 0xffu);
    if (e == 0 || e == 255) return kUncertain;  // subnormal, infinity, NaN
    emin = e < emin ? e : emin;
    emax = e > emax ? e : emax;
  }
  if (emax - emin > kIntegerExponentSpread) return kUncertain;
  std::int64_t x[18];
  for (int k = 0; k < 18; ++k) {
    if ((bits[k] & 0x7fffffffu) == 0) {
      x[k] = 0;
      continue;
    }
    const int e = static_cast<int>((bits[k] >> 23) & 0xffu);
    const std::int64_t v = static_cast<std::int64_t>((bits[k] & 0x7fffffu) | 0x800000u) << (e - emin);
    x[k] = (bits[k] >> 31) ? -v : v;
  }
  __extension__ typedef __int128 I;  // (__extension__: a GNU type, accepted under -Wpedantic)
  // the difference vectors a1 - a0, b1 - b0, c1 - c0
  const std::int64_t a[3] = {x[3] - x[0], x[4] - x[1], x[5] - x[2]};
  const std::int64_t b[3] = {x[9] - x[6], x[10] - x[7], x[11] - x[8]};
  const std::int64_t c[3] = {x[15] - x[12], x[16] - x[13], x[17] - x[14]};
  const I bc0 = I(b[1]) * c[2] - I(b[2]) * c[1];
  const I bc1 = I(b[2]) * c[0] - I(b[0]) * c[2];
  const I bc2 = I(b[0]) * c[1] - I(b[1]) * c[0];
  const I det = a[0] * bc0 + a[1] * bc1 + a[2] * bc2;
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
#else
  (void)a0, (void)a1, (void)b0, (void)b1, (void)c0, (void)c1;
  return kUncertain;
#endif
}

/// Stage 2 only: the exact sign, from the coordinates (orient_sign_integer
/// where it applies, else ExactFloat).
template <class F>
SEPAX_ROBUST_COLD int orient_sign_exact(const Vec3<F>& a0, const Vec3<F>& a1, const Vec3<F>& b0,
                                        const Vec3<F>& b1, const Vec3<F>& c0, const Vec3<F>& c1) {
  if constexpr (std::is_same_v<F, float>) {
    const int s = orient_sign_integer(a0, a1, b0, b1, c0, c1);
    if (s != kUncertain) return s;
  }
  const auto a = exact_diff(a1, a0);
  const auto b = exact_diff(b1, b0);
  const auto c = exact_diff(c1, c0);
  return exact_sign(exact_dot(a, exact_cross(b, c)));
}

/// sign det[a1 - a0, b1 - b0, c1 - c0], exact, for F = float or double.
/// If `fallbacks` is given it is incremented when the exact stage ran.
template <class F>
inline int orient_sign(const Vec3<F>& a0, const Vec3<F>& a1, const Vec3<F>& b0, const Vec3<F>& b1,
                       const Vec3<F>& c0, const Vec3<F>& c1, std::int64_t* fallbacks = nullptr) {
  static_assert(std::is_same_v<F, float> || std::is_same_v<F, double>,
                "orient_sign is for float and double coordinates");
  const int s = orient_filter(a0[0], a0[1], a0[2], a1[0], a1[1], a1[2], b0[0], b0[1], b0[2], b1[0], b1[1],
                              b1[2], c0[0], c0[1], c0[2], c1[0], c1[1], c1[2]);
  if (s != kUncertain) return s;
  if (fallbacks) ++*fallbacks;
  return orient_sign_exact(a0, a1, b0, b1, c0, c1);
}

/// orient3d: sign det[q - p, r - p, s - p] = sign ((q - p) x (r - p)) . (s - p):
/// positive when s lies on the side of the plane (p, q, r) that (q-p) x (r-p)
/// points to.
template <class F>
inline int orient3d(const Vec3<F>& p, const Vec3<F>& q, const Vec3<F>& r, const Vec3<F>& s,
                    std::int64_t* fallbacks = nullptr) {
  // det[q-p, r-p, s-p] = det[s-p, q-p, r-p] (cyclic permutation).
  return orient_sign(p, s, p, q, p, r, fallbacks);
}

}  // namespace sepax::robust
