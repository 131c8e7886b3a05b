// Test shapes for the traversal and cache tests: random triangulated hulls of
// points on a sphere (built in double by an O(n^4) facet test, rejected when
// any four points are nearly coplanar so that the exact image is convex too),
// rigid motions in double, and exact rational rotations (integer quaternions)
// for exact types.
#pragma once

#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include <sepax/convex_hull.hpp>
#include <sepax/convex_polyhedron.hpp>

namespace sepax::test {

using V3 = Vec3<double>;

inline V3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  for (;;) {
    V3 v(n(rng), n(rng), n(rng));
    const double l = v.norm();
    if (l > 1e-3) return v / l;
  }
}

/// Hull of n random points on a sphere of radius r (triangles only).
/// nullopt when the sample is too close to degenerate.
inline std::optional<ConvexPolyhedron<double>> try_sphere_hull(std::mt19937_64& rng, int n, double r = 1.0) {
  std::vector<V3> p;
  for (int i = 0; i < n; ++i) p.push_back(r * random_unit(rng));
  std::vector<std::vector<int>> faces;
  const double margin = 1e-7 * r * r * r;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        const V3 nn = (p[j] - p[i]).cross(p[k] - p[i]);
        int pos = 0, neg = 0;
        for (int m = 0; m < n; ++m) {
          if (m == i || m == j || m == k) continue;
          const double d = nn.dot(p[m] - p[i]);
          if (std::abs(d) < margin) return std::nullopt;
          (d > 0 ? pos : neg)++;
        }
        if (pos == 0) faces.push_back({i, j, k});
        if (neg == 0) faces.push_back({i, k, j});
      }
  try {
    return ConvexPolyhedron<double>::from_faces(p, faces);
  } catch (const InvalidInput&) {
    return std::nullopt;
  }
}

inline ConvexPolyhedron<double> sphere_hull(std::mt19937_64& rng, int n, double r = 1.0) {
  for (;;) {
    if (auto h = try_sphere_hull(rng, n, r)) return *h;
  }
}

/// Hull of n random points on a sphere of radius r by sepax's own hull
/// builder: fast enough for hundreds of points, unlike sphere_hull's brute
/// force over every triple (O(n^4)).  The points are float values and the
/// hull also passes ConvexPolyhedron<float>'s validation, so
/// ConvexPolyhedron<float>::convert_from of it is the same shape.
inline ConvexPolyhedron<double> large_sphere_hull(std::mt19937_64& rng, int n, double r = 1.0) {
  for (;;) {
    std::vector<V3> p;
    for (int i = 0; i < n; ++i) p.push_back((r * random_unit(rng)).cast<float>().cast<double>());
    try {
      auto h = convex_hull<double>(p);
      (void)ConvexPolyhedron<float>::convert_from(h);
      return h;
    } catch (const InvalidInput&) {
    }
  }
}

inline Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  const V3 axis = random_unit(rng);
  std::uniform_real_distribution<double> u(0.0, 6.283185307179586);
  return Eigen::AngleAxisd(u(rng), axis).toRotationMatrix();
}

inline ConvexPolyhedron<double> moved(const ConvexPolyhedron<double>& p, const Eigen::Matrix3d& r,
                                      const V3& t) {
  std::vector<V3> v;
  for (const auto& x : p.vertices()) v.push_back(r * x + t);
  return p.with_vertices(std::move(v));
}

/// Exact rotation by the integer quaternion (w, x, y, z) (any non-zero one),
/// then translation by t; for exact T the result is exactly rigid.
template <Number T>
ConvexPolyhedron<T> rotated_exact(const ConvexPolyhedron<T>& p, int w, int x, int y, int z,
                                  const Vec3<T>& t) {
  const T s(w * w + x * x + y * y + z * z);
  const T m[3][3] = {{T(w * w + x * x - y * y - z * z), T(2 * (x * y - w * z)), T(2 * (x * z + w * y))},
                     {T(2 * (x * y + w * z)), T(w * w - x * x + y * y - z * z), T(2 * (y * z - w * x))},
                     {T(2 * (x * z - w * y)), T(2 * (y * z + w * x)), T(w * w - x * x - y * y + z * z)}};
  std::vector<Vec3<T>> out;
  for (const auto& v : p.vertices()) {
    Vec3<T> q;
    for (int i = 0; i < 3; ++i) {
      T acc = m[i][0] * v[0];
      acc = acc + m[i][1] * v[1];
      acc = acc + m[i][2] * v[2];
      q[i] = T(acc / s + t[i]);
    }
    out.push_back(q);
  }
  return p.with_vertices(std::move(out));
}

}  // namespace sepax::test
