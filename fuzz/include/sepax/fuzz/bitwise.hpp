// sepax/fuzz/bitwise.hpp
//
// Bit-for-bit equality of SAT results and contact manifolds, for the
// comparisons whose contract is identity (margins without an early exit,
// posed against pre-posed queries, warm against fresh queries): every float
// compared by its bits (so -0 != +0 and a NaN equals only the same NaN), exact
// types by value.
#pragma once

#include <cstring>
#include <type_traits>

#include <sepax/contact_manifold.hpp>
#include <sepax/sat_result.hpp>

namespace sepax::fuzz {

template <class T>
bool same_bits(const T& x, const T& y) {
  if constexpr (std::is_floating_point_v<T>) {
    return std::memcmp(&x, &y, sizeof(T)) == 0;
  } else {
    return x == y;
  }
}

template <class T>
bool same_bits(const Vec3<T>& x, const Vec3<T>& y) {
  return same_bits(x[0], y[0]) && same_bits(x[1], y[1]) && same_bits(x[2], y[2]);
}

template <class T>
bool same_bits(const Separation<T>& x, const Separation<T>& y) {
  return same_bits(x.num, y.num) && same_bits(x.norm2, y.norm2);
}

/// Overlap, feature, separation, axis and early exit (not the stats).
template <class T>
bool same_bits(const SatResult<T>& x, const SatResult<T>& y) {
  return x.overlap == y.overlap && x.early_out == y.early_out && x.feature == y.feature &&
         same_bits(x.separation, y.separation) && same_bits(x.axis, y.axis);
}

/// Kind, feature, normal, separation, faces and every point (ids, positions,
/// separations).
template <class T>
bool same_bits(const ContactManifold<T>& x, const ContactManifold<T>& y) {
  if (x.kind != y.kind || !(x.feature == y.feature) || !same_bits(x.normal, y.normal) ||
      !same_bits(x.norm2, y.norm2) || !same_bits(x.separation, y.separation) ||
      x.reference_shape != y.reference_shape || x.reference_face != y.reference_face ||
      x.incident_face != y.incident_face || x.support_fallback != y.support_fallback ||
      x.points.size() != y.points.size())
    return false;
  for (std::size_t i = 0; i < x.points.size(); ++i) {
    const auto &p = x.points[i], &q = y.points[i];
    if (!(p.id == q.id) || !same_bits(p.position, q.position) || !same_bits(p.point_a, q.point_a) ||
        !same_bits(p.point_b, q.point_b) || !same_bits(p.separation, q.separation))
      return false;
  }
  return true;
}

}  // namespace sepax::fuzz
