// sepax/sat_gauss_map.hpp
//
// sat::gauss_map: the SAT of Gregorius' GDC 2013 talk.
//
// Face axes as in the brute force (a support scan per face).  Edge pairs are
// pruned by the Minkowski-face test: edge eA is the arc between its two face
// normals on A's Gauss map, edge eB the arc between the *negated* normals of
// its faces on the Gauss map of -B; the pair is a face of A - B iff the arcs
// cross (ArcSigns, sat_kernel.hpp).  The kernel decides it with its batched
// minkowski_faces when it has one (one edge of A against up to
// kMinkowskiBatch edges of B, SIMD over B's lane arrays), else with its
// short-circuit minkowski_face, else with arc_signs.  A surviving,
// non-parallel pair is measured in O(1): the plane through eA with normal
// eA x eB, oriented away from A's centroid, and the height of eB above it.
// Same result and tie-break as sat::brute_force.
#pragma once

#include <algorithm>

#include "best_axis.hpp"
#include "plain_kernel.hpp"

namespace sepax::sat {

template <SatKernel K>
SatResult<typename K::FT> gauss_map_with(K& k, const SatOptions& opt = {}, const Feature* seed = nullptr) {
  check_options(opt);
  detail::BestAxis<K> best;
  SatStats stats;
  if (detail::seed_best(k, best, stats, opt, seed, true)) return best.result(k, stats, true);
  if (detail::scan_face_axes(k, best, stats, opt)) return best.result(k, stats, true);
  const int na = k.a().edge_count(), nb = k.b().edge_count();
  // A pair whose arcs cross: measure it.  True to stop (early out).
  auto visit = [&](int ea, int cur) {
    if constexpr (HasEdgePairBelow<K>) {
      // certainly below the best: consider would reject it (best_axis.hpp)
      if (best.pair_certainly_below(k, ea, cur)) {
        ++stats.minkowski_faces;
        return false;
      }
    }
    if (k.edges_parallel(ea, cur)) return false;
    ++stats.minkowski_faces;
    const auto s = k.edge_separation(ea, cur);
    const Feature feat = Feature::edges(ea, cur);
    best.consider(k, s, feat);
    if (stops_early(k, s, feat, opt)) {
      stats.edge_pairs += cur + 1;  // this row's pairs looked at so far (earlier rows: below)
      return true;
    }
    return false;
  };
  for (int ea = 0; ea < na; ++ea) {
    if constexpr (HasMinkowskiFaces<K>) {
      // The kernel tests eA against a batch of B's edges at once.
      int found[kMinkowskiBatch];
      for (int lo = 0; lo < nb; lo += kMinkowskiBatch) {
        const int n = k.minkowski_faces(ea, lo, std::min(nb, lo + kMinkowskiBatch), found);
        for (int i = 0; i < n; ++i) {
          if (visit(ea, found[i])) return best.result(k, stats, true);
        }
      }
    } else {
      int eb = 0;
      while (eb < nb) {
        // Tight scan to the next pair whose arcs cross (the common pair is
        // rejected here).  Written with the test first and the bound check
        // last, so the test's loads of eA's data run on every iteration: with
        // PlainKernel (no stores, no calls on this path) the compiler hoists
        // them out of the scan.
        if constexpr (HasMinkowskiFace<K>) {
          while (!k.minkowski_face(ea, eb) && ++eb < nb) {
          }
        } else {
          while (!k.arc_signs(ea, eb).minkowski_face() && ++eb < nb) {
          }
        }
        if (eb == nb) break;
        if (visit(ea, eb++)) return best.result(k, stats, true);
      }
    }
    stats.edge_pairs += nb;
  }
  if (detail::scan_side_axes(k, best, stats, opt)) return best.result(k, stats, true);
  return best.result(k, stats, false);
}

template <class Policy = policy::Plain, Number T>
SatResult<T> gauss_map(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b,
                       const SatOptions& opt = {}) {
  kernel_t<Policy, T> k(a, b);
  return gauss_map_with(k, opt);
}

}  // namespace sepax::sat
