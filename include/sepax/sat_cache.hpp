// sepax/sat_cache.hpp
//
// SatCache<T>: temporal coherence for repeated SAT queries of one pair of
// shapes at nearby poses.  The cache holds the feature and separation of the
// last result; a cached query re-checks that feature first.  The cache's
// content never changes a verdict: a stale, foreign or out-of-range feature
// only costs one re-evaluation.
//
//   SatCache          the last answer's feature and separation, hit/miss counters
//   reevaluate        a cached feature at the current pose, by the kernel's predicates
//   early_out_result  the result of a query that stops at one proven feature
//   cache_hit         the early-out half: the cached feature, if it still separates
//   cached_run        the SAT half: warm-started with the cached feature
//   cached_with       cache_hit, else cached_run (any kernel); cached (a policy and T)
//
// The posed queries (posed_queries.hpp) run the early-out check on a partial
// image of B' and, after a miss, a margin pre-check whose answer the cache
// then keeps, before the SAT.
#pragma once

#include <cstdint>
#include <optional>
#include <type_traits>
#include <utility>

#include "plain_kernel.hpp"

namespace sepax {

/// One pair's cache: the last answer's feature and separation.
template <class T>
struct SatCache {
  bool valid = false;        ///< feature and separation hold an answer
  Feature feature;           ///< the last answer's feature
  Separation<T> separation;  ///< the last answer's separation
  std::int64_t hits = 0;     ///< early-out queries answered by the cached feature
  std::int64_t misses = 0;   ///< queries that ran the SAT

  /// Forget the answer and the counters.
  void reset() { *this = SatCache{}; }
  /// Keep an answer's feature and separation (the next query re-checks it).
  void remember(const Feature& f, const Separation<T>& s) {
    valid = true;
    feature = f;
    separation = s;
  }
};

namespace sat {

/// The cached feature re-evaluated at the current pose with the same kernel
/// predicates every SAT uses for that feature:
///   FaceA(f, _)   k.face_query_a(f)  (support vertex re-found, lowest index
///                                     among the exactly deepest)
///   FaceB(_, g)   k.face_query_b(g)
///   EdgePair      still a Minkowski face (k.arc_signs strict) and not
///                 parallel (k.edges_parallel), then k.edge_separation
///   SideA/SideB   k.side_query_a / k.side_query_b (both shapes flat)
/// nullopt if its indices are out of range (ignored) or an edge pair is no
/// longer a non-parallel Minkowski face.
template <SatKernel K>
std::optional<std::pair<Feature, Separation<typename K::FT>>> reevaluate(K& k, const Feature& f) {
  using T = typename K::FT;
  switch (f.type) {
    case FeatureType::FaceA: {
      if (f.a < 0 || f.a >= k.a().face_count()) return std::nullopt;
      const auto q = k.face_query_a(f.a);
      return std::pair<Feature, Separation<T>>{Feature::face_a(f.a, q.support_vertex), q.separation};
    }
    case FeatureType::FaceB: {
      if (f.b < 0 || f.b >= k.b().face_count()) return std::nullopt;
      const auto q = k.face_query_b(f.b);
      return std::pair<Feature, Separation<T>>{Feature::face_b(q.support_vertex, f.b), q.separation};
    }
    case FeatureType::EdgePair: {
      if (f.a < 0 || f.a >= k.a().edge_count() || f.b < 0 || f.b >= k.b().edge_count()) return std::nullopt;
      if (!k.arc_signs(f.a, f.b).minkowski_face() || k.edges_parallel(f.a, f.b)) return std::nullopt;
      return std::pair<Feature, Separation<T>>{f, k.edge_separation(f.a, f.b)};
    }
    case FeatureType::SideA: {
      if (f.a < 0 || f.a >= k.a().edge_count() || !(k.a().is_flat() && k.b().is_flat())) return std::nullopt;
      const auto q = k.side_query_a(f.a);
      return std::pair<Feature, Separation<T>>{Feature::side_a(f.a, q.support_vertex), q.separation};
    }
    case FeatureType::SideB: {
      if (f.b < 0 || f.b >= k.b().edge_count() || !(k.a().is_flat() && k.b().is_flat())) return std::nullopt;
      const auto q = k.side_query_b(f.b);
      return std::pair<Feature, Separation<T>>{Feature::side_b(q.support_vertex, f.b), q.separation};
    }
  }
  return std::nullopt;
}

/// The result of a query that stops at one feature f, evaluated by k with
/// separation s proven beyond the margin (stops_early): separated, early_out,
/// axis k.axis(f), stats counting f and k's exact fallbacks.
template <SatKernel K>
SatResult<typename K::FT> early_out_result(const K& k, const Feature& f,
                                           const Separation<typename K::FT>& s) {
  SatResult<typename K::FT> r;
  r.overlap = false;
  r.feature = f;
  r.separation = s;
  r.axis = k.axis(f);
  r.early_out = true;
  const FeatureType ty = f.type;
  r.stats.face_axes = ty == FeatureType::FaceA || ty == FeatureType::FaceB ? 1 : 0;
  r.stats.edge_pairs = ty == FeatureType::EdgePair ? 1 : 0;
  r.stats.side_axes = ty == FeatureType::SideA || ty == FeatureType::SideB ? 1 : 0;
  r.stats.minkowski_faces = r.stats.edge_pairs;
  r.stats.exact_fallbacks = k.exact_fallbacks();
  return r;
}

/// The early-out half of a cached query: with opt.early_out and a valid
/// cache, the cached feature re-evaluated with k; if it separates beyond the
/// margin (k.sign > 0), the hit's result (and the cache updated, hits
/// counted), else nullopt (the cache untouched).  A hit is overlap = false,
/// early_out = true, the re-evaluated feature, exactly the separation the SATs
/// compute for that feature at this pose, axis = k.axis(feature): the
/// early_out contract of SatOptions (a separating axis, not necessarily the
/// one of maximum separation; the verdict is always the fresh one).  The
/// kernel need only answer for that feature: the posed queries build it on a
/// partial image of B (posing.hpp, "Staged posing").
template <SatKernel K>
std::optional<SatResult<typename K::FT>> cache_hit(K& k, SatCache<typename K::FT>& cache,
                                                   const SatOptions& opt) {
  using T = typename K::FT;
  if (!opt.early_out || !cache.valid) return std::nullopt;
  const auto ev = reevaluate(k, cache.feature);
  if (!ev || !stops_early(k, ev->second, ev->first, opt)) return std::nullopt;
  SatResult<T> r = early_out_result(k, ev->first, ev->second);
  cache.remember(r.feature, r.separation);
  ++cache.hits;
  return r;
}

/// The SAT half of a cached query: run, the cache set to its result, misses
/// counted.  Without early_out the result is exactly what the SAT returns on
/// its own.  Warm start: when run takes a seed (the posed queries;
/// sat::gauss_map_with, brute_force_with and traversal_with have the
/// parameter), the cached feature is its first candidate: a candidate the SAT
/// evaluates anyway, with the same value, so the result (feature, separation,
/// verdict) is the fresh one, while every pruning test starts from a strong
/// best.  Not for the plain float/double traversal, whose climb in rounding
/// arithmetic need not reproduce a seed's full-scan value.  With early_out,
/// after a miss the SAT's result is returned unchanged (for overlapping
/// shapes exactly the fresh one, feature and separation included).
template <SatKernel K, class Run>
SatResult<typename K::FT> cached_run(K& k, SatCache<typename K::FT>& cache, const SatOptions& opt,
                                     Run&& run) {
  SatResult<typename K::FT> r;
  if constexpr (std::is_invocable_v<Run&, K&, const SatOptions&, const Feature*>) {
    // warm start: the cached feature is the SAT's first candidate
    r = run(k, opt, cache.valid ? &cache.feature : nullptr);
  } else {
    r = run(k, opt);
  }
  cache.remember(r.feature, r.separation);
  ++cache.misses;
  return r;
}

/// Cached query with a kernel built for (A, B): cache_hit, else cached_run.
/// run(k, opt) runs the SAT, e.g.
/// [](auto& k, const SatOptions& o) { return sat::gauss_map_with(k, o); }.
/// When run also takes a seed, run(k, opt, const Feature* seed), the SAT is
/// warm-started: the cached feature is passed as its first candidate (see
/// cached_run).
template <SatKernel K, class Run>
SatResult<typename K::FT> cached_with(K& k, SatCache<typename K::FT>& cache, const SatOptions& opt,
                                      Run&& run) {
  if (auto hit = cache_hit(k, cache, opt)) return *hit;
  return cached_run(k, cache, opt, std::forward<Run>(run));
}

/// Cached query of A and B under a policy; run as for cached_with.
template <class Policy = policy::Plain, Number T, class Run>
SatResult<T> cached(SatCache<T>& cache, const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b, Run&& run,
                    const SatOptions& opt = {}) {
  kernel_t<Policy, T> k(a, b);
  return cached_with(k, cache, opt, std::forward<Run>(run));
}

}  // namespace sat
}  // namespace sepax
