// sepax/robust/cgal_hull.hpp
//
// cgal::exact_hull<T, K>(points): the convex hull of a point set as a
// validated ConvexPolyhedron<T>, computed with CGAL::convex_hull_3 in an exact
// CGAL kernel K (default CGAL::Epeck), every decision exact:
//   1. points converted to K exactly (never through double for exact T);
//      exact duplicates merged; bad input refused (InvalidInput);
//   2. all points exactly coplanar -> a flat double-sided polygon (2D hull);
//   3. otherwise CGAL::convex_hull_3, exactly coplanar triangles merged into
//      maximal faces, boundary loops extracted, collinear and interior
//      vertices removed;
//   4. ConvexPolyhedron<T>::from_faces on the ORIGINAL input coordinates of the
//      surviving points (nothing is rounded or moved), so the result validates.
// For float/double T the combinatorics are those of the exact hull of the
// float points (converted exactly); the output keeps the float coordinates.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/error.hpp>
#include <sepax/robust/cgal_adapters.hpp>

namespace sepax::cgal {

namespace hull_detail {
struct LessXYZ {
  template <class P>
  bool operator()(const P& a, const P& b) const {
    return CGAL::compare_xyz(a, b) == CGAL::SMALLER;
  }
};

inline int find(std::vector<int>& parent, int x) {
  while (parent[static_cast<std::size_t>(x)] != x) {
    parent[static_cast<std::size_t>(x)] =
        parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    x = parent[static_cast<std::size_t>(x)];
  }
  return x;
}
}  // namespace hull_detail

/// The steps of the header comment, in detail:
///   1. points converted to K exactly (cgal_adapters.hpp: never through double
///      for exact T); exact duplicates merged; fewer than 3 distinct points ->
///      InvalidInput(TooFewPoints); all on one line -> InvalidInput(Collinear);
///      NaN/infinity (float T) -> InvalidInput(NonFinite).
///   2. all points exactly coplanar -> a flat double-sided polygon: the 2D hull
///      (monotone chain, exact orientation tests, collinear boundary points
///      dropped) in the projection that drops the normal's largest coordinate.
///   3. otherwise CGAL::convex_hull_3 into a triangulated Surface_mesh; adjacent
///      triangles that are exactly coplanar are merged into one face (maximal
///      faces); each face's boundary loop is extracted; vertices left in the
///      middle of an edge (exactly collinear with their loop neighbours) and
///      vertices inside merged faces are removed.
///   4. ConvexPolyhedron<T>::from_faces on the original input coordinates.
template <Number T, class K = CGAL::Epeck>
ConvexPolyhedron<T> exact_hull(const std::vector<Vec3<T>>& points) {
  using P3 = typename K::Point_3;
  using FT = typename K::FT;
  std::vector<P3> pts;   // distinct points, in first-occurrence order
  std::vector<int> src;  // input index of each distinct point
  std::map<P3, int, hull_detail::LessXYZ> index;
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      if (!number_traits<T>::is_finite(points[i][c]))
        throw InvalidInput(ErrorCode::NonFinite,
                           "point " + std::to_string(i) + " has a non-finite coordinate");
    const P3 p(convert_number<FT>(points[i][0]), convert_number<FT>(points[i][1]),
               convert_number<FT>(points[i][2]));
    if (index.emplace(p, static_cast<int>(pts.size())).second) {
      pts.push_back(p);
      src.push_back(static_cast<int>(i));
    }
  }
  const auto out_point = [&](int distinct) {
    return points[static_cast<std::size_t>(src[static_cast<std::size_t>(distinct)])];
  };
  if (pts.size() < 3)
    throw InvalidInput(ErrorCode::TooFewPoints,
                       "a hull needs at least 3 distinct points, got " + std::to_string(pts.size()));
  std::size_t i2 = 2;
  while (i2 < pts.size() && CGAL::collinear(pts[0], pts[1], pts[i2])) ++i2;
  if (i2 == pts.size()) throw InvalidInput(ErrorCode::Collinear, "all points lie on one line");
  std::size_t i3 = 2;
  while (i3 < pts.size() && CGAL::orientation(pts[0], pts[1], pts[i2], pts[i3]) == CGAL::COPLANAR) ++i3;

  if (i3 == pts.size()) {
    // ---- flat: 2D hull in the projection dropping the normal's largest coordinate
    const auto n = CGAL::cross_product(pts[1] - pts[0], pts[i2] - pts[0]);
    const FT ax = CGAL::abs(n.x()), ay = CGAL::abs(n.y()), az = CGAL::abs(n.z());
    const int drop = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
    const int u = (drop + 1) % 3, w = (drop + 2) % 3;
    std::vector<int> order(pts.size());
    std::iota(order.begin(), order.end(), 0);
    const auto cu = [&](int i) { return pts[static_cast<std::size_t>(i)].cartesian(u); };
    const auto cw = [&](int i) { return pts[static_cast<std::size_t>(i)].cartesian(w); };
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return cu(a) < cu(b) || (cu(a) == cu(b) && cw(a) < cw(b)); });
    const auto turn = [&](int o, int a, int b) {  // sign of the 2D cross (a-o) x (b-o)
      return CGAL::sign(FT((cu(a) - cu(o)) * (cw(b) - cw(o)) - (cw(a) - cw(o)) * (cu(b) - cu(o))));
    };
    std::vector<int> hull;
    for (int pass = 0; pass < 2; ++pass) {  // monotone chain, strictly convex corners only
      const std::size_t base = hull.size();
      for (int idx : order) {
        while (hull.size() >= base + 2 && turn(hull[hull.size() - 2], hull.back(), idx) != CGAL::POSITIVE)
          hull.pop_back();
        hull.push_back(idx);
      }
      hull.pop_back();
      std::reverse(order.begin(), order.end());
    }
    std::vector<Vec3<T>> loop;
    for (int i : hull) loop.push_back(out_point(i));
    return ConvexPolyhedron<T>::polygon(std::move(loop));
  }

  // ---- solid: CGAL's triangulated hull, then maximal faces
  using Mesh = CGAL::Surface_mesh<P3>;
  Mesh sm;
  CGAL::convex_hull_3(pts.begin(), pts.end(), sm);
  using fd = typename Mesh::Face_index;
  using hd = typename Mesh::Halfedge_index;
  const int nf = static_cast<int>(sm.number_of_faces());
  std::map<fd, int> fid;
  std::vector<fd> flist;
  for (const fd f : sm.faces()) {
    fid.emplace(f, static_cast<int>(flist.size()));
    flist.push_back(f);
  }
  std::vector<int> parent(static_cast<std::size_t>(nf));
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto e : sm.edges()) {
    const hd h = sm.halfedge(e), o = sm.opposite(h);
    if (sm.is_border(h) || sm.is_border(o)) continue;
    const P3& a = sm.point(sm.source(h));
    const P3& b = sm.point(sm.target(h));
    const P3& c = sm.point(sm.target(sm.next(h)));
    const P3& d = sm.point(sm.target(sm.next(o)));
    if (CGAL::coplanar(a, b, c, d)) {
      const int x = hull_detail::find(parent, fid.at(sm.face(h))),
                y = hull_detail::find(parent, fid.at(sm.face(o)));
      if (x != y) parent[static_cast<std::size_t>(x)] = y;
    }
  }
  // boundary loops of each group (CCW seen from outside, as CGAL's hull faces)
  std::map<int, std::map<typename Mesh::Vertex_index, hd>> boundary;  // group -> source -> halfedge
  for (const hd h : sm.halfedges()) {
    if (sm.is_border(h) || sm.is_border(sm.opposite(h))) continue;
    const int g = hull_detail::find(parent, fid.at(sm.face(h)));
    const int go = hull_detail::find(parent, fid.at(sm.face(sm.opposite(h))));
    if (g != go) boundary[g].emplace(sm.source(h), h);
  }
  std::vector<std::vector<typename Mesh::Vertex_index>> loops;
  for (auto& [g, by_source] : boundary) {
    std::vector<typename Mesh::Vertex_index> loop;
    hd h = by_source.begin()->second;
    const hd start = h;
    do {
      loop.push_back(sm.source(h));
      h = by_source.at(sm.target(h));
      if (loop.size() > by_source.size()) throw std::logic_error("exact_hull: face boundary is not one loop");
    } while (h != start);
    // drop corners in the middle of an edge (exactly collinear with neighbours)
    bool changed = true;
    while (changed && loop.size() > 3) {
      changed = false;
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const auto& pv = sm.point(loop[(i + loop.size() - 1) % loop.size()]);
        const auto& cv = sm.point(loop[i]);
        const auto& nv = sm.point(loop[(i + 1) % loop.size()]);
        if (CGAL::collinear(pv, cv, nv)) {
          loop.erase(loop.begin() + static_cast<std::ptrdiff_t>(i));
          changed = true;
          break;
        }
      }
    }
    loops.push_back(std::move(loop));
  }
  // keep the vertices some face uses, in input order
  std::map<typename Mesh::Vertex_index, int> distinct_of;
  for (const auto v : sm.vertices()) distinct_of.emplace(v, index.at(sm.point(v)));
  std::vector<int> used;
  for (const auto& l : loops)
    for (const auto v : l) used.push_back(distinct_of.at(v));
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::map<int, int> out_index;
  std::vector<Vec3<T>> verts;
  for (int d : used) {
    out_index.emplace(d, static_cast<int>(verts.size()));
    verts.push_back(out_point(d));
  }
  std::vector<std::vector<int>> faces;
  for (const auto& l : loops) {
    std::vector<int> f;
    for (const auto v : l) f.push_back(out_index.at(distinct_of.at(v)));
    faces.push_back(std::move(f));
  }
  return ConvexPolyhedron<T>::from_faces(std::move(verts), faces);
}

}  // namespace sepax::cgal
