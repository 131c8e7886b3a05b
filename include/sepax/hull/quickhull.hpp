// sepax/hull/quickhull.hpp
//
// Quickhull on triangles, the steps of one build (Builder::build):
//   1. build: the initial simplex from extreme points (the farthest pair, the point farthest from their
//      line, the point farthest from that plane); a set within the flat tolerance of a plane goes to the
//      flat hull (flat_hull.hpp), one within it of a line is Collinear.
//   2. solid: the tetrahedron, every other point assigned to the conflict list of a face it is outside.
//   3. expand: the farthest conflict point of a face is the eye; the visible region grows from that face;
//      its boundary is the horizon, coned to the eye; the removed faces' points are assigned to new faces.
//   4. sweep (float T): points kept on a face within eps are tested against the faces around them again.
//   5. merge_and_build (face_merge.hpp) groups the triangles into faces.
//   6. remove_vertices (float and double, large hulls; vertex_removal.hpp): the clean-up's rejected
//      vertices taken out of the triangles, and quickhull and the face stage go on from there.
// The predicates (outside, sees, zero_area, the eye) are HullTraits<T>'s (traits.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory_resource>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "../error.hpp"
#include "../number_traits.hpp"
#include "../orientation_filter.hpp"
#include "../tolerances.hpp"
#include "builder.hpp"
#include "hull_distance.hpp"
#include "orientation_filter.hpp"
#include "plane_tree.hpp"

namespace sepax::hull::detail {

// Triangle f's plane (exact T with double points: computed on first use).
template <Number T>
inline const Plane<T>& Builder<T>::plane(int f) {
  Tri& t = tris_[as_index(f)];
  if (!t.has_plane) {
    assign_plane_through(t.pl, local_point(t.v[0]), local_point(t.v[1]), local_point(t.v[2]));
    t.has_plane = true;
  }
  return t.pl;
}

// One build on the active points: the initial simplex, then the flat hull or quickhull.
template <Number T>
inline std::optional<ConvexPolyhedron<T>> Builder<T>::build(const std::vector<int>& active,
                                                            std::vector<int>& reject) {
  if (active.size() < 3) {
    throw InvalidInput(ErrorCode::TooFewPoints, "convex_hull: fewer than 3 distinct points remain");
  }
  // Farthest pair among the extreme points of each axis.
  std::array<int, 6> ext{};
  for (int c = 0; c < 3; ++c) {
    int lo = active[0], hi = active[0];
    for (int i : active) {
      if (local_point(i)[c] < local_point(lo)[c]) lo = i;
      if (local_point(i)[c] > local_point(hi)[c]) hi = i;
    }
    ext[as_index(2 * c)] = lo;
    ext[as_index(2 * c + 1)] = hi;
  }
  int a = ext[0], b = ext[1];
  T best = squared_norm(Vec3<T>(local_point(b) - local_point(a)));
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) {
      const T d = squared_norm(Vec3<T>(local_point(ext[as_index(j)]) - local_point(ext[as_index(i)])));
      if (d > best) {
        best = d;
        a = ext[as_index(i)];
        b = ext[as_index(j)];
      }
    }
  // Point farthest from line ab.  Exact T with double points: the farthest by the double estimate, when
  // it is certainly off the line (certainly_nonzero_cross; any point off the line gives a valid simplex);
  // otherwise the scan in T.
  const Vec3<T> ab(local_point(b) - local_point(a));
  int c = -1;
  T best_c(0);
  if (shadow_) {
    double best_est = 0;
    const Vec3<double> dab(qd_[as_index(b)] - qd_[as_index(a)]);
    for (int i : active) {
      const double e =
          squared_norm(Vec3<double>(cross(dab, Vec3<double>(qd_[as_index(i)] - qd_[as_index(a)]))));
      if (e > best_est) {
        best_est = e;
        c = i;
      }
    }
    if (c >= 0 && !certainly_nonzero_cross(qd_[as_index(a)], qd_[as_index(b)], qd_[as_index(c)])) c = -1;
    if (c >= 0) best_c = squared_norm(cross(ab, Vec3<T>(local_point(c) - local_point(a))));
  }
  if (c < 0) {
    for (int i : active) {
      const T d = squared_norm(cross(ab, Vec3<T>(local_point(i) - local_point(a))));
      if (d > best_c) {
        best_c = d;
        c = i;
      }
    }
  }
  const bool collinear = c < 0 || Traits::collinear(best_c, ab, flat_);
  if (collinear) {
    throw InvalidInput(ErrorCode::Collinear,
                       "convex_hull: all points lie on one line" + std::string(Traits::kFlatNote));
  }
  // Point farthest from plane abc.
  // (exact T with double points: the farthest by the filter's estimate, when it is certainly off the plane)
  const Plane<T> base = plane_through(local_point(a), local_point(b), local_point(c));
  int d = -1;
  T best_d(0);
  if (shadow_) {
    double best_est = 0;
    bool certain = false;
    for (int i : active) {
      const FilteredSign r =
          orientation_filter(qd_[as_index(a)], qd_[as_index(b)], qd_[as_index(c)], qd_[as_index(i)]);
      if (std::abs(r.det) > best_est) {
        best_est = std::abs(r.det);
        certain = r.certain;
        d = i;
      }
    }
    if (!certain) d = -1;
    if (d >= 0) best_d = abs_of(height(base, d));
  }
  if (d < 0) {
    for (int i : active) {
      const T h = abs_of(height(base, i));
      if (h > best_d) {
        best_d = h;
        d = i;
      }
    }
  }
  if (d < 0 || best_d <= flat_) return polygon(active, base.normal, reject);
  if (simplex_[0] < 0) simplex_ = {a, b, c, d};
  active_ = active;
  base_normal_ = base.normal;
  return solid(active, a, b, c, d, reject);
}

// A new triangle, its plane computed from the apex opposite its longest edge.
template <Number T>
inline int Builder<T>::new_tri(int p0, int p1, int p2) {
  Tri& t = tris_.emplace_back();  // (built in place: no temporary to move for exact T)
  if (!list_pool_.empty()) {      // (a dead triangle's storage: the conflict list grows without allocating)
    t.conflict = std::move(list_pool_.back());
    list_pool_.pop_back();
  }
  t.v = {p0, p1, p2};
  t.nb = {-1, -1, -1};
  Traits::set_plane(*this, t, p0, p1, p2);
  return static_cast<int>(tris_.size()) - 1;
}

// The face indices [first, last) as a range for assign_among (std::views::iota
// does not compile with clang 14 on libstdc++ 12's <ranges>).
struct FaceIndexRange {
  struct iterator {
    int i;
    int operator*() const { return i; }
    iterator& operator++() {
      ++i;
      return *this;
    }
    bool operator!=(const iterator& o) const { return i != o.i; }
  };
  int first, last;
  iterator begin() const { return {first}; }
  iterator end() const { return {last}; }
};

// Assign p to the conflict list of the first of faces [first, end) it is
// outside (Traits::classify); float T: otherwise keep it on the face it is
// highest above, within eps (Traits::NearFace).
template <Number T>
inline void Builder<T>::assign(int p, int first) {
  assign_among(p, FaceIndexRange{first, static_cast<int>(tris_.size())});
}

// assign over the faces listed (ascending; those no longer alive are passed over).
template <Number T>
template <class Faces>
inline void Builder<T>::assign_among(int p, const Faces& faces) {
  typename Traits::NearFace near;
  if (!conflict_among(p, faces, Traits::outside_limit(*this, p), near)) near.keep(*this, p);
}

// assign_among's rule over faces (ascending; those no longer alive are passed over), from a NearFace that
// may already hold faces before them: puts p on the conflict list of the first face it is outside (more
// than limit above, Traits::classify) and returns true; otherwise offers every face to near and returns
// false (the caller then keeps p on near's face).
template <Number T>
template <class Faces, class Limit>
inline bool Builder<T>::conflict_among(int p, const Faces& faces, const Limit& limit,
                                       typename Traits::NearFace& near) {
  for (const int f : faces) {
    if (!tris_[as_index(f)].alive) continue;
    const auto side = Traits::classify(*this, f, p, limit);
    if (side.outside) {
      tris_[as_index(f)].conflict.push_back(p);
      return true;
    }
    near.offer(side, f);
  }
  return false;
}

// Drops the faces no longer alive from live_faces_ (which keeps its index order).
template <Number T>
inline void Builder<T>::drop_dead_live_faces() {
  std::erase_if(live_faces_, [&](int f) { return !tris_[as_index(f)].alive; });
  live_dead_ = 0;
}

/// Float T, a forced eye on many live faces that re-assigns `points` points: keeps live_tree_ over
/// live_faces_ (a face that dies after is passed over by assign_live), built again when the passes that
/// assign_live would otherwise make add up to the cost of a build.  Without a tree each point passes over
/// every live face, with one over the faces made since the tree; those face tests (points x faces) are
/// counted in live_scan_debt_ across eyes, and the tree is built anew once they reach
/// kPlaneTreeBuildPasses passes over the live faces.  Forced steps that re-assign a point or two each (a
/// cylinder's lateral surface) thus share one tree instead of each passing over every face, and the
/// passes made between two builds cost about what a build does.  Either way assign_live finds the same
/// face.
template <Number T>
inline void Builder<T>::index_live_faces(std::size_t points) {
  if constexpr (Traits::kRechecksRounding) {
    if (live_faces_.size() < as_index(kPlaneTreeFaces)) return;
    const std::size_t passed = live_tree_ ? tris_.size() - live_tree_end_ : live_faces_.size();
    live_scan_debt_ += static_cast<double>(points) * static_cast<double>(passed);
    if (live_scan_debt_ < kPlaneTreeBuildPasses * static_cast<double>(live_faces_.size())) return;
    live_scan_debt_ = 0;
    drop_dead_live_faces();
    live_tree_faces_ = live_faces_;
    live_tree_end_ = tris_.size();
    live_tree_.emplace(static_cast<int>(live_tree_faces_.size()), [&](int k) -> const Plane<T>& {
      return tris_[as_index(live_tree_faces_[as_index(k)])].pl;
    });
  }
}

/// assign_among(p, live_faces_), the same decision: on many live faces (float T) through live_tree_ for the
/// faces it holds, then conflict_among over the faces made since (all later in index order).  assign_among
/// puts p on the conflict list of the first live face it is outside (height above threshold(p)), else keeps
/// it on the first face of the largest height if that is above 0: the tree's first_above_or_highest (a dead
/// face's height taken as -infinity) answers both for its faces, and its highest face is offered to the
/// NearFace that conflict_among goes on with, as assign_among's pass would have offered it.
template <Number T>
inline void Builder<T>::assign_live(int p) {
  const std::vector<int>& live = live_faces_;
  if constexpr (!Traits::kRechecksRounding) {
    assign_among(p, live);
  } else {
    if (!live_tree_ || live.size() < as_index(kPlaneTreeFaces)) {
      assign_among(p, live);
      return;
    }
    const T limit = Traits::outside_limit(*this, p);
    const auto r = live_tree_->first_above_or_highest(local_point(p), limit, [&](int k) {
      const Tri& t = tris_[as_index(live_tree_faces_[as_index(k)])];
      return t.alive ? height(t.pl, p) : -std::numeric_limits<T>::infinity();
    });
    if (r.above) {
      tris_[as_index(live_tree_faces_[as_index(r.face)])].conflict.push_back(p);
      return;
    }
    typename Traits::NearFace near;
    if (r.face >= 0) near.offer(typename Traits::Side{false, r.height}, live_tree_faces_[as_index(r.face)]);
    const auto made_since = std::lower_bound(live.begin(), live.end(), static_cast<int>(live_tree_end_));
    if (!conflict_among(p, std::span<const int>(made_since, live.end()), limit, near)) near.keep(*this, p);
  }
}

// How far above a face p must be to be outside it: eps, or 0 for a point
// pinned by a repair pass (it becomes a vertex whenever it is outside).
template <Number T>
inline T Builder<T>::threshold(int p) const {
  return pinned_[as_index(p)] ? T(0) : eps_;
}

// Float T, after the conflict lists are empty: a point kept on a face (at
// most eps above it) was only ever tested against the faces created with
// that face, but later cones may have replaced a neighbouring face it was
// also (within eps) above by a face tilted below it.  Test every such
// point against every live face; one more than eps above any face goes
// back to that face's conflict list and the quickhull loop runs again.
// Each sweep that moves a point adds a vertex or drops an eye, so the sweeps terminate.
// A point the last sweep kept after a search of the faces around its own is kept again without one while
// its face, its threshold and every face that search reached are unchanged (sweep_memo_): a clean-up
// round or an eye then costs searches only around the faces it replaced.
template <Number T>
inline bool Builder<T>::sweep() {
  if constexpr (!Traits::kRechecksRounding) {
    return false;
  } else {
    std::vector<int> live;
    for (std::size_t f = 0; f < tris_.size(); ++f)
      if (tris_[f].alive && !is_zero(tris_[f].pl.normal)) live.push_back(static_cast<int>(f));
    bool moved = false;
    double on_count = 0;
    for (int f : live) on_count += static_cast<double>(tris_[as_index(f)].on.size());
    // Large hulls: instead of every live face, the faces connected to the
    // point's own face through faces it is less than kHullOutsideBound x eps
    // below (a face it is above is among them on a convex surface); the
    // first in creation order, as the scan would find.
    const bool scan = on_count * static_cast<double>(live.size()) <= kHullPointScanPairs;
    const T reach = -(static_cast<T>(kHullOutsideBound) * eps_);
    const bool walk = sweep_walks.load(std::memory_order_relaxed);
    std::vector<int> seen(scan ? 0 : tris_.size(), -1), queue;
    // (the search's answer for a kept point is a function of the point, its face, its threshold and the
    // faces the search reached: while every one of those is still alive, their neighbours are the same
    // faces and the answer is the last sweep's, none above; sweep_memo_ holds what it needs to know)
    std::vector<SweepMemo<T>> memo(scan ? 0 : welded_count());
    std::vector<int> memo_faces;
    if (!scan) memo_faces.reserve(sweep_faces_.size());
    auto recall = [&](int p, int f) {
      if (as_index(p) >= sweep_memo_.size()) return false;
      const SweepMemo<T>& m = sweep_memo_[as_index(p)];
      if (m.face != f || !(m.limit == threshold(p))) return false;
      const auto first = sweep_faces_.begin() + static_cast<std::ptrdiff_t>(m.start);
      const auto last = first + static_cast<std::ptrdiff_t>(m.size);
      if (!std::all_of(first, last, [&](int g) { return tris_[as_index(g)].alive; })) return false;
      memo[as_index(p)] = SweepMemo<T>{f, m.limit, memo_faces.size(), m.size};
      memo_faces.insert(memo_faces.end(), first, last);
      return true;
    };
    // (the scan's first live face above a point, through a tree of their planes on many faces: the same
    // face)
    std::optional<PlaneTree<T>> planes;
    if (scan && on_count >= kPlaneTreePoints && live.size() >= as_index(kPlaneTreeFaces)) {
      planes.emplace(static_cast<int>(live.size()),
                     [&](int k) -> const Plane<T>& { return tris_[as_index(live[as_index(k)])].pl; });
    }
    for (int f : live) {
      std::vector<int>& on = tris_[as_index(f)].on;
      std::size_t keep = 0;
      for (std::size_t i = 0; i < on.size(); ++i) {
        const int p = on[i];
        int out = -1;
        if (scan && planes) {
          const int k = planes->first_above(local_point(p), threshold(p), [&](int j) {
            return height(tris_[as_index(live[as_index(j)])].pl, p);
          });
          if (k >= 0) out = live[as_index(k)];
        } else if (scan) {
          for (std::size_t k = 0; k < live.size() && out < 0; ++k)
            if (height(tris_[as_index(live[k])].pl, p) > threshold(p)) out = live[k];
        } else if (!recall(p, f)) {
          out = first_above_nearby(p, f, reach, walk, seen, queue);
          if (out < 0) {
            memo[as_index(p)] = SweepMemo<T>{f, threshold(p), memo_faces.size(), queue.size()};
            memo_faces.insert(memo_faces.end(), queue.begin(), queue.end());
          }
        }
        if (out >= 0) {
          tris_[as_index(out)].conflict.push_back(p);
          moved = true;
        } else {
          on[keep++] = p;
        }
      }
      on.resize(keep);
    }
    sweep_memo_ = std::move(memo);
    sweep_faces_ = std::move(memo_faces);
    return moved;
  }
}

// The sweep's search on a large hull for kept point p on face f: among the faces connected to f through
// faces p is not more than -reach below (a zero-area face passed through), the first in creation order that
// p is more than threshold(p) above, or -1.  A coplanar region (a cylinder's cap) is within reach of every
// point on it, so the search first walks from f to the neighbour nearest p while that brings it nearer, and
// if it ends within -reach of p, passes only through faces whose triangle is that near p (a face p is
// outside by more than eps is then among them on a convex surface: the point of the hull nearest p is on
// one); a walk that ends farther (or none: walk false, sweep_walks) passes through every such face, as
// from f.  seen (one entry per triangle)
// marks the faces reached for p; queue is scratch.
template <Number T>
inline int Builder<T>::first_above_nearby(int p, int f, T reach, bool walk, std::vector<int>& seen,
                                          std::vector<int>& queue) const {
  const T limit = threshold(p);
  const Vec3<double> x = vec_to_double(local_point(p));
  const double near = -to_double(reach);
  auto distance = [&](int g) {
    const Tri& t = tris_[as_index(g)];
    return distance_to_triangle(x, vec_to_double(local_point(t.v[0])), vec_to_double(local_point(t.v[1])),
                                vec_to_double(local_point(t.v[2])));
  };
  queue.assign(1, f);
  seen[as_index(f)] = p;
  double at = walk ? distance(f) : 0.0;
  for (int g = f; walk && at > near;) {
    int best = -1;
    for (const int n : tris_[as_index(g)].nb) {
      if (seen[as_index(n)] == p) continue;
      const double d = distance(n);
      if (d < at) {
        at = d;
        best = n;
      }
    }
    if (best < 0) break;
    seen[as_index(best)] = p;
    queue.push_back(best);
    g = best;
  }
  const bool local = walk && at <= near;
  int out = -1;
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const int g = queue[k];
    const Tri& t = tris_[as_index(g)];
    if (!is_zero(t.pl.normal)) {
      const T h = height(t.pl, p);
      if (h > limit && (out < 0 || g < out)) out = g;
      if (h < reach) continue;
    }
    if (local && distance(g) > near) continue;
    for (const int n : t.nb)
      if (seen[as_index(n)] != p) {
        seen[as_index(n)] = p;
        queue.push_back(n);
      }
  }
  return out;
}

// The position of vertex from in t (the edge from -> next).
template <Number T>
inline int Builder<T>::edge_index(const Tri& t, int from) {
  for (int i = 0; i < 3; ++i)
    if (t.v[as_index(i)] == from) return i;
  return -1;
}

// Quickhull from the tetrahedron abcd, then the faces merged and extracted.
template <Number T>
inline std::optional<ConvexPolyhedron<T>> Builder<T>::solid(const std::vector<int>& active, int a, int b,
                                                            int c, int d, std::vector<int>& reject) {
  tris_.clear();
  if constexpr (!std::is_trivially_copyable_v<T>) {
    // An exact T's triangle holds a plane of numbers that allocate, and so does moving one (gmpxx's
    // moved-from value): room for about the triangles a quickhull of these points makes (2 per hull vertex
    // on the final hull, and those it replaces on the way), so that the vector rarely grows.
    tris_.reserve(3 * active.size() + 8);
  }
  merge_record_.valid = false;  // (its triangle indices are reused)
  sweep_memo_.clear();          // (the triangle indices it holds are reused)
  sweep_faces_.clear();
  tris_state_ = TrisState::solid_build;
  live_faces_.clear();
  live_made_ = 0;
  live_dead_ = 0;
  live_tree_.reset();
  live_scan_debt_ = 0;
  eye_visits_.assign(welded_count(), 0);
  // Orient the tetrahedron so that its faces point outward.
  if (height(plane_through(local_point(a), local_point(b), local_point(c)), d) > T(0)) std::swap(b, c);
  const int t0 = new_tri(a, b, c);  // d below
  const int t1 = new_tri(a, d, b);
  const int t2 = new_tri(b, d, c);
  const int t3 = new_tri(c, d, a);
  tris_[as_index(t0)].nb = {t1, t2, t3};
  tris_[as_index(t1)].nb = {t3, t2, t0};
  tris_[as_index(t2)].nb = {t1, t3, t0};
  tris_[as_index(t3)].nb = {t2, t1, t0};
  for (int p : active)
    if (p != a && p != b && p != c && p != d) assign(p, 0);
  return quickhull_and_faces(reject);
}

// Quickhull until every conflict list is empty (and, float T, the sweep moves no point), then the faces
// merged and extracted.  From solid's tetrahedron, or (float T, a repair pass) from the previous pass's
// triangles with the pinned points on conflict lists (resume, repair.hpp).
template <Number T>
inline std::optional<ConvexPolyhedron<T>> Builder<T>::quickhull_and_faces(std::vector<int>& reject) {
  do {
    // (a step whose visible region was widened can leave points on
    // conflict lists of faces the pass is already past)
    for (bool pending = true; pending;) {
      expand();
      pending = false;
      for (const Tri& t : tris_) pending = pending || (t.alive && !t.conflict.empty());
    }
  } while (sweep());
  nomerge_.assign(tris_.size(), 0);
  splits_ = 0;
  return merge_and_build(reject);
}

// Quickhull until every conflict list is empty.
template <Number T>
inline void Builder<T>::expand() {
  std::vector<int> visible, stack, mark, touched;
  for (std::size_t fi = 0; fi < tris_.size();) {
    if (!tris_[fi].alive || tris_[fi].conflict.empty()) {
      ++fi;
      continue;
    }
    // eye: the conflict point farthest above this face
    auto& cf = tris_[fi].conflict;
    const std::size_t best = Traits::farthest(*this, static_cast<int>(fi), cf);
    const int eye = cf[best];
    cf.erase(cf.begin() + static_cast<std::ptrdiff_t>(best));
    if (++eye_visits_[as_index(eye)] > kHullMaxEyeVisits) {
      // Float only: the point was removed from the surface and re-entered it
      // more than kHullMaxEyeVisits times (rounding); drop it as below.
      Traits::rounding_case("a point became the eye again and again (a bug)");
      continue;
    }
    // visible region: connected faces the eye is strictly above
    for (int t : touched) mark[as_index(t)] = 0;  // 0 unknown, 1 visible, 2 not visible
    mark.resize(tris_.size(), 0);
    touched.assign(1, static_cast<int>(fi));
    visible.clear();
    bool forced = false;
    stack.assign(1, static_cast<int>(fi));
    mark[fi] = 1;
    for (;;) {
      while (!stack.empty()) {
        const int f = stack.back();
        stack.pop_back();
        visible.push_back(f);
        for (int nbf : tris_[as_index(f)].nb) {
          if (mark[as_index(nbf)] != 0) continue;
          touched.push_back(nbf);
          const bool vis = Traits::sees(*this, nbf, eye);
          mark[as_index(nbf)] = vis ? 1 : 2;
          if (vis) stack.push_back(nbf);
        }
      }
      // A zero-area triangle has no plane: it joins the visible region when
      // two of its neighbours are visible (so it never becomes an island).
      // Float T: so does a triangle whose plane the eye is (within eps)
      // on: otherwise the two cone triangles over its edges fold over it,
      // enclosing the vertex between those edges (Traits::may_join).
      // The eye may be below such a face, so the quickhull lemma (a point
      // above a visible face is inside the new hull or above a new face)
      // does not hold for it: its points, and the vertices the step
      // removes, are then tested against every live face.
      for (int f : touched) {
        if (mark[as_index(f)] != 2) continue;
        const bool flat_tri = Traits::zero_area(*this, f);
        if (!Traits::may_join(*this, f, eye, flat_tri)) continue;
        int nvis = 0;
        for (int nbf : tris_[as_index(f)].nb) nvis += mark[as_index(nbf)] == 1;
        if (nvis >= 2) {
          mark[as_index(f)] = 1;
          stack.push_back(f);
          if (!flat_tri && !(height(tris_[as_index(f)].pl, eye) > T(0))) forced = true;
        }
      }
      if (stack.empty()) break;
    }
    // horizon: directed edges from visible to non-visible faces, as a cycle
    // (starting at the first vertex in the hash map's order: the order of
    // the new faces steers later float decisions, so it is kept as it is;
    // the map's nodes and buckets come from a buffer kept between eyes,
    // which leaves its order unchanged)
    std::pmr::monotonic_buffer_resource pool(horizon_pool_.data(), horizon_pool_.size());
    std::pmr::unordered_map<int, std::pair<int, int>> next(&pool);  // from -> (to, outside face)
    bool simple = true;
    for (int f : visible) {
      const Tri& t = tris_[as_index(f)];
      for (int i = 0; i < 3; ++i) {
        if (mark[as_index(t.nb[as_index(i)])] == 1) continue;
        if (!next.emplace(t.v[as_index(i)], std::make_pair(t.v[as_index((i + 1) % 3)], t.nb[as_index(i)]))
                 .second)
          simple = false;
      }
    }
    std::vector<std::array<int, 3>>& horizon = horizon_;  // (from, to, outside)
    horizon.clear();
    if (simple && !next.empty()) {
      const int start = next.begin()->first;
      int cur = start;
      do {
        const auto it = next.find(cur);
        if (it == next.end()) {
          simple = false;
          break;
        }
        horizon.push_back({cur, it->second.first, it->second.second});
        cur = it->second.first;
      } while (cur != start && horizon.size() <= next.size());
      if (horizon.size() != next.size()) simple = false;
    }
    if (!simple) {
      Traits::rounding_case("non-simple horizon (a bug)");
      // Float only: rounding made the visible region not a disk.  The eye
      // is then nearly on the hull; drop it and go on with this face's
      // other conflict points (fi is still alive).
      continue;
    }
    // cone the horizon to the eye
    const int first_new = static_cast<int>(tris_.size());
    const int nh = static_cast<int>(horizon.size());
    for (int j = 0; j < nh; ++j) new_tri(horizon[as_index(j)][0], horizon[as_index(j)][1], eye);
    for (int j = 0; j < nh; ++j) {
      Tri& t = tris_[as_index(first_new + j)];
      const int out = horizon[as_index(j)][2];
      t.nb[0] = out;
      t.nb[1] = first_new + (j + 1) % nh;
      t.nb[2] = first_new + (j + nh - 1) % nh;
      Tri& o = tris_[as_index(out)];
      o.nb[as_index(edge_index(o, horizon[as_index(j)][1]))] = first_new + j;
    }
    // re-distribute the visible faces' conflict points, and their vertices
    // that are no longer on the surface (inside in exact arithmetic; float:
    // tested like any other point); to the new faces, or when the region was
    // forced, to every live face (listed once, in index order: the faces
    // assign(p, 0) would test; the list is kept between steps: the faces made
    // since are appended, so it stays in index order, and the faces dead since
    // are dropped once they may be half of it, or before a tree is built of it
    // (a dead face in the list is passed over); on many faces searched through
    // a tree of their planes, assign_live)
    std::vector<int>& live = live_faces_;
    if (forced) {
      if (2 * live_dead_ > live.size()) drop_dead_live_faces();
      for (; live_made_ < tris_.size(); ++live_made_)
        if (tris_[live_made_].alive) live.push_back(static_cast<int>(live_made_));
      std::size_t points = 0;  // (at least the points re-assigned below)
      for (int f : visible) points += tris_[as_index(f)].conflict.size() + tris_[as_index(f)].on.size();
      index_live_faces(points);
    }
    auto reassign = [&](int p) {
      if (forced) {
        assign_live(p);
      } else {
        assign(p, first_new);
      }
    };
    if constexpr (Traits::kRechecksRounding) {
      std::vector<int>& gone = gone_;
      gone.clear();
      for (int f : visible)
        for (int v : tris_[as_index(f)].v) gone.push_back(v);
      std::sort(gone.begin(), gone.end());
      gone.erase(std::unique(gone.begin(), gone.end()), gone.end());
      for (int v : gone) {
        bool kept = v == eye;
        for (const auto& hz : horizon) kept = kept || hz[0] == v;
        if (!kept) reassign(v);
      }
    }
    std::vector<int>& pts = moved_;
    live_dead_ += visible.size();  // (an overcount: not every visible face is listed)
    for (int f : visible) {
      Tri& t = tris_[as_index(f)];
      t.alive = false;
      pts.assign(t.conflict.begin(), t.conflict.end());
      pts.insert(pts.end(), t.on.begin(), t.on.end());
      // (a dead face keeps no storage: its lists' arrays go to the faces made next, new_tri)
      for (std::vector<int>* list : {&t.conflict, &t.on}) {
        if (list->capacity() == 0) continue;
        list->clear();
        list_pool_.push_back(std::move(*list));
        *list = std::vector<int>();
      }
      for (int p : pts) reassign(p);
    }
  }
}

}  // namespace sepax::hull::detail
