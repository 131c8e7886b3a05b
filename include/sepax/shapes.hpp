// sepax/shapes.hpp
//
// Ready-made convex shapes over any T.  Sizes are given as doubles and
// converted with from_double (exact for exact T); trigonometric vertices are
// rounded to double first, then converted exactly, so a float and an exact
// prism built from the same arguments have the same vertices up to the float
// rounding of those doubles.
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "convex_polyhedron.hpp"
#include "error.hpp"
#include "number_traits.hpp"
#include "vec3.hpp"

namespace sepax::shapes {

/// A point given in doubles, in T: a coordinate finite as a double that T cannot hold (1e300 in float) is
/// BadScale naming it ("coordinate x of vertex 0 (1e+300) is beyond the range of float"), not an
/// infinity for validation to call non-finite.  `what` and `index` name the point.
template <Number T>
Vec3<T> point_from_double(const Vec3<double>& p, std::size_t index, const char* what = "vertex") {
  const Vec3<T> x = vec_from_double<T>(p);
  for (int c = 0; c < 3; ++c)
    if (std::isfinite(p[c]) && !number_traits<T>::is_finite(x[c]))
      throw coordinate_beyond_range(c, what, index, p[c], number_traits<T>::name);
  return x;
}

/// Axis-aligned box centred at the origin with half extents (hx, hy, hz).
template <Number T>
ConvexPolyhedron<T> box(double hx, double hy, double hz) {
  std::vector<Vec3<T>> v;
  for (int i = 0; i < 8; ++i) {
    const double x = ((i & 1) ^ ((i >> 1) & 1)) ? hx : -hx;
    const double y = (i & 2) ? hy : -hy;
    const double z = (i & 4) ? hz : -hz;
    v.push_back(point_from_double<T>(Vec3<double>(x, y, z), v.size()));
  }
  // 0(-,-,-) 1(+,-,-) 2(+,+,-) 3(-,+,-) 4(-,-,+) 5(+,-,+) 6(+,+,+) 7(-,+,+)
  return ConvexPolyhedron<T>::from_faces(
      std::move(v), {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}});
}

template <Number T>
ConvexPolyhedron<T> cube(double half = 1.0) {
  return box<T>(half, half, half);
}

/// Regular tetrahedron with vertices (s,s,s), (s,-s,-s), (-s,s,-s), (-s,-s,s).
template <Number T>
ConvexPolyhedron<T> tetrahedron(double s = 1.0) {
  std::vector<Vec3<T>> v{
      point_from_double<T>(Vec3<double>(s, s, s), 0), point_from_double<T>(Vec3<double>(s, -s, -s), 1),
      point_from_double<T>(Vec3<double>(-s, s, -s), 2), point_from_double<T>(Vec3<double>(-s, -s, s), 3)};
  return ConvexPolyhedron<T>::from_faces(std::move(v), {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
}

/// Regular n-sided prism (a cylinder approximation) around the z axis:
/// circumradius r, half height h.  n >= 3.  For n so large that neighbouring
/// sides round to one plane in T (about 6.7e5 sides in double) validation
/// refuses it with ErrorCode::NotConvex ("adjacent and coplanar").
template <Number T>
ConvexPolyhedron<T> prism(int n, double r = 1.0, double h = 1.0) {
  if (n < 3)
    throw InvalidInput(ErrorCode::TooFewPoints, "a prism needs at least 3 sides, got " + std::to_string(n));
  std::vector<Vec3<T>> v;
  for (int k = 0; k < 2; ++k) {
    for (int i = 0; i < n; ++i) {
      const double t = 2.0 * std::numbers::pi * i / n;
      v.push_back(point_from_double<T>(Vec3<double>(r * std::cos(t), r * std::sin(t), k ? h : -h), v.size()));
    }
  }
  std::vector<std::vector<int>> faces;
  std::vector<int> bottom, top;
  for (int i = 0; i < n; ++i) {
    top.push_back(n + i);
    bottom.push_back(n - 1 - i);
    const int j = (i + 1) % n;
    faces.push_back({i, j, n + j, n + i});
  }
  faces.push_back(bottom);
  faces.push_back(top);
  return ConvexPolyhedron<T>::from_faces(std::move(v), faces);
}

/// Double-sided regular n-gon in the plane z = 0, circumradius r, front normal +z.
template <Number T>
ConvexPolyhedron<T> regular_polygon(int n, double r = 1.0) {
  if (n < 3)
    throw InvalidInput(ErrorCode::TooFewPoints, "a polygon needs at least 3 sides, got " + std::to_string(n));
  std::vector<Vec3<T>> v;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * std::numbers::pi * i / n;
    v.push_back(point_from_double<T>(Vec3<double>(r * std::cos(t), r * std::sin(t), 0.0), v.size()));
  }
  return ConvexPolyhedron<T>::polygon(std::move(v));
}

/// Double-sided triangle a, b, c (front normal (b-a) x (c-a)).
template <Number T>
ConvexPolyhedron<T> triangle(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  return ConvexPolyhedron<T>::polygon({a, b, c});
}

}  // namespace sepax::shapes
