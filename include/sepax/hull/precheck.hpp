// sepax/hull/precheck.hpp
//
// Float T: check what ConvexPolyhedron validation will check, with half its tolerances, so the builder
// never hands validation a hull it would refuse (Builder::prevalidate):
//   1. plane_triple: the vertex triple validation takes each face's plane from (as convex_polyhedron.hpp);
//   2. start_at_best_apex: each loop starts at its best-conditioned corner;
//   3. per face and start of its loop: the plane triple's shape, planarity, convexity (every vertex, or on a
//      large hull the local certificate across each edge) and no reflex corner;
//   4. adjacent faces validation would see as coplanar are merged (or one loses a vertex);
//   5. a face that still fails loses its least significant vertex (least_significant); BadScale when
//      float cannot resolve the shape that far from the origin.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <type_traits>
#include <vector>

#include "../convex_polyhedron.hpp"
#include "../error.hpp"
#include "../number_traits.hpp"
#include "../tolerances.hpp"
#include "builder.hpp"
#include "vertex_tree.hpp"

namespace sepax::hull::detail {

// The loop positions of the vertex triple validation takes a face's plane from: the largest triangle
// (0, j, k) of the loop, or (0, n/3, 2n/3) for more than 16 vertices.
template <Number T>
inline std::array<int, 3> plane_triple(const std::vector<Vec3<T>>& pts) {
  const int n = static_cast<int>(pts.size());
  std::array<int, 3> best{0, 1, 2};
  if (n <= 16) {
    T best_area(-1);
    for (int j = 1; j + 1 < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        const T a =
            squared_norm(cross(Vec3<T>(pts[as_index(j)] - pts[0]), Vec3<T>(pts[as_index(k)] - pts[0])));
        if (a > best_area) {
          best_area = a;
          best = {0, j, k};
        }
      }
  } else {
    best = {0, n / 3, (2 * n) / 3};
  }
  return best;
}

// ConvexPolyhedron takes each face's plane from a triangle with apex at
// the loop's first vertex, as (v_j - v_0) x (v_k - v_0).  In floating point
// that cross product loses relative accuracy u / sin(angle at v_0), which
// is catastrophic for a thin face whose first vertex is at a sharp corner.
// Start each loop at its corner with the largest sine.
template <Number T>
inline void Builder<T>::start_at_best_apex(std::vector<int>& l) const {
  const std::size_t n = l.size();
  std::size_t best = 0;
  T best_s(-1);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3<T> e1(input_point(l[(i + n - 1) % n]) - input_point(l[i])),
        e2(input_point(l[(i + 1) % n]) - input_point(l[i]));
    const T d = length(e1) * length(e2);
    const T sine = d > T(0) ? T(length(cross(e1, e2)) / d) : T(0);
    if (sine > best_s) {
      best_s = sine;
      best = i;
    }
  }
  std::rotate(l.begin(), l.begin() + static_cast<std::ptrdiff_t>(best), l.end());
}

// The vertex whose removal loses the least: the one nearest the segment
// between its neighbours (the segment, not the line: a needle's tip is
// near the line through two points behind it, but far from them).
template <Number T>
inline int Builder<T>::least_significant(const std::vector<int>& l) const {
  const std::size_t n = l.size();
  int best = l[0];
  T best_d(-1);
  bool best_pin = false;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3<T> a = local_point(l[(i + n - 1) % n]), b = local_point(l[(i + 1) % n]), v = local_point(l[i]);
    const Vec3<T> e(b - a), av(v - a), bv(v - b);
    const T el = length(e);
    T d;
    if (!(el > T(0)) || dot(av, e) <= T(0)) {
      d = length(av);
    } else if (dot(bv, e) >= T(0)) {
      d = length(bv);
    } else {
      d = T(length(cross(e, av)) / el);
    }
    // (a point a repair pass pinned only if every vertex of the face is)
    const bool pin = pinned_[as_index(l[i])] != 0;
    if (best_d < T(0) || (pin == best_pin ? d < best_d : best_pin)) {
      best_d = d;
      best = l[i];
      best_pin = pin;
    }
  }
  return best;
}

// The directed edges of a set of face loops, by tail vertex: find(u, v) is
// the face with edge u -> v and the edge's position in that face's loop
// (the last such face, if several have it), or null.
class FaceEdges {
 public:
  struct Edge {
    int head, face, pos;
  };
  FaceEdges(const std::vector<std::vector<int>>& loops, std::size_t points) : start_(points + 1, 0) {
    for (const auto& l : loops)
      for (int v : l) ++start_[as_index(v) + 1];
    for (std::size_t v = 0; v < points; ++v) start_[v + 1] += start_[v];
    edges_.resize(as_index(start_.back()));
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (std::size_t f = 0; f < loops.size(); ++f) {
      const auto& l = loops[f];
      for (std::size_t i = 0; i < l.size(); ++i)
        edges_[as_index(fill[as_index(l[i])]++)] = {l[(i + 1) % l.size()], static_cast<int>(f),
                                                    static_cast<int>(i)};
    }
  }
  const Edge* find(int u, int v) const {
    for (int k = start_[as_index(u) + 1]; k-- > start_[as_index(u)];)
      if (edges_[as_index(k)].head == v) return &edges_[as_index(k)];
    return nullptr;
  }
  std::size_t size() const { return edges_.size(); }

 private:
  std::vector<int> start_;
  std::vector<Edge> edges_;
};

// Solids also get: merges, adjacent faces that validation would see as
// coplanar (and not split apart); split, faces that fail only planarity,
// convexity or a reflex corner (not a zero or sliver plane triangle).
//
// A face whose loop fails only because of where it starts (validation's
// plane triple has its apex at the first vertex: for a twisted sliver
// quad, one start gives a plane all four vertices are within tolerance of,
// another does not) is started at the first corner that passes instead.
template <Number T>
inline void Builder<T>::prevalidate(std::vector<std::vector<int>>& loops, std::vector<int>& reject, bool flat,
                                    std::vector<std::pair<int, int>>* merges,
                                    const std::vector<int>* loop_group, std::vector<int>* split,
                                    ScannedPlanes<T>* scanned) {
  std::vector<int> used;  // the loops' vertices, ascending
  {
    std::vector<char> on_loop(welded_count(), 0);
    for (const auto& l : loops)
      for (int v : l) on_loop[as_index(v)] = 1;
    for (std::size_t v = 0; v < on_loop.size(); ++v)
      if (on_loop[v]) used.push_back(static_cast<int>(v));
  }
  Vec3<T> lo = input_point(used[0]), hi = input_point(used[0]);
  double max_abs = 0;
  for (int v : used)
    for (int c = 0; c < 3; ++c) {
      if (input_point(v)[c] < lo[c]) lo[c] = input_point(v)[c];
      if (input_point(v)[c] > hi[c]) hi[c] = input_point(v)[c];
      max_abs = std::max(max_abs, std::abs(to_double(input_point(v)[c])));
    }
  double d2 = 0;
  for (int c = 0; c < 3; ++c) {
    const double w = to_double(T(hi[c] - lo[c]));
    d2 += w * w;
  }
  const double ext = std::sqrt(d2);
  const T plan_tol = static_cast<T>(kHullPrecheckFraction * Tolerances<T>::kPlanarity * ext);
  const T conv_tol = static_cast<T>(kHullPrecheckFraction * Tolerances<T>::kConvexity * ext);
  const T copl_tol = static_cast<T>(kHullPrecheckCoplanarMargin * Tolerances<T>::kCoplanar / 4 * ext);
  std::vector<Plane<T>> planes;
  // directed edge (u, v) -> (its face, its position in that face's loop)
  const FaceEdges edge_face(loops, welded_count());
  // Convexity: every used vertex against each face plane, or on a large hull
  // the local certificate (as validation): across each edge, the two
  // vertices of the neighbouring face next to that edge.
  const bool scan =
      flat || static_cast<double>(loops.size()) * static_cast<double>(used.size()) <= kConvexityScanPairs;
  // A solid's edges, once: the face across edge i of face f (loops[f][i] -> loops[f][i + 1]) and that
  // face's two vertices next to the edge (the local certificate's witnesses), at across[edge_start[f] + i]
  // (face -1: no twin, an open surface from_faces refuses).
  struct Across {
    int face = -1, w1 = -1, w2 = -1;
  };
  std::vector<Across> across;
  std::vector<int> edge_start(loops.size() + 1, 0);
  if (!flat) {
    across.reserve(edge_face.size());
    for (std::size_t f = 0; f < loops.size(); ++f) {
      const auto& l = loops[f];
      for (std::size_t i = 0; i < l.size(); ++i) {
        Across a;
        if (const auto* twin = edge_face.find(l[(i + 1) % l.size()], l[i])) {
          const auto& m = loops[as_index(twin->face)];
          const std::size_t k = m.size();
          a = {twin->face, m[(as_index(twin->pos) + 2) % k], m[(as_index(twin->pos) + k - 1) % k]};
        }
        across.push_back(a);
      }
      edge_start[f + 1] = static_cast<int>(across.size());
    }
  }
  // (a solid's scan through the tree; a flat pair of faces scans its few vertices directly)
  const VertexTree<T> tree(scan && !flat ? used : std::vector<int>{}, [&](int v) { return input_point(v); });
  std::vector<char> bad(loops.size(), 0);
  std::vector<std::size_t> start(loops.size(), 0);  // loops[f] rotated by start[f] since across was built
  std::vector<int> rotated;                         // (one loop, rotated)
  std::vector<Vec3<T>> pts;                         // (its points)
  for (std::size_t f = 0; f < loops.size(); ++f) {
    for (std::size_t rot = 0; rot < (flat ? 1 : loops[f].size()); ++rot) {
      rotated.assign(loops[f].begin(), loops[f].end());
      std::rotate(rotated.begin(), rotated.begin() + static_cast<std::ptrdiff_t>(rot), rotated.end());
      pts.clear();
      for (int v : rotated) pts.push_back(input_point(v));
      auto t = plane_triple(pts);
      if (flat && f == 1) {  // the back face reuses the front triple, reversed
        std::vector<Vec3<T>> front;
        for (int v : loops[0]) front.push_back(input_point(v));
        const auto t0 = plane_triple(front);
        const std::size_t n = rotated.size();
        // loops[1] is loops[0] reversed: position i there is n-1-i here
        t = {static_cast<int>(n - 1 - as_index(t0[0])), static_cast<int>(n - 1 - as_index(t0[2])),
             static_cast<int>(n - 1 - as_index(t0[1]))};
      }
      const Plane<T> pl = plane_through(pts[as_index(t[0])], pts[as_index(t[1])], pts[as_index(t[2])]);
      if (rot == 0) planes.push_back(pl);
      auto h = [&](int v) { return T(dot(pl.normal, input_point(v)) - pl.offset); };
      bool ok = !is_zero(pl.normal);
      // (validation: aspect > sliver; here with a margin)
      ok = ok &&
           sepax::detail::triangle_aspect(pts[as_index(t[0])], pts[as_index(t[1])], pts[as_index(t[2])]) >
               kHullPrecheckSliverMargin * Tolerances<T>::kSliver;
      const bool shape_ok = ok;
      for (int v : rotated) ok = ok && abs_of(h(v)) <= plan_tol;
      if (scan) {
        // every used vertex, those the tree proves below conv_tol skipped (the same decision)
        if (flat) {
          for (int v : used) ok = ok && h(v) <= conv_tol;
        } else if (ok) {
          tree.may_exceed(pl, conv_tol, [&](int v) { ok = ok && h(v) <= conv_tol; });
        }
      } else {
        for (int e = edge_start[f]; e < edge_start[f + 1] && ok; ++e) {
          const Across& a = across[as_index(e)];
          if (a.face >= 0) ok = h(a.w1) <= conv_tol && h(a.w2) <= conv_tol;
        }
      }
      // corners as validation sees them: no reflex turn about this normal
      const std::size_t n = rotated.size();
      for (std::size_t i = 0; i < n && ok; ++i) {
        const Vec3<T> ab(input_point(rotated[i]) - input_point(rotated[(i + n - 1) % n]));
        const Vec3<T> bc(input_point(rotated[(i + 1) % n]) - input_point(rotated[i]));
        const T lab = length(ab);
        ok = lab > T(0) && !(dot(pl.normal, cross(ab, bc)) < -(conv_tol * lab));
      }
      if (ok) {
        bad[f] = 0;
        if (rot != 0) loops[f] = rotated;
        start[f] = rot;
        planes[f] = pl;
        break;
      }
      if (rot == 0) {
        bad[f] = 1;
        if (shape_ok && split != nullptr) split->push_back(static_cast<int>(f));
      }
    }
  }
  if (split != nullptr) {
    std::erase_if(*split, [&](int f) { return !bad[as_index(f)]; });
  }
  // (a solid's scanned planes: every used vertex at most conv_tol above each face's passing plane)
  if (scanned != nullptr) {
    scanned->planes.clear();
    if (scan && !flat) scanned->planes = planes;
    scanned->below = conv_tol;
  }
  for (std::size_t f = 0; f < loops.size() && !flat; ++f) {
    if (bad[f]) continue;
    const auto& l = loops[f];
    for (std::size_t i = 0; i < l.size() && !bad[f]; ++i) {
      const Across& a = across[as_index(edge_start[f]) + (start[f] + i) % l.size()];
      if (a.face < 0) continue;
      const int g = a.face;
      // every vertex of g within copl_tol of f's plane; the witnesses first (off the edge: the vertices
      // that usually fail)
      auto near = [&](int v) {
        return abs_of(T(dot(planes[f].normal, input_point(v)) - planes[f].offset)) <= copl_tol;
      };
      bool coplanar = near(a.w1) && near(a.w2);
      for (std::size_t k = 0; k < loops[as_index(g)].size() && coplanar; ++k)
        coplanar = near(loops[as_index(g)][k]);
      if (coplanar && merges != nullptr &&
          !split_apart(groups_[as_index((*loop_group)[f])], groups_[as_index((*loop_group)[as_index(g)])])) {
        merges->emplace_back(static_cast<int>(f), g);
        break;
      }
      if (coplanar) bad[loops[f].size() <= loops[as_index(g)].size() ? f : as_index(g)] = 1;
    }
  }
  bool any = false;
  for (std::size_t f = 0; f < loops.size(); ++f) {
    if (!bad[f]) continue;
    any = true;
    reject.push_back(least_significant(loops[f]));
  }
  if (any && kHullFarRounding * number_traits<T>::unit_roundoff * max_abs > Tolerances<T>::kPlanarity * ext) {
    throw InvalidInput(
        ErrorCode::BadScale,
        "convex_hull: the points are up to " + std::to_string(max_abs) + " from the origin, too far for " +
            std::string(number_traits<T>::name) + " to resolve a shape of extent " + std::to_string(ext) +
            " within the validation tolerance; use convex_hull_local (the hull in its own frame)" +
            (std::is_same_v<T, float> ? ", or double" : ""));
  }
  std::sort(reject.begin(), reject.end());
  reject.erase(std::unique(reject.begin(), reject.end()), reject.end());
}

}  // namespace sepax::hull::detail
