// What the adapter skips from one step to the next, and the bounds that
// allow it (docs/bullet.md, "Coherence"); each bound is derived on the
// constant or function that implements it:
//   * bounding spheres: a pair whose spheres are farther apart than the margin
//     plus a rounding slack gets no point and no query;
//   * the kept face: after a query whose contact is a face, the face is
//     re-evaluated while B moved little (kKeepMotion, motion_bound) and the
//     pair cannot have become beyond the margin;
//   * kept apart: after a query that proved the pair beyond the margin, no
//     query runs while the motion since cannot have closed the gap.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <sepax/transform.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "contact_choice.hpp"

namespace sepax::bullet {

/// * The kept face.  After a SAT query whose contact (contact_choice.hpp) is
///   a face, the adapter keeps that face and the relative pose x0 the query
///   ran at.  At a later step with relative pose x1 every vertex of B (in
///   A's frame) is within
///       delta = |R1 - R0|_F reach_B + |t1 - t0|
///   of where it was (reach_B: B's largest |v| in its local frame), so every
///   axis's separation, the SAT's maximum among them, moved by at most
///   delta (plus the rounding of both images, kSlack).  While delta is at
///   most kKeepMotion * kAbsTolerance * min(extent A, extent B) (half the
///   contact choice's tolerance) and the SAT's separation at x0 plus delta
///   and the slack stays within the margin (so the pair is still not beyond
///   it), the kept face is re-evaluated instead of querying the SAT again:
///   the contact is the one chosen at x0, its depth exact for x1, and no
///   other axis can have overtaken it by more than 2 delta.
/// * Kept apart.  After a query that proved the pair beyond the margin with
///   separation s0 along an axis (fixed in A's frame) at relative pose x0,
///   the separation along that axis at x1 is at least s0 - delta: while
///   s0 - delta - slack exceeds the margin the pair is still beyond it (the
///   SAT, whose maximum is at least that, would stop too), and no query runs.
/// The kept face holds while B moved at most this fraction of the contact
/// choice's tolerance (x kAbsTolerance x the smaller extent), dimensionless.
inline constexpr double kKeepMotion = 0.5;
/// Relative slack for the rounding of the posed images and of the double
/// evaluations below (float images: a few units of 2^-24 of the coordinates).
inline constexpr double kSlack = 1e-6;

/// How far a relative pose moved from x0 to x1, in double: |R1 - R0|_F and
/// |t1 - t0| (each difference of two floats, its square and their sums in
/// double).  The kept face reads both delta and stays_rigid's |E|_F from
/// one evaluation.
struct Motion {
  /// |R1 - R0|_F, dimensionless.
  double rotation = 0;
  /// |t1 - t0|, in the translations' length unit.
  double translation = 0;
};

inline Motion motion_between(const RigidTransform<float>& x0, const RigidTransform<float>& x1) {
#if defined(__SSE2__)
  // The differences and their squares two entries at a time (SSE2 lanes:
  // each the scalar code's conversion, subtraction and product), the sums
  // in the scalar code's order below.  The rotation is column-major
  // (Eigen): lanes hold (0,0) (1,0) | (2,0) (0,1) | (1,1) (2,1) |
  // (0,2) (1,2), and (2,2) alone.
  static_assert(!RigidTransform<float>::Matrix3::IsRowMajor);
  const float* a = x0.rotation.data();
  const float* b = x1.rotation.data();
  auto squares = [](__m128 lo, __m128 hi, __m128d& s0, __m128d& s1) {
    const __m128d d0 = _mm_sub_pd(_mm_cvtps_pd(hi), _mm_cvtps_pd(lo));
    const __m128d d1 = _mm_sub_pd(_mm_cvtps_pd(_mm_movehl_ps(hi, hi)), _mm_cvtps_pd(_mm_movehl_ps(lo, lo)));
    s0 = _mm_mul_pd(d0, d0);
    s1 = _mm_mul_pd(d1, d1);
  };
  __m128d q0, q1, q2, q3;
  squares(_mm_loadu_ps(a), _mm_loadu_ps(b), q0, q1);
  squares(_mm_loadu_ps(a + 4), _mm_loadu_ps(b + 4), q2, q3);
  auto lane0 = [](__m128d v) { return _mm_cvtsd_f64(v); };
  auto lane1 = [](__m128d v) { return _mm_cvtsd_f64(_mm_unpackhi_pd(v, v)); };
  const double d22 = static_cast<double>(b[8]) - static_cast<double>(a[8]);
  double r2 = 0, t2 = 0;
  auto tra = [&](int i) {
    const double d = static_cast<double>(x1.translation[i]) - static_cast<double>(x0.translation[i]);
    t2 += d * d;
  };
  r2 += lane0(q0), r2 += lane1(q1), r2 += lane0(q3), tra(0);  // (0,0) (0,1) (0,2)
  r2 += lane1(q0), r2 += lane0(q2), r2 += lane1(q3), tra(1);  // (1,0) (1,1) (1,2)
  r2 += lane0(q1), r2 += lane1(q2), r2 += d22 * d22, tra(2);  // (2,0) (2,1) (2,2)
  return Motion{std::sqrt(r2), std::sqrt(t2)};
#else
  // the sums in the order (i, j) row by row, written out (the loops were
  // not unrolled)
  double r2 = 0, t2 = 0;
  auto rot = [&](int i, int j) {
    const double d = static_cast<double>(x1.rotation(i, j)) - static_cast<double>(x0.rotation(i, j));
    r2 += d * d;
  };
  auto tra = [&](int i) {
    const double d = static_cast<double>(x1.translation[i]) - static_cast<double>(x0.translation[i]);
    t2 += d * d;
  };
  rot(0, 0), rot(0, 1), rot(0, 2), tra(0);
  rot(1, 0), rot(1, 1), rot(1, 2), tra(1);
  rot(2, 0), rot(2, 1), rot(2, 2), tra(2);
  return Motion{std::sqrt(r2), std::sqrt(t2)};
#endif
}

/// delta above for a motion m and B's reach, in double.
inline double motion_bound(const Motion& m, double reach) { return m.rotation * reach + m.translation; }

/// delta above for relative poses x0 and x1, in double.
inline double motion_bound(const RigidTransform<float>& x0, const RigidTransform<float>& x1, double reach) {
  return motion_bound(motion_between(x0, x1), reach);
}

/// The slack of delta and of the separations it bounds: kSlack of the
/// coordinates involved (B's reach and both translations).
inline double motion_slack(const RigidTransform<float>& x0, const RigidTransform<float>& x1, double reach) {
  double m = reach;
  for (int i = 0; i < 3; ++i) {
    m += std::abs(static_cast<double>(x0.translation[i])) + std::abs(static_cast<double>(x1.translation[i]));
  }
  return kSlack * m;
}

/// An upper bound on |R^T R - I|_F for x's rotation R (its float entries
/// taken exactly): check_rigid's own evaluation with its rounding bound
/// (posing.hpp, detail::rotation_defect).
inline double rotation_defect(const RigidTransform<float>& x) { return sepax::detail::rotation_defect(x); }

/// True when check_rigid(x1) (posing.hpp) is certain to pass, given
/// omega0 = rotation_defect(x0) of a pose x0 that passed it and the motion
/// m from x0 to x1 (motion_between).  With
/// E = R1 - R0,
///   R1^T R1 - I = (R0^T R0 - I) + E^T R0 + R0^T E + E^T E,
/// so |R1^T R1 - I|_F <= omega0 + 2 |R0|_2 |E|_F + |E|_F^2, and
/// |R0|_2^2 <= 1 + omega0 (the largest eigenvalue of R0^T R0).  e bounds
/// |E|_F from above: each difference of two floats is within a relative
/// 2^-53 in double, the sum of squares and the square root within a
/// relative 1e-15, inside the (1 + 1e-10); the bound's own double
/// evaluation is inside the same factor.  check_rigid's computed defect
/// exceeds the exact one by at most a relative 1e-10 plus 1e-13 (its
/// rounding above, with |R|_F^2 <= 3 (1 + 1e-3)), far inside the 1e-9
/// kept below its limit of 1e-3.  Its determinant test passes too: every
/// R0 + t E, t in [0, 1], has the same defect bound < 1, hence no zero
/// singular value, so det R1 has det R0's sign (positive), and with a
/// defect <= 1e-3 |det R1| >= (1 - 1e-3)^(3/2), far beyond the rounding of
/// its double evaluation.  NaN entries fail the comparison: the check runs.
inline bool stays_rigid(double omega0, const Motion& m) {
  const double e = m.rotation * (1 + 1e-10);
  const double bound = (omega0 + 2 * std::sqrt(1 + omega0) * e + e * e) * (1 + 1e-10);
  return bound <= 1e-3 - 1e-9;
}

/// True when the bounding spheres (centres c in local frames, radii r) at
/// poses (rot_a, ta) and (rot_b, tb) - rotation rows and translations as
/// Bullet stores them, read before any conversion - are farther apart than
/// margin (with the slack).
template <class Basis, class Origin>
bool spheres_beyond(const Basis& rot_a, const Origin& ta, const std::array<double, 3>& ca, double ra,
                    const Basis& rot_b, const Origin& tb, const std::array<double, 3>& cb, double rb,
                    double margin) {
  // Each centre's row i as t_i + r_i0 c_0 + r_i1 c_1 + r_i2 c_2, summed left
  // to right; written out (the loops over i and j were not unrolled).
  auto centre = [](const Basis& rot, const Origin& t, const std::array<double, 3>& c, int i) {
    double w = static_cast<double>(t[i]);
    w += static_cast<double>(rot[i][0]) * c[0];
    w += static_cast<double>(rot[i][1]) * c[1];
    w += static_cast<double>(rot[i][2]) * c[2];
    return w;
  };
  double d2 = 0, scale = ra + rb;
  auto add_row = [&](int i) {
    const double wa = centre(rot_a, ta, ca, i), wb = centre(rot_b, tb, cb, i);
    d2 += (wb - wa) * (wb - wa);
    scale += std::abs(wa) + std::abs(wb);
  };
  add_row(0);
  add_row(1);
  add_row(2);
  const double reach = ra + rb + margin + kSlack * scale;
  return d2 > reach * reach;
}

}  // namespace sepax::bullet
