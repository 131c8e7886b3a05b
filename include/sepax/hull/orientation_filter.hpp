// sepax/hull/orientation_filter.hpp
//
// Filters for the exact hull's predicates on points whose coordinates are exactly doubles, so that "is p
// above face abc" (sepax::orientation_filter, orientation_filter.hpp) and "is triangle abc of non-zero
// area" (below) cost a few flops instead of exact arithmetic; each decides in double when its error bound
// allows, else not at all (the caller decides exactly in its own number type).
#pragma once

#include <cmath>

#include "../orientation_filter.hpp"
#include "../vec3.hpp"

namespace sepax::hull {

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
