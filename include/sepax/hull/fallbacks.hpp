// sepax/hull/fallbacks.hpp
//
// Float T: the results tried when the repair passes cannot keep every point near the hull (repair.hpp):
//   1. simplex_hull: the first build's initial simplex (a needle's two tips);
//   2. thin_plane: whether the points are within kHullSlabHalfThickness x eps of one plane;
//   3. shadow_out: how far the points' shadow on that plane reaches beyond the hull's;
//   4. projected_slab: the flat polygon of the points projected onto the slab's mid-plane;
//   5. tent_hull: the hull of the points plus each lost point lifted kHullTentLift x eps into the slab.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "../convex_polyhedron.hpp"
#include "../error.hpp"
#include "../tolerances.hpp"
#include "builder.hpp"
#include "hull_distance.hpp"
#include "polygon_2d.hpp"
#include "precheck.hpp"
#include "vertex_tree.hpp"

namespace sepax::hull::detail {

// Float T: the tetrahedron of the first build's initial simplex (the
// farthest pair, the point farthest from their line, the point farthest
// from that plane), validated; none if the set was flat or it fails.
template <Number T>
inline std::optional<ConvexPolyhedron<T>> Builder<T>::simplex_hull() {
  if (simplex_[0] < 0) return std::nullopt;
  auto [a, b, c, d] = simplex_;
  if (height(plane_through(local_point(a), local_point(b), local_point(c)), d) > T(0)) std::swap(b, c);
  std::vector<Vec3<T>> verts{input_point(a), input_point(b), input_point(c), input_point(d)};
  const std::vector<std::vector<int>> faces{{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
  try {
    auto h = ConvexPolyhedron<T>::from_faces(std::move(verts), faces);
    out_vertex_.assign(pts_.size(), 0);
    for (int v : {a, b, c, d}) out_vertex_[as_index(v)] = 1;
    return h;
  } catch (const InvalidInput&) {
    return std::nullopt;
  }
}

// Float T, the slab fallback (repair.hpp, try_projected_slab).  Whether the welded points
// are within kHullSlabHalfThickness * eps of one plane: the plane of h's largest face
// (one O(n) pass; a well-shaped set stops here), then, if they are within
// twice that of it, the face or coordinate plane across which they spread
// least (a coordinate plane if within 2 eps of the least).  nrm
// is its unit normal, [lo, hi] the points' range of heights along it.
// A candidate normal's range over a few points (those extreme along 13
// fixed directions) is a lower bound of its range over all of them, and
// rules out most of a slab's side faces at once (their normals lie along
// the slab); the rest are measured in full.
template <Number T>
inline bool Builder<T>::thin_plane(const ConvexPolyhedron<T>& h, Vec3<double>& nrm, double& lo,
                                   double& hi) const {
  const double e = to_double(eps_);
  const PolygonFaces polygons = polygon_faces(h, centre_);
  const std::vector<PolygonFace>& faces = polygons.faces;
  auto width = [&](const Vec3<double>& n, double& l, double& u) {
    l = 1e300;
    u = -1e300;
    for (std::size_t i = 0; i < pts_.size(); ++i) {
      const double t = dot(n, vec_to_double(local_point(static_cast<int>(i))));
      l = std::min(l, t);
      u = std::max(u, t);
    }
  };
  // The same range, by the pass above for the first kPasses normals, then through a VertexTree of the
  // points (its largest dot product along n and along -n, the value the pass finds: rounding to nearest
  // is symmetric, so the smallest dot along n is exactly minus the largest along -n).  The normals the
  // lower bound leaves are those across the slab, where the tree's bounds are all near the answer and a
  // query visits most of it: a pass is cheaper than building the tree, unless there are many.
  constexpr int kPasses = 8;
  int passes = 0;
  std::optional<VertexTree<double>> tree;
  auto range = [&](const Vec3<double>& n, double& l, double& u) {
    if (passes < kPasses) {
      ++passes;
      width(n, l, u);
      return;
    }
    if (!tree) {
      std::vector<int> all(pts_.size());
      for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
      tree.emplace(all, [&](int v) { return vec_to_double(local_point(v)); });
    }
    auto along = [&](const Vec3<double>& m) {
      return tree->max_height(Plane<double>{m, 0.0},
                              [&](int v) { return dot(m, vec_to_double(local_point(v))); });
    };
    u = std::max(-1e300, along(n));
    l = std::min(1e300, -along(Vec3<double>(-n)));
  };
  std::size_t big = faces.size();
  double big_area = -1;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (faces[f].area > big_area && squared_norm(faces[f].n) > 0) {
      big_area = faces[f].area;
      big = f;
    }
  }
  if (big == faces.size()) return false;
  width(faces[big].n, lo, hi);
  if (hi - lo > kHullSlabCandidateWidth * e) return false;
  nrm = faces[big].n;
  // The lower bound: the points' values along n are the ones range gives the
  // largest and smallest of, so over a subset the largest is no larger and
  // the smallest no smaller, and (rounding is monotone) the subset's
  // difference is at most range's u - l.  A normal whose subset difference
  // already exceeds the bar cannot be chosen: skipping it changes nothing.
  // (Less a margin for a dot product evaluated here with FMA contraction and
  // there without, or the other way: each evaluation of the 3-term dot of a
  // unit n and x is within 3u sum |n_i x_i| <= 3 sqrt(3) u M of the exact
  // value, M the largest |coordinate| of any point (attained by an axis's
  // extreme point, a probe), so two differ by at most 6 sqrt(3) u M < 2^-49 M
  // for double u = 2^-53; 2^-44 M covers both ends with room to spare.)
  const std::vector<int> probes = extreme_points();
  double reach = 0;
  for (const int i : probes)
    for (int c = 0; c < 3; ++c) reach = std::max(reach, std::abs(to_double(local_point(i)[c])));
  const double margin = 0x1p-44 * reach;
  auto probed_width = [&](const Vec3<double>& n) {
    double l = 1e300, u = -1e300;
    for (const int i : probes) {
      const double t = dot(n, vec_to_double(local_point(i)));
      l = std::min(l, t);
      u = std::max(u, t);
    }
    return (u - l) - margin;
  };
  for (const auto& fc : faces) {
    if (squared_norm(fc.n) == 0 || !(probed_width(fc.n) < hi - lo)) continue;
    double l = 0, u = 0;
    range(fc.n, l, u);
    if (u - l < hi - lo) {
      nrm = fc.n;
      lo = l;
      hi = u;
    }
  }
  // A coordinate plane nearly as thin is preferred: projections onto it
  // share one coordinate exactly, so they stay coplanar in T (far from
  // the origin, float rounding of projections onto a tilted plane is
  // more than the planarity tolerance).
  for (int c = 0; c < 3; ++c) {
    Vec3<double> n(0, 0, 0);
    n[c] = 1;
    if (!(probed_width(n) <= hi - lo + kHullSlabAxisPreference * e)) continue;
    double l = 0, u = 0;
    range(n, l, u);
    if (u - l <= hi - lo + kHullSlabAxisPreference * e) {
      nrm = n;
      lo = l;
      hi = u;
    }
  }
  return hi - lo <= kHullSlabThickness * e;
}

// Float T: the welded points with the largest and the smallest value of
// dot(d, local point) for 13 fixed directions d (the axes, the face
// diagonals, the body diagonals): a few points spread the way the set
// spreads (thin_plane's lower bounds of widths).
template <Number T>
inline std::vector<int> Builder<T>::extreme_points() const {
  constexpr int kDirections = 13;
  static constexpr double kDir[kDirections][3] = {{1, 0, 0},  {0, 1, 0},  {0, 0, 1},  {1, 1, 0},  {1, -1, 0},
                                                  {1, 0, 1},  {1, 0, -1}, {0, 1, 1},  {0, 1, -1}, {1, 1, 1},
                                                  {1, 1, -1}, {1, -1, 1}, {1, -1, -1}};
  std::array<double, kDirections> lo, hi;
  lo.fill(1e300);
  hi.fill(-1e300);
  std::array<int, 2 * kDirections> at{};
  for (std::size_t i = 0; i < pts_.size(); ++i) {
    const Vec3<double> x = vec_to_double(local_point(static_cast<int>(i)));
    for (int d = 0; d < kDirections; ++d) {
      const double* w = kDir[d];
      const double t = w[0] * x[0] + w[1] * x[1] + w[2] * x[2];
      if (t < lo[static_cast<std::size_t>(d)]) {
        lo[static_cast<std::size_t>(d)] = t;
        at[static_cast<std::size_t>(2 * d)] = static_cast<int>(i);
      }
      if (t > hi[static_cast<std::size_t>(d)]) {
        hi[static_cast<std::size_t>(d)] = t;
        at[static_cast<std::size_t>(2 * d + 1)] = static_cast<int>(i);
      }
    }
  }
  std::vector<int> out(at.begin(), at.end());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Float T: how far (in units of eps) the points' shadow on a plane (unit
// normal nrm) reaches beyond the shadow of h's vertices: the largest
// distance of a projected point from the 2D hull of the projected vertices
// (face_distance, O(log n) a point on a large loop), a lower bound on its
// distance from h (projection moves no two points apart).
template <Number T>
inline double Builder<T>::shadow_out(const ConvexPolyhedron<T>& h, const Vec3<double>& nrm) const {
  const auto [ax, bx] = plane_basis(nrm);
  const Vec3<double> c = vec_to_double(centre_);
  std::vector<std::array<double, 2>> v;
  for (const auto& x : h.vertices()) {
    const Vec3<double> l(vec_to_double(x) - c);
    v.push_back({dot(ax, l), dot(bx, l)});
  }
  const std::vector<std::size_t> loop = hull_2d(v, 0.0);
  if (loop.size() < 3) return 1e300;
  // the loop as a face in the plane z = 0 of the basis (ax, bx, nrm)
  std::vector<Vec3<double>> corners;
  for (std::size_t k : loop) corners.emplace_back(v[k][0], v[k][1], 0.0);
  PolygonFace shadow;
  shadow.v = corners;
  shadow.n = Vec3<double>(0, 0, 1);
  // A disk and a square about the corners' mean, shrunk to 99% of the largest inside every edge line (none
  // when the mean is not inside every edge): a shadow point within either is inside the shadow by at
  // least 1% of the mean's distance from the nearest edge line, where face_distance's sign tests (cross
  // products of differences, each within a few ulps of |edge| x diameter) cannot call it beyond an edge
  // while that margin exceeds 2^-40 of the shadow's diameter; its distance is 0 without them.  (The square
  // of half-side s is inside an edge at distance d with unit normal (nx, ny) while s (|nx| + |ny|) <= d.)
  double cx = 0, cy = 0;
  for (const Vec3<double>& p : corners) {
    cx += p[0];
    cy += p[1];
  }
  cx /= static_cast<double>(corners.size());
  cy /= static_cast<double>(corners.size());
  double inner = 1e300, square = 1e300, diameter = 0;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Vec3<double>& a = corners[k];
    const Vec3<double>& b = corners[(k + 1) % corners.size()];
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double len = std::sqrt(ex * ex + ey * ey);
    diameter = std::max({diameter, std::abs(a[0] - cx), std::abs(a[1] - cy)});
    if (!(len > 0)) continue;
    // (the loop is counter-clockwise: the mean is left of every edge)
    const double d = (ex * (cy - a[1]) - ey * (cx - a[0])) / len;
    inner = std::min(inner, d);
    square = std::min(square, d / ((std::abs(ex) + std::abs(ey)) / len));
  }
  diameter *= 4;  // (twice the largest |coordinate - mean| bounds a width; twice again for a diagonal)
  const bool usable = inner > 0x1p-40 * diameter;
  const double disk = usable ? 0.99 * inner : 0.0;
  const double disk2 = disk * disk;
  const double half_side = usable ? 0.99 * square : 0.0;
  double worst = 0;
  for (std::size_t i = 0; i < pts_.size(); ++i) {
    const Vec3<double> x = vec_to_double(local_point(static_cast<int>(i)));
    const double px = dot(ax, x), py = dot(bx, x);
    const double dx = px - cx, dy = py - cy;
    if (dx * dx + dy * dy < disk2 || (std::abs(dx) < half_side && std::abs(dy) < half_side)) continue;
    worst = std::max(worst, face_distance(shadow, Vec3<double>(px, py, 0.0), 0.0));
  }
  return worst / to_double(eps_);
}

// Float T: the flat double-sided polygon of the welded points projected
// onto the plane dot(nrm, x) = (lo + hi) / 2 (thin_plane), their 2D hull
// in double with a corner within eps of its neighbours' line dropped, as
// the flat builder does; validated (the first start of the loop
// validation accepts).  Its vertices are projections, not input points;
// every point is within its height, at most (hi - lo) / 2, of the
// polygon.  None if validation refuses every start.
template <Number T>
inline std::optional<ConvexPolyhedron<T>> Builder<T>::projected_slab(const Vec3<double>& nrm, double lo,
                                                                     double hi) {
  const double e = to_double(eps_);
  const std::size_t n = pts_.size();
  const double mid = (lo + hi) / 2;
  const auto [ax, bx] = plane_basis(nrm);
  std::vector<std::array<double, 2>> p2(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3<double> x = vec_to_double(local_point(static_cast<int>(i)));
    p2[i] = {dot(ax, x), dot(bx, x)};
  }
  const std::vector<std::size_t> loop = hull_2d(p2, e);
  if (loop.size() < 3) return std::nullopt;
  std::vector<Vec3<T>> verts;
  for (std::size_t i : loop) {
    const Vec3<double> x(p2[i][0] * ax + p2[i][1] * bx + mid * nrm);
    verts.push_back(Vec3<T>(vec_cast<T>(x) + centre_));
  }
  for (std::size_t rot = 0; rot < verts.size(); ++rot) {
    std::vector<Vec3<T>> v = verts;
    std::rotate(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(rot), v.end());
    // Rounding the projections to T moved them off their plane by up to
    // u |x| (more than the planarity tolerance once a plane triple's
    // tilt is extrapolated, for float far from the origin): project the
    // other vertices again, in double, onto the plane of the rounded
    // triple validation will use, and round them once more.
    const auto tri = plane_triple(v);
    const Vec3<double> p0(vec_to_double(v[as_index(tri[0])]) - vec_to_double(centre_));
    const Vec3<double> tn =
        cross(Vec3<double>(vec_to_double(v[as_index(tri[1])]) - vec_to_double(centre_) - p0),
              Vec3<double>(vec_to_double(v[as_index(tri[2])]) - vec_to_double(centre_) - p0));
    const double tl2 = squared_norm(tn);
    if (tl2 > 0) {
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (static_cast<int>(i) == tri[0] || static_cast<int>(i) == tri[1] || static_cast<int>(i) == tri[2])
          continue;
        const Vec3<double> x(vec_to_double(v[i]) - vec_to_double(centre_));
        const Vec3<double> y(x - (dot(tn, Vec3<double>(x - p0)) / tl2) * tn);
        v[i] = Vec3<T>(vec_cast<T>(y) + centre_);
      }
    }
    try {
      auto r = ConvexPolyhedron<T>::polygon(std::move(v));
      out_vertex_.assign(pts_.size(), 0);  // (no input point is a vertex)
      return r;
    } catch (const InvalidInput&) {
    }
  }
  return std::nullopt;
}

// Float T, the tent fallback (repair.hpp, try_tent): when every repair pass,
// the simplex and the slab polygon leave a point more than kHullRepairTolerance out,
// the hull of the input points plus, for each such point p, the point
// p + kHullTentLift * eps * m, m the unit normal of the thinnest direction
// of the set (the face normal of h across which the points spread
// least) pointing from p's side towards the middle of that spread; built
// by a second build (which does not try a tent itself), so validated.
//
// Why (docs/hull.md, "Slab corners"): on a slab whose rim faces rise
// inward with slope t/d (thickness t, a few hundred eps, over a rim
// width d of a good part of the extent), the two rim faces at a bottom
// corner whose turn is small are within a fraction of eps of coplanar:
// validation refuses them as adjacent coplanar faces (coplanar/4), and
// merged they leave the corner on two faces only (bottom and rim), so it
// must go, far beyond the bottom's edge (the rim's edge on the bottom is
// horizontally undetermined by eps * d / t).  No polyhedron with input
// points as vertices keeps it.  The lifted copy p' sees the rim faces at
// p (it is kHullTentLift * eps above them; they rise by much less than that
// between p and its neighbours) and not the bottom; its cone makes two
// near-vertical faces through the bottom edges at p (their far vertices
// are as far apart as p is from its neighbours' segment: not coplanar)
// and rim faces, so p keeps three faces and p' at least three.  Every
// input point is inside the result (it contains the points' hull); the
// result reaches at most kHullTentLift * eps beyond it (p' is that far from
// p).  None if the second build fails.
template <Number T>
inline std::optional<ConvexPolyhedron<T>> Builder<T>::tent_hull(const ConvexPolyhedron<T>& h,
                                                                Vec3<double>& nrm) {
  std::vector<int> lost;
  double lost_height = 0;
  out_vertex_.assign(pts_.size(), 0);  // (measure every point)
  outside_points(h, lost, lost_height);
  if (lost.empty()) return std::nullopt;
  const PolygonFaces polygons = polygon_faces(h, centre_);
  const std::vector<PolygonFace>& faces = polygons.faces;
  double lo = 0, hi = 0, spread = 1e300;
  for (const auto& fc : faces) {
    if (squared_norm(fc.n) == 0) continue;
    double l = 1e300, u = -1e300;
    for (std::size_t i = 0; i < pts_.size(); ++i) {
      const double t = dot(fc.n, vec_to_double(local_point(static_cast<int>(i))));
      l = std::min(l, t);
      u = std::max(u, t);
    }
    if (u - l < spread) {
      spread = u - l;
      nrm = fc.n;
      lo = l;
      hi = u;
    }
  }
  if (!(spread < 1e300)) return std::nullopt;
  const double lift = kHullTentLift * to_double(eps_), mid = (lo + hi) / 2;
  std::vector<Vec3<T>> aug(in_.begin(), in_.end());
  for (int p : lost) {
    const double hp = dot(nrm, vec_to_double(local_point(p)));
    const Vec3<double> m = hp < mid ? nrm : Vec3<double>(-nrm);
    aug.push_back(vec_cast<T>(Vec3<double>(vec_to_double(input_point(p)) + lift * m)));
  }
  try {
    auto r = build_hull<T>(std::span<const Vec3<T>>(aug.data(), aug.size()), false);
    out_vertex_.assign(pts_.size(), 0);  // (its vertices are measured too)
    return r;
  } catch (const InvalidInput&) {
    return std::nullopt;
  }
}

}  // namespace sepax::hull::detail
