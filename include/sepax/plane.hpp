// sepax/plane.hpp
//
// Plane<T>, a face's plane (outward normal and offset), and what builds one:
//   * plane_through(a, b, c), plane_through_cross(a, e1, e2, c): the plane of
//     three points, normalised when T normalises, scale-safe for float/double;
//   * detail::triangle_aspect(a, b, c): the height-over-side measure by which
//     ConvexPolyhedron and the hull builder refuse sliver plane triangles;
//   * HasExactPlane<T>: a number type's own route to plane_through's values.
#pragma once

#include <algorithm>
#include <cmath>
#include <concepts>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

#include "number_traits.hpp"
#include "vec3.hpp"

namespace sepax {

template <class T>
struct Plane {
  Vec3<T> normal;  ///< outward; unit length iff number_traits<T>::normalizes
  T offset;        ///< normal . x == offset on the plane
};

namespace detail {

/// Float and double: |N| / L^2 for N = (b - a) x (c - a) and L the longest
/// side of triangle abc, i.e. its height over its longest side (computed on the
/// sides scaled by a power of two, so at any scale; 0 for a zero or
/// non-finite side).  Rounding alone gives collinear points an aspect up to
/// about 14u; ConvexPolyhedron refuses faces whose plane triangle has an
/// aspect not above Tolerances::sliver (and the hull builder checks 2x that).
template <class T>
double triangle_aspect(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  static_assert(std::is_floating_point_v<T>);
  Vec3<T> u(b - a), w(c - a);
  const T m = max_abs2(u, w);
  if (!(m > T(0)) || !(m <= std::numeric_limits<T>::max())) return 0;
  const int e = pow2_exponent(m);
  u = scale_pow2(u, e);
  w = scale_pow2(w, e);
  const double n = std::sqrt(static_cast<double>(squared_norm(cross(u, w))));
  const double l2 =
      static_cast<double>(std::max({squared_norm(u), squared_norm(w), squared_norm(Vec3<T>(w - u))}));
  return n / l2;
}

}  // namespace detail

/// Plane through three points, normalised when T normalises.
///
/// For float and double the unit normal is scale-safe (scaled_cross in
/// vec3.hpp): when |N|^2 of N = (b - a) x (c - a) would overflow or underflow
/// (coordinates beyond about 1e+-77 for double, 1e+-9 for float), N is taken
/// from b - a and c - a scaled by a power of two.  Wherever the unscaled
/// formula neither overflows nor underflows the normal is bit for bit the one
/// it gives -- the same planes as before, and the robust kernel's error bound
/// on them (robust_kernel.hpp, normal_error; normal_conditioning() here)
/// still holds.  If b - a or c - a themselves overflow, the normal is not
/// finite; ConvexPolyhedron reports that as BadScale.
template <Number T>
inline Plane<T> plane_through_cross(const Vec3<T>& a, const Vec3<T>& e1, const Vec3<T>& e2, const Vec3<T>& c);
/// An exact number type may supply number_traits<T>::exact_plane(out, a, b, c): out = plane_through(a, b, c)'s
/// values (the normal (b - a) x (c - a), the offset normal . a) by a faster route where the route applies,
/// returning true, and false with out untouched where it does not (plane_through then computes them in T).
/// The result is written into out so that an existing plane's numbers are reused.  mpq_class does, for
/// points whose coordinates are dyadic rationals (robust/number_types.hpp).
template <class T>
concept HasExactPlane = number_traits<T>::is_exact && requires(Plane<T>& out, const Vec3<T>& v) {
  { number_traits<T>::exact_plane(out, v, v, v) } -> std::same_as<bool>;
};

namespace detail {
/// plane_through's general formula, in T (the route every type has).
template <Number T>
inline Plane<T> plane_through_in_t(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  const Vec3<T> e1(b - a), e2(c - a);
  return plane_through_cross(a, e1, e2, Vec3<T>(cross(e1, e2)));
}
}  // namespace detail

template <Number T>
inline Plane<T> plane_through(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  if constexpr (HasExactPlane<T>) {
    Plane<T> p;
    if (number_traits<T>::exact_plane(p, a, b, c)) return p;
  }
  return detail::plane_through_in_t(a, b, c);
}
/// out = plane_through(a, b, c), into out's numbers where T has its own route (HasExactPlane).
template <Number T>
inline void assign_plane_through(Plane<T>& out, const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  if constexpr (HasExactPlane<T>) {
    if (number_traits<T>::exact_plane(out, a, b, c)) return;
  }
  out = detail::plane_through_in_t(a, b, c);
}
/// plane_through(a, a + e1, a + e2) given e1 = b - a, e2 = c - a (as T
/// computes them) and c = cross(e1, e2), computed by the caller.
template <Number T>
inline Plane<T> plane_through_cross(const Vec3<T>& a, const Vec3<T>& e1, const Vec3<T>& e2,
                                    const Vec3<T>& c) {
  Vec3<T> n = scaled_cross(e1, e2, c);
  if constexpr (number_traits<T>::normalizes) {
    const T len = number_traits<T>::sqrt(squared_norm(n));
    if (len > T(0)) n = Vec3<T>(n[0] / len, n[1] / len, n[2] / len);
  }
  const T off = dot(n, a);
  return Plane<T>{n, off};
}

}  // namespace sepax
