// sepax/robust/parallel.hpp
//
// (P2) Exact parallelism of two segments' directions:
//
//     parallel(a0, a1, b0, b1)  <=>  (a1 - a0) x (b1 - b0) == 0   exactly
//
// for float or double points (a zero-length direction is parallel to
// everything, as the exact cross product says).  Three stages:
//   1. a filter in double that proves the cross product NON-zero (the common
//      answer) with ~25 flops;
//   2. an exact test without multi-precision when every difference and every
//      product is exact in double (error-free transformations: TwoSum for the
//      differences, fma residuals for the products).  This decides the usual
//      exactly-parallel inputs (boxes, prisms, axis-aligned edges) cheaply;
//   3. otherwise the exact cross product in ExactFloat.
//
// The filter's bound is derived on parallel_filter_maybe.
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>

#include <sepax/robust/exact_float.hpp>
#include <sepax/vec3.hpp>

namespace sepax::robust {

namespace detail {
inline constexpr double kParallelRel = 5.0 * 0x1p-53;
inline constexpr double kParallelUnderflow = 0x1p-1070;

// Knuth's TwoSum for a - b: true iff fl(a - b) is exact.  Additions only, so
// FMA contraction cannot change it.
inline bool difference_is_exact(double a, double b, double& d) {
  d = a - b;
  const double bv = a - d;   // the part of b that made it into d
  const double av = d + bv;  // the part of a that made it into d
  const double eb = bv - b;
  const double ea = a - av;
  return ea + eb == 0.0 && std::isfinite(d);
}

// Product exactness via the fma residual (std::fma rounds once, always).  The
// residual x*y - p is itself representable only without underflow: for
// |p| >= 2^-900 the exact product's last bit is far above 2^-1074; a zero
// product is exact only when a factor is zero.
inline bool product_is_exact(double x, double y, double& p) {
  p = x * y;
  if (p == 0.0) return x == 0.0 || y == 0.0;
  return std::isfinite(p) && std::fabs(p) >= 0x1p-900 && std::fma(x, y, -p) == 0.0;
}
}  // namespace detail

/// Stage 1: returns false ("certainly not parallel") or kUncertain-style true
/// ("could be parallel").  Exposed for tests.
///
/// Derivation of the bound (kParallelRel, kParallelUnderflow):
/// u = 2^-53, round to nearest.  With A = a1 - a0, B = b1 - b0 exact and Ã, B̃ the
/// rounded differences, component x of the cross product is computed as
///     c_x = fl(fl(Ã_y B̃_z) - fl(Ã_z B̃_y)).
/// Each of its two terms meets 2 roundings of differences, 1 of the product and
/// 1 of the subtraction (fewer when contracted to an fma):
///     |c_x - (A x B)_x| <= γ_4 Q_x,   Q_x = |A_y B_z| + |A_z B_y|.
/// The computed Q̃_x (rounded differences, 2 products, 1 addition, all terms
/// >= 0) satisfies Q̃_x >= (1-u)^4 Q_x, so the error is <= 4u(1+9u) Q̃_x.  The
/// bound fl(5u Q̃_x + g) (<= 2 roundings down) exceeds 4u(1+9u)Q̃_x + g(1-u)^2.
/// Underflow: each product may lose <= η/2 (η = 2^-1074), <= η per component;
/// g = 2^-1070 = 16η covers it.  If |c_x| > bound for some x, then (A x B)_x != 0.
/// Overflow or NaN make every comparison false: stages 2-3 decide.
inline bool parallel_filter_maybe(const double a[3], const double b[3]) {
  const double pyz = a[1] * b[2], pzy = a[2] * b[1];
  const double pzx = a[2] * b[0], pxz = a[0] * b[2];
  const double pxy = a[0] * b[1], pyx = a[1] * b[0];
  const double cx = pyz - pzy, cy = pzx - pxz, cz = pxy - pyx;
  const double bx = detail::kParallelRel * (std::fabs(pyz) + std::fabs(pzy)) + detail::kParallelUnderflow;
  const double by = detail::kParallelRel * (std::fabs(pzx) + std::fabs(pxz)) + detail::kParallelUnderflow;
  const double bz = detail::kParallelRel * (std::fabs(pxy) + std::fabs(pyx)) + detail::kParallelUnderflow;
  return !(std::fabs(cx) > bx || std::fabs(cy) > by || std::fabs(cz) > bz);
}

/// Exact: (a1 - a0) x (b1 - b0) == 0, evaluated in ExactFloat only.
template <class F>
SEPAX_ROBUST_COLD bool parallel_exact(const Vec3<F>& a0, const Vec3<F>& a1, const Vec3<F>& b0,
                                      const Vec3<F>& b1) {
  const auto c = exact_cross(exact_diff(a1, a0), exact_diff(b1, b0));
  return exact_sign(c[0]) == 0 && exact_sign(c[1]) == 0 && exact_sign(c[2]) == 0;
}

template <class F>
SEPAX_ROBUST_COLD bool parallel_stage2(const Vec3<F>& a0, const Vec3<F>& a1, const Vec3<F>& b0,
                                       const Vec3<F>& b1);

/// Exact: (a1 - a0) x (b1 - b0) == 0 for float or double points.  `fallbacks`
/// (if given) counts the calls the filter could not decide.
template <class F>
inline bool parallel(const Vec3<F>& a0, const Vec3<F>& a1, const Vec3<F>& b0, const Vec3<F>& b1,
                     std::int64_t* fallbacks = nullptr) {
  static_assert(std::is_same_v<F, float> || std::is_same_v<F, double>,
                "parallel is for float and double coordinates");
  const double a[3] = {static_cast<double>(a1[0]) - a0[0], static_cast<double>(a1[1]) - a0[1],
                       static_cast<double>(a1[2]) - a0[2]};
  const double b[3] = {static_cast<double>(b1[0]) - b0[0], static_cast<double>(b1[1]) - b0[1],
                       static_cast<double>(b1[2]) - b0[2]};
  if (!parallel_filter_maybe(a, b)) return false;
  if (fallbacks) ++*fallbacks;
  return parallel_stage2(a0, a1, b0, b1);
}

/// Stages 2 and 3 (exact).
template <class F>
SEPAX_ROBUST_COLD bool parallel_stage2(const Vec3<F>& a0, const Vec3<F>& a1, const Vec3<F>& b0,
                                       const Vec3<F>& b1) {
  double a[3], b[3];
  bool diffs_exact = true;
  for (int i = 0; i < 3; ++i) {
    diffs_exact &= detail::difference_is_exact(a1[i], a0[i], a[i]);
    diffs_exact &= detail::difference_is_exact(b1[i], b0[i], b[i]);
  }
  if (diffs_exact) {
    // Stage 2: (A x B)_x = A_y B_z - A_z B_y is zero iff the two (exact)
    // products are equal; compared directly, so no rounding is involved.
    double p[6];
    const bool prods_exact =
        detail::product_is_exact(a[1], b[2], p[0]) && detail::product_is_exact(a[2], b[1], p[1]) &&
        detail::product_is_exact(a[2], b[0], p[2]) && detail::product_is_exact(a[0], b[2], p[3]) &&
        detail::product_is_exact(a[0], b[1], p[4]) && detail::product_is_exact(a[1], b[0], p[5]);
    if (prods_exact) return p[0] == p[1] && p[2] == p[3] && p[4] == p[5];
  }
  return parallel_exact(a0, a1, b0, b1);
}

}  // namespace sepax::robust
