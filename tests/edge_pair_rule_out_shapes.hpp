// Shapes for the edge-pair rule-out tests (tests/core and tests/robust): generic
// hulls at random poses, and near-degenerate pairs (parallel and coplanar
// edges, flat polygons, thin slabs, noisy boxes, small shapes far from the
// origin) at scales from 2^-40 to 2^100.  check_rule_out runs a kernel's
// edge_pair_ruled_out against its own test on every edge pair of every pair.
#pragma once

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <random>
#include <type_traits>
#include <utility>
#include <vector>

#include <sepax/convex_hull.hpp>
#include <sepax/posing.hpp>
#include <sepax/shapes.hpp>
#include <sepax/transform.hpp>

namespace sepax::testing {

struct RuleOutCount {
  long pairs = 0, ruled_out = 0, unsound = 0;
  long generic_pairs = 0, generic_ruled_out = 0;
};

/// The checks of every rule-out test on its counts: no pair ruled out that
/// the kernel's test accepts, enough pairs, and on the generic hulls (points
/// on spheres and in balls, random poses) most pairs ruled out: most are no
/// Minkowski faces, and the wings show it.
inline void check_counts(const RuleOutCount& n) {
  INFO("pairs " << n.pairs << ", ruled out " << n.ruled_out << ", generic " << n.generic_pairs << " / "
                << n.generic_ruled_out);
  CHECK(n.unsound == 0);
  CHECK(n.pairs > 100000);
  CHECK(10 * n.generic_ruled_out > 8 * n.generic_pairs);
}

/// x rounded to T through a volatile: g++ 12 -O2 (SLP vectorizer) may drop
/// a double -> float -> double round trip on Eigen 3-vectors
/// (fuzz/src/case_io.cpp), and the tests compare T values with their doubles.
template <class T>
T rounded(double x) {
  volatile T f = static_cast<T>(x);
  return f;
}

/// v rounded to T coordinate by coordinate (rounded).
template <class T>
Vec3<T> rounded_vec(const Vec3<double>& v) {
  return Vec3<T>(rounded<T>(v[0]), rounded<T>(v[1]), rounded<T>(v[2]));
}

/// Three normal deviates of g, drawn in order, times s, rounded to T.
template <class T>
Vec3<T> random_vec(std::normal_distribution<double>& g, std::mt19937_64& rng, double s) {
  const double x = g(rng), y = g(rng), z = g(rng);
  return rounded_vec<T>(Vec3<double>(s * x, s * y, s * z));
}

template <class T>
RigidTransform<T> random_pose(std::mt19937_64& rng, double move) {
  std::normal_distribution<double> g;
  const double w = g(rng), x = g(rng), y = g(rng), z = g(rng);
  return RigidTransform<T>::from_quaternion(w, x, y, z,
                                            Vec3<T>(T(move * g(rng)), T(move * g(rng)), T(move * g(rng))));
}

/// Hull of n points on the unit sphere (ball: in the unit ball).
template <class T>
ConvexPolyhedron<T> random_hull(std::mt19937_64& rng, int n, bool ball) {
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> r01(0, 1);
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < n; ++i) {
    Vec3<double> d(g(rng), g(rng), g(rng));
    d /= d.norm();
    if (ball) d *= std::cbrt(r01(rng));
    pts.push_back(rounded_vec<T>(d));
  }
  return convex_hull(pts);
}

/// A generic pair i: hulls of 8-64 sphere or ball points, B at a random pose
/// near A.
template <class T>
std::pair<ConvexPolyhedron<T>, ConvexPolyhedron<T>> random_pair(std::mt19937_64& rng, int i) {
  const int sizes[] = {8, 12, 20, 32, 64};
  const ConvexPolyhedron<T> a = random_hull<T>(rng, sizes[i % 5], i % 3 == 0);
  const ConvexPolyhedron<T> b = random_hull<T>(rng, sizes[(i / 5) % 5], i % 4 == 0);
  return {posed(a, random_pose<T>(rng, 0.2)), posed(b, random_pose<T>(rng, 1.5))};
}

/// p scaled by 2^k (exact) and translated by t (rounded to T).
template <class T>
ConvexPolyhedron<T> scaled_moved(const ConvexPolyhedron<T>& p, int k, const Vec3<double>& t) {
  std::vector<Vec3<T>> v;
  for (const auto& q : p.vertices())
    v.emplace_back(rounded<T>(std::ldexp(double(q[0]), k) + t[0]),
                   rounded<T>(std::ldexp(double(q[1]), k) + t[1]),
                   rounded<T>(std::ldexp(double(q[2]), k) + t[2]));
  return p.with_vertices(std::move(v));
}

/// The near-degenerate pairs: each pair (A, B) in one frame.
template <class T>
std::vector<std::pair<ConvexPolyhedron<T>, ConvexPolyhedron<T>>> degenerate_pairs(std::mt19937_64& rng) {
  std::vector<std::pair<ConvexPolyhedron<T>, ConvexPolyhedron<T>>> out;
  const ConvexPolyhedron<T> cube = shapes::cube<T>(1.0);
  const ConvexPolyhedron<T> slab = shapes::box<T>(1.0, 1.0, 1e-4);
  const ConvexPolyhedron<T> prism = shapes::prism<T>(32, 1.0, 0.5);
  const ConvexPolyhedron<T> square = shapes::regular_polygon<T>(4, 1.0);
  const ConvexPolyhedron<T> hexagon = shapes::regular_polygon<T>(6, 0.7);
  const ConvexPolyhedron<T> tet = shapes::tetrahedron<T>(1.0);
  // a box with coordinates off by about 1e-7 (faces that are not quite planar
  // in T are refused: so a noisy point set, hulled)
  std::normal_distribution<double> g;
  std::vector<Vec3<T>> noisy;
  for (int i = 0; i < 8; ++i)
    for (int r = 0; r < 3; ++r)
      noisy.emplace_back(rounded<T>((i & 1 ? 1 : -1) + 1e-7 * g(rng)),
                         rounded<T>((i & 2 ? 1 : -1) + 1e-7 * g(rng)),
                         rounded<T>((i & 4 ? 1 : -1) + 1e-7 * g(rng)));
  const ConvexPolyhedron<T> noisy_box = convex_hull(noisy);
  const std::vector<ConvexPolyhedron<T>> shapes_list = {cube, slab, prism, square, hexagon, tet, noisy_box};
  // in one frame: translations that make faces and edges touch or overlap
  // exactly, and quarter turns (parallel edges)
  const Vec3<double> moves[] = {{0, 0, 2}, {2, 0, 0}, {0.5, 0.5, 1.0},
                                {1, 1, 0}, {0, 0, 0}, {0.3, -0.2, 1e-6}};
  for (std::size_t i = 0; i < shapes_list.size(); ++i) {
    for (std::size_t j = 0; j < shapes_list.size(); ++j) {
      for (const auto& m : moves) out.emplace_back(shapes_list[i], scaled_moved(shapes_list[j], 0, m));
      // a quarter turn about z and a small tilt
      out.emplace_back(shapes_list[i],
                       posed(shapes_list[j], RigidTransform<T>::from_quaternion(
                                                 std::cos(0.25 * M_PI), 0, 0, std::sin(0.25 * M_PI),
                                                 Vec3<T>(T(0.2), T(0.1), T(1.0)))));
      out.emplace_back(shapes_list[i],
                       posed(shapes_list[j],
                             RigidTransform<T>::from_quaternion(1, 1e-4, 0, 0, Vec3<T>(T(0), T(0), T(1.5)))));
    }
  }
  // scales (2^k: exact) and small shapes far from the origin
  const int ks[] = {-40, -20, 20, 60, 100};
  for (const int k : ks) {
    auto [a, b] = random_pair<T>(rng, k & 7);
    out.emplace_back(scaled_moved(a, k, {0, 0, 0}), scaled_moved(b, k, {0, 0, 0}));
    out.emplace_back(scaled_moved(cube, k, {0, 0, 0}), scaled_moved(cube, k, {std::ldexp(1.0, k + 1), 0, 0}));
  }
  for (const double far : {100.0, 1e4}) {
    auto [a, b] = random_pair<T>(rng, 3);
    out.emplace_back(scaled_moved(a, -7, {far, far, 0}), scaled_moved(b, -7, {far, far, 0.01}));
    out.emplace_back(scaled_moved(cube, -7, {far, 0, 0}), scaled_moved(cube, -7, {far + 0.015625, 0, 0}));
  }
  return out;
}

/// Every edge pair of every pair: ruled out implies the kernel's own test
/// rejects it.  make(a, b) builds the kernel.  The shapes are built in T; a
/// kernel over another (exact) type E takes them converted exactly
/// (ConvexPolyhedron<E>::convert_from).
template <class T, class E = T, class Make>
RuleOutCount check_rule_out(Make make) {
  RuleOutCount n;
  std::mt19937_64 rng(42);
  auto run = [&](const ConvexPolyhedron<T>& ta, const ConvexPolyhedron<T>& tb, bool generic) {
    const auto convert = [](const ConvexPolyhedron<T>& p) {
      if constexpr (std::is_same_v<E, T>) {
        return p;
      } else {
        return ConvexPolyhedron<E>::convert_from(p);
      }
    };
    const ConvexPolyhedron<E> a = convert(ta), b = convert(tb);
    const auto k = make(a, b);
    for (int ea = 0; ea < a.edge_count(); ++ea) {
      for (int eb = 0; eb < b.edge_count(); ++eb) {
        const bool out = k.edge_pair_ruled_out(ea, eb);
        ++n.pairs;
        n.generic_pairs += generic;
        if (!out) continue;
        ++n.ruled_out;
        n.generic_ruled_out += generic;
        if (!k.edges_parallel(ea, eb) && k.edge_separation_full(ea, eb)) ++n.unsound;
      }
    }
  };
  for (int i = 0; i < 60; ++i) {
    const auto [a, b] = random_pair<T>(rng, i);
    run(a, b, true);
  }
  for (const auto& [a, b] : degenerate_pairs<T>(rng)) {
    run(a, b, false);
    run(b, a, false);
  }
  return n;
}

}  // namespace sepax::testing
