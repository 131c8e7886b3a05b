// sepax/hull/orientation_filter.hpp
//
// The sign of det[b - a, c - a, p - a] for points whose coordinates are doubles, decided in double when a
// semi-static error bound allows (almost always), else not at all (the caller decides exactly in its own
// number type).  The exact hull uses it on points that are exactly doubles, so that its hot predicates
// ("is p above face abc") cost a few flops instead of exact arithmetic; every sign it returns is exact.
#pragma once

#include <cmath>

#include "../vec3.hpp"

namespace sepax::hull {

/// The determinant and whether its sign is certain.
struct FilteredSign {
  double det = 0;        ///< det[b - a, c - a, p - a] rounded (a magnitude estimate, always)
  bool certain = false;  ///< sign(det) is the exact sign
};

/// Semi-static filter for sign det[A, B, C], A = b - a, B = c - a, C = p - a, in double.
///
/// Derivation (round to nearest, u = 2^-53; the same as robust/orientation.hpp's filter, with its a0 = a):
/// det is a sum of six terms +-A_i B_j C_k.  One term meets at most 8 roundings on its way (3 of its
/// differences, the product B_j C_k, the minor's subtraction, the product A_i m_i, 2 additions), each a
/// factor (1 + d), |d| <= u, so |det~ - det| <= gamma_8 P, gamma_k = k u / (1 - k u), P the permanent
/// sum |A_i| (|B_j C_k| + |B_k C_j|) of the exact differences.  The computed permanent P~ takes 5 roundings
/// per non-negative term on top of |A~_i| >= (1 - u)|A_i|, so P~ >= (1 - u)^8 P and the error is at most
/// 8u (1 + 18u) P~ <= 9u (1 - u)^2 P~, which fl(9u P~ + G) bounds (two roundings down at most).  FMA
/// contraction only removes roundings, so the bound holds with it on or off.  Underflow: each product
/// that underflows errs by at most 2^-1075; over the three minors and the outer products that is at most
/// 4 * 2^-1074 (M + 1), M = max |A~_i|, which G = (M + 1) 2^-1068 covers.  Overflow: the filter gives up
/// when P~ >= 2^1000 (below it no intermediate overflows) or is not finite.
inline FilteredSign orientation_filter(const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c,
                                       const Vec3<double>& p) {
  const double ax = b[0] - a[0], ay = b[1] - a[1], az = b[2] - a[2];
  const double bx = c[0] - a[0], by = c[1] - a[1], bz = c[2] - a[2];
  const double cx = p[0] - a[0], cy = p[1] - a[1], cz = p[2] - a[2];
  const double mx = by * cz - bz * cy, my = bz * cx - bx * cz, mz = bx * cy - by * cx;
  FilteredSign r;
  r.det = ax * mx + ay * my + az * mz;
  const double px = std::abs(by * cz) + std::abs(bz * cy);
  const double py = std::abs(bz * cx) + std::abs(bx * cz);
  const double pz = std::abs(bx * cy) + std::abs(by * cx);
  const double perm = std::abs(ax) * px + std::abs(ay) * py + std::abs(az) * pz;
  if (!(perm < 0x1p1000)) return r;  // (also NaN)
  const double m = std::fmax(std::abs(ax), std::fmax(std::abs(ay), std::abs(az)));
  const double bound = 9.0 * 0x1p-53 * perm + (m + 1.0) * 0x1p-1068;
  r.certain = std::abs(r.det) > bound;
  return r;
}

/// Whether u x w is certainly not the zero vector, for doubles u = b - a, w = c - a computed from double
/// points: some component's computed value exceeds its error bound.  A component u_j w_k - u_k w_j meets at
/// most 4 roundings per term (2 differences, the product, the subtraction): error <= gamma_4 (|u_j w_k| +
/// |u_k w_j|) exactly, <= 5u (the computed sum) + 2^-1070 (underflow) as for the determinant above.  False
/// when undecided (the caller decides exactly).
inline bool certainly_nonzero_cross(const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double wx = c[0] - a[0], wy = c[1] - a[1], wz = c[2] - a[2];
  auto decided = [](double p, double q) {
    const double s = std::abs(p) + std::abs(q);
    if (!(s < 0x1p1000)) return false;
    return std::abs(p - q) > 5.0 * 0x1p-53 * s + 0x1p-1070;
  };
  return decided(uy * wz, uz * wy) || decided(uz * wx, ux * wz) || decided(ux * wy, uy * wx);
}

}  // namespace sepax::hull
