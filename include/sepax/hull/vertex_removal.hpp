// sepax/hull/vertex_removal.hpp
//
// Step 6 of quickhull (quickhull.hpp), float and double, on large hulls: the vertices the clean-up rejects
// (a merged face's corner within eps of its neighbours' line) taken out of the last build's triangles
// instead of building the hull again without them:
//   1. remove_vertices: each rejected vertex's star found among the live triangles, one at a time;
//   2. remove_vertex: the star deleted, the hole capped by the hull of its link and of the points kept
//      on the star's faces (gift-wrapped from the hole's boundary), kept only as a disk convex within
//      eps; else wrapped again over the link alone, the star's other points handed back to quickhull.
// A removal that cannot be kept makes the caller build from the start.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "../number_traits.hpp"
#include "builder.hpp"
#include "quickhull.hpp"

namespace sepax::hull::detail {

/// Float T, on at least kLocalRemovalFaces live triangles: the vertices the clean-up rejected are taken
/// out of the last build's quickhull triangles one at a time (remove_vertex), so the build goes on from
/// there (quickhull_and_faces) instead of starting over without them.  Exact T and small hulls (cheap to
/// build again) always start over.  False when the triangles cannot take the removal (not a solid build's;
/// a vertex's hole that remove_vertex does not fill; a removal's surface already refused by validation in
/// this hull, local_removal_refused_): the caller then builds from the start, which resets the triangles.
template <Number T>
inline bool Builder<T>::remove_vertices(const std::vector<int>& reject) {
  if constexpr (!Traits::kRepairs) {
    return false;
  } else {
    if (tris_state_ == TrisState::none || local_removal_refused_) return false;
    tris_state_ = TrisState::none;  // (until every removal has succeeded)
    // rejected point -> a live triangle around it (-1: none found)
    std::vector<int> where(welded_count(), -2);
    for (int r : reject) where[as_index(r)] = -1;
    std::size_t live = 0;
    for (std::size_t f = 0; f < tris_.size(); ++f) {
      if (!tris_[f].alive) continue;
      ++live;
      for (int v : tris_[f].v)
        if (where[as_index(v)] == -1) where[as_index(v)] = static_cast<int>(f);
    }
    if (live < kLocalRemovalFaces) return false;
    const std::size_t first_new = tris_.size();
    for (int r : reject) {
      int t = where[as_index(r)];
      if (t >= 0 && !tris_[as_index(t)].alive) {
        t = -1;  // (an earlier removal replaced it: the star is among the triangles made since)
        for (std::size_t f = first_new; f < tris_.size() && t < 0; ++f)
          if (tris_[f].alive && edge_index(tris_[f], r) >= 0) t = static_cast<int>(f);
      }
      if (t < 0 || !remove_vertex(r, t)) return false;
    }
    std::erase_if(active_, [&](int p) { return where[as_index(p)] != -2; });
    tris_state_ = TrisState::solid_build;
    return true;
  }
}

/// Float T: vertex v out of the triangulation, given a live triangle around it.  Its star (the triangles
/// around v, each facing the star's direction: the sum of their normals) is deleted and the hole is capped
/// by the hull of the star's link and of the points kept on the star's faces, gift-wrapped from the hole's
/// boundary: across each open edge ab, among the candidates on the hole's side (their triangle facing the
/// star's direction) and not above the triangle across ab, the p that every other one is below the plane
/// of abp; among the candidates within the plane's rounding of it (ties), the one seeing ab at the largest
/// angle (the Delaunay choice, so a flat cap does not fold over itself).  Removing a point keeps every hull
/// edge between the other points, so the link's edges stay edges and the cap is the hull's there.  The cap
/// is kept only as a disk (every edge met twice, 2 I + B - 2 triangles on B boundary and I inner
/// vertices) of triangles with area, each convex within eps across each of its edges both ways (a
/// neighbour's far vertex at most eps above it, and its own at most eps above the neighbour).  A cap not
/// kept (its triangles left dead) is wrapped again over the link's points alone, the hull of the link,
/// held to the same test; the star's other points then go back to quickhull with the rest.  When neither
/// cap is kept, false, the triangles left changed.  The candidates that are not vertices of the cap are
/// assigned to the cap's triangles (a conflict list, or kept on a face within eps), and quickhull goes on
/// from there: its cone steps add those outside the cap.
template <Number T>
inline bool Builder<T>::remove_vertex(int v, int from) {
  std::vector<int> star(1, from);
  for (std::size_t k = 0; k < star.size(); ++k)
    for (const int n : tris_[as_index(star[k])].nb)
      if (tris_[as_index(n)].alive && edge_index(tris_[as_index(n)], v) >= 0 &&
          std::find(star.begin(), star.end(), n) == star.end())
        star.push_back(n);
  // The hole's boundary: each star triangle's edge a -> b opposite v, kept triangle across it.  open: the
  // edges the cap still needs, each with the triangle across it.
  struct Open {
    int a, b, across;
  };
  std::vector<Open> open;
  std::vector<int> cand;
  Vec3<T> up(T(0), T(0), T(0));  // the star's direction: the sum of its triangles' normals
  for (const int f : star) {
    const Tri& t = tris_[as_index(f)];
    const int i = edge_index(t, v);
    const int a = t.v[as_index((i + 1) % 3)], b = t.v[as_index((i + 2) % 3)];
    const int o = t.nb[as_index((i + 1) % 3)];
    if (edge_index(tris_[as_index(o)], v) >= 0) return false;
    open.push_back({a, b, o});
    cand.push_back(a);
    cand.insert(cand.end(), t.on.begin(), t.on.end());
    cand.insert(cand.end(), t.conflict.begin(), t.conflict.end());
    up = Vec3<T>(up + t.pl.normal);
  }
  for (const int f : star)
    if (!(dot(tris_[as_index(f)].pl.normal, up) > T(0))) return false;  // (the star is not a fan along up)
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  // (candidates this near the plane of the best triangle are ties: its rounding)
  const T tie = T(kHullPlaneRoundingSlack * number_traits<T>::unit_roundoff * extent_);
  {
    std::vector<int> from_v;
    for (const Open& e : open) from_v.push_back(e.a);
    std::sort(from_v.begin(), from_v.end());
    if (std::adjacent_find(from_v.begin(), from_v.end()) != from_v.end()) return false;  // a pinched link
  }
  for (const int f : star) {
    Tri& t = tris_[as_index(f)];
    t.alive = false;
    std::vector<int>().swap(t.conflict);
    std::vector<int>().swap(t.on);
  }
  const std::size_t boundary = open.size();
  std::vector<int> link;  // (the link's points: the second attempt's candidates)
  for (const Open& e : open) link.push_back(e.a);
  std::sort(link.begin(), link.end());
  const std::vector<Open> hole = open;
  std::vector<int> cap_vertices;  // (sorted, of the last cap wrapped)
  // The cap gift-wrapped from the hole's boundary over the candidates pool, its triangles from tris_[first]:
  // false when it is not kept (its triangles then dead, the boundary's neighbours still pointing at them).
  auto wrap = [&](const std::vector<int>& pool, int first) {
    auto fail = [&] {
      for (std::size_t f = as_index(first); f < tris_.size(); ++f) tris_[f].alive = false;
      return false;
    };
    open = hole;
    while (!open.empty()) {
      if (tris_.size() - as_index(first) > 2 * pool.size()) return fail();
      const Open e = open.back();
      open.pop_back();
      const Vec3<T>& pa = local_point(e.a);
      const Vec3<T>& pb = local_point(e.b);
      const Plane<T>& outer = tris_[as_index(e.across)].pl;
      auto facing = [&](int q) {
        return dot(cross(Vec3<T>(pb - pa), Vec3<T>(local_point(q) - pa)), up) > T(0) &&
               !(height(outer, q) > T(0));
      };
      int p = -1;
      Plane<T> pl{Vec3<T>(T(0), T(0), T(0)), T(0)};
      for (const int q : pool) {
        if (q == e.a || q == e.b || !facing(q)) continue;
        if (p < 0 || height(pl, q) > T(0)) {
          p = q;
          pl = plane_through(pa, pb, local_point(q));
        }
      }
      if (p < 0) return fail();
      // (the Delaunay choice among the ties: the largest angle at p)
      T best_cos(2);
      int best = p;
      for (const int q : pool) {
        if (q == e.a || q == e.b || !facing(q) || height(pl, q) < -tie) continue;
        const Vec3<T> qa(pa - local_point(q)), qb(pb - local_point(q));
        const T c = T(dot(qa, qb) / (length(qa) * length(qb)));
        if (c < best_cos) {
          best_cos = c;
          best = q;
        }
      }
      const int nt = new_tri(e.a, e.b, best);
      if (Traits::zero_area(*this, nt)) return fail();
      Tri& o = tris_[as_index(e.across)];
      tris_[as_index(nt)].nb[0] = e.across;
      o.nb[as_index(edge_index(o, e.b))] = nt;
      // its other edges x -> y (at position k): met by the open edge x -> y, else open for y -> x
      const std::array<std::array<int, 3>, 2> sides{{{e.b, best, 1}, {best, e.a, 2}}};
      for (const std::array<int, 3>& side : sides) {
        const int x = side[0], y = side[1], k = side[2];  // (named ints: lambdas below capture them)
        const auto match =
            std::find_if(open.begin(), open.end(), [&](const Open& m) { return m.a == x && m.b == y; });
        if (match != open.end()) {
          Tri& m = tris_[as_index(match->across)];
          tris_[as_index(nt)].nb[as_index(k)] = match->across;
          m.nb[as_index(edge_index(m, y))] = nt;
          open.erase(match);
        } else {
          if (std::any_of(open.begin(), open.end(), [&](const Open& m) { return m.a == y && m.b == x; }))
            return fail();  // (the edge y -> x already needed: the cap would not be a surface)
          open.push_back({y, x, nt});
        }
      }
    }
    // a disk, convex within eps across each of its edges
    cap_vertices.clear();
    for (std::size_t f = as_index(first); f < tris_.size(); ++f)
      for (const int u : tris_[f].v) cap_vertices.push_back(u);
    std::sort(cap_vertices.begin(), cap_vertices.end());
    cap_vertices.erase(std::unique(cap_vertices.begin(), cap_vertices.end()), cap_vertices.end());
    const std::size_t inner = cap_vertices.size() - boundary;
    if (tris_.size() - as_index(first) != 2 * inner + boundary - 2) return fail();
    for (std::size_t f = as_index(first); f < tris_.size(); ++f) {
      const Tri& t = tris_[f];
      for (int i = 0; i < 3; ++i) {
        const Tri& n = tris_[as_index(t.nb[as_index(i)])];
        const int across = n.v[as_index((edge_index(n, t.v[as_index(i)]) + 1) % 3)];
        if (height(t.pl, across) > eps_ || height(n.pl, t.v[as_index((i + 2) % 3)]) > eps_) {
          return fail();
        }
      }
    }
    return true;
  };
  int first_cap = static_cast<int>(tris_.size());
  if (!wrap(cand, first_cap)) {
    if (cand.size() == link.size()) return false;  // (the link is every candidate: the same cap)
    first_cap = static_cast<int>(tris_.size());
    if (!wrap(link, first_cap)) return false;
  }
  for (const int q : cand)
    if (q != v && !std::binary_search(cap_vertices.begin(), cap_vertices.end(), q)) assign(q, first_cap);
  return true;
}

}  // namespace sepax::hull::detail
