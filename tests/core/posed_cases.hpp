// Test helpers for the posed queries (prepared_shape.hpp): random poses,
// shape sets, and the exact comparison of a posed result with the pre-posed
// reference (the same SAT on (A, posed(B, relative_pose(pose_a, pose_b))),
// its axis mapped to world by pose_a).
#pragma once

#include <cmath>
#include <cstring>
#include <optional>
#include <span>
#include <type_traits>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include <sepax/prepared_shape.hpp>
#include <sepax/sat.hpp>
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
  return RigidTransform<T>::from_quaternion(
      g(rng), g(rng), g(rng), g(rng),
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
  return from_integer_quaternion<T>(
      w, x, y, z,
      Vec3<T>(from_double<T>(c(rng) / 64.0), from_double<T>(c(rng) / 64.0), from_double<T>(c(rng) / 64.0)));
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
void require_same_result(const SatResult<T>& posed, const SatResult<T>& ref,
                         const RigidTransform<T>& pose_a) {
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

/// The margin pre-check of a posed query with early_out (posed_queries.hpp,
/// float/double) on the pre-posed pair (A, bp): what the posed query answers
/// before running a SAT; nullopt when it does not answer (or no early_out,
/// or exact T).
template <class Policy, Number T>
std::optional<SatResult<T>> precheck_reference(const PreparedShape<T>& a, const PreparedShape<T>& b,
                                               const RigidTransform<T>& x, const ConvexPolyhedron<T>& bp,
                                               const SatOptions& opt) {
  if constexpr (std::is_floating_point_v<T>) {
    if (opt.early_out) {
      return sat::detail::margin_precheck_with<Policy>(
          a, b, x, opt, [&](std::span<const int>) -> const ConvexPolyhedron<T>& { return bp; });
    }
  }
  return std::nullopt;
}

/// Every posed SAT against its pre-posed reference at `poses` random pose
/// pairs per pair of shapes, with and without early_out/margin (the
/// reference of an early-out query: precheck_reference, else the SAT).
template <class Policy, Number T, class PoseGen>
int check_posed_against_reference(const std::vector<ConvexPolyhedron<T>>& shapes, std::mt19937_64& rng,
                                  int poses, PoseGen&& pose) {
  std::vector<PreparedShape<T>> prepared;
  for (const auto& s : shapes) prepared.emplace_back(s);
  int checked = 0;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    for (std::size_t j = 0; j < shapes.size(); ++j) {
      for (int p = 0; p < poses; ++p) {
        const RigidTransform<T> pa = pose(rng), pb = pose(rng);
        const RigidTransform<T> x = relative_pose(pa, pb);
        const ConvexPolyhedron<T> bp = posed(shapes[j], x);
        for (const SatOptions opt : {SatOptions{}, SatOptions{true, 0.0}, SatOptions{true, 0.25}}) {
          for (SatAlgorithm alg : kSatAlgorithms) {
            INFO("shapes " << i << ", " << j << " pose " << p << " " << to_string(alg) << " early_out "
                           << opt.early_out << " margin " << opt.margin);
            const SatResult<T> r = sat::run<Policy>(alg, prepared[i], pa, prepared[j], pb, opt);
            // with early_out: the margin pre-check on the pre-posed pair, else the SAT
            const auto pre = precheck_reference<Policy>(prepared[i], prepared[j], x, bp, opt);
            const SatResult<T> ref = pre ? *pre : sat::run<Policy>(alg, shapes[i], bp, opt);
            require_same_result(r, ref, pa);
            ++checked;
          }
        }
      }
    }
  }
  return checked;
}

/// Every derived array of p bit for bit q's (vertices, planes, per-edge
/// arrays, lanes and their padding, bounds, normal_conditioning()); the 9
/// edge lane arrays only with edge_lanes (a posed B' without them:
/// PreparedShape::posed_scratch(x, false)).
template <class T>
void require_same_derived(const ConvexPolyhedron<T>& p, const ConvexPolyhedron<T>& q,
                          bool edge_lanes = true) {
  auto same = [](const auto& x, const auto& y) {
    if constexpr (number_traits<T>::is_exact)
      return x == y;
    else
      return std::memcmp(&x, &y, sizeof(x)) == 0;  // bits (signed zeros, NaN payloads)
  };
  REQUIRE(p.vertex_count() == q.vertex_count());
  REQUIRE(p.face_count() == q.face_count());
  REQUIRE(p.edge_count() == q.edge_count());
  for (int v = 0; v < p.vertex_count(); ++v) REQUIRE(same(p.vertex(v), q.vertex(v)));
  for (int f = 0; f < p.face_count(); ++f) {
    REQUIRE(same(p.plane(f).normal, q.plane(f).normal));
    REQUIRE(same(p.plane(f).offset, q.plane(f).offset));
  }
  for (int e = 0; e < p.edge_count(); ++e) {
    REQUIRE(same(p.edge_direction(e), q.edge_direction(e)));
    REQUIRE(same(p.edge_normal(e, 0), q.edge_normal(e, 0)));
    REQUIRE(same(p.edge_normal(e, 1), q.edge_normal(e, 1)));
  }
  REQUIRE(p.lanes_bounded() == q.lanes_bounded());
  REQUIRE(p.lane_edge_stride() == q.lane_edge_stride());
  REQUIRE(p.lane_vertex_stride() == q.lane_vertex_stride());
  for (int k = 0; edge_lanes && k < 9; ++k) {
    REQUIRE(std::memcmp(p.lane_edge(k), q.lane_edge(k), sizeof(T) * std::size_t(p.lane_edge_stride())) == 0);
  }
  for (int c = 0; c < 3; ++c) {
    REQUIRE(std::memcmp(p.lane_vertex(c), q.lane_vertex(c),
                        sizeof(T) * std::size_t(p.lane_vertex_stride())) == 0);
  }
  REQUIRE(same(p.centroid(), q.centroid()));
  REQUIRE(same(p.bounds_min(), q.bounds_min()));
  REQUIRE(same(p.bounds_max(), q.bounds_max()));
  REQUIRE(p.extent() == q.extent());
  REQUIRE(p.max_abs_coordinate() == q.max_abs_coordinate());
  REQUIRE(p.normal_conditioning() == q.normal_conditioning());
}

/// The reference of a cached posed query on the full pre-posed pair (A, bp),
/// bp = posed(B, x), x = relative_pose(pose_a, pose_b): sat::cache_hit, else
/// the margin pre-check (precheck_reference, unless the cache's last answer
/// was not beyond the margin; the cache takes its feature), else
/// sat::cached_run warm-started like the posed SATs.
template <class Policy, Number T>
SatResult<T> cached_reference(SatAlgorithm alg, const PreparedShape<T>& a, const PreparedShape<T>& b,
                              const RigidTransform<T>& x, const ConvexPolyhedron<T>& bp,
                              const SatOptions& opt, SatCache<T>& cache) {
  kernel_t<Policy, T> k(a.polyhedron(), bp);
  if (auto hit = sat::cache_hit(k, cache, opt)) return *hit;
  if (sat::detail::cache_says_near(&cache, opt)) {
    // no pre-check: the SAT runs
  } else if (auto pre = precheck_reference<Policy>(a, b, x, bp, opt)) {
    cache.remember(pre->feature, pre->separation);
    return *pre;
  }
  switch (alg) {
    case SatAlgorithm::brute_force:
      return sat::cached_run(k, cache, opt, [](auto& kk, const SatOptions& o, const Feature* s) {
        return sat::brute_force_with(kk, o, s);
      });
    case SatAlgorithm::traversal:
      return sat::cached_run(k, cache, opt, [&](auto& kk, const SatOptions& o, const Feature* s) {
        return sat::traversal_with(kk, a.walk(), b.walk(), o, nullptr, s);
      });
    case SatAlgorithm::gauss_map:
      break;
  }
  return sat::cached_run(k, cache, opt, [](auto& kk, const SatOptions& o, const Feature* s) {
    return sat::gauss_map_with(kk, o, s);
  });
}

/// What check_warm_against_reference saw: cache hits per feature type
/// (FeatureType order), misses with early_out, queries compared.
struct WarmCounts {
  int hits[5] = {0, 0, 0, 0, 0};
  int prechecked = 0;    // early-out answers of the margin pre-check (no cache hit)
  int early_misses = 0;  // early_out queries that ran to the full result
  int compared = 0;
};

/// On the 7 local shapes with 3 pose pairs: every query compared, and every
/// path taken (hits on a face of A, a face of B, an edge pair, margin
/// pre-check answers, misses).
inline void check_every_warm_path_taken(const WarmCounts& n) {
  CHECK(n.compared == 7 * 7 * 3 * 3 * 4 * 2);
  CHECK(n.hits[0] > 20);
  CHECK(n.hits[1] > 20);
  CHECK(n.hits[2] > 5);
  CHECK(n.prechecked > 20);
  CHECK(n.early_misses > 100);
}

/// The warm early-out path (a cache hit decided on a partial image of B',
/// posing.hpp "Staged posing") against the cached query on the full B'
/// (cached_reference): for every pair of shapes and `poses` random pose
/// pairs, a cache from the query at a nearby earlier pose and a random
/// (often non-separating, sometimes out-of-range) feature, with and
/// without early_out at several margins.  Hit or miss, cache content,
/// overlap, early_out, feature, separation and axis are bit for bit the
/// reference's (exact_fallbacks: at most the reference's, which also counts
/// the re-evaluation the query no longer repeats); after an early-out
/// answer (a hit or the margin pre-check, both on a partial image),
/// finishing the posing in the scratch gives the full B' bit for bit.
/// on_early(i, j, bp, opt, result) lets the caller check every early-out
/// answer further.
template <class Policy, Number T, class OnEarly>
WarmCounts check_warm_against_reference(const std::vector<ConvexPolyhedron<T>>& shapes, std::mt19937_64& rng,
                                        int poses, OnEarly&& on_early) {
  std::vector<PreparedShape<T>> prepared;
  for (const auto& s : shapes) prepared.emplace_back(s);
  WarmCounts n;
  std::normal_distribution<double> g;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    for (std::size_t j = 0; j < shapes.size(); ++j) {
      for (int p = 0; p < poses; ++p) {
        const RigidTransform<T> pa = random_pose<T>(rng, 1.0), pb = random_pose<T>(rng, 3.5);
        // the earlier pose: pb moved a little (a coherent step)
        const RigidTransform<T> step = RigidTransform<T>::from_quaternion(
            1.0, 0.01 * g(rng), 0.01 * g(rng), 0.01 * g(rng),
            Vec3<T>(from_double<T>(0.02 * g(rng)), from_double<T>(0.02 * g(rng)),
                    from_double<T>(0.02 * g(rng))));
        const RigidTransform<T> pb0 = pb * step;
        const RigidTransform<T> x = relative_pose(pa, pb);
        const ConvexPolyhedron<T> bp = posed(shapes[j], x);
        for (SatAlgorithm alg : kSatAlgorithms) {
          for (const SatOptions opt :
               {SatOptions{}, SatOptions{true, 0.0}, SatOptions{true, 0.02}, SatOptions{true, 0.3}}) {
            for (int source = 0; source < 2; ++source) {
              SatCache<T> cache;
              if (source == 0) {
                (void)sat::run<Policy>(alg, prepared[i], pa, prepared[j], pb0, SatOptions{}, &cache);
              } else {
                cache.valid = true;
                const int fa = shapes[i].face_count(), fb = shapes[j].face_count();
                const int ea = shapes[i].edge_count(), eb = shapes[j].edge_count();
                switch (rng() % 3) {
                  case 0:
                    cache.feature = Feature::face_a(static_cast<int>(rng() % (fa + 1)), 0);
                    break;
                  case 1:
                    cache.feature = Feature::face_b(0, static_cast<int>(rng() % (fb + 1)));
                    break;
                  default:
                    cache.feature = Feature::edges(static_cast<int>(rng() % (ea + 1)),
                                                   static_cast<int>(rng() % (eb + 1)));
                }
              }
              SatCache<T> ref_cache = cache;
              INFO("shapes " << i << ", " << j << " pose " << p << " " << to_string(alg) << " early_out "
                             << opt.early_out << " margin " << opt.margin << " cached "
                             << to_string(cache.feature));
              const SatResult<T> ref =
                  cached_reference<Policy>(alg, prepared[i], prepared[j], x, bp, opt, ref_cache);
              const SatResult<T> r = sat::run<Policy>(alg, prepared[i], pa, prepared[j], pb, opt, &cache);
              REQUIRE(cache.hits == ref_cache.hits);
              REQUIRE(cache.misses == ref_cache.misses);
              REQUIRE(cache.feature == ref_cache.feature);
              require_same_separation(cache.separation, ref_cache.separation);
              REQUIRE(r.overlap == ref.overlap);
              REQUIRE(r.early_out == ref.early_out);
              REQUIRE(r.feature == ref.feature);
              require_same_separation(r.separation, ref.separation);
              const Vec3<T> axis = pa.rotate(ref.axis);
              for (int c = 0; c < 3; ++c) REQUIRE(r.axis[c] == axis[c]);
              REQUIRE(r.stats.face_axes == ref.stats.face_axes);
              REQUIRE(r.stats.edge_pairs == ref.stats.edge_pairs);
              REQUIRE(r.stats.exact_fallbacks <= ref.stats.exact_fallbacks);
              if (r.early_out) on_early(i, j, bp, opt, r);
              if (cache.hits > 0) {
                ++n.hits[static_cast<int>(r.feature.type)];
              } else if (r.early_out) {
                ++n.prechecked;
              } else if (opt.early_out) {
                ++n.early_misses;
              }
              if (r.early_out) require_same_derived(prepared[j].posed_scratch(x), bp);
              ++n.compared;
            }
          }
        }
      }
    }
  }
  return n;
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
            INFO("shapes " << i << ", " << j << " sequence " << kind << " step " << s << " "
                           << to_string(alg));
            const auto fresh = sat::run<Policy>(alg, prepared[i], pa, prepared[j], poses[s]);
            const auto warm =
                sat::run<Policy>(alg, prepared[i], pa, prepared[j], poses[s], SatOptions{}, &full_cache);
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
