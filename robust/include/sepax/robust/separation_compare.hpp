// sepax/robust/separation_compare.hpp
//
// (P3) Exact separations and their exact comparison, in three stages:
//   1. the robust kernel compares its float/double separation values with a
//      per-feature error bound (robust_kernel_values.hpp) and comes here only
//      when two candidates are closer than the bounds;
//   2. compare_interval: the same polynomials in interval arithmetic;
//   3. compare_exact: the polynomials in ExactFloat, compared without sqrt or
//      division (compare_by_signs).
// A separation is num / sqrt(norm2) (separation.hpp):
//   face f (plane triple p0, p1, p2) against point p:
//       N = (p1 - p0) x (p2 - p0),  num = N . (p - p0),  norm2 = |N|^2
//   edge pair (eA = hA - tA, eB = hB - tB), orientation sigma = +-1:
//       n = eA x eB,  num = sigma * n . (pB - pA),  norm2 = |n|^2
// The rule is sepax::compare's for rationals, so a decision made here is the
// decision PlainKernel<mpq_class> makes on the same values.
#pragma once

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>

#include <sepax/robust/exact_float.hpp>
#include <sepax/robust/orientation.hpp>  // kUncertain
#include <sepax/vec3.hpp>

namespace sepax::robust {

/// A separation num / sqrt(norm2) as its two polynomials, in number type N.
template <class N>
struct SeparationPoly {
  N num;
  N norm2;
};

using ExactSeparation = SeparationPoly<ExactFloat>;

/// Interval_nt without per-operation rounding-mode switches: its operations
/// are valid only inside a CGAL::Protect_FPU_rounding<true> scope (rounding
/// upward), which compare_interval opens once.
using IntervalFloat = CGAL::Interval_nt_advanced;
using IntervalSeparation = SeparationPoly<IntervalFloat>;

/// The order of two separations num / sqrt(norm2) from the signs of their
/// polynomials: signs of num first; equal non-zero signs: num1^2 n2 vs
/// num2^2 n1, reversed when both are negative.  sign(x) returns -1, 0, +1 or
/// kUncertain; any uncertain sign makes the answer kUncertain.  Requires
/// norm2 > 0 for both.
template <class N, class Sign>
inline int compare_by_signs(const SeparationPoly<N>& a, const SeparationPoly<N>& b, Sign&& sign) {
  const int sa = sign(a.num), sb = sign(b.num);
  if (sa == kUncertain || sb == kUncertain) return kUncertain;
  if (sa != sb) return sa < sb ? -1 : 1;
  if (sa == 0) return 0;
  const int mag = sign(a.num * a.num * b.norm2 - b.num * b.num * a.norm2);
  if (mag == kUncertain) return kUncertain;
  return sa > 0 ? mag : -mag;
}

/// Stage 3: -1, 0, +1 as a < b, a == b, a > b (as real numbers
/// num / sqrt(norm2)), exactly: signs first; equal non-zero signs:
/// num1^2 * norm2_2  vs  num2^2 * norm2_1, reversed when both are negative.
/// Requires norm2 > 0 for both.
inline int compare_exact(const ExactSeparation& a, const ExactSeparation& b) {
  return compare_by_signs(a, b, [](const ExactFloat& x) { return exact_sign(x); });
}

/// Face with plane triple (p0, p1, p2) against point p (N = ExactFloat: exact;
/// N = IntervalFloat: enclosures, inside Protect_FPU_rounding<true>).
template <class N = ExactFloat, class F>
inline SeparationPoly<N> face_separation_poly(const Vec3<F>& p0, const Vec3<F>& p1, const Vec3<F>& p2,
                                              const Vec3<F>& p) {
  const auto n = exact_cross(diff_as<N>(p1, p0), diff_as<N>(p2, p0));
  return {exact_dot(n, diff_as<N>(p, p0)), exact_dot(n, n)};
}

/// Edge pair: n = (hA - tA) x (hB - tB), num = sigma * n . (pB - pA).
template <class N = ExactFloat, class F>
inline SeparationPoly<N> edge_separation_poly(const Vec3<F>& ta, const Vec3<F>& ha, const Vec3<F>& tb,
                                              const Vec3<F>& hb, const Vec3<F>& pa, const Vec3<F>& pb,
                                              int sigma) {
  const auto n = exact_cross(diff_as<N>(ha, ta), diff_as<N>(hb, tb));
  N num = exact_dot(n, diff_as<N>(pb, pa));
  if (sigma < 0) num = -num;
  return {num, exact_dot(n, n)};
}

/// Stage 2: compare_exact's rule on enclosures.  The kernel's bounds are per
/// shape pair and sized for the worst-conditioned face (about 1e-5 of the
/// shapes' size for float hulls of random points), so two distinct candidates
/// closer than that reach here now and then (1 to 2 queries in 64 on sphere16
/// hulls); their intervals, of width about 1e-15 of the values, separate them
/// without GMP.  Only exact ties (and values whose intervals overflow or
/// underflow) go on to the exact stage.  make_a and make_b build the
/// two IntervalSeparations (face_separation_poly / edge_separation_poly with
/// N = IntervalFloat); they run inside the rounding scope opened here.
/// Returns -1, 0, +1 only when the enclosures decide (0 only when both
/// numerators are exactly 0: a point interval [0, 0] encloses only 0), and
/// kUncertain otherwise (overlap, overflow to infinity, NaN).  Never wrong
/// when it decides: every interval encloses the exact value of its
/// polynomial, so a strict sign of an interval is the exact sign.
template <class MakeA, class MakeB>
inline int compare_interval(MakeA&& make_a, MakeB&& make_b) {
  CGAL::Protect_FPU_rounding<true> upward;
  const IntervalSeparation a = make_a();
  const IntervalSeparation b = make_b();
  return compare_by_signs(a, b, [](const IntervalFloat& x) {
    if (x.inf() > 0) return 1;
    if (x.sup() < 0) return -1;
    if (x.inf() == 0 && x.sup() == 0) return 0;
    return kUncertain;  // straddles 0, or NaN
  });
}

}  // namespace sepax::robust
