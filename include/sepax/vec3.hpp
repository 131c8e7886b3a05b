// sepax/vec3.hpp
//
// Vectors are Eigen::Matrix<T,3,1>.  Eigen is used for storage and for the
// element-wise + and -; the products that decide signs (dot, cross, triple) are
// written out here with a fixed evaluation order, so that
//   * the forward error bounds in robust/ can be derived for exactly these
//     operation sequences, and
//   * exact number types never meet an Eigen reduction they were not written for.
#pragma once

#include <Eigen/Core>

#include "number_traits.hpp"

namespace sepax {

template <class T>
using Vec3 = Eigen::Matrix<T, 3, 1>;

template <class T>
using Vec2 = Eigen::Matrix<T, 2, 1>;

/// a.x*b.x + a.y*b.y + a.z*b.z, evaluated left to right.
template <class T>
inline T dot(const Vec3<T>& a, const Vec3<T>& b) {
  T s = a[0] * b[0];
  s = s + a[1] * b[1];
  s = s + a[2] * b[2];
  return s;
}

template <class T>
inline Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  T x = a[1] * b[2] - a[2] * b[1];
  T y = a[2] * b[0] - a[0] * b[2];
  T z = a[0] * b[1] - a[1] * b[0];
  return Vec3<T>(x, y, z);
}

/// a . (b x c) = det[a, b, c].
template <class T>
inline T triple(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  return dot(a, cross(b, c));
}

template <class T>
inline T squared_norm(const Vec3<T>& a) {
  return dot(a, a);
}

template <class T>
inline bool is_zero(const Vec3<T>& a) {
  const T z(0);
  return a[0] == z && a[1] == z && a[2] == z;
}

/// Convert a vector of doubles to T element by element (exact for exact T).
template <Number T>
inline Vec3<T> vec_from_double(const Vec3<double>& v) {
  return Vec3<T>(from_double<T>(v[0]), from_double<T>(v[1]), from_double<T>(v[2]));
}

/// For reporting only: the nearest doubles.
template <Number T>
inline Vec3<double> vec_to_double(const Vec3<T>& v) {
  return Vec3<double>(to_double(v[0]), to_double(v[1]), to_double(v[2]));
}

/// Convert from a floating type U (float or double) to any T.  float -> double
/// and double -> rational are exact; double -> float rounds to nearest.
/// Conversions out of an exact type are not offered: they would round.
template <Number T, Number U>
inline Vec3<T> vec_cast(const Vec3<U>& v) {
  if constexpr (std::is_same_v<T, U>) {
    return v;
  } else {
    static_assert(!number_traits<U>::is_exact,
                  "vec_cast from an exact type would go through double: use vec_to_double "
                  "for reporting");
    return Vec3<T>(from_double<T>(to_double(v[0])), from_double<T>(to_double(v[1])),
                   from_double<T>(to_double(v[2])));
  }
}

}  // namespace sepax
