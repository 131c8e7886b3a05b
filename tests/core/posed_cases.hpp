// Test helpers for the posed queries (prepared_shape.hpp): random poses,
// shape sets, and the exact comparison of a posed result with the pre-posed
// reference (the same SAT on (A, posed(B, relative_pose(pose_a, pose_b))),
// its axis mapped to world by pose_a).
#pragma once

#include <cmath>
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

/// A coherent pose sequence of B relative to a fixed A (identity): kind 0
/// resting (B on A, small jitter), 1 sliding (B pushed along x across A),
/// 2 rolling (B turning about y while moving along x), `steps` poses with a
/// small change each.
template <Number T>
std::vector<RigidTransform<T>> pose_sequence(int kind, int steps, double height) {
  std::vector<RigidTransform<T>> out;
  for (int s = 0; s < steps; ++s) {
    const double u = static_cast<double>(s) / steps;
    double w = 1, x = 0, y = 0, z = 0;
    Vec3<double> t(0, 0, height);
    if (kind == 0) {
      z = 0.01 * std::sin(7.0 * u);
      t = Vec3<double>(0.002 * std::cos(11.0 * u), 0.001 * (s % 3), height - 0.003 * std::sin(5.0 * u));
    } else if (kind == 1) {
      z = 0.2;
      t = Vec3<double>(-1.0 + 2.0 * u, 0.1, height);
    } else {
      y = std::sin(0.5 * 3.0 * u);
      w = std::cos(0.5 * 3.0 * u);
      t = Vec3<double>(-0.8 + 1.6 * u, 0.0, height);
    }
    out.push_back(RigidTransform<T>::from_quaternion(
        w, x, y, z, Vec3<T>(from_double<T>(t[0]), from_double<T>(t[1]), from_double<T>(t[2]))));
  }
  return out;
}

/// Along every sequence and pair of shapes: the cached (warm) posed query
/// returns the fresh one's feature, separation (bit for bit) and verdict
/// (full queries), and the fresh verdict with a separation beyond the margin
/// (early-out queries).  Returns the number of queries compared.
template <class Policy, Number T>
int check_warm_sequences(const std::vector<ConvexPolyhedron<T>>& shapes, int steps) {
  std::vector<PreparedShape<T>> prepared;
  for (const auto& s : shapes) prepared.emplace_back(s);
  const RigidTransform<T> pa;
  int compared = 0;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    for (std::size_t j = 0; j < shapes.size(); ++j) {
      for (int kind = 0; kind < 3; ++kind) {
        const auto poses = pose_sequence<T>(kind, steps, 0.9);
        for (SatAlgorithm alg : kSatAlgorithms) {
          SatCache<T> full_cache, early_cache;
          SatOptions early;
          early.early_out = true;
          early.margin = 0.02;
          for (std::size_t s = 0; s < poses.size(); ++s) {
            INFO("shapes " << i << ", " << j << " sequence " << kind << " step " << s << " " << to_string(alg));
            const auto fresh = sat::run<Policy>(alg, prepared[i], pa, prepared[j], poses[s]);
            const auto warm = sat::run<Policy>(alg, prepared[i], pa, prepared[j], poses[s], SatOptions{}, &full_cache);
            REQUIRE(warm.feature == fresh.feature);
            require_same_separation(warm.separation, fresh.separation);
            REQUIRE(warm.overlap == fresh.overlap);
            const auto e = sat::run<Policy>(alg, prepared[i], pa, prepared[j], poses[s], early, &early_cache);
            REQUIRE(e.overlap == fresh.overlap);
            if (e.early_out) {
              REQUIRE(compare(e.separation, Separation<T>{from_double<T>(early.margin), T(1)}) > 0);
            } else {
              REQUIRE(e.feature == fresh.feature);
              require_same_separation(e.separation, fresh.separation);
            }
            ++compared;
          }
        }
      }
    }
  }
  return compared;
}

}  // namespace sepax::test
