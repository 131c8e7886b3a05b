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
//   2. when the filter cannot decide, an exact evaluation with ExactFloat
//      (exact_float.hpp) from the coordinates.
// The result is exact for all finite inputs, with or without FMA contraction.
#pragma once

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

/// Stage 2 only: the exact sign, from the coordinates.
template <class F>
SEPAX_ROBUST_COLD int orient_sign_exact(const Vec3<F>& a0, const Vec3<F>& a1, const Vec3<F>& b0,
                                        const Vec3<F>& b1, const Vec3<F>& c0, const Vec3<F>& c1) {
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
