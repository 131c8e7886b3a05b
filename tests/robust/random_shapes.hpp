// Test helpers for tests/robust: random convex hulls of points on a sphere
// (brute-force hull with exact orientation predicates, so every face is exact)
// and random rigid poses.  Not a hull builder for users (see convex_hull.hpp).
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/robust/orientation.hpp>

namespace sepax::testing {

inline Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  q.normalize();
  return q.toRotationMatrix();
}

/// The vertices of p mapped by x -> scale * R x + t (in double), rounded to T.
template <class T>
ConvexPolyhedron<T> posed(const ConvexPolyhedron<T>& p, const Eigen::Matrix3d& r, const Vec3<double>& t,
                          double scale = 1.0) {
  std::vector<Vec3<T>> v;
  for (const auto& x : p.vertices()) {
    const Vec3<double> y = scale * (r * x.template cast<double>()) + t;
    v.push_back(y.template cast<T>());
  }
  return p.with_vertices(std::move(v));
}

/// Exact translation by t (t chosen by the caller so that v + t is exact in T).
template <class T>
ConvexPolyhedron<T> translated(const ConvexPolyhedron<T>& p, const Vec3<T>& t) {
  std::vector<Vec3<T>> v;
  for (const auto& x : p.vertices()) v.push_back(Vec3<T>(x + t));
  return p.with_vertices(std::move(v));
}

/// Convex hull of n random points on the sphere of the given radius (all
/// faces triangles; retried until the points are in general position and the
/// hull validates).
template <class T>
ConvexPolyhedron<T> random_sphere_hull(std::mt19937_64& rng, int n, double radius = 1.0) {
  std::normal_distribution<double> g;
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < n; ++i) {
      Vec3<double> d(g(rng), g(rng), g(rng));
      d *= radius / d.norm();
      pts.push_back(d.template cast<T>());
    }
    std::vector<std::vector<int>> faces;
    bool degenerate = false;
    for (int i = 0; i < n && !degenerate; ++i) {
      for (int j = i + 1; j < n && !degenerate; ++j) {
        for (int k = j + 1; k < n && !degenerate; ++k) {
          int pos = 0, neg = 0;
          for (int l = 0; l < n; ++l) {
            if (l == i || l == j || l == k) continue;
            const int s = robust::orient3d(pts[i], pts[j], pts[k], pts[l]);
            if (s > 0)
              ++pos;
            else if (s < 0)
              ++neg;
            else
              degenerate = true;
            if (pos && neg) break;
          }
          if (pos == 0)
            faces.push_back({i, j, k});
          else if (neg == 0)
            faces.push_back({i, k, j});
        }
      }
    }
    if (degenerate) continue;
    std::vector<int> used(static_cast<std::size_t>(n), 0);
    for (const auto& f : faces)
      for (int v : f) used[static_cast<std::size_t>(v)] = 1;
    bool all_used = true;
    for (int u : used) all_used = all_used && u;
    if (!all_used) continue;  // a point inside the hull (cannot happen on a sphere, but rounding)
    try {
      return ConvexPolyhedron<T>::from_faces(std::move(pts), faces);
    } catch (const InvalidInput&) {
      continue;
    }
  }
  throw std::runtime_error("random_sphere_hull: no valid hull in 100 attempts");
}

}  // namespace sepax::testing
