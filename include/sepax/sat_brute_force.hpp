// sepax/sat_brute_force.hpp
//
// sat::brute_force: the reference SAT, O(n^3).
//
// Candidate axes: every face normal of A and of B, and eA x eB for every pair
// of non-parallel edges.  Every axis is evaluated by projecting both shapes
// fully onto it (no Gauss map, no O(1) shortcut).  An edge-pair axis counts
// only when the two edges are the supporting features of A and B along it
// (A's edge at A's extreme, B's edge at B's opposite extreme): exactly then is
// eA x eB the normal of a face of the Minkowski difference A - B.  Without this
// check a separated pair would report directions that are not face normals of
// A - B, and no faster SAT could be checked against it.  The check is done by
// projection, independently of the Gauss-map arc test it verifies.  Kernels
// with edge_pair_ruled_out first rule out most pairs by the heights of two
// neighbouring vertices of each edge (float and double: in double with a
// derived bound, edge_pair_rule_out.hpp; exact types: the exact signs): the
// same pairs are kept.
#pragma once

#include "best_axis.hpp"
#include "plain_kernel.hpp"

namespace sepax::sat {

/// Run the brute-force SAT with a kernel built for (A, B).
template <SatKernel K>
SatResult<typename K::FT> brute_force_with(K& k, const SatOptions& opt = {}, const Feature* seed = nullptr) {
  check_options(opt);
  detail::BestAxis<K> best;
  SatStats stats;
  if (detail::seed_best(k, best, stats, opt, seed, false)) return best.result(k, stats, true);
  if (detail::scan_face_axes(k, best, stats, opt)) return best.result(k, stats, true);
  for (int ea = 0; ea < k.a().edge_count(); ++ea) {
    for (int eb = 0; eb < k.b().edge_count(); ++eb) {
      ++stats.edge_pairs;
      if constexpr (HasEdgePairRuledOut<K>) {
        if (k.edge_pair_ruled_out(ea, eb)) continue;  // a pair the two calls below would skip
      }
      if (k.edges_parallel(ea, eb)) continue;
      const auto s = k.edge_separation_full(ea, eb);
      if (!s) continue;
      ++stats.minkowski_faces;
      const Feature feat = Feature::edges(ea, eb);
      best.consider(k, *s, feat);
      if (stops_early(k, *s, feat, opt)) return best.result(k, stats, true);
    }
  }
  if (detail::scan_side_axes(k, best, stats, opt)) return best.result(k, stats, true);
  return best.result(k, stats, false);
}

/// Brute-force SAT of A and B (both in one frame) under a policy.
template <class Policy = policy::Plain, Number T>
SatResult<T> brute_force(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b,
                         const SatOptions& opt = {}) {
  kernel_t<Policy, T> k(a, b);
  return brute_force_with(k, opt);
}

}  // namespace sepax::sat
