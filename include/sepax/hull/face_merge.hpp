// sepax/hull/face_merge.hpp
//
// Triangles into faces (union-find over the live triangles, Builder::merge_and_build):
//   1. plane merges: adjacent groups that are coplanar (exact T: exactly; float T: either sees every vertex
//      of the other less than eps below its area-weighted plane) are united, until nothing changes;
//   2. zero-area triangles join the face across their longest edge (then plane merges again);
//   3. float T with pinned points: a merge that would strand a pinned vertex (strands_vertex) is refused,
//      and faces folded over one are split back into their triangles (fold_choice, split_groups);
//   4. extract (face_loops.hpp) turns every group into a loop.
#pragma once

#include <algorithm>
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

// Unites the groups of x and y (the union's vertices, split ids, area and plane).
template <Number T>
inline void Builder<T>::unite(int x, int y) {
  x = find(x);
  y = find(y);
  if (x == y) return;
  Group& gx = groups_[as_index(x)];
  Group& gy = groups_[as_index(y)];
  std::vector<int> vs;
  std::set_union(gx.verts.begin(), gx.verts.end(), gy.verts.begin(), gy.verts.end(), std::back_inserter(vs));
  gx.verts = std::move(vs);
  if (!gy.splits.empty()) {
    std::vector<int> sp;
    std::set_union(gx.splits.begin(), gx.splits.end(), gy.splits.begin(), gy.splits.end(),
                   std::back_inserter(sp));
    gx.splits = std::move(sp);
  }
  Traits::add_area(gx, gy);
  if (gx.degenerate && !gy.degenerate) {
    gx.pl = gy.pl;
    gx.plane_tri = gy.plane_tri;
  }
  gx.degenerate = gx.degenerate && gy.degenerate;
  parent_[as_index(y)] = x;
  if (as_index(x) < group_version_.size()) ++group_version_[as_index(x)];
  Traits::refit(*this, gx);
}

// Groups the live triangles into faces, then extracts their loops.
template <Number T>
inline std::optional<ConvexPolyhedron<T>> Builder<T>::merge_and_build(std::vector<int>& reject) {
  std::vector<int> live;
  for (std::size_t f = 0; f < tris_.size(); ++f)
    if (tris_[f].alive) live.push_back(static_cast<int>(f));
  parent_.assign(tris_.size(), 0);
  std::iota(parent_.begin(), parent_.end(), 0);
  // (read only by strands_vertex, which needs a pinned point)
  if (any_pinned_) {
    star_.assign(q_.size(), {});
    for (int f : live)
      for (int v : tris_[as_index(f)].v) star_[as_index(v)].push_back(f);
  }
  // (a group per triangle index, read only for live triangles: each is reset in place, keeping its
  // vectors' storage across the merges and rebuilds of one build; its plane is set by init_group_plane
  // where the traits read it, float T, and exact T never reads it)
  groups_.resize(tris_.size(), Group{});  // (new entries copied from one: cheap for shared T values)
  for (int f : live) {
    const Tri& t = tris_[as_index(f)];
    Group& g = groups_[as_index(f)];
    g.verts.assign({t.v[0], t.v[1], t.v[2]});
    std::sort(g.verts.begin(), g.verts.end());
    g.plane_tri = f;
    Traits::init_group_plane(*this, g, f);
    g.degenerate = Traits::zero_area(*this, f);
    g.splits.clear();
    if (nomerge_[as_index(f)] != 0) g.splits.push_back(nomerge_[as_index(f)]);
    g.area = Traits::triangle_area(*this, t);
  }
  // Plane merges until nothing changes; then zero-area triangles join a
  // neighbouring face, and if any did, plane merges again: a zero-area
  // triangle between two coplanar faces kept them apart, and once it has
  // joined one of them they are adjacent (left unmerged, validation would
  // refuse the pair and the clean-up would drop a real corner).
  //
  // A pair of groups found apart (split apart, certainly apart or not coplanar: functions of the two
  // groups alone) stays apart until one of them changes: each edge slot remembers the pair and the
  // groups' versions (bumped by unite) it was found apart with, and is not tested again while they hold.
  // (strands_vertex depends on the other groups too: a pair it kept apart is tested again.)
  struct Apart {
    int x = -1, y = -1, vx = 0, vy = 0;
  };
  std::vector<Apart> apart(tris_.size() * 3);
  group_version_.assign(tris_.size(), 0);
  for (bool joined = true; joined;) {
    joined = false;
    for (bool changed = true; changed;) {
      changed = false;
      for (int f : live) {
        for (int i = 0; i < 3; ++i) {
          const int x = find(f), y = find(tris_[as_index(f)].nb[as_index(i)]);
          if (x == y || groups_[as_index(x)].degenerate || groups_[as_index(y)].degenerate) continue;
          Apart& known = apart[as_index(3 * f + i)];
          const int vx = group_version_[as_index(x)], vy = group_version_[as_index(y)];
          if (known.x == x && known.y == y && known.vx == vx && known.vy == vy) continue;
          if (split_apart(groups_[as_index(x)], groups_[as_index(y)]) ||
              Traits::certainly_apart(*this, x, y) ||
              !Traits::coplanar(*this, groups_[as_index(x)], groups_[as_index(y)])) {
            known = Apart{x, y, vx, vy};
            continue;
          }
          if (!strands_vertex(x, y)) {
            unite(x, y);
            changed = true;
          }
        }
      }
    }
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
  return extract(live, reject);
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
    for (int v : gr.verts) d = std::max(d, std::abs(to_double(height(gr.pl, v))));
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
