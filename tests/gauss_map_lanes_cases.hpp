// The Gauss map's SIMD paths (simd_lanes.hpp, ConvexPolyhedron's lane arrays,
// PlainKernel::minkowski_faces and the lane support scan) against the scalar
// code they replace, pair by pair and face by face.  Included by
// core/sat_gauss_map_lanes_test.cpp (SSE2) and core/sat_gauss_map_nosimd_test.cpp
// (SEPAX_NO_SIMD: the one-lane fallback), so both code paths are checked.
#pragma once

#include <catch2/catch.hpp>

#include <bit>
#include <cstring>
#include <random>
#include <set>
#include <vector>

#include <sepax/plain_kernel.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/shapes.hpp>

#include "sat_cases.hpp"
#include "traversal_shapes.hpp"

namespace sepax::test::lanes {

template <class T>
bool same_bits(T x, T y) {
  return std::memcmp(&x, &y, sizeof(T)) == 0;
}

/// PlainKernel without the batched member: gauss_map_with then takes the
/// scalar minkowski_face scan (HasMinkowskiFaces is false for it).
template <class T>
struct ScalarArcKernel : PlainKernel<T> {
  using PlainKernel<T>::PlainKernel;
  int minkowski_faces(int, int, int, int*) const = delete;
};

/// Shape pairs: the zoo posed at random (partial lane groups: 6, 9, 12, 18
/// edges), sphere hulls of 8 to 100 points (E up to 294 > kMinkowskiBatch: two
/// batches), and exactly touching boxes (many arc products exactly zero).
template <class T>
std::vector<std::pair<ConvexPolyhedron<T>, ConvexPolyhedron<T>>> pairs() {
  std::vector<std::pair<ConvexPolyhedron<T>, ConvexPolyhedron<T>>> out;
  const auto z = zoo<T>();
  std::mt19937 rng(4242);
  for (int i = 0; i < 60; ++i) {
    out.emplace_back(apply_pose(z[static_cast<std::size_t>(i) % z.size()], random_pose(rng, 8)),
                     apply_pose(z[static_cast<std::size_t>(i / 7) % z.size()], random_pose(rng, 8)));
  }
  std::mt19937_64 rng64(99);
  for (int n : {8, 13, 32, 64, 100}) {
    const auto a = sphere_hull(rng64, n);
    const auto b = moved(sphere_hull(rng64, n, 0.8), random_rotation(rng64), V3(0.4, -0.3, 0.2));
    out.emplace_back(ConvexPolyhedron<T>::convert_from(a), ConvexPolyhedron<T>::convert_from(b));
  }
  const auto box = shapes::box<T>(1, 1, 1);
  for (double x : {0.0, 1.0, 2.0}) {
    for (double y : {0.0, 1.0, 2.0}) {
      out.emplace_back(box, translated(shapes::box<T>(0.5, 1, 0.75), v3<T>(x, y, 2.0)));
    }
  }
  return out;
}

template <class T>
void check_lane_arrays(const ConvexPolyhedron<T>& p) {
  const int se = p.lane_edge_stride(), sv = p.lane_vertex_stride();
  REQUIRE(se % ConvexPolyhedron<T>::kLanePad == 0);
  REQUIRE(sv % ConvexPolyhedron<T>::kLanePad == 0);
  REQUIRE(se >= p.edge_count());
  REQUIRE(sv >= p.vertex_count());
  int wrong = 0;
  for (int e = 0; e < se; ++e) {
    for (int c = 0; c < 3; ++c) {
      const bool pad = e >= p.edge_count();
      const auto i = static_cast<std::size_t>(e);
      wrong += !same_bits(p.lane_edge(c)[i], pad ? T(0) : p.edge_normal(e, 0)[c]);
      wrong += !same_bits(p.lane_edge(3 + c)[i], pad ? T(0) : T(-p.edge_normal(e, 1)[c]));
      wrong += !same_bits(p.lane_edge(6 + c)[i], pad ? T(0) : p.edge_direction(e)[c]);
    }
  }
  for (int v = 0; v < p.vertex_count(); ++v) {
    for (int c = 0; c < 3; ++c)
      wrong += !same_bits(p.lane_vertex(c)[static_cast<std::size_t>(v)], p.vertex(v)[c]);
  }
  CHECK(wrong == 0);
}

/// Every pair: the batched test (in the batches gauss_map_with uses) accepts
/// exactly the eb the scalar arc_signs accepts.  Returns the accepted count.
template <class T>
long check_arc_pairs(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b) {
  const PlainKernel<T> k(a, b);
  long accepted = 0;
  int found[kMinkowskiBatch];
  for (int ea = 0; ea < a.edge_count(); ++ea) {
    std::vector<int> batched, scalar;
    for (int lo = 0; lo < b.edge_count(); lo += kMinkowskiBatch) {
      const int n = k.minkowski_faces(ea, lo, std::min(b.edge_count(), lo + kMinkowskiBatch), found);
      batched.insert(batched.end(), found, found + n);
    }
    int short_circuit_differs = 0;
    for (int eb = 0; eb < b.edge_count(); ++eb) {
      const bool s = k.arc_signs(ea, eb).minkowski_face();
      short_circuit_differs += s != k.minkowski_face(ea, eb);
      if (s) scalar.push_back(eb);
    }
    CHECK(short_circuit_differs == 0);
    INFO("ea " << ea << " of " << a.edge_count() << ", E_B " << b.edge_count());
    CHECK(batched == scalar);
    accepted += static_cast<long>(scalar.size());
  }
  return accepted;
}

/// Every face: the kernel's face query (lane scan from 8 vertices on) finds
/// the vertex and the value of the scalar loop (first index of the minimum).
template <class T>
void check_face_queries(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b) {
  const PlainKernel<T> k(a, b);
  auto scalar = [](const ConvexPolyhedron<T>& p, int f, const ConvexPolyhedron<T>& q) {
    int best = 0;
    T h = dot(p.plane(f).normal, q.vertex(0));
    for (int i = 1; i < q.vertex_count(); ++i) {
      const T g = dot(p.plane(f).normal, q.vertex(i));
      if (g < h) {
        h = g;
        best = i;
      }
    }
    return std::pair<int, T>(best, T(h - p.plane(f).offset));
  };
  for (int f = 0; f < a.face_count(); ++f) {
    const auto q = k.face_query_a(f);
    const auto [v, h] = scalar(a, f, b);
    CHECK(q.support_vertex == v);
    CHECK(same_bits(q.separation.num, h));
  }
  for (int f = 0; f < b.face_count(); ++f) {
    const auto q = k.face_query_b(f);
    const auto [v, h] = scalar(b, f, a);
    CHECK(q.support_vertex == v);
    CHECK(same_bits(q.separation.num, h));
  }
}

template <class T>
void check_same_result(const SatResult<T>& x, const SatResult<T>& y) {
  CHECK(x.feature == y.feature);
  CHECK(x.overlap == y.overlap);
  CHECK(same_bits(x.separation.num, y.separation.num));
  CHECK(x.early_out == y.early_out);
  CHECK(x.stats.edge_pairs == y.stats.edge_pairs);
  CHECK(x.stats.minkowski_faces == y.stats.minkowski_faces);
}

template <class T>
void run_all() {
  long accepted = 0;
  int huge = 0;
  auto all = pairs<T>();
  // coordinates beyond 2^60: no lane arrays are used (scalar fallbacks)
  const auto big = scaled(shapes::box<T>(1, 0.5, 0.75), T(1e20), v3<T>(0, 0, 0));
  const auto big2 = scaled(shapes::prism<T>(6, 1.0, 0.5), T(1e20), v3<T>(0.25e20, 0, 0.5e20));
  all.emplace_back(big, big2);
  for (const auto& [a, b] : all) {
    INFO("E_A " << a.edge_count() << " E_B " << b.edge_count());
    if (!a.lanes_bounded()) ++huge;
    check_lane_arrays(a);
    check_lane_arrays(b);
    accepted += check_arc_pairs(a, b);
    check_face_queries(a, b);
    ScalarArcKernel<T> ks(a, b);
    for (bool early : {false, true}) {
      const auto r = sat::gauss_map(a, b, SatOptions{early});
      check_same_result(r, sat::gauss_map_with(ks, SatOptions{early}));
    }
  }
  CHECK(huge == 1);
  CHECK(accepted > 1000);
}

}  // namespace sepax::test::lanes
