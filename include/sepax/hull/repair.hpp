// sepax/hull/repair.hpp
//
// The whole build (Builder::run):
//   1. welding (welded_points.hpp);
//   2. build passes: build, then the points the clean-up rejects taken out of the triangles (float, large
//      hulls: remove_vertices, vertex_removal.hpp) or the hull rebuilt without them, until a hull validates;
//   3. float T: every point that is not a vertex is measured against the result (outside_points); points
//      more than kHullRepairTolerance x eps out are pinned and put back, and the hull rebuilt (from the last
//      pass's quickhull triangles when they can take the pinned points, resume), for at most
//      kHullMaxRepairs repair passes, keeping the best result, and no more once a pass repeats the one
//      before (the same result, digest, the same points taken out by the clean-up at its end, leaving out
//      only points already pinned: Builder::repeats);
//   4. float T: the fallback policy (fallbacks.hpp) when no pass keeps every point within that tolerance.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "../convex_polyhedron.hpp"
#include "../error.hpp"
#include "../number_traits.hpp"
#include "../tolerances.hpp"
#include "builder.hpp"
#include "fallbacks.hpp"
#include "hull_distance.hpp"
#include "plane_tree.hpp"
#include "quickhull.hpp"
#include "radix_sort.hpp"
#include "vertex_removal.hpp"

namespace sepax::hull::detail {

/// Build, then take the points the clean-up rejects out of the triangles and go on from there
/// (remove_vertices), or when they cannot be, rebuild without them, until a hull validates.  A pass after the
/// first (may_fail) may reject points until the rest is Collinear or too few: it then returns none, and the
/// best earlier pass is kept.  A repair pass (float T) first offers the points it pinned to the previous
/// pass's triangles (resume); it builds from the start when they cannot take them.
template <Number T>
inline std::optional<ConvexPolyhedron<T>> Builder<T>::build_pass(bool may_fail,
                                                                 const std::vector<int>& pinned) {
  try {
    std::optional<ConvexPolyhedron<T>> result;
    std::vector<int> reject;
    if (!pinned.empty()) result = resume(pinned, reject);
    bool built = result || !reject.empty();  // (none with reject empty: the triangles could not resume)
    if (tris_state_ == TrisState::solid_result) tris_state_ = TrisState::solid_build;
    for (;;) {
      if (!built) {
        std::vector<int> active;
        for (std::size_t i = 0; i < pts_.size(); ++i)
          if (!removed_[i]) active.push_back(static_cast<int>(i));
        result = build(active, reject);
      }
      built = false;
      // the clean-up's rejects out of the triangles where they can be (remove_vertices), else the next
      // build starts over without them
      // (a surface validation refuses after a removal: the build starts over without the removed points,
      // and so does every later clean-up of this hull)
      while (!result && !reject.empty()) {
        for (int r : reject) removed_[as_index(r)] = 1;
        if (!remove_vertices(reject)) break;
        reject.clear();
        result = faces_of_local_surface(reject);
      }
      if (result) {
        if (!result->is_flat()) tris_state_ = TrisState::solid_result;  // (a flat one is polygon's: none)
        return result;
      }
      if (local_surface_failed_) {
        local_surface_failed_ = false;
        local_removal_refused_ = true;
        tris_state_ = TrisState::none;
        continue;
      }
      if (reject.empty()) throw std::logic_error("convex_hull: clean-up made no progress (a bug)");
      reject.clear();
    }
  } catch (const InvalidInput&) {
    if (!may_fail) throw;
    return std::nullopt;
  }
}

/// Float T, a repair pass: the previous pass's quickhull triangles (its result's, every conflict list
/// empty) take the points just pinned, instead of a build from the start: each is taken off the face it
/// was kept on and put on the conflict list of the first live face it is above (its threshold is 0 now,
/// as in a build from the start), and quickhull goes on from there (eyes, sweep), then the face stage.
/// The result is measured like any pass's.  None with reject empty when the triangles cannot take the
/// points (the last result flat; a pinned point a vertex of the triangles, or above none of them; more
/// points x faces than kHullResumeScanPairs to search): the pass then builds from the start.  None with
/// reject filled when the clean-up rejects points: the pass builds from the start without them.
template <Number T>
inline std::optional<ConvexPolyhedron<T>> Builder<T>::resume(const std::vector<int>& pinned,
                                                             std::vector<int>& reject) {
  if constexpr (!Traits::kRepairs) {
    return std::nullopt;
  } else {
    if (tris_state_ != TrisState::solid_result) return std::nullopt;
    tris_state_ = TrisState::solid_build;
    std::vector<char> mark(welded_count(), 0);  // 1: pinned now; 2: a vertex of a live triangle
    std::size_t live = 0;
    for (const Tri& t : tris_) {
      if (!t.alive) continue;
      ++live;
      for (int v : t.v) mark[as_index(v)] = 2;
    }
    if (static_cast<double>(pinned.size()) * static_cast<double>(live) > kHullResumeScanPairs)
      return std::nullopt;
    for (int p : pinned) {
      if (mark[as_index(p)] == 2) return std::nullopt;
      mark[as_index(p)] = 1;
    }
    for (Tri& t : tris_)
      if (t.alive) std::erase_if(t.on, [&](int p) { return mark[as_index(p)] == 1; });
    for (int p : pinned) {
      typename Traits::NearFace near;
      if (!conflict_among(p, FaceIndexRange{0, static_cast<int>(tris_.size())},
                          Traits::outside_limit(*this, p), near))
        return std::nullopt;  // (the build from the start resets the triangles)
    }
    eye_visits_.assign(welded_count(), 0);  // (kHullMaxEyeVisits counts within one pass)
    active_.insert(active_.end(), pinned.begin(), pinned.end());
    std::sort(active_.begin(), active_.end());
    active_.erase(std::unique(active_.begin(), active_.end()), active_.end());
    std::optional<ConvexPolyhedron<T>> result = faces_of_local_surface(reject);
    if (local_surface_failed_) {  // (none with reject empty: the pass builds from the start)
      local_surface_failed_ = false;
      tris_state_ = TrisState::none;
      return std::nullopt;
    }
    if (result && !result->is_flat()) tris_state_ = TrisState::solid_result;
    return result;
  }
}

/// Float T: measures every point against a pass's result (outside_points) and keeps the result in log if it
/// is nearer every point, or lower, than the results before; outside receives the points farther than
/// kHullRepairTolerance x eps.  Returns the result's digest when outside is not empty (a repair pass may
/// follow, and build_hull compares the digests of consecutive passes), else 0 (no hash taken).
template <Number T>
inline std::uint64_t Builder<T>::measure(ConvexPolyhedron<T> result, std::vector<int>& outside,
                                         RepairLog<T>& log) {
  double height = 0;
  const double out = outside_points(result, outside, height);
  const std::uint64_t d = outside.empty() ? 0 : digest(result);
  const bool is_lowest = !log.has_lowest() || height < log.lowest_height;
  if (!log.nearest || out < log.nearest_out) {
    log.set_nearest(std::move(result), out, height);
    if (is_lowest) {  // (one result, held once)
      log.lowest.reset();
      log.lowest_is_nearest = true;
      log.lowest_height = height;
    }
  } else if (is_lowest) {
    log.lowest = std::move(result);
    log.lowest_is_nearest = false;
    log.lowest_height = height;
  }
  return d;
}

/// Float T: the points a repair pass puts back, pinned: each becomes a vertex whenever it is above the hull
/// at all, and is rejected by the clean-up only when nothing else can be.
template <Number T>
inline void Builder<T>::pin(const std::vector<int>& outside) {
  removed_at_pin_ = removed_hash();
  any_pinned_ = true;
  for (int p : outside) {
    removed_[as_index(p)] = 0;
    pinned_[as_index(p)] = 1;
  }
}

/// Float T: whether the pass just measured (after a repair pass, before pin) repeats the one before: the
/// same result (its digest equal to the last pass's), the same points taken out by the clean-up at its end
/// as at the end of the last pass (removed_hash), and no point outside it that an earlier pass did not
/// pin.  The next pass then starts with the pinned and removed points this one started with.  (A pass
/// whose clean-up took out another point starts the next one without it, which can build another hull:
/// not a repeat.  A pinned point the clean-up takes out again in every pass is one.)
template <Number T>
inline bool Builder<T>::repeats(std::uint64_t digest, std::uint64_t last_digest,
                                const std::vector<int>& outside) const {
  return digest == last_digest && removed_hash() == removed_at_pin_ &&
         std::none_of(outside.begin(), outside.end(), [&](int p) { return !pinned_[as_index(p)]; });
}

/// A 64-bit FNV-1a-style hash (a word per index) of the indices of the points the clean-up has taken out
/// (removed_).
template <Number T>
inline std::uint64_t Builder<T>::removed_hash() const {
  std::uint64_t x = 0xcbf29ce484222325ull;
  for (std::size_t i = 0; i < removed_.size(); ++i)
    if (removed_[i]) x = (x ^ static_cast<std::uint64_t>(i)) * 0x100000001b3ull;
  return x;
}

/// Float T: a 64-bit FNV-1a hash of h's vertex coordinates and face loops, in their order: equal for
/// equal results (a repair pass that repeated the last one).
template <Number T>
inline std::uint64_t Builder<T>::digest(const ConvexPolyhedron<T>& h) {
  std::uint64_t x = 0xcbf29ce484222325ull;
  auto mix = [&](const void* data, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) x = (x ^ c[i]) * 0x100000001b3ull;
  };
  for (const Vec3<T>& v : h.vertices()) mix(v.data(), 3 * sizeof(T));
  for (int f = 0; f < h.face_count(); ++f) {
    int e = h.face(f).edge;
    for (int i = 0; i < h.face(f).count; ++i, e = h.half_edge(e).next)
      mix(&h.half_edge(e).origin, sizeof(int));
  }
  return x;
}

/// Float T, the fallback policy once the repair passes are done: the nearest result, unless the initial
/// simplex (a needle), the projected slab or a tent is nearer every point.
template <Number T>
inline ConvexPolyhedron<T> Builder<T>::choose_result(RepairLog<T>& log) {
  if (log.nearest_out > kHullRepairTolerance) try_simplex(log);
  if (auto slab = try_projected_slab(log)) return std::move(*slab);
  std::optional<ConvexPolyhedron<T>>& chosen =
      log.nearest_height > kHullHeightSafe && log.nearest_height > log.lowest_height ? log.lowest_result()
                                                                                     : log.nearest;
  if (log.nearest_out > kHullHeightSafe && tent_) {
    if (auto tent = try_tent(*chosen)) return std::move(*tent);
  }
  return std::move(*chosen);
}

/// The passes could not keep every point near the hull (a needle a few eps thick, whose faces all fold within
/// eps): the initial simplex contains the segment between the farthest pair, so it may be nearer every
/// point than the best pass; it replaces the nearest result if so.
template <Number T>
inline void Builder<T>::try_simplex(RepairLog<T>& log) {
  std::vector<int> none;
  if (auto t = simplex_hull()) {
    double t_height = 0;
    const double t_out = outside_points(*t, none, t_height);
    if (t_out < log.nearest_out) log.set_nearest(std::move(*t), t_out, t_height);
  }
}

/// A slab thinner than the bound whose rim corners every pass folded away (or whose rim faces are so nearly
/// parallel that a point beyond the rim is below both their planes, so the measure saw it inside: measured
/// here by the slab's shadow, the points projected onto its plane against the projected hull): the flat
/// polygon of the projections onto the slab's mid-plane is within the half-thickness of every point, in
/// height and in distance.  Returned when nearer every point than the nearest result.
template <Number T>
inline std::optional<ConvexPolyhedron<T>> Builder<T>::try_projected_slab(const RepairLog<T>& log) {
  Vec3<double> nrm(0, 0, 0);
  double lo = 0, hi = 0;
  if (thin_plane(*log.nearest, nrm, lo, hi)) {
    // (a flat result's shadow is itself: its measure already holds every point's distance from it)
    const double gap =
        log.nearest->is_flat() ? log.nearest_out : std::max(log.nearest_out, shadow_out(*log.nearest, nrm));
    if (gap > kHullHeightSafe) {
      std::vector<int> none;
      if (auto s = projected_slab(nrm, lo, hi)) {
        double s_height = 0;
        if (outside_points(*s, none, s_height) < gap) return s;
      }
    }
  }
  return std::nullopt;
}

/// A slab corner that every pass lost (fallbacks.hpp, tent_hull): if the chosen result would leave a point
/// more than kHullHeightSafe out, the hull of the points plus a copy of each point it loses, lifted
/// kHullTentLift x eps into the slab, when nearer every point and its shadow on the slab's plane holds every
/// point's shadow (the distance check can miss a lost needle tip: the tent is for slabs).
template <Number T>
inline std::optional<ConvexPolyhedron<T>> Builder<T>::try_tent(const ConvexPolyhedron<T>& chosen) {
  std::vector<int> none;
  double c_height = 0;
  out_vertex_.assign(pts_.size(), 0);  // (measure every point)
  const double c_out = outside_points(chosen, none, c_height);
  Vec3<double> t_nrm(0, 0, 0);
  if (c_out > kHullHeightSafe) {
    if (auto t = tent_hull(chosen, t_nrm)) {
      double t_height = 0;
      const double t_out = std::max(outside_points(*t, none, t_height), shadow_out(*t, t_nrm));
      if (t_out <= kHullRepairTolerance && (t_height <= kHullHeightSafe || t_height <= c_height)) return t;
    }
  }
  return std::nullopt;
}

// Float T: the welded points more than kHullRepairTolerance * eps above a face plane
// of h (evaluated as a user would, on the input coordinates; plus their
// rounding) or that far from its face polygons (polygon_distance: a point
// within eps of two planes of a thin wedge can be far beyond its edge);
// returns the largest of either in units of eps, and in height the
// largest height alone.
template <Number T>
inline double Builder<T>::outside_points(const ConvexPolyhedron<T>& h, std::vector<int>& outside,
                                         double& height) const {
  // (a hull with every point a vertex measures nothing: no polygons or climb to prepare)
  if (std::find(out_vertex_.begin(), out_vertex_.end(), char{0}) == out_vertex_.end()) return 0;
  double max_abs = 0;
  for (std::size_t i = 0; i < pts_.size(); ++i)
    for (int c = 0; c < 3; ++c)
      max_abs = std::max(max_abs, std::abs(to_double(input_point(static_cast<int>(i))[c])));
  const double e = to_double(eps_);
  const double slack = kHullPlaneRoundingSlack * number_traits<T>::unit_roundoff * max_abs;
  double worst = 0;
  PolygonFaces polygons = polygon_faces(h, centre_);
  const std::vector<PolygonFace>& faces = polygons.faces;
  DeepInside<T> deep(
      h, faces, kHullDeepInsideSlack * slack + kHullDeepInsidePlanarity * Tolerances<T>::kPlanarity * extent_,
      pts_.size());
  // (large solids: a point near the surface measured against the faces near the climb's, else every face)
  const bool near_faces = deep.enabled() && deep.local();
  if (!near_faces) polygons.fill_lanes();
  std::vector<int> near;        // large solids: the faces measured for a point near the surface
  std::vector<double> heights;  // (polygon_distance's scratch)
  std::vector<int> seen(faces.size(), -1);
  std::optional<PlaneTree<T>> planes;  // (h's face planes, built when a point is measured against all)
  const std::size_t first_outside = outside.size();
  for (const int p : measure_order(deep.enabled())) {
    auto plane_height = [&](int f) {
      return to_double(T(dot(h.plane(f).normal, input_point(p)) - h.plane(f).offset));
    };
    double hp = -1e300;
    const std::vector<int>* subset = nullptr;
    if (deep.enabled() && deep(vec_to_double(local_point(p)))) continue;
    if (near_faces) {
      // the faces connected to the climb's face through faces the point is
      // less than the bound below (every face it can be above or near)
      near.assign(1, deep.face());
      seen[as_index(deep.face())] = p;
      const double reach = -kHullMeasureReach * e - slack;
      for (std::size_t k = 0; k < near.size(); ++k) {
        const double hf = plane_height(near[k]);
        hp = std::max(hp, hf);
        if (hf < reach && k > 0) continue;
        auto add = [&](int g) {
          if (seen[as_index(g)] != p) {
            seen[as_index(g)] = p;
            near.push_back(g);
          }
        };
        const std::span<const int> nb = deep.neighbours(near[k]);
        if (nb.size() < kFanSearchCorners) {
          for (int g : nb) add(g);
          continue;
        }
        // a face of many edges (a cylinder's cap): the neighbours across its edge nearest the point and,
        // each way from it, across the edges while the neighbour is within reach of the point or the edge
        // is (the point's height over the faces around the rim falls away from it)
        const Vec3<double> x = vec_to_double(local_point(p));
        const PolygonFace& fc = faces[as_index(near[k])];
        double d2 = 0;
        bool inside = false;
        const std::size_t e0 = fan_edge(fc, x, d2, inside);
        add(nb[e0]);
        for (const std::size_t step : {std::size_t{1}, nb.size() - 1}) {
          for (std::size_t edge = (e0 + step) % nb.size(); edge != e0; edge = (edge + step) % nb.size()) {
            if (!(plane_height(nb[edge]) >= reach) && !(edge_distance2(fc, edge, x) <= reach * reach)) break;
            add(nb[edge]);
          }
        }
      }
      subset = &near;
    } else {
      // the largest height above every face plane (on many faces through the tree of planes: the value
      // of the pass)
      if (h.face_count() < kPlaneTreeFaces) {
        for (int f = 0; f < h.face_count(); ++f) hp = std::max(hp, plane_height(f));
      } else {
        if (!planes) planes.emplace(h.face_count(), [&](int f) -> const Plane<T>& { return h.plane(f); });
        const T top = planes->max_height(input_point(p), [&](int f) {
          return T(dot(h.plane(f).normal, input_point(p)) - h.plane(f).offset);
        });
        hp = std::max(hp, to_double(top));
      }
    }
    hp -= slack;
    height = std::max(height, hp / e);
    hp = std::max(
        hp, polygon_distance(polygons, h.is_flat(), vec_to_double(local_point(p)), heights, subset) - slack);
    worst = std::max(worst, hp / e);
    if (hp > kHullRepairTolerance * e) outside.push_back(p);
  }
  std::sort(outside.begin() + static_cast<std::ptrdiff_t>(first_outside), outside.end());
  return worst;
}

/// Float T: the welded points that are not vertices of the result (out_vertex_: the pre-check held those
/// within conv_tol = 2 eps), in index order, or with
/// `coherent` in the order of a Morton code of their local coordinates (21 bits a coordinate over the
/// points' bounding box), so that consecutive points are near each other: the climb DeepInside starts from
/// the last one's face is then short (index order is lexicographic, in which consecutive points can lie on
/// opposite sides of the hull).
template <Number T>
inline std::vector<int> Builder<T>::measure_order(bool coherent) const {
  std::vector<int> order;
  for (std::size_t i = 0; i < pts_.size(); ++i)
    if (!out_vertex_[i]) order.push_back(static_cast<int>(i));
  if (!coherent || order.size() < 2) return order;
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const int p : order)
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], to_double(local_point(p)[c]));
      hi[c] = std::max(hi[c], to_double(local_point(p)[c]));
    }
  auto spread = [](std::uint64_t v) {  // the low 21 bits of v at every third bit
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffull;
    v = (v | v << 16) & 0x1f0000ff0000ffull;
    v = (v | v << 8) & 0x100f00f00f00f00full;
    v = (v | v << 4) & 0x10c30c30c30c30c3ull;
    v = (v | v << 2) & 0x1249249249249249ull;
    return v;
  };
  std::vector<std::pair<std::uint64_t, int>> keyed;
  keyed.reserve(order.size());
  for (const int p : order) {
    std::uint64_t key = 0;
    for (int c = 0; c < 3; ++c) {
      const double w = hi[c] - lo[c];
      const double q = w > 0 ? (to_double(local_point(p)[c]) - lo[c]) / w * 2097151.0 : 0.0;
      key |= spread(static_cast<std::uint64_t>(std::clamp(q, 0.0, 2097151.0))) << c;
    }
    keyed.emplace_back(key, p);
  }
  // (by key, ties in point order: keyed is in point order and the radix sort is stable)
  radix_sort<1>(keyed, [](const std::pair<std::uint64_t, int>& k, int) { return k.first; });
  for (std::size_t k = 0; k < keyed.size(); ++k) order[k] = keyed[k].second;
  return order;
}

}  // namespace sepax::hull::detail
