// sepax/hull/face_merge.hpp
//
// Triangles into faces (union-find over the live triangles, Builder::merge_and_build):
//   1. plane merges: adjacent groups that are coplanar (exact T: exactly; float T: either sees every vertex
//      of the other less than eps below its area-weighted plane) are united, until nothing changes (float T
//      after a local removal: merge_locally, only around the replaced triangles, the rest as recorded);
//   2. zero-area triangles join the face across their longest edge (then plane merges again);
//   3. float T with pinned points: a merge that would strand a pinned vertex (strands_vertex) is refused,
//      and faces folded over one are split back into their triangles (fold_choice, split_groups);
//   4. extract (face_loops.hpp) turns every group into a loop.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

#include "../number_traits.hpp"
#include "../orientation_filter.hpp"
#include "builder.hpp"

namespace sepax::hull::detail {

// Groups holding triangles of the same split face may not merge again.
template <Number T>
inline bool Builder<T>::split_apart(const Group& a, const Group& b) {
  for (int x : a.splits)
    if (std::binary_search(b.splits.begin(), b.splits.end(), x)) return true;
  return false;
}

// |(v1 - v0) x (v2 - v0)|^2 / 4, from the edge lengths (Heron), accurate
// for thin triangles where the cross product is not.
template <Number T>
inline T Builder<T>::tri_area2(const Tri& t) const {
  T a = length(Vec3<T>(local_point(t.v[1]) - local_point(t.v[0])));
  T b = length(Vec3<T>(local_point(t.v[2]) - local_point(t.v[1])));
  T c = length(Vec3<T>(local_point(t.v[0]) - local_point(t.v[2])));
  if (a < b) std::swap(a, b);
  if (b < c) std::swap(b, c);
  if (a < b) std::swap(a, b);
  // a >= b >= c: Kahan's stable form of Heron's formula
  const T p = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  return p > T(0) ? T(p / T(16)) : T(0);
}

// The root of x's group (path halving).
template <Number T>
inline int Builder<T>::find(int x) {
  while (parent_[as_index(x)] != x) {
    parent_[as_index(x)] = parent_[as_index(parent_[as_index(x)])];
    x = parent_[as_index(x)];
  }
  return x;
}

// Up to this many vertices new to a group are inserted one by one (a move of the larger part), more by a
// merge.
inline constexpr std::size_t kUniteInserts = 4;

// Unites the groups of x and y (the union's vertices, split ids, area and plane).
template <Number T>
inline void Builder<T>::unite(int x, int y) {
  x = find(x);
  y = find(y);
  if (x == y) return;
  Group& gx = groups_[as_index(x)];
  Group& gy = groups_[as_index(y)];
  if constexpr (Traits::kRepairs) {
    // (a union after the recorded plane merges: the root's recorded group kept for merge_locally)
    auto& kept = merge_record_.kept;
    if (merge_record_.recorded &&
        std::none_of(kept.begin(), kept.end(), [&](const auto& k) { return k.first == x; }))
      kept.emplace_back(x, gx);
  }
  // The union: the smaller group's vertices looked up in the larger's (a face of many triangles is united
  // one triangle at a time: no pass over its vertices), the missing ones inserted.
  const bool y_larger = gy.verts.size() > gx.verts.size();
  const std::vector<int>& small = y_larger ? gx.verts : gy.verts;
  const std::vector<int>& large = y_larger ? gy.verts : gx.verts;
  shared_.clear();
  added_.clear();
  for (const int v : small)
    (std::binary_search(large.begin(), large.end(), v) ? shared_ : added_).push_back(v);
  Traits::unite_sum(*this, gx, gy, shared_);
  if (y_larger) union_.assign(gy.verts.begin(), gy.verts.end());
  std::vector<int>& out = y_larger ? union_ : gx.verts;
  if (added_.size() <= kUniteInserts) {  // (a triangle joining a face adds a vertex or none)
    for (const int v : added_) out.insert(std::upper_bound(out.begin(), out.end(), v), v);
  } else {
    const std::size_t before = out.size();
    out.insert(out.end(), added_.begin(), added_.end());
    std::inplace_merge(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(before), out.end());
  }
  if (y_larger) gx.verts.swap(union_);
  if (!gy.splits.empty()) {
    std::vector<int> sp;
    std::set_union(gx.splits.begin(), gx.splits.end(), gy.splits.begin(), gy.splits.end(),
                   std::back_inserter(sp));
    gx.splits = std::move(sp);
  }
  Traits::add_area(gx, gy);
  if (gx.degenerate && !gy.degenerate) {
    Traits::adopt_plane(gx, gy);
    gx.plane_tri = gy.plane_tri;
  }
  gx.degenerate = gx.degenerate && gy.degenerate;
  parent_[as_index(y)] = x;
  if (as_index(x) < group_version_.size()) ++group_version_[as_index(x)];
  Traits::refit(*this, gx);
}

// Triangle f's own group (reset in place, keeping its vectors' storage across the merges and rebuilds of one
// build; its fitted plane and area are set by init_group_fit where the traits keep them, float T).
template <Number T>
inline void Builder<T>::init_group(int f) {
  const Tri& t = tris_[as_index(f)];
  Group& g = groups_[as_index(f)];
  g.verts.assign({t.v[0], t.v[1], t.v[2]});
  std::sort(g.verts.begin(), g.verts.end());
  g.plane_tri = f;
  Traits::init_group_fit(*this, g, f);
  g.degenerate = Traits::zero_area(*this, f);
  g.splits.clear();
  if (nomerge_[as_index(f)] != 0) g.splits.push_back(nomerge_[as_index(f)]);
}

// Groups the live triangles into faces, then extracts their loops.
template <Number T>
inline std::optional<ConvexPolyhedron<T>> Builder<T>::merge_and_build(std::vector<int>& reject) {
  std::vector<int> live;
  for (std::size_t f = 0; f < tris_.size(); ++f)
    if (tris_[f].alive) live.push_back(static_cast<int>(f));
  merge_record_.recorded = false;
  if (merge_locally(live)) {
    local_face_stages.fetch_add(1, std::memory_order_relaxed);
    record_merges(live, true);
    return extract(live, reject);
  }
  parent_.assign(tris_.size(), 0);
  std::iota(parent_.begin(), parent_.end(), 0);
  // (read only by strands_vertex, which needs a pinned point)
  if (any_pinned_) {
    star_.assign(welded_count(), {});
    for (int f : live)
      for (int v : tris_[as_index(f)].v) star_[as_index(v)].push_back(f);
  }
  // (a group per triangle index, read only for live triangles)
  groups_.resize(tris_.size(), Group{});  // (new entries copied from one: cheap for shared T values)
  bool any_degenerate = false;
  for (int f : live) {
    init_group(f);
    any_degenerate = any_degenerate || groups_[as_index(f)].degenerate;
  }
  // Plane merges until nothing changes; then zero-area triangles join a
  // neighbouring face, and if any did, plane merges again: a zero-area
  // triangle between two coplanar faces kept them apart, and once it has
  // joined one of them they are adjacent (left unmerged, validation would
  // refuse the pair and the clean-up would drop a real corner).
  std::vector<ApartPair> apart(live.size() * 3);
  group_version_.assign(tris_.size(), 0);
  for (bool joined = true; joined;) {
    joined = false;
    plane_merges(live, nullptr, apart);
    // Zero-area triangles join the face across their longest edge.
    for (bool changed = true; changed;) {
      changed = false;
      for (int f : live) {
        if (!groups_[as_index(find(f))].degenerate) continue;
        const Tri& t = tris_[as_index(f)];
        int li = 0;
        T ll(-1);
        for (int i = 0; i < 3; ++i) {
          const T l =
              squared_norm(Vec3<T>(local_point(t.v[as_index((i + 1) % 3)]) - local_point(t.v[as_index(i)])));
          if (l > ll) {
            ll = l;
            li = i;
          }
        }
        int target = find(t.nb[as_index(li)]);
        if (groups_[as_index(target)].degenerate) {
          for (int i = 0; i < 3; ++i)
            if (!groups_[as_index(find(t.nb[as_index(i)]))].degenerate) target = find(t.nb[as_index(i)]);
        }
        if (!groups_[as_index(target)].degenerate) {
          unite(target, find(f));
          changed = true;
          joined = true;
        }
      }
    }
  }
  for (int f : live) {
    if (groups_[as_index(find(f))].degenerate)
      throw std::logic_error("convex_hull: a zero-area face could not be merged (a bug)");
  }
  record_merges(live, !any_degenerate);
  return extract(live, reject);
}

// Plane merges among the triangles tris (ascending), passes over them until nothing changes: adjacent groups
// that are coplanar (and not split apart, nor, with pinned points, stranding one) are united.  With among
// (per triangle), only across the edges between two triangles it marks.
//
// A pair of groups found apart (split apart, certainly apart or not coplanar: functions of the two groups
// alone) stays apart until one of them changes: each edge slot (apart[3 k + i] for tris[k]'s edge i)
// remembers the pair and the groups' versions (bumped by unite) it was found apart with, and is not tested
// again while they hold.  (strands_vertex depends on the other groups too: a pair it kept apart is tested
// again.)
template <Number T>
inline void Builder<T>::plane_merges(const std::vector<int>& tris, const std::vector<char>* among,
                                     std::vector<ApartPair>& apart) {
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t k = 0; k < tris.size(); ++k) {
      const int f = tris[k];
      for (int i = 0; i < 3; ++i) {
        const int n = tris_[as_index(f)].nb[as_index(i)];
        if (among != nullptr && !(*among)[as_index(n)]) continue;
        const int x = find(f), y = find(n);
        if (x == y || groups_[as_index(x)].degenerate || groups_[as_index(y)].degenerate) continue;
        ApartPair& known = apart[3 * k + as_index(i)];
        const int vx = group_version_[as_index(x)], vy = group_version_[as_index(y)];
        if (known.x == x && known.y == y && known.vx == vx && known.vy == vy) continue;
        if (split_apart(groups_[as_index(x)], groups_[as_index(y)]) || Traits::certainly_apart(*this, x, y) ||
            !Traits::coplanar(*this, groups_[as_index(x)], groups_[as_index(y)])) {
          known = ApartPair{x, y, vx, vy};
          continue;
        }
        if (!strands_vertex(x, y)) {
          unite(x, y);
          changed = true;
        }
      }
    }
  }
}

// Float T, a face stage after a local removal (remove_vertices: the last face stage's triangles, some of them
// replaced by quickhull since): its plane merges done again only where they can differ.  The plane merges of
// a group of triangles depend on its own triangles and on the tests across its border, every one of which
// failed (one that passed would have united the two groups): a group whose triangles and neighbours are
// unchanged, among groups whose are, merges as recorded (merge_record_).  The groups that lost a triangle or
// whose triangles' vertices or neighbours changed are merged again from their triangles, with the new
// triangles (plane_merges: in index order, as the passes over every triangle, across the edges among them);
// each group merged again that borders the rest must come out as recorded (its triangles, and so every test
// it took, the same), else the groups it borders are merged again too, until it does.  The rest keeps its
// recorded roots and groups.  False (the caller merges every triangle) without a record to go on from, with
// pinned points (strands_vertex depends on the groups around a vertex), split faces or a zero-area triangle.
template <Number T>
inline bool Builder<T>::merge_locally(const std::vector<int>& live) {
  if constexpr (!Traits::kRepairs) {
    return false;
  } else {
    MergeRecord<T>& rec = merge_record_;
    if (!local_face_merges.load(std::memory_order_relaxed) || !rec.valid || any_pinned_ || splits_ != 0 ||
        rec.root.size() > tris_.size())
      return false;
    const std::size_t old = rec.root.size();
    // the recorded groups' triangles: members[start[r], start[r + 1]) for root r, ascending
    std::vector<int> start(old + 1, 0), members;
    for (std::size_t f = 0; f < old; ++f)
      if (rec.root[f] >= 0) ++start[as_index(rec.root[f]) + 1];
    for (std::size_t r = 0; r < old; ++r) start[r + 1] += start[r];
    members.resize(as_index(start[old]));
    {
      std::vector<int> fill(start.begin(), start.end() - 1);
      for (std::size_t f = 0; f < old; ++f)
        if (rec.root[f] >= 0) members[as_index(fill[as_index(rec.root[f])]++)] = static_cast<int>(f);
    }
    // per recorded root: 0 kept, 1 merged again, 2 merged again having lost a triangle
    std::vector<char> again(old, 0);
    for (std::size_t f = 0; f < old; ++f) {
      const int r = rec.root[f];
      if (r < 0) continue;
      const Tri& t = tris_[f];
      if (!t.alive) {
        again[as_index(r)] = 2;
      } else if (again[as_index(r)] == 0 &&
                 rec.tri[f] != std::array<int, 6>{t.v[0], t.v[1], t.v[2], t.nb[0], t.nb[1], t.nb[2]}) {
        again[as_index(r)] = 1;
      }
    }
    for (int f : live)
      if (as_index(f) < old && rec.root[as_index(f)] < 0) return false;  // (not the recorded triangles)
    parent_.resize(tris_.size());
    groups_.resize(tris_.size(), Group{});
    group_version_.resize(tris_.size(), 0);
    for (auto& [r, g] : rec.kept) groups_[as_index(r)] = std::move(g);
    rec.kept.clear();
    for (int f : live) parent_[as_index(f)] = as_index(f) < old ? rec.root[as_index(f)] : f;
    std::vector<char> among(tris_.size(), 0);
    std::vector<int> region, count(tris_.size(), 0);
    std::vector<char> as_recorded(old, 0);  // per root merged again: 0 not known, 1 as recorded, 2 not
    std::vector<ApartPair> apart;
    for (;;) {
      region.clear();
      for (int f : live) {
        const bool in = as_index(f) >= old || again[as_index(rec.root[as_index(f)])] != 0;
        among[as_index(f)] = in;
        if (in) region.push_back(f);
      }
      for (int f : region) {
        parent_[as_index(f)] = f;
        init_group(f);
        group_version_[as_index(f)] = 0;
        if (groups_[as_index(f)].degenerate) return false;
      }
      apart.assign(region.size() * 3, ApartPair{});
      plane_merges(region, &among, apart);
      for (int f : region) ++count[as_index(find(f))];
      std::fill(as_recorded.begin(), as_recorded.end(), 0);
      auto recorded = [&](int f) {  // f's group as recorded, its triangles all alive
        const int r = as_index(f) < old ? rec.root[as_index(f)] : -1;
        if (r < 0 || again[as_index(r)] == 2) return false;
        if (as_recorded[as_index(r)] == 0) {
          const int g = find(f);
          bool same = g == r && count[as_index(g)] == start[as_index(r) + 1] - start[as_index(r)];
          for (int k = start[as_index(r)]; k < start[as_index(r) + 1] && same; ++k)
            same = find(members[as_index(k)]) == g;
          as_recorded[as_index(r)] = same ? 1 : 2;
        }
        return as_recorded[as_index(r)] == 1;
      };
      bool grown = false;
      for (int f : region)
        for (const int n : tris_[as_index(f)].nb) {
          if (among[as_index(n)]) continue;
          if (as_index(n) >= old || rec.root[as_index(n)] < 0)
            return false;  // (not a live recorded triangle)
          if (!recorded(f) && again[as_index(rec.root[as_index(n)])] == 0) {
            again[as_index(rec.root[as_index(n)])] = 1;
            grown = true;
          }
        }
      for (int f : region) count[as_index(find(f))] = 0;
      if (!grown) return true;  // (no zero-area triangle: the zero-area joins have nothing to do)
    }
  }
}

// Float T: the plane merges just done recorded for the next face stage (merge_locally), when it can go on
// from them: on triangles a removal may go on from (kLocalRemovalFaces), with no pinned point, split face
// or zero-area triangle.
template <Number T>
inline void Builder<T>::record_merges(const std::vector<int>& live, bool valid) {
  if constexpr (Traits::kRepairs) {
    MergeRecord<T>& rec = merge_record_;
    rec.valid = valid && !any_pinned_ && splits_ == 0 && live.size() >= kLocalRemovalFaces;
    rec.kept.clear();
    rec.recorded = rec.valid;
    if (!rec.valid) return;
    rec.root.assign(tris_.size(), -1);
    for (int f : live) rec.root[as_index(f)] = find(f);
    rec.tri.resize(tris_.size());
    for (std::size_t f = 0; f < tris_.size(); ++f) {
      const Tri& t = tris_[f];
      rec.tri[f] = {t.v[0], t.v[1], t.v[2], t.nb[0], t.nb[1], t.nb[2]};
    }
  }
}

// Float T: would merging groups x and y (roots) leave a vertex they share
// on only two faces (so that it is dropped as the middle of an edge) while
// it is more than kHullFoldDistance * eps from the segment between its neighbours
// along that edge?  On a needle or thin slab every face is within eps of
// every vertex, and such a merge can fold faces over a real corner (the
// tip of a needle).
template <Number T>
inline bool Builder<T>::strands_vertex(int x, int y) {
  if (!any_pinned_) return false;
  const Group& gx = groups_[as_index(x)];
  const Group& gy = groups_[as_index(y)];
  std::vector<int> shared;
  std::set_intersection(gx.verts.begin(), gx.verts.end(), gy.verts.begin(), gy.verts.end(),
                        std::back_inserter(shared));
  auto group = [&](int t) {
    const int g = find(t);
    return g == y ? x : g;
  };
  for (int v : shared) {
    if (!pinned_[as_index(v)]) continue;
    std::vector<int> gs;
    for (int t : star_[as_index(v)]) gs.push_back(group(t));
    std::sort(gs.begin(), gs.end());
    gs.erase(std::unique(gs.begin(), gs.end()), gs.end());
    if (gs.size() == 1) return true;  // it would be inside a face
    if (gs.size() != 2) continue;
    // its neighbours along the boundary between the two faces
    std::vector<int> ends;
    for (int t : star_[as_index(v)]) {
      const Tri& tr = tris_[as_index(t)];
      for (int i = 0; i < 3; ++i) {
        const int u = tr.v[as_index(i)], w = tr.v[as_index((i + 1) % 3)];
        if (u != v) continue;
        if (group(t) != group(tr.nb[as_index(i)])) ends.push_back(w);
      }
      for (int i = 0; i < 3; ++i) {
        const int u = tr.v[as_index(i)], w = tr.v[as_index((i + 1) % 3)];
        if (w != v) continue;
        if (group(t) != group(tr.nb[as_index(i)])) ends.push_back(u);
      }
    }
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    if (ends.size() != 2) continue;
    if (segment_distance(v, ends[0], ends[1]) > kHullFoldDistance * to_double(eps_)) return true;
  }
  return false;
}

// Float T: which faces to split at folds (vertex -> the groups it is
// on).  Of the two faces a stranded pinned vertex is on, only the one
// that is less planar (the larger height of one of its vertices above or
// below its fitted plane) is split, if it can be (two or more plain
// unsplit triangles; else the other).  A vertex on two faces, while
// being a corner of both, means one of them bends over it: on a slab,
// the exactly planar bottom and a rim face merged from two triangles
// within eps of each other's plane (they fold over the corner).
// The planar face is not split as well: its triangles could not merge
// again, and validation would see them as coplanar neighbours, each such
// pair costing a corner.  If the less planar
// face folds again after its split, the next pass finds it unsplittable
// and splits the other, so no fold is left standing.
template <Number T>
inline std::vector<int> Builder<T>::fold_choice(const std::vector<int>& live,
                                                const std::map<int, std::vector<int>>& folds) {
  std::vector<int> ids;
  if (folds.empty()) return ids;
  std::unordered_map<int, int> plain;  // group -> plain unsplit triangles
  for (int f : live) plain[find(f)] += !is_zero(tris_[as_index(f)].pl.normal) && nomerge_[as_index(f)] == 0;
  auto bend = [&](int g) {
    const Group& gr = groups_[as_index(g)];
    double d = 0;
    for (int v : gr.verts) d = std::max(d, std::abs(to_double(height(Traits::group_plane(*this, gr), v))));
    return d;
  };
  for (const auto& [v, gs0] : folds) {
    std::vector<int> gs = gs0;
    std::sort(gs.begin(), gs.end());
    gs.erase(std::unique(gs.begin(), gs.end()), gs.end());
    std::vector<std::pair<double, int>> order;
    for (int g : gs) order.emplace_back(-bend(g), g);
    std::sort(order.begin(), order.end());
    for (const auto& [negd, g] : order) {
      if (plain[g] >= 2) {
        ids.push_back(g);
        break;
      }
    }
  }
  return ids;
}

// Split groups (ids of their root triangles) back into their triangles,
// which may not merge with each other again; a group with fewer than two
// plain (non-zero-area) unsplit triangles is left alone.  True if any was
// split.
template <Number T>
inline bool Builder<T>::split_groups(const std::vector<int>& live, std::vector<int> ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  if (ids.empty()) return false;
  std::unordered_map<int, std::vector<int>> members;  // group -> live triangles
  for (int f : live) members[find(f)].push_back(f);
  bool any_split = false;
  for (int g : ids) {
    std::vector<int>& m = members[g];
    int plain = 0;
    for (int t : m) plain += !is_zero(tris_[as_index(t)].pl.normal) && nomerge_[as_index(t)] == 0;
    if (plain < 2) continue;
    ++splits_;
    for (int t : m)
      if (nomerge_[as_index(t)] == 0) nomerge_[as_index(t)] = splits_;
    any_split = true;
  }
  return any_split;
}

// Euclidean distance of point v from the segment between points a and b
// (double, on the local coordinates; exact conversion for float).
template <Number T>
inline double Builder<T>::segment_distance(int v, int a, int b) const {
  return distance_to_segment(vec_to_double(local_point(v)), vec_to_double(local_point(a)),
                             vec_to_double(local_point(b)));
}

}  // namespace sepax::hull::detail
