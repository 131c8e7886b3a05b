// sepax/robust/separation_compare.hpp
//
// (P3) Exact separations and their exact comparison.
//
// A candidate axis' separation is num / sqrt(norm2) with num and norm2
// polynomials in the input coordinates (separation.hpp):
//   face f (plane triple p0, p1, p2) against point p:
//       N = (p1 - p0) x (p2 - p0),  num = N . (p - p0),  norm2 = |N|^2
//   edge pair (eA = hA - tA, eB = hB - tB), orientation sigma = +-1:
//       n = eA x eB,  num = sigma * n . (pB - pA),  norm2 = |n|^2
// ExactSeparation holds them exactly (ExactFloat, exact_float.hpp), and
// compare_exact orders two of them exactly without sqrt or division:
//   signs first; equal non-zero signs: num1^2 * norm2_2  vs  num2^2 * norm2_1,
//   reversed when both are negative.
// This is the same rule as sepax::compare for rationals, so a decision made
// here is the decision PlainKernel<mpq_class> makes on the same values.
//
// The filter for (P3) lives where the approximate values already exist: the
// robust kernel compares its float/double separation values with a
// per-feature error bound (robust_kernel.hpp) and only comes here when the two
// candidates are closer than the bounds.
#pragma once

#include <sepax/robust/exact_float.hpp>
#include <sepax/vec3.hpp>

namespace sepax::robust {

struct ExactSeparation {
  ExactFloat num;
  ExactFloat norm2;
};

/// -1, 0, +1 as a < b, a == b, a > b (as real numbers num / sqrt(norm2)).
/// Requires norm2 > 0 for both.
inline int compare_exact(const ExactSeparation& a, const ExactSeparation& b) {
  const int sa = exact_sign(a.num), sb = exact_sign(b.num);
  if (sa != sb) return sa < sb ? -1 : 1;
  if (sa == 0) return 0;
  const ExactFloat lhs = a.num * a.num * b.norm2;
  const ExactFloat rhs = b.num * b.num * a.norm2;
  const int mag = exact_sign(lhs - rhs);
  return sa > 0 ? mag : -mag;
}

/// Face with plane triple (p0, p1, p2) against point p.
template <class F>
inline ExactSeparation face_separation_exact(const Vec3<F>& p0, const Vec3<F>& p1, const Vec3<F>& p2,
                                             const Vec3<F>& p) {
  const auto n = exact_cross(exact_diff(p1, p0), exact_diff(p2, p0));
  return {exact_dot(n, exact_diff(p, p0)), exact_dot(n, n)};
}

/// Edge pair: n = (hA - tA) x (hB - tB), num = sigma * n . (pB - pA).
template <class F>
inline ExactSeparation edge_separation_exact(const Vec3<F>& ta, const Vec3<F>& ha, const Vec3<F>& tb,
                                             const Vec3<F>& hb, const Vec3<F>& pa, const Vec3<F>& pb,
                                             int sigma) {
  const auto n = exact_cross(exact_diff(ha, ta), exact_diff(hb, tb));
  ExactFloat num = exact_dot(n, exact_diff(pb, pa));
  if (sigma < 0) num = -num;
  return {num, exact_dot(n, n)};
}

}  // namespace sepax::robust
