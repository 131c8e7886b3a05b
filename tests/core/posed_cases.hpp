// Test helpers for the posed queries (prepared_shape.hpp): random poses,
// shape sets, and the exact comparison of a posed result with the pre-posed
// reference (the same SAT on (A, posed(B, relative_pose(pose_a, pose_b))),
// its axis mapped to world by pose_a).
#pragma once

#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include <sepax/prepared_shape.hpp>
#include <sepax/shapes.hpp>

#include "traversal_shapes.hpp"

namespace sepax::test {

/// A random pose: a random unit quaternion (normalised in double by
/// from_quaternion) and a translation of length up to `reach`.
template <Number T>
RigidTransform<T> random_pose(std::mt19937_64& rng, double reach) {
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0.0, reach);
  const V3 t = u(rng) * random_unit(rng);
  return RigidTransform<T>::from_quaternion(g(rng), g(rng), g(rng), g(rng),
                                            Vec3<T>(from_double<T>(t[0]), from_double<T>(t[1]), from_double<T>(t[2])));
}

/// A random exact-rational pose (integer quaternion, dyadic translation).
template <Number T>
RigidTransform<T> random_integer_pose(std::mt19937_64& rng, double reach) {
  std::uniform_int_distribution<long> q(-9, 9);
  long w, x, y, z;
  do {
    w = q(rng), x = q(rng), y = q(rng), z = q(rng);
  } while (w == 0 && x == 0 && y == 0 && z == 0);
  std::uniform_int_distribution<int> c(-static_cast<int>(reach * 64), static_cast<int>(reach * 64));
  return from_integer_quaternion<T>(w, x, y, z,
                                    Vec3<T>(from_double<T>(c(rng) / 64.0), from_double<T>(c(rng) / 64.0),
                                            from_double<T>(c(rng) / 64.0)));
}

/// Local shapes of every kind the SATs see: sphere hulls, boxes, a prism
/// (high-valence caps), a tetrahedron and a flat polygon.
template <Number T>
std::vector<ConvexPolyhedron<T>> local_shapes(std::mt19937_64& rng) {
  std::vector<ConvexPolyhedron<T>> out;
  for (int n : {8, 16, 32}) out.push_back(ConvexPolyhedron<T>::convert_from(large_sphere_hull(rng, n)));
  out.push_back(shapes::box<T>(0.5, 0.25, 1.0));
  out.push_back(shapes::prism<T>(12, 0.8, 0.5));
  out.push_back(shapes::tetrahedron<T>(0.9));
  out.push_back(shapes::regular_polygon<T>(6, 0.7));
  return out;
}

template <class T>
void require_same_separation(const Separation<T>& x, const Separation<T>& y) {
  REQUIRE(x.num == y.num);
  REQUIRE(x.norm2 == y.norm2);
}

/// posed == reference (the pre-posed SAT's result with its axis mapped by
/// pose_a), every field bit for bit.
template <class T>
void require_same_result(const SatResult<T>& posed, const SatResult<T>& ref, const RigidTransform<T>& pose_a) {
  REQUIRE(posed.overlap == ref.overlap);
  REQUIRE(posed.feature == ref.feature);
  require_same_separation(posed.separation, ref.separation);
  REQUIRE(posed.early_out == ref.early_out);
  const Vec3<T> axis = pose_a.rotate(ref.axis);
  for (int c = 0; c < 3; ++c) REQUIRE(posed.axis[c] == axis[c]);
  REQUIRE(posed.stats.face_axes == ref.stats.face_axes);
  REQUIRE(posed.stats.edge_pairs == ref.stats.edge_pairs);
  REQUIRE(posed.stats.minkowski_faces == ref.stats.minkowski_faces);
  REQUIRE(posed.stats.exact_fallbacks == ref.stats.exact_fallbacks);
}

/// Every posed SAT against its pre-posed reference at `poses` random pose
/// pairs per pair of shapes, with and without early_out/margin.
template <class Policy, Number T, class PoseGen>
int check_posed_against_reference(const std::vector<ConvexPolyhedron<T>>& shapes, std::mt19937_64& rng, int poses,
                                  PoseGen&& pose) {
  std::vector<PreparedShape<T>> prepared;
  for (const auto& s : shapes) prepared.emplace_back(s);
  int checked = 0;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    for (std::size_t j = 0; j < shapes.size(); ++j) {
      for (int p = 0; p < poses; ++p) {
        const RigidTransform<T> pa = pose(rng), pb = pose(rng);
        const ConvexPolyhedron<T> bp = posed(shapes[j], relative_pose(pa, pb));
        for (const SatOptions opt : {SatOptions{}, SatOptions{true, 0.0}, SatOptions{true, 0.25}}) {
          for (SatAlgorithm alg : kSatAlgorithms) {
            INFO("shapes " << i << ", " << j << " pose " << p << " " << to_string(alg) << " early_out "
                           << opt.early_out << " margin " << opt.margin);
            const SatResult<T> r = sat::run<Policy>(alg, prepared[i], pa, prepared[j], pb, opt);
            const SatResult<T> ref = sat::run<Policy>(alg, shapes[i], bp, opt);
            require_same_result(r, ref, pa);
            ++checked;
          }
        }
      }
    }
  }
  return checked;
}

}  // namespace sepax::test
