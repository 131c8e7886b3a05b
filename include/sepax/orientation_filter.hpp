// sepax/orientation_filter.hpp
//
// The semi-static filter for the sign of a 3x3 determinant of difference
// vectors in double,
//
//     det[a1 - a0, b1 - b0, c1 - c0] = (a1 - a0) . ((b1 - b0) x (c1 - c0)),
//
// which decides almost every call with ~30 flops and otherwise says it cannot
// (the caller then decides exactly in its own arithmetic).  Every sign it
// gives is exact, with or without FMA contraction.  robust/orientation.hpp
// (the robust policy's predicates) and the hull's exact-type predicates on
// double coordinates both decide through it.
//
//   FilteredSign          the computed determinant and whether its sign is certain
//   orientation_filter    the filter (18 coordinates; its error bound is derived on it)
//                         and the point-versus-plane form det[b - a, c - a, p - a]
#pragma once

#include <cmath>

#include "vec3.hpp"

namespace sepax {

/// The filter's computed determinant and whether its sign is certain.
struct FilteredSign {
  double det = 0;        ///< det[A, B, C] rounded (a magnitude estimate, always)
  bool certain = false;  ///< sign(det) is the exact sign (then det != 0)
};

namespace detail {
inline constexpr double kOrientRel = 9.0 * 0x1p-53;  ///< 9u, derived on orientation_filter
inline constexpr double kUnderflowUnit = 0x1p-1068;  ///< 64 eta, eta = 2^-1074
inline constexpr double kOverflowGuard = 0x1p1000;   ///< the permanent above which the filter gives up
}  // namespace detail

/// det[A, B, C], A = a1 - a0, B = b1 - b0, C = c1 - c0, with the certainty of
/// its sign.
///
/// Error bound:
/// Round to nearest, double, u = 2^-53.  Write A = a1 - a0, B = b1 - b0,
/// C = c1 - c0 (exact), and Ã, B̃, C̃ for the computed (rounded) differences.
/// The code evaluates, in this order,
///     Ã_i = fl(a1_i - a0_i)                                      (9 roundings)
///     m_x = fl(fl(B̃_y C̃_z) - fl(B̃_z C̃_y))   (and cyclically m_y, m_z)
///     det = fl(fl(fl(Ã_x m_x) + fl(Ã_y m_y)) + fl(Ã_z m_z))
/// det(A,B,C) is a sum of six terms ±A_i B_j C_k.  Following one term through
/// the evaluation, it meets: 3 roundings of its three differences, 1 of the
/// product B̃_j C̃_k, 1 of the minor's subtraction, 1 of the product Ã_i m_i,
/// and at most 2 of the two additions: at most 8 roundings, each a factor
/// (1 + d) with |d| <= u.  Hence, absent underflow and overflow,
///     |det_computed - det(A,B,C)| <= γ_8 * P,   γ_k = k u / (1 - k u),
///     P = Σ |A_i| (|B_j C_k| + |B_k C_j|)      (the permanent, exact inputs).
/// FMA: if the compiler contracts a product into the following addition
/// (-ffp-contract=fast, -march=native), that product is not rounded on its own:
/// its factor (1 + d) becomes 1.  A per-rounding bound counts an upper bound on
/// the number of roundings, so it holds for every contraction pattern.
/// The computed permanent P̃ uses the rounded differences (|Ã_i| >= (1-u)|A_i|)
/// and 5 roundings per term (2 products, 3 additions; all terms >= 0, so a
/// contracted fma only removes a rounding): P̃ >= (1-u)^8 P.  Therefore
///     error <= γ_8 (1-u)^-8 P̃ <= 8u (1 + 18u) P̃.
/// The bound is computed as fl(9u * P̃ + G) (two roundings down at most, or one
/// with fma): 9u (1-u)^2 >= 8u (1 + 18u), so it is an upper bound on the error
/// term 8u(1+18u)P̃ plus G.
/// Underflow: a product may underflow, with absolute error <= η/2, η = 2^-1074
/// (sums and differences of doubles are exact when the result is subnormal).
/// Per minor that is <= η; multiplied by |Ã_i| and rounded, plus η/2 for the
/// outer product, summed over three terms: <= 3 η M (1+u)^4 + 1.5 η (1+u)^2
/// <= 4 η (M + 1), M = max_i |Ã_i|.  The permanent's own underflow lowers P̃ by
/// at most the same amount, which costs γ_8 * 4η(M+1), negligible.
/// G = (M + 1) * 2^-1068 = 64 η (M + 1) (a product by a power of two, exact or
/// rounded by at most η/2 when subnormal) covers both with a wide margin.
/// Overflow: if P̃ >= 2^1000 the filter gives up (every intermediate of det is
/// bounded in magnitude by the corresponding partial permanent, so below that
/// nothing overflows); NaN/inf make the comparison false and also give up.
/// Decision: if |det_computed| > bound then sign(det_computed) = sign(det).
/// The same constants hold for float inputs, which convert exactly to double.
inline FilteredSign orientation_filter(double a0x, double a0y, double a0z, double a1x, double a1y, double a1z,
                                       double b0x, double b0y, double b0z, double b1x, double b1y, double b1z,
                                       double c0x, double c0y, double c0z, double c1x, double c1y,
                                       double c1z) {
  const double ax = a1x - a0x, ay = a1y - a0y, az = a1z - a0z;
  const double bx = b1x - b0x, by = b1y - b0y, bz = b1z - b0z;
  const double cx = c1x - c0x, cy = c1y - c0y, cz = c1z - c0z;
  const double byz = by * cz, bzy = bz * cy;
  const double bzx = bz * cx, bxz = bx * cz;
  const double bxy = bx * cy, byx = by * cx;
  const double mx = byz - bzy, my = bzx - bxz, mz = bxy - byx;
  FilteredSign r;
  double det = ax * mx;
  det = det + ay * my;
  det = det + az * mz;
  r.det = det;
  const double aax = std::fabs(ax), aay = std::fabs(ay), aaz = std::fabs(az);
  double perm = aax * (std::fabs(byz) + std::fabs(bzy));
  perm = perm + aay * (std::fabs(bzx) + std::fabs(bxz));
  perm = perm + aaz * (std::fabs(bxy) + std::fabs(byx));
  if (!(perm < detail::kOverflowGuard)) return r;  // (also NaN)
  double m = aax > aay ? aax : aay;
  m = m > aaz ? m : aaz;
  const double bound = detail::kOrientRel * perm + (m + 1.0) * detail::kUnderflowUnit;
  r.certain = det > bound || -det > bound;
  return r;
}

/// det[b - a, c - a, p - a]: positive when p lies on the side of the plane
/// (a, b, c) that (b - a) x (c - a) points to.
inline FilteredSign orientation_filter(const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c,
                                       const Vec3<double>& p) {
  return orientation_filter(a[0], a[1], a[2], b[0], b[1], b[2], a[0], a[1], a[2], c[0], c[1], c[2], a[0],
                            a[1], a[2], p[0], p[1], p[2]);
}

}  // namespace sepax
