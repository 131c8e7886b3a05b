// sepax/sat_gauss_map.hpp
//
// sat::gauss_map: the SAT of Gregorius' GDC 2013 talk.
//
// Face axes as in the brute force (a support scan per face).  Edge pairs are
// pruned by the Minkowski-face test: edge eA is the arc between its two face
// normals on A's Gauss map, edge eB the arc between the *negated* normals of
// its faces on the Gauss map of -B; the pair is a face of A - B iff the arcs
// cross (ArcSigns, sat_kernel.hpp).  A surviving, non-parallel pair is measured
// in O(1): the plane through eA with normal eA x eB, oriented away from A's
// centroid, and the height of eB above it.  Same result and tie-break as
// sat::brute_force.
#pragma once

#include "best_axis.hpp"
#include "plain_kernel.hpp"

namespace sepax::sat {

template <SatKernel K>
SatResult<typename K::FT> gauss_map_with(K& k, const SatOptions& opt = {}) {
  detail::BestAxis<K> best;
  SatStats stats;
  if (detail::scan_face_axes(k, best, stats, opt)) return best.result(k, stats, true);
  for (int ea = 0; ea < k.a().edge_count(); ++ea) {
    for (int eb = 0; eb < k.b().edge_count(); ++eb) {
      ++stats.edge_pairs;
      if (!k.arc_signs(ea, eb).minkowski_face()) continue;
      if (k.edges_parallel(ea, eb)) continue;
      ++stats.minkowski_faces;
      const auto s = k.edge_separation(ea, eb);
      const Feature feat = Feature::edges(ea, eb);
      best.consider(k, s, feat);
      if (opt.early_out && k.sign(s, feat) > 0) return best.result(k, stats, true);
    }
  }
  return best.result(k, stats, false);
}

template <class Policy = policy::Plain, Number T>
SatResult<T> gauss_map(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b,
                       const SatOptions& opt = {}) {
  kernel_t<Policy, T> k(a, b);
  return gauss_map_with(k, opt);
}

}  // namespace sepax::sat
