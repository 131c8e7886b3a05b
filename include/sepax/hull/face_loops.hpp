// sepax/hull/face_loops.hpp
//
// Each face group's boundary loop, and the clean-up before output (Builder::extract):
//   1. boundary edges of every group, chained into one loop per group (a pinched loop or a face with a hole
//      rejects the offending vertices; fewer than 4 faces left is a flat set: the flat hull);
//   2. vertices on only two faces (the middle of an edge) are dropped, unless a pinned one marks a fold
//      (float T: the folded face is split and the faces merged again);
//   3. every corner strictly convex (float T: farther than eps from its neighbours' line), else the middle
//      point of the three is rejected and the hull rebuilt without it;
//   4. float T: precheck.hpp's check as validation will see it (merges, splits or a rejected vertex);
//   5. the output: compact vertex numbering, the input coordinates, validated by from_faces.
#pragma once

#include <algorithm>
#include <cstddef>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "../convex_polyhedron.hpp"
#include "builder.hpp"
#include "to_polyhedron.hpp"

namespace sepax::hull::detail {

// The faces' loops of the current groups, cleaned up; the validated hull, or none with reject filled.
template <Number T>
inline std::optional<ConvexPolyhedron<T>> Builder<T>::extract(const std::vector<int>& live,
                                                              std::vector<int>& reject) {
  // boundary edges of each group, grouped by group (stable: in triangle order).  A group is its root
  // triangle, so the edges are bucketed by root index (a counting sort: the order of a stable sort by
  // group, in linear time).
  struct BoundaryEdge {
    int group, from, to;
  };
  std::vector<BoundaryEdge> found;
  found.reserve(live.size() * 3);
  std::vector<int> roots;  // (ascending: live is)
  std::vector<std::size_t> group_start(tris_.size() + 1, 0);
  for (int f : live) {
    const int g = find(f);
    if (g == f) roots.push_back(g);
    const Tri& t = tris_[as_index(f)];
    for (int i = 0; i < 3; ++i)
      if (find(t.nb[as_index(i)]) != g) {
        found.push_back({g, t.v[as_index(i)], t.v[as_index((i + 1) % 3)]});
        ++group_start[as_index(g) + 1];
      }
  }
  for (std::size_t g = 0; g < tris_.size(); ++g) group_start[g + 1] += group_start[g];
  std::vector<BoundaryEdge> bnd(found.size());
  {
    std::vector<std::size_t> fill(group_start.begin(), group_start.end() - 1);
    for (const BoundaryEdge& e : found) bnd[fill[as_index(e.group)]++] = e;
  }
  // group -> its edges bnd[edge_start[k], edge_start[k + 1]) for roots[k] (every group with edges is a root)
  std::vector<std::size_t> edge_start(roots.size() + 1, bnd.size());
  for (std::size_t k = 0; k < roots.size(); ++k) edge_start[k] = group_start[as_index(roots[k])];
  bool collapsed = roots.size() < 4;
  for (std::size_t k = 0; k < roots.size(); ++k) collapsed = collapsed || edge_start[k] == edge_start[k + 1];
  if (collapsed) {
    // Float only: everything merged into fewer than 4 faces, so the set is
    // flat within the merge tolerance although the simplex test did not
    // see it: build the flat polygon instead.
    Traits::rounding_case("exact hull collapsed (a bug)");
    return polygon(active_, base_normal_, reject);
  }
  std::vector<std::vector<int>> loops;
  // (each loop's storage comes from loop_pool_ and goes back to it when this extraction ends, so the
  // extractions of a build's clean-up rounds and repair passes allocate about once per face)
  struct ReturnLoops {
    std::vector<std::vector<int>>& loops;
    std::vector<std::vector<int>>& pool;
    ~ReturnLoops() {
      try {
        for (auto& l : loops) pool.push_back(std::move(l));
      } catch (...) {  // (out of memory: the loops not returned are freed)
      }
    }
  } return_loops{loops, loop_pool_};
  // (and before an extraction starts again from here, so that it draws on them)
  auto recycle_loops = [&] {
    for (auto& l : loops) loop_pool_.push_back(std::move(l));
    loops.clear();
  };
  std::vector<int> loop_group;
  loops.reserve(roots.size());
  loop_group.reserve(roots.size());
  next_vertex_.assign(welded_count(), -1);
  for (std::size_t k = 0; k < roots.size(); ++k) {
    const int g = roots[k];
    const std::span<const BoundaryEdge> edges(bnd.data() + edge_start[k], edge_start[k + 1] - edge_start[k]);
    for (const auto& e : edges) {
      if (next_vertex_[as_index(e.from)] >= 0) {
        reject.push_back(e.from);  // pinched loop
      } else {
        next_vertex_[as_index(e.from)] = e.to;
      }
    }
    auto clear_next = [&] {
      for (const auto& e : edges) next_vertex_[as_index(e.from)] = -1;
    };
    if (!reject.empty()) {
      clear_next();
      continue;
    }
    // the loop through the first edge; any other edges form extra loops
    std::vector<int> loop;
    if (!loop_pool_.empty()) {
      loop = std::move(loop_pool_.back());
      loop_pool_.pop_back();
      loop.clear();
    }
    loop.reserve(edges.size());  // (a disk's loop: one vertex per boundary edge)
    const int start = edges.front().from;
    int cur = start;
    do {
      loop.push_back(cur);
      cur = next_vertex_[as_index(cur)];
      if (cur < 0) throw std::logic_error("convex_hull: open face boundary (a bug)");
    } while (cur != start && loop.size() <= edges.size());
    clear_next();
    if (loop.size() != edges.size()) {
      // a face with a hole: reject the vertices of the other loops
      std::vector<int> sorted = loop;
      std::sort(sorted.begin(), sorted.end());
      for (const auto& e : edges)
        if (!std::binary_search(sorted.begin(), sorted.end(), e.from)) reject.push_back(e.from);
      continue;
    }
    loops.push_back(std::move(loop));
    loop_group.push_back(g);
  }
  if (!reject.empty()) {
    Traits::rounding_case("a merged face is not a disk (a bug)");
    return std::nullopt;
  }
  // Vertices on only two faces lie in the middle of an edge: drop them.
  std::vector<int>& degree = degree_;
  degree.assign(welded_count(), 0);
  for (const auto& l : loops)
    for (int v : l) ++degree[as_index(v)];
  if (any_pinned_) {
    // ... unless a repair pass pinned them (they were far from the hull
    // without them) and they are more than kHullFoldDistance * eps from the segment
    // between their neighbours: then the two faces met at a fold, merged
    // within eps over a real corner (on a needle or thin slab every face
    // is within eps of every vertex: such a merge can cut off the tip of a
    // needle).  The less planar of the two faces it is
    // on (fold_choice) is split back into its triangles (which may not
    // merge again) and the faces merged again.
    // Every split marks more triangles, so this terminates; a face that
    // cannot be split any more drops the vertex.
    std::map<int, std::vector<int>> folds;  // stranded pinned vertex -> its groups
    for (std::size_t li = 0; li < loops.size(); ++li) {
      const auto& l = loops[li];
      const std::size_t n = l.size();
      for (std::size_t i = 0; i < n; ++i) {
        if (degree[as_index(l[i])] >= 3 || !pinned_[as_index(l[i])]) continue;
        std::size_t a = (i + n - 1) % n, b = (i + 1) % n;
        while (a != i && degree[as_index(l[a])] < 3) a = (a + n - 1) % n;
        while (b != i && degree[as_index(l[b])] < 3) b = (b + 1) % n;
        if (a == i || b == i) continue;
        if (segment_distance(l[i], l[a], l[b]) > kHullFoldDistance * to_double(eps_))
          folds[l[i]].push_back(loop_group[li]);
      }
    }
    if (split_groups(live, fold_choice(live, folds))) {
      reject.clear();
      recycle_loops();
      return merge_and_build(reject);
    }
  }
  for (auto& l : loops) {
    std::erase_if(l, [&](int v) { return degree[as_index(v)] < 3; });
  }
  // Every corner strictly convex; otherwise reject the middle of the three
  // points (it is within tolerance of the segment of the other two).  The
  // other two are its witnesses: a point is not rejected in a rebuild where
  // it witnesses another rejection, nor when one of its own witnesses is
  // rejected (two near-duplicate points at a real corner each fail the
  // corner test with the other as the middle; rejecting both would lose
  // the corner).  Such rejections wait for the next rebuild; the first
  // failing corner of a rebuild is always rejected, so rebuilds still progress.
  std::vector<char> rejected(welded_count(), 0), witness(welded_count(), 0);
  std::vector<int> group_size;  // triangles per group root (kTriangleFacesConvex)
  if constexpr (Traits::kTriangleFacesConvex) {
    group_size.assign(tris_.size(), 0);
    for (int f : live) ++group_size[as_index(find(f))];
  }
  int pinned_fallback = -1;
  for (int r : reject) rejected[as_index(r)] = 1;
  for (std::size_t li = 0; li < loops.size(); ++li) {
    const auto& l = loops[li];
    const Group& g = groups_[as_index(loop_group[li])];  // (its plane only when a corner is tested)
    const std::size_t n = l.size();
    if (n < 3) {
      for (int v : l) {
        reject.push_back(v);
        rejected[as_index(v)] = 1;
      }
      if (reject.empty()) throw std::logic_error("convex_hull: empty face (a bug)");
      continue;
    }
    // Exact T: a face that is one triangle (with area: the zero-area ones
    // have joined others) turns left at every corner, by |normal|^2.
    if constexpr (Traits::kTriangleFacesConvex) {
      if (group_size[as_index(loop_group[li])] == 1) continue;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const int pa = l[(i + n - 1) % n], pb = l[i], pc = l[(i + 1) % n];
      const Vec3<T> e1(local_point(pb) - local_point(pa)), e2(local_point(pc) - local_point(pb));
      const T turn = dot(Traits::group_plane(*this, g).normal, cross(e1, e2));
      if (Traits::convex_corner(*this, turn, e1, e2)) continue;
      // the point opposite the longest side of triangle (pa, pb, pc)
      const T lab = squared_norm(e1), lbc = squared_norm(e2),
              lca = squared_norm(Vec3<T>(local_point(pa) - local_point(pc)));
      int mid = pb;
      if (lab >= lbc && lab >= lca) mid = pc;
      if (lbc >= lab && lbc >= lca) mid = pa;
      if (lca >= lab && lca >= lbc) mid = pb;
      const int w1 = mid == pa ? pb : pa, w2 = mid == pc ? pb : pc;
      if (witness[as_index(mid)] || rejected[as_index(w1)] || rejected[as_index(w2)] ||
          rejected[as_index(mid)])
        continue;
      // a point a repair pass pinned (it was far from the hull without
      // it) is rejected only if nothing else is
      if (pinned_[as_index(mid)]) {
        if (pinned_fallback < 0) pinned_fallback = mid;
        continue;
      }
      rejected[as_index(mid)] = 1;
      witness[as_index(w1)] = witness[as_index(w2)] = 1;
      reject.push_back(mid);
    }
  }
  if (reject.empty() && pinned_fallback >= 0) reject.push_back(pinned_fallback);
  if (!reject.empty()) {
    std::sort(reject.begin(), reject.end());
    reject.erase(std::unique(reject.begin(), reject.end()), reject.end());
    return std::nullopt;
  }
  ScannedPlanes<T> scanned;  // float: the planes the pre-check scanned every vertex against
  if constexpr (Traits::kPrechecks) {
    for (auto& l : loops) start_at_best_apex(l);
    // Adjacent faces that validation would see as coplanar are merged
    // (and the loops extracted again) rather than losing a vertex: the
    // smaller face's "least significant" vertex can be a real corner.
    // Every merge joins two groups, so this terminates.
    //
    // A merged face that fails planarity or convexity as validation sees
    // it (a twisted sliver quad between two near-duplicate pairs, say) is
    // split back into its triangles, which may not merge again, rather
    // than losing a vertex.  Every split marks more triangles, so this
    // terminates too.
    std::vector<std::pair<int, int>> merges;
    std::vector<int> split;
    prevalidate(loops, reject, false, &merges, &loop_group, &split, &scanned);
    std::vector<int> split_ids;
    for (int f : split) split_ids.push_back(loop_group[as_index(f)]);
    if (split_groups(live, split_ids)) {
      reject.clear();
      recycle_loops();
      return merge_and_build(reject);
    }
    if (!merges.empty()) {
      reject.clear();
      for (const auto& [f, g] : merges) unite(loop_group[as_index(f)], loop_group[as_index(g)]);
      recycle_loops();
      return extract(live, reject);
    }
    if (!reject.empty()) return std::nullopt;
  }
  // Output: compact vertex numbering, original input coordinates.
  std::vector<int>& index = next_vertex_;  // welded point -> output vertex
  index.assign(welded_count(), -1);
  std::vector<Vec3<T>> verts;
  std::vector<Vec3<double>> verts_double;  // exact T with double points: the same vertices as doubles
  out_vertex_.assign(pts_.size(), 0);
  for (const auto& l : loops)
    for (int v : l) out_vertex_[as_index(v)] = 1;
  std::vector<std::vector<int>>& faces = loops;
  for (auto& l : faces) {
    for (int& v : l) {
      if (index[as_index(v)] < 0) {
        index[as_index(v)] = static_cast<int>(verts.size());
        verts.push_back(in_[as_index(pts_[as_index(v)])]);
        if (shadow_) verts_double.push_back(qd_[as_index(v)]);
      }
      v = index[as_index(v)];
    }
  }
  return finish([&] {
    return HullPolyhedron<T>::from_faces(std::move(verts), faces, shadow_ ? &verts_double : nullptr,
                                         scanned.planes.empty() ? nullptr : &scanned);
  });
}

}  // namespace sepax::hull::detail
