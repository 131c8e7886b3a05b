// tools/reference/convex_hull_reference.hpp: the quadratic hull builder that
// tools/hull_compare.cpp compares convex_hull against, in namespace sepax::reference.
// convex_hull(points): the convex hull of a point set as a validated
// ConvexPolyhedron<T>, for every number type T (one template, no copies).
//
// Algorithm (quickhull with a clean-up pass):
//   1. Reject NaN/Inf (NonFinite, naming the point).  Weld points closer than
//      Tolerances<T>::kWeld * extent (exact T: remove exact duplicates only).
//      Fewer than 3 distinct points -> TooFewPoints.
//   2. Initial simplex from extreme points: the farthest pair (a, b), the point
//      c farthest from line ab (all within flat*extent of it -> Collinear), the
//      point d farthest from plane abc.  If every point is within
//      flat*extent of plane abc (exactly on it for exact T) the result is a
//      flat double-sided polygon: the 2D convex hull in that plane.
//   3. Quickhull on triangles: every face keeps a conflict list of the points
//      more than coplanar*extent above it (exact T: strictly above); the
//      farthest point of a face is added, the faces it sees are removed and
//      the horizon is coned to it.  Float T: a point 0..eps above a face is
//      kept on it and re-tested when the face is replaced; when no conflicts
//      are left every kept point is tested against every face (one more than
//      eps above goes back to a conflict list).  Only a point below every
//      face it was tested against is dropped.
//   4. Merge: adjacent triangles are grouped into faces.  Exact T: a group is a
//      maximal set of exactly coplanar triangles.  Float T: two groups merge
//      when either one sees every vertex of the other (not shared with it)
//      less than coplanar*extent below its area-weighted plane (nearly
//      coplanar, or concave through rounding).  Zero-area triangles join the
//      neighbour across their longest edge.
//   5. Extract each group's boundary loop; remove vertices left on only two
//      faces (the middle of an edge); check that every loop is simple and
//      strictly convex (float T: every corner more than coplanar*extent away
//      from the line through its neighbours).  A corner that fails is a point
//      (nearly, or for exact T exactly) on the segment between two other hull
//      points: it is removed from the point set and the hull is rebuilt.
//      Float T then checks the result the way ConvexPolyhedron validation
//      will (same plane triples, half the tolerances) after starting each
//      loop at its best-conditioned corner; a face that would fail loses its
//      least significant vertex and the hull is rebuilt -- unless another
//      start of the loop passes, or the face is two faces validation sees as
//      coplanar (merged), or a merged face that can be split back into its
//      triangles.  Every rebuild removes at least one point, every merge or
//      split changes the faces, so the builder terminates.
//   6. Build through ConvexPolyhedron<T>::from_faces, so the result is
//      validated.  A builder output failing validation is a builder bug and is
//      reported as std::logic_error, not as InvalidInput.
//   7. Float T: check every point that is not a vertex against the result:
//      its height above the planes and its Euclidean distance from the face
//      polygons; points more than 2 x eps out are put back, pinned and the
//      hull rebuilt, at most max_repairs times, keeping the best result.  A
//      pinned point is outside a face as soon as it is above it; two faces
//      are not merged when that would leave a pinned vertex inside a face or
//      on only those two faces far (> 2 eps) from the segment between its
//      neighbours (a fold: on a needle or thin slab every face is within eps
//      of every vertex), and faces that already fold over one are split back
//      into their triangles; a pinned point is rejected by the clean-up only
//      when nothing else can be.  If no round keeps every point within 2 eps,
//      the initial simplex (which holds the segment between the farthest
//      pair: a needle's two tips) is returned when it is nearer every point
//      than the best round.  If the points are within
//      hull_slab_half_thickness (63) x eps of a face plane of the best
//      round and it (or its shadow on that plane) is more than 32 eps from
//      a point, the flat polygon of the points projected onto the slab's
//      mid-plane is returned when nearer every point (its vertices are
//      projections, not input points).  If the result would still leave a
//      point more than 32 eps out (a slab corner whose rim faces validation
//      cannot tell apart), the hull of the points plus a copy of each lost
//      point lifted hull_tent_lift (8) x eps into the slab (a "tent") is
//      returned when it keeps every point within 2 eps.  (docs/hull.md:
//      every point within hull_outside_bound = 64 x eps of every face
//      plane, and of the hull, Euclidean, for every set measured.)
//
// Float T computes every decision on the points translated by the centre of
// their bounding box (so an offset from the origin does not cost precision);
// the output vertices are the original input points (never moved or rounded).
// Exact T makes every decision exactly; tolerances are zero.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <map>
#include <numeric>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/error.hpp>
#include <sepax/number_traits.hpp>
#include <sepax/tolerances.hpp>
#include <sepax/vec3.hpp>

namespace sepax::reference {

/// float/double: how far outside its hull an input point may be, in units of
/// Tolerances<T>::kCoplanar * extent (docs/hull.md, "Guarantees"): its height
/// above any face plane, and its Euclidean distance from the hull (measured
/// over every stress set, not proven; docs/hull.md gives the numbers).
inline constexpr double hull_outside_bound = 64;

/// float/double: a point set whose repair rounds failed (docs/hull.md) and
/// that lies within this many coplanar * extent of one plane (a slab up to
/// twice as thick) is returned as the flat polygon of its points projected
/// onto the slab's mid-plane, whose vertices are then not input points.
/// One less than hull_outside_bound: every point is within its height (at
/// most this) of that polygon, and the rest is left for rounding.
inline constexpr double hull_slab_half_thickness = hull_outside_bound - 1;

/// float/double: a point set whose repair rounds lost a slab corner
/// (docs/hull.md, "Slab corners") is returned as the hull of its points
/// plus a copy of each lost point moved this many coplanar * extent into
/// the slab; those copies are vertices that are not input points, and the
/// result reaches at most this far beyond the points' hull.  Eight: above
/// the merge tolerance (1) and validation's coplanar-face tolerance (1/4)
/// with room for the rim's own rise near the corner (a few eps at most).
inline constexpr double hull_tent_lift = 8;

namespace hull_detail {

inline std::size_t sz(int i) { return static_cast<std::size_t>(i); }

template <Number T>
class Builder {
 public:
  explicit Builder(std::span<const Vec3<T>> input) : in_(input) {}

  ConvexPolyhedron<T> run() {
    check_input();
    weld();
    // Build, and rebuild without the points the clean-up pass rejects.
    // Float T: then check every point against the result; points outside
    // by more than repair_tol are pinned (made vertices whenever they are
    // above the hull at all) and put back, and the hull is rebuilt, for a
    // bounded number of repair rounds.
    std::vector<char> removed(pts_.size(), 0);
    pinned_.assign(pts_.size(), 0);
    // best: nearest every point (height or Euclidean distance, whichever is
    // larger); best_h: lowest heights, returned instead when best's heights
    // exceed both height_safe and best_h's (the plane bound is kept first).
    std::optional<ConvexPolyhedron<T>> best, best_h;
    double best_out = 0, best_height = 0, best_h_height = 0;
    for (int repairs = 0;; ++repairs) {
      std::optional<ConvexPolyhedron<T>> result;
      bool failed = false;  // a repair round's rebuild lost too many points
      try {
        for (;;) {
          std::vector<int> active;
          for (std::size_t i = 0; i < pts_.size(); ++i)
            if (!removed[i]) active.push_back(static_cast<int>(i));
          std::vector<int> reject;
          result = build(active, reject);
          if (result) break;
          if (reject.empty()) throw std::logic_error("convex_hull: clean-up made no progress (a bug)");
          for (int r : reject) removed[sz(r)] = 1;
        }
      } catch (const InvalidInput&) {
        // (a repair round may reject points until the rest is Collinear or
        // too few: keep the best earlier round)
        if (!best) throw;
        failed = true;
      }
      if constexpr (exact) {
        return std::move(*result);
      } else {
        std::vector<int> outside;
        if (!failed) {
          double height = 0;
          const double out = outside_points(*result, outside, height);
          if (!best_h || height < best_h_height) {
            best_h = result;
            best_h_height = height;
          }
          if (!best || out < best_out) {
            best = std::move(result);
            best_out = out;
            best_height = height;
          }
        }
        if (failed || outside.empty() || repairs == max_repairs) {
          if (best_out > repair_tol) {
            // The rounds could not keep every point near the hull (a needle
            // a few eps thick, whose faces all fold within eps): the initial
            // simplex contains the segment between the farthest pair, so
            // it may be nearer every point than the best round.
            std::vector<int> none;
            if (auto t = simplex_hull()) {
              double t_height = 0;
              const double t_out = outside_points(*t, none, t_height);
              if (t_out < best_out) {
                best = std::move(t);
                best_out = t_out;
                best_height = t_height;
              }
            }
          }
          // A slab thinner than the bound whose rim corners every round
          // folded away (or whose rim faces are so nearly parallel that a
          // point beyond the rim is below both their planes, so the check
          // above saw it inside: measured here by the slab's shadow, the
          // points projected onto its plane against the projected hull):
          // the flat polygon of the projections onto the slab's mid-plane
          // is within the half-thickness of every point, in height and in
          // distance.
          Vec3<double> nrm(0, 0, 0);
          double lo = 0, hi = 0;
          if (thin_plane(*best, nrm, lo, hi)) {
            const double gap = std::max(best_out, shadow_out(*best, nrm));
            if (gap > height_safe) {
              std::vector<int> none;
              if (auto s = projected_slab(nrm, lo, hi)) {
                double s_height = 0;
                if (outside_points(*s, none, s_height) < gap) return std::move(*s);
              }
            }
          }
          std::optional<ConvexPolyhedron<T>>& chosen =
              best_height > height_safe && best_height > best_h_height ? best_h : best;
          // A slab corner that every round lost (below, tent_hull): if the
          // result would leave a point more than height_safe out, the hull
          // of the points plus a copy of each point it loses, lifted
          // tent_lift * eps into the slab, when nearer every point and its
          // shadow on the slab's plane holds every point's shadow (the
          // distance check above can miss a lost needle tip: the tent is
          // for slabs).
          if (best_out > height_safe && tent_) {
            std::vector<int> none;
            double c_height = 0;
            out_vertex_.assign(pts_.size(), 0);  // (measure every point)
            const double c_out = outside_points(*chosen, none, c_height);
            Vec3<double> t_nrm(0, 0, 0);
            if (c_out > height_safe) {
              if (auto t = tent_hull(*chosen, t_nrm)) {
                double t_height = 0;
                const double t_out = std::max(outside_points(*t, none, t_height), shadow_out(*t, t_nrm));
                if (t_out <= repair_tol && (t_height <= height_safe || t_height <= c_height))
                  return std::move(*t);
              }
            }
          }
          return std::move(*chosen);
        }
        any_pinned_ = true;
        for (int p : outside) {
          removed[sz(p)] = 0;
          pinned_[sz(p)] = 1;
        }
      }
    }
  }

 private:
  static constexpr int max_repairs = 8;
  static constexpr double repair_tol = 2.0;  // x coplanar * extent
  static constexpr double far_tol = 2.0;     // x coplanar * extent (pinned vertices, below)
  // x coplanar * extent: a result nearer every point (Euclidean) is returned
  // only if its plane heights are at most this, or no worse than the lowest
  // of any round (the height bound, hull_outside_bound, is kept first)
  static constexpr double height_safe = 32.0;  // half of hull_outside_bound
  // x coplanar * extent: the largest half-thickness of a slab replaced by
  // its projected polygon (that polygon's height and distance bound)
  static constexpr double slab_max = hull_slab_half_thickness;
  // x coplanar * extent: how far tent_hull lifts a lost corner into the slab
  // (and so how far its result may reach beyond the points' hull)
  static constexpr double tent_lift = hull_tent_lift;

  // Float T, the tent fallback (run() above): when every round, the
  // simplex and the slab polygon leave a point more than repair_tol out,
  // the hull of the input points plus, for each such point p, the point
  // p + tent_lift * eps * m, m the unit normal of the thinnest direction
  // of the set (the face normal of h across which the points spread
  // least) pointing from p's side towards the middle of that spread; built
  // by a second Builder (which does not try a tent itself), so validated.
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
  // p (it is tent_lift * eps above them; they rise by much less than that
  // between p and its neighbours) and not the bottom; its cone makes two
  // near-vertical faces through the bottom edges at p (their far vertices
  // are as far apart as p is from its neighbours' segment: not coplanar)
  // and rim faces, so p keeps three faces and p' at least three.  Every
  // input point is inside the result (it contains the points' hull); the
  // result reaches at most tent_lift * eps beyond it (p' is that far from
  // p).  None if the second build fails.
  std::optional<ConvexPolyhedron<T>> tent_hull(const ConvexPolyhedron<T>& h, Vec3<double>& nrm) {
    std::vector<int> lost;
    double lost_height = 0;
    out_vertex_.assign(pts_.size(), 0);  // (measure every point)
    outside_points(h, lost, lost_height);
    if (lost.empty()) return std::nullopt;
    const std::vector<PolygonFace> faces = polygon_faces(h);
    double lo = 0, hi = 0, spread = 1e300;
    for (const auto& fc : faces) {
      if (squared_norm(fc.n) == 0) continue;
      double l = 1e300, u = -1e300;
      for (std::size_t i = 0; i < pts_.size(); ++i) {
        const double t = dot(fc.n, vec_to_double(Q(static_cast<int>(i))));
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
    const double lift = tent_lift * to_double(eps_), mid = (lo + hi) / 2;
    std::vector<Vec3<T>> aug(in_.begin(), in_.end());
    for (int p : lost) {
      const double hp = dot(nrm, vec_to_double(Q(p)));
      const Vec3<double> m = hp < mid ? nrm : Vec3<double>(-nrm);
      aug.push_back(vec_cast<T>(Vec3<double>(vec_to_double(X(p)) + lift * m)));
    }
    Builder<T> second(std::span<const Vec3<T>>(aug.data(), aug.size()));
    second.tent_ = false;
    try {
      auto r = second.run();
      out_vertex_.assign(pts_.size(), 0);  // (its vertices are measured too)
      return r;
    } catch (const InvalidInput&) {
      return std::nullopt;
    }
  }

  // Float T: the welded points more than repair_tol * eps above a face plane
  // of h (evaluated as a user would, on the input coordinates; plus their
  // rounding) or that far from its face polygons (polygon_distance: a point
  // within eps of two planes of a thin wedge can be far beyond its edge);
  // returns the largest of either in units of eps, and in height the
  // largest height alone.
  double outside_points(const ConvexPolyhedron<T>& h, std::vector<int>& outside, double& height) const {
    double max_abs = 0;
    for (std::size_t i = 0; i < pts_.size(); ++i)
      for (int c = 0; c < 3; ++c) max_abs = std::max(max_abs, std::abs(to_double(X(static_cast<int>(i))[c])));
    const double e = to_double(eps_);
    const double slack = 8.0 * number_traits<T>::unit_roundoff * max_abs;
    double worst = 0;
    const std::vector<PolygonFace> faces = polygon_faces(h);
    for (std::size_t i = 0; i < pts_.size(); ++i) {
      if (out_vertex_[i]) continue;  // (the pre-check held it within conv_tol = 2 eps)
      double hp = -1e300;
      for (int f = 0; f < h.face_count(); ++f)
        hp = std::max(hp, to_double(T(dot(h.plane(f).normal, X(static_cast<int>(i))) - h.plane(f).offset)));
      hp -= slack;
      height = std::max(height, hp / e);
      hp = std::max(hp, polygon_distance(faces, h.is_flat(), vec_to_double(Q(static_cast<int>(i)))) - slack);
      worst = std::max(worst, hp / e);
      if (hp > repair_tol * e) outside.push_back(static_cast<int>(i));
    }
    return worst;
  }

  // Float T: the tetrahedron of the first build's initial simplex (the
  // farthest pair, the point farthest from their line, the point farthest
  // from that plane), validated; none if the set was flat or it fails.
  std::optional<ConvexPolyhedron<T>> simplex_hull() {
    if (simplex_[0] < 0) return std::nullopt;
    auto [a, b, c, d] = simplex_;
    if (height(plane_through(Q(a), Q(b), Q(c)), d) > T(0)) std::swap(b, c);
    std::vector<Vec3<T>> verts{X(a), X(b), X(c), X(d)};
    const std::vector<std::vector<int>> faces{{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
    try {
      auto h = ConvexPolyhedron<T>::from_faces(std::move(verts), faces);
      out_vertex_.assign(pts_.size(), 0);
      for (int v : {a, b, c, d}) out_vertex_[sz(v)] = 1;
      return h;
    } catch (const InvalidInput&) {
      return std::nullopt;
    }
  }

  // Float T, the slab fallback (run() above).  Whether the welded points
  // are within slab_max * eps of one plane: the plane of h's largest face
  // (one O(n) pass; a well-shaped set stops here), then, if they are within
  // twice that of it, the face or coordinate plane across which they spread
  // least (a coordinate plane if within 2 eps of the least).  nrm
  // is its unit normal, [lo, hi] the points' range of heights along it.
  bool thin_plane(const ConvexPolyhedron<T>& h, Vec3<double>& nrm, double& lo, double& hi) const {
    const double e = to_double(eps_);
    const std::vector<PolygonFace> faces = polygon_faces(h);
    auto width = [&](const Vec3<double>& n, double& l, double& u) {
      l = 1e300;
      u = -1e300;
      for (std::size_t i = 0; i < pts_.size(); ++i) {
        const double t = dot(n, vec_to_double(Q(static_cast<int>(i))));
        l = std::min(l, t);
        u = std::max(u, t);
      }
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
    if (hi - lo > 4 * slab_max * e) return false;
    nrm = faces[big].n;
    for (const auto& fc : faces) {
      if (squared_norm(fc.n) == 0) continue;
      double l = 0, u = 0;
      width(fc.n, l, u);
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
      double l = 0, u = 0;
      width(n, l, u);
      if (u - l <= hi - lo + 2 * e) {
        nrm = n;
        lo = l;
        hi = u;
      }
    }
    return hi - lo <= 2 * slab_max * e;
  }

  // Float T: how far (in units of eps) the points' shadow on a plane (unit
  // normal nrm) reaches beyond the shadow of h's vertices: the largest
  // signed distance of a projected point beyond an edge of the 2D hull of
  // the projected vertices (a lower bound on its distance from h).
  double shadow_out(const ConvexPolyhedron<T>& h, const Vec3<double>& nrm) const {
    const auto [ax, bx] = plane_basis(nrm);
    const Vec3<double> c = vec_to_double(centre_);
    std::vector<std::array<double, 2>> v;
    for (const auto& x : h.vertices()) {
      const Vec3<double> l(vec_to_double(x) - c);
      v.push_back({dot(ax, l), dot(bx, l)});
    }
    std::vector<std::size_t> loop = hull_2d(v, 0.0);
    if (loop.size() < 3) return 1e300;
    double worst = 0;
    for (std::size_t i = 0; i < pts_.size(); ++i) {
      const Vec3<double> x = vec_to_double(Q(static_cast<int>(i)));
      const std::array<double, 2> p{dot(ax, x), dot(bx, x)};
      double out = -1e300;
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const auto& a = v[loop[k]];
        const auto& b = v[loop[(k + 1) % loop.size()]];
        const double ex = b[0] - a[0], ey = b[1] - a[1];
        const double len = std::hypot(ex, ey);
        if (len > 0) out = std::max(out, (ex * (p[1] - a[1]) - ey * (p[0] - a[0])) / -len);
      }
      worst = std::max(worst, out);
    }
    return worst / to_double(eps_);
  }

  // An orthonormal basis of the plane with unit normal n.
  static std::pair<Vec3<double>, Vec3<double>> plane_basis(const Vec3<double>& n) {
    int k = 0;
    for (int c = 1; c < 3; ++c)
      if (std::abs(n[c]) < std::abs(n[k])) k = c;
    Vec3<double> ax(0, 0, 0);
    ax[k] = 1;
    ax = Vec3<double>(ax - dot(ax, n) * n);
    ax = Vec3<double>(ax / std::sqrt(squared_norm(ax)));
    return {ax, cross(n, ax)};
  }

  // Counter-clockwise 2D hull (Andrew's monotone chain) of p, indices into
  // p; a corner whose neighbours' line passes within tol of it (either end
  // point within tol of the other edge's line) is dropped.
  static std::vector<std::size_t> hull_2d(const std::vector<std::array<double, 2>>& p, double tol) {
    const std::size_t n = p.size();
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return p[i] < p[j]; });
    auto left = [&](std::size_t i0, std::size_t i1, std::size_t i2) {
      const double ex = p[i1][0] - p[i0][0], ey = p[i1][1] - p[i0][1];
      const double fx = p[i2][0] - p[i1][0], fy = p[i2][1] - p[i1][1];
      const double len = std::max(std::hypot(ex, ey), std::hypot(fx, fy));
      return ex * fy - ey * fx > tol * len;
    };
    return monotone_chain(order, left);
  }

  // Andrew's monotone chain: the counter-clockwise loop of the points that
  // `order` lists, sorted (lower chain forwards, upper chain backwards); a
  // corner stays only while left(previous, corner, next) holds.  Shared by
  // the flat builder (polygon) and the slab fallback (hull_2d).
  template <class I, class Left>
  static std::vector<I> monotone_chain(const std::vector<I>& order, Left left) {
    const std::size_t n = order.size();
    std::vector<I> loop;
    for (int pass = 0; pass < 2 && n > 0; ++pass) {
      const std::size_t base = loop.size();
      for (std::size_t idx = 0; idx < n; ++idx) {
        const I q = pass == 0 ? order[idx] : order[n - 1 - idx];
        while (loop.size() >= base + 2 && !left(loop[loop.size() - 2], loop.back(), q)) loop.pop_back();
        loop.push_back(q);
      }
      loop.pop_back();  // the last point of each chain is the first of the next
    }
    return loop;
  }

  // Float T: the flat double-sided polygon of the welded points projected
  // onto the plane dot(nrm, x) = (lo + hi) / 2 (thin_plane), their 2D hull
  // in double with a corner within eps of its neighbours' line dropped, as
  // the flat builder does; validated (the first start of the loop
  // validation accepts).  Its vertices are projections, not input points;
  // every point is within its height, at most (hi - lo) / 2, of the
  // polygon.  None if validation refuses every start.
  std::optional<ConvexPolyhedron<T>> projected_slab(const Vec3<double>& nrm, double lo, double hi) {
    const double e = to_double(eps_);
    const std::size_t n = pts_.size();
    const double mid = (lo + hi) / 2;
    const auto [ax, bx] = plane_basis(nrm);
    std::vector<std::array<double, 2>> p2(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3<double> x = vec_to_double(Q(static_cast<int>(i)));
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
      const Vec3<double> p0(vec_to_double(v[sz(tri[0])]) - vec_to_double(centre_));
      const Vec3<double> tn = cross(Vec3<double>(vec_to_double(v[sz(tri[1])]) - vec_to_double(centre_) - p0),
                                    Vec3<double>(vec_to_double(v[sz(tri[2])]) - vec_to_double(centre_) - p0));
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

  // Float T: the faces of an output polyhedron as polygons in double, on the
  // local coordinates, with Newell normals (well conditioned for thin faces).
  struct PolygonFace {
    std::vector<Vec3<double>> v;
    Vec3<double> n;
    double off = 0;
    double area = 0;
  };
  std::vector<PolygonFace> polygon_faces(const ConvexPolyhedron<T>& h) const {
    const Vec3<double> c = vec_to_double(centre_);
    std::vector<PolygonFace> faces;
    for (int f = 0; f < h.face_count(); ++f) {
      PolygonFace fc;
      for (int v : h.face_vertices(f)) fc.v.push_back(Vec3<double>(vec_to_double(h.vertex(v)) - c));
      Vec3<double> n(0, 0, 0), m(0, 0, 0);
      for (std::size_t i = 0; i < fc.v.size(); ++i) {
        const Vec3<double>& a = fc.v[i];
        const Vec3<double>& b = fc.v[(i + 1) % fc.v.size()];
        n += Vec3<double>((a[1] - b[1]) * (a[2] + b[2]), (a[2] - b[2]) * (a[0] + b[0]),
                          (a[0] - b[0]) * (a[1] + b[1]));
        m += a;
      }
      const double len = std::sqrt(squared_norm(n));
      if (len > 0) n = n / len;
      fc.n = n;
      fc.area = len / 2;
      fc.off = dot(n, Vec3<double>(m / static_cast<double>(fc.v.size())));
      faces.push_back(std::move(fc));
    }
    return faces;
  }

  // Euclidean distance of x from the polyhedron given by faces: the distance
  // to the nearest face polygon (its height if it projects inside the
  // polygon, else the distance to the nearest edge), or 0 if x is below that
  // face (inside).  (Not "below every face plane": the plane of a tiny face
  // is poorly determined far from it, and a point deep inside can be above
  // it.)  A flat polygon is always measured to its polygon.
  static double polygon_distance(const std::vector<PolygonFace>& faces, bool flat, const Vec3<double>& x) {
    double best = 1e300;
    bool above = false;  // above a face at the nearest distance (within rounding)
    for (const auto& fc : faces) {
      const double h = dot(fc.n, x) - fc.off;
      if (std::abs(h) > best * (1 + 1e-9)) continue;  // (the polygon is no nearer than its plane)
      bool inside = true;
      double d = 1e300;
      const std::size_t n = fc.v.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3<double>& a = fc.v[i];
        const Vec3<double>& b = fc.v[(i + 1) % n];
        const Vec3<double> e(b - a), ax(x - a);
        if (dot(cross(e, fc.n), ax) > 0) inside = false;
        const double l2 = squared_norm(e);
        const double t = l2 > 0 ? std::clamp(dot(ax, e) / l2, 0.0, 1.0) : 0.0;
        d = std::min(d, std::sqrt(squared_norm(Vec3<double>(ax - t * e))));
      }
      if (inside) d = std::abs(h);
      if (d < best * (1 - 1e-9)) {
        best = d;
        above = h > 0;
      } else if (d <= best * (1 + 1e-9)) {
        best = std::min(best, d);
        above = above || h > 0;
      }
    }
    return flat || above ? best : 0.0;
  }

  // ---- input, tolerances, welding -------------------------------------------------

  static constexpr bool exact = number_traits<T>::is_exact;

  void check_input() {
    for (std::size_t i = 0; i < in_.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        if (!number_traits<T>::is_finite(in_[i][c])) {
          std::ostringstream s;
          s << "convex_hull: point " << i << " has a non-finite coordinate (NaN or infinity)";
          throw InvalidInput(ErrorCode::NonFinite, s.str());
        }
      }
    }
    if (in_.size() < 3) {
      throw InvalidInput(ErrorCode::TooFewPoints, "convex_hull: needs at least 3 distinct points, got " +
                                                      std::to_string(in_.size()) + " points");
    }
    Vec3<T> lo = in_[0], hi = in_[0];
    for (const auto& p : in_) {
      for (int c = 0; c < 3; ++c) {
        if (p[c] < lo[c]) lo[c] = p[c];
        if (p[c] > hi[c]) hi[c] = p[c];
      }
    }
    double d2 = 0;
    for (int c = 0; c < 3; ++c) {
      const double w = to_double(T(hi[c] - lo[c]));
      d2 += w * w;
    }
    extent_ = std::sqrt(d2);
    if constexpr (!exact) {
      if (!std::isfinite(extent_) || !std::isfinite(extent_ * extent_ * extent_ * 8.0) ||
          !number_traits<T>::is_finite(static_cast<T>(extent_ * extent_ * 4.0))) {
        throw InvalidInput(ErrorCode::BadScale,
                           "convex_hull: the point set's extent " + format_number(extent_) + " overflows " +
                               std::string(number_traits<T>::name) + " in plane computations");
      }
      // Decisions are made on coordinates relative to the box centre.
      const T two(2);
      centre_ = Vec3<T>((lo[0] + hi[0]) / two, (lo[1] + hi[1]) / two, (lo[2] + hi[2]) / two);
      eps_ = static_cast<T>(Tolerances<T>::kCoplanar * extent_);
      flat_ = static_cast<T>(Tolerances<T>::kFlat * extent_);
      weld_ = static_cast<T>(Tolerances<T>::kWeld * extent_);
    } else {
      centre_ = Vec3<T>(T(0), T(0), T(0));
      eps_ = flat_ = weld_ = T(0);
    }
  }

  Vec3<T> local(const Vec3<T>& p) const {
    if constexpr (exact) {
      return p;
    } else {
      return Vec3<T>(p - centre_);
    }
  }

  void weld() {
    std::vector<Vec3<T>> loc;
    loc.reserve(in_.size());
    for (const auto& p : in_) loc.push_back(local(p));
    std::vector<int> order(in_.size());
    std::iota(order.begin(), order.end(), 0);
    auto lex = [&](int i, int j) {
      const auto& a = loc[sz(i)];
      const auto& b = loc[sz(j)];
      if (a[0] != b[0]) return a[0] < b[0];
      if (a[1] != b[1]) return a[1] < b[1];
      if (a[2] != b[2]) return a[2] < b[2];
      return i < j;
    };
    std::sort(order.begin(), order.end(), lex);
    if constexpr (exact) {
      for (std::size_t k = 0; k < order.size(); ++k) {
        if (k > 0 && loc[sz(order[k])] == loc[sz(order[k - 1])]) continue;
        add_point(order[k], loc[sz(order[k])]);
      }
    } else {
      // Sweep in x: a point is welded to an earlier representative within weld.
      const T w2 = weld_ * weld_;
      std::size_t window = 0;  // first representative with x >= current x - weld
      for (int i : order) {
        const Vec3<T>& p = loc[sz(i)];
        while (window < q_.size() && q_[window][0] < p[0] - weld_) ++window;
        bool dup = false;
        for (std::size_t r = window; r < q_.size() && !dup; ++r) {
          const Vec3<T> d(q_[r] - p);
          dup = squared_norm(d) <= w2;
        }
        if (!dup) add_point(i, p);
      }
    }
    if (pts_.size() < 3) {
      throw InvalidInput(ErrorCode::TooFewPoints,
                         "convex_hull: needs at least 3 distinct points, got " + std::to_string(pts_.size()) +
                             " after merging duplicates" +
                             (exact ? "" : " (points closer than the weld tolerance)"));
    }
  }

  void add_point(int input_index, const Vec3<T>& loc) {
    pts_.push_back(input_index);
    q_.push_back(loc);
  }

  // ---- geometry on local coordinates --------------------------------------------

  struct Tri {
    std::array<int, 3> v{};   // welded point indices, counter-clockwise from outside
    std::array<int, 3> nb{};  // triangle across edge v[i] -> v[i+1]
    Plane<T> pl;
    bool alive = true;
    std::vector<int> conflict;
    // float T: points above this face by at most eps (on it within the
    // tolerance).  They are not outside, but they are not inside either: when
    // the face is replaced they are tested against the new faces again.
    std::vector<int> on;
  };

  const Vec3<T>& Q(int i) const { return q_[sz(i)]; }

  T height(const Plane<T>& pl, int p) const { return T(dot(pl.normal, Q(p)) - pl.offset); }

  // Length of a vector as T for float types (not used for exact T).
  static T length(const Vec3<T>& v) {
    if constexpr (exact) {
      (void)v;
      return T(0);
    } else {
      return number_traits<T>::sqrt(squared_norm(v));
    }
  }

  // ---- the build ---------------------------------------------------------------

  std::optional<ConvexPolyhedron<T>> build(const std::vector<int>& active, std::vector<int>& reject) {
    if (active.size() < 3) {
      throw InvalidInput(ErrorCode::TooFewPoints, "convex_hull: fewer than 3 distinct points remain");
    }
    // Farthest pair among the extreme points of each axis.
    std::array<int, 6> ext{};
    for (int c = 0; c < 3; ++c) {
      int lo = active[0], hi = active[0];
      for (int i : active) {
        if (Q(i)[c] < Q(lo)[c]) lo = i;
        if (Q(i)[c] > Q(hi)[c]) hi = i;
      }
      ext[sz(2 * c)] = lo;
      ext[sz(2 * c + 1)] = hi;
    }
    int a = ext[0], b = ext[1];
    T best = squared_norm(Vec3<T>(Q(b) - Q(a)));
    for (int i = 0; i < 6; ++i)
      for (int j = i + 1; j < 6; ++j) {
        const T d = squared_norm(Vec3<T>(Q(ext[sz(j)]) - Q(ext[sz(i)])));
        if (d > best) {
          best = d;
          a = ext[sz(i)];
          b = ext[sz(j)];
        }
      }
    // Point farthest from line ab.
    const Vec3<T> ab(Q(b) - Q(a));
    int c = -1;
    T best_c(0);
    for (int i : active) {
      const T d = squared_norm(cross(ab, Vec3<T>(Q(i) - Q(a))));
      if (d > best_c) {
        best_c = d;
        c = i;
      }
    }
    bool collinear = c < 0;
    if constexpr (!exact) {
      // distance of c from the line = |ab x ac| / |ab|
      if (!collinear) collinear = number_traits<T>::sqrt(best_c) <= flat_ * length(ab);
    }
    if (collinear) {
      throw InvalidInput(ErrorCode::Collinear, "convex_hull: all points lie on one line" +
                                                   std::string(exact ? "" : " (within the flat tolerance)"));
    }
    // Point farthest from plane abc.
    const Plane<T> base = plane_through(Q(a), Q(b), Q(c));
    int d = -1;
    T best_d(0);
    for (int i : active) {
      const T h = abs_of(height(base, i));
      if (h > best_d) {
        best_d = h;
        d = i;
      }
    }
    if (d < 0 || best_d <= flat_) return polygon(active, base.normal, reject);
    if (simplex_[0] < 0) simplex_ = {a, b, c, d};
    active_ = active;
    base_normal_ = base.normal;
    return solid(active, a, b, c, d, reject);
  }

  // ---- flat point sets: 2D hull (Andrew's monotone chain) -----------------------

  std::optional<ConvexPolyhedron<T>> polygon(const std::vector<int>& active, const Vec3<T>& n,
                                             std::vector<int>& reject) {
    // Sort on the two coordinates other than n's largest component (exact
    // for exact T); decide turns in 3D against n.
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (abs_of(n[i]) > abs_of(n[k])) k = i;
    // Sort along the in-plane axis the points spread most on: the tolerant
    // turn test below only drops points between their neighbours in sort
    // order, so for a needle sorted across its width (by its tiny
    // coordinate first) it dropped one end of the needle (half the extent).
    int u = (k + 1) % 3, w = (k + 2) % 3;
    {
      auto spread = [&](int c) {
        T lo = Q(active[0])[c], hi = lo;
        for (int i : active) {
          lo = std::min(lo, Q(i)[c]);
          hi = std::max(hi, Q(i)[c]);
        }
        return T(hi - lo);
      };
      if (spread(w) > spread(u)) std::swap(u, w);
    }
    std::vector<int> pts = active;
    std::sort(pts.begin(), pts.end(), [&](int i, int j) {
      if (Q(i)[u] != Q(j)[u]) return Q(i)[u] < Q(j)[u];
      return Q(i)[w] < Q(j)[w];
    });
    const bool flip = n[k] < T(0);
    const T nlen = length(n);
    auto left = [&](int p0, int p1, int p2) {
      const Vec3<T> e1(Q(p1) - Q(p0));
      T t = dot(n, cross(e1, Vec3<T>(Q(p2) - Q(p1))));
      if (flip) t = -t;
      if constexpr (exact) {
        return t > T(0);
      } else {
        // distance of p2 from the line p0 p1 (and of p0 from p1 p2) > eps
        const T len = std::max(length(e1), length(Vec3<T>(Q(p2) - Q(p1))));
        return t > eps_ * nlen * len;
      }
    };
    std::vector<int> hull = monotone_chain(pts, left);
    if (hull.size() < 3) {
      throw InvalidInput(ErrorCode::Collinear, "convex_hull: all points lie on one line" +
                                                   std::string(exact ? "" : " (within tolerance)"));
    }
    if constexpr (!exact) {
      // Start at the best-conditioned corner, or if validation would refuse
      // that (a slab up to flat*extent thick is off the plane triple by more
      // than the planarity tolerance from some starts), at the first corner
      // it accepts, rather than losing a vertex.
      start_at_best_apex(hull);
      for (std::size_t rot = 0; rot < hull.size(); ++rot) {
        std::vector<int> front = hull;
        std::rotate(front.begin(), front.begin() + static_cast<std::ptrdiff_t>(rot), front.end());
        std::vector<std::vector<int>> both{front, std::vector<int>(front.rbegin(), front.rend())};
        std::vector<int> r;
        prevalidate(both, r, true);
        if (rot == 0) reject = r;
        if (r.empty()) {
          reject.clear();
          hull = std::move(front);
          break;
        }
      }
      if (!reject.empty()) return std::nullopt;
    }
    std::vector<Vec3<T>> loop;
    out_vertex_.assign(pts_.size(), 0);
    for (int i : hull) {
      loop.push_back(in_[sz(pts_[sz(i)])]);
      out_vertex_[sz(i)] = 1;
    }
    return finish([&] { return ConvexPolyhedron<T>::polygon(std::move(loop)); });
  }

  // ---- solids: quickhull ---------------------------------------------------------

  int new_tri(int p0, int p1, int p2) {
    Tri t;
    t.v = {p0, p1, p2};
    t.nb = {-1, -1, -1};
    if constexpr (exact) {
      t.pl = plane_through(Q(p0), Q(p1), Q(p2));
    } else {
      // apex at the largest angle (opposite the longest edge): the cross
      // product of the two edges from there loses the least accuracy
      const T l0 = squared_norm(Vec3<T>(Q(p1) - Q(p0)));  // opposite p2
      const T l1 = squared_norm(Vec3<T>(Q(p2) - Q(p1)));  // opposite p0
      const T l2 = squared_norm(Vec3<T>(Q(p0) - Q(p2)));  // opposite p1
      if (l1 >= l0 && l1 >= l2) {
        t.pl = plane_through(Q(p0), Q(p1), Q(p2));
      } else if (l2 >= l0) {
        t.pl = plane_through(Q(p1), Q(p2), Q(p0));
      } else {
        t.pl = plane_through(Q(p2), Q(p0), Q(p1));
      }
    }
    tris_.push_back(std::move(t));
    return static_cast<int>(tris_.size()) - 1;
  }

  // Assign p to the first of faces [first, end) it is above by more than eps.
  // Float T: otherwise, if p is above any of them (by at most eps), keep it
  // on the one it is highest above; only a point below all of them is
  // dropped.  (A point within eps above a face is on the hull now, but a
  // later eye can replace that face by faces tilted away from it: a new face
  // through a short horizon edge and an eye barely above the old plane,
  // extrapolated across a wide thin face, can leave the point hundreds of
  // eps outside.  Dropping such points was what lost them.)
  void assign(int p, int first) {
    [[maybe_unused]] int on_face = -1;
    [[maybe_unused]] T on_height(0);
    for (std::size_t f = sz(first); f < tris_.size(); ++f) {
      if (!tris_[f].alive) continue;
      const T h = height(tris_[f].pl, p);
      if (h > threshold(p)) {
        tris_[f].conflict.push_back(p);
        return;
      }
      if constexpr (!exact) {
        if (h > on_height) {
          on_height = h;
          on_face = static_cast<int>(f);
        }
      }
    }
    if constexpr (!exact) {
      if (on_face >= 0) tris_[sz(on_face)].on.push_back(p);
    }
  }

  // How far above a face p must be to be outside it: eps, or 0 for a point
  // pinned by a repair round (it becomes a vertex whenever it is outside).
  T threshold(int p) const {
    if constexpr (exact) {
      (void)p;
      return T(0);
    } else {
      return pinned_[sz(p)] ? T(0) : eps_;
    }
  }

  // Float T, after the conflict lists are empty: a point kept on a face (at
  // most eps above it) was only ever tested against the faces created with
  // that face, but later cones may have replaced a neighbouring face it was
  // also (within eps) above by a face tilted below it.  Test every such
  // point against every live face; one more than eps above any face goes
  // back to that face's conflict list and the quickhull loop runs again.
  // Each round adds a vertex or drops an eye, so the rounds terminate.
  bool sweep() {
    if constexpr (exact) {
      return false;
    } else {
      std::vector<int> live;
      for (std::size_t f = 0; f < tris_.size(); ++f)
        if (tris_[f].alive && !is_zero(tris_[f].pl.normal)) live.push_back(static_cast<int>(f));
      bool moved = false;
      for (int f : live) {
        std::vector<int>& on = tris_[sz(f)].on;
        std::size_t keep = 0;
        for (std::size_t i = 0; i < on.size(); ++i) {
          const int p = on[i];
          int out = -1;
          for (std::size_t k = 0; k < live.size() && out < 0; ++k)
            if (height(tris_[sz(live[k])].pl, p) > threshold(p)) out = live[k];
          if (out >= 0) {
            tris_[sz(out)].conflict.push_back(p);
            moved = true;
          } else {
            on[keep++] = p;
          }
        }
        on.resize(keep);
      }
      return moved;
    }
  }

  static int edge_index(const Tri& t, int from) {
    for (int i = 0; i < 3; ++i)
      if (t.v[sz(i)] == from) return i;
    return -1;
  }

  std::optional<ConvexPolyhedron<T>> solid(const std::vector<int>& active, int a, int b, int c, int d,
                                           std::vector<int>& reject) {
    tris_.clear();
    // Orient the tetrahedron so that its faces point outward.
    if (height(plane_through(Q(a), Q(b), Q(c)), d) > T(0)) std::swap(b, c);
    const int t0 = new_tri(a, b, c);  // d below
    const int t1 = new_tri(a, d, b);
    const int t2 = new_tri(b, d, c);
    const int t3 = new_tri(c, d, a);
    tris_[sz(t0)].nb = {t1, t2, t3};
    tris_[sz(t1)].nb = {t3, t2, t0};
    tris_[sz(t2)].nb = {t1, t3, t0};
    tris_[sz(t3)].nb = {t2, t1, t0};
    for (int p : active)
      if (p != a && p != b && p != c && p != d) assign(p, 0);

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
  void expand() {
    std::vector<int> visible, stack, mark, touched;
    for (std::size_t fi = 0; fi < tris_.size();) {
      if (!tris_[fi].alive || tris_[fi].conflict.empty()) {
        ++fi;
        continue;
      }
      // eye: the conflict point farthest above this face
      auto& cf = tris_[fi].conflict;
      std::size_t best = 0;
      T bh = height(tris_[fi].pl, cf[0]);
      for (std::size_t i = 1; i < cf.size(); ++i) {
        const T h = height(tris_[fi].pl, cf[i]);
        if (h > bh) {
          bh = h;
          best = i;
        }
      }
      const int eye = cf[best];
      cf.erase(cf.begin() + static_cast<std::ptrdiff_t>(best));
      // visible region: connected faces the eye is strictly above
      for (int t : touched) mark[sz(t)] = 0;  // 0 unknown, 1 visible, 2 not visible
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
          for (int nbf : tris_[sz(f)].nb) {
            if (mark[sz(nbf)] != 0) continue;
            touched.push_back(nbf);
            const Tri& nt = tris_[sz(nbf)];
            const bool vis = !is_zero(nt.pl.normal) && height(nt.pl, eye) > T(0);
            mark[sz(nbf)] = vis ? 1 : 2;
            if (vis) stack.push_back(nbf);
          }
        }
        // A zero-area triangle has no plane: it joins the visible region when
        // two of its neighbours are visible (so it never becomes an island).
        // Float T: so does a triangle whose plane the eye is (within eps)
        // on: otherwise the two cone triangles over its edges fold over it,
        // enclosing the vertex between those edges (integer grids: 3000..9000
        // x eps out).
        // The eye may be below such a face, so the quickhull lemma (a point
        // above a visible face is inside the new hull or above a new face)
        // does not hold for it: its points, and the vertices the step
        // removes, are then tested against every live face.
        for (int f : touched) {
          if (mark[sz(f)] != 2) continue;
          const bool flat_tri = is_zero(tris_[sz(f)].pl.normal);
          if (!flat_tri && (exact || height(tris_[sz(f)].pl, eye) < -eps_)) continue;
          int nvis = 0;
          for (int nbf : tris_[sz(f)].nb) nvis += mark[sz(nbf)] == 1;
          if (nvis >= 2) {
            mark[sz(f)] = 1;
            stack.push_back(f);
            if (!flat_tri && !(height(tris_[sz(f)].pl, eye) > T(0))) forced = true;
          }
        }
        if (stack.empty()) break;
      }
      // horizon: directed edges from visible to non-visible faces, as a cycle
      std::unordered_map<int, std::pair<int, int>> next;  // from -> (to, outside face)
      bool simple = true;
      for (int f : visible) {
        const Tri& t = tris_[sz(f)];
        for (int i = 0; i < 3; ++i) {
          if (mark[sz(t.nb[sz(i)])] == 1) continue;
          if (!next.emplace(t.v[sz(i)], std::make_pair(t.v[sz((i + 1) % 3)], t.nb[sz(i)])).second)
            simple = false;
        }
      }
      std::vector<std::array<int, 3>> horizon;  // (from, to, outside)
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
        if constexpr (exact) throw std::logic_error("convex_hull: non-simple horizon (a bug)");
        // Float only: rounding made the visible region not a disk.  The eye
        // is then nearly on the hull; drop it and go on with this face's
        // other conflict points (fi is still alive).
        continue;
      }
      // cone the horizon to the eye
      const int first_new = static_cast<int>(tris_.size());
      const int nh = static_cast<int>(horizon.size());
      for (int j = 0; j < nh; ++j) new_tri(horizon[sz(j)][0], horizon[sz(j)][1], eye);
      for (int j = 0; j < nh; ++j) {
        Tri& t = tris_[sz(first_new + j)];
        const int out = horizon[sz(j)][2];
        t.nb[0] = out;
        t.nb[1] = first_new + (j + 1) % nh;
        t.nb[2] = first_new + (j + nh - 1) % nh;
        Tri& o = tris_[sz(out)];
        o.nb[sz(edge_index(o, horizon[sz(j)][1]))] = first_new + j;
      }
      // re-distribute the visible faces' conflict points, and their vertices
      // that are no longer on the surface (inside in exact arithmetic; float:
      // tested like any other point)
      if constexpr (!exact) {
        std::vector<int> gone;
        for (int f : visible)
          for (int v : tris_[sz(f)].v) gone.push_back(v);
        std::sort(gone.begin(), gone.end());
        gone.erase(std::unique(gone.begin(), gone.end()), gone.end());
        for (int v : gone) {
          bool kept = v == eye;
          for (const auto& hz : horizon) kept = kept || hz[0] == v;
          if (!kept) assign(v, forced ? 0 : first_new);
        }
      }
      for (int f : visible) {
        Tri& t = tris_[sz(f)];
        t.alive = false;
        std::vector<int> pts = std::move(t.conflict);
        t.conflict.clear();
        pts.insert(pts.end(), t.on.begin(), t.on.end());
        t.on.clear();
        for (int p : pts) assign(p, forced ? 0 : first_new);
      }
    }
  }

  // ---- merging triangles into faces -------------------------------------------

  struct Group {
    std::vector<int> verts;                        // sorted welded point indices
    Vec3<T> area = Vec3<T>(T(0), T(0), T(0));      // float: sum of triangle cross products
    Plane<T> pl{Vec3<T>(T(0), T(0), T(0)), T(0)};  // (initialised: groups_ copies Group{})
    bool degenerate = false;                       // a single zero-area triangle
    std::vector<int> splits;                       // sorted ids of the split faces its triangles came from
  };

  // Groups holding triangles of the same split face may not merge again.
  static bool split_apart(const Group& a, const Group& b) {
    for (int x : a.splits)
      if (std::binary_search(b.splits.begin(), b.splits.end(), x)) return true;
    return false;
  }

  // |(v1 - v0) x (v2 - v0)|^2 / 4, from the edge lengths (Heron), accurate
  // for thin triangles where the cross product is not.
  T tri_area2(const Tri& t) const {
    T a = length(Vec3<T>(Q(t.v[1]) - Q(t.v[0])));
    T b = length(Vec3<T>(Q(t.v[2]) - Q(t.v[1])));
    T c = length(Vec3<T>(Q(t.v[0]) - Q(t.v[2])));
    if (a < b) std::swap(a, b);
    if (b < c) std::swap(b, c);
    if (a < b) std::swap(a, b);
    // a >= b >= c: Kahan's stable form of Heron's formula
    const T p = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
    return p > T(0) ? T(p / T(16)) : T(0);
  }

  int find(int x) {
    while (parent_[sz(x)] != x) {
      parent_[sz(x)] = parent_[sz(parent_[sz(x)])];
      x = parent_[sz(x)];
    }
    return x;
  }

  void refit(Group& g) {
    if constexpr (!exact) {
      Vec3<T> n = g.area;
      const T len = length(n);
      if (len > T(0)) n = Vec3<T>(n[0] / len, n[1] / len, n[2] / len);
      T off(0);
      for (int v : g.verts) off = off + dot(n, Q(v));
      off = off / static_cast<T>(g.verts.size());
      g.pl = Plane<T>{n, off};
    }
  }

  // Should groups ga and gb (adjacent, non-degenerate) be one face?
  bool coplanar(const Group& ga, const Group& gb) const {
    if constexpr (exact) {
      return is_zero(cross(ga.pl.normal, gb.pl.normal)) && dot(ga.pl.normal, gb.pl.normal) > T(0);
    } else {
      // Either face sees every vertex of the other (not shared with it) less
      // than eps below its plane.  (Either: a thin face's own plane is poorly
      // determined, so the other face's plane may be the one that tells.)
      auto close = [&](const Group& g, const Group& h) {
        for (int v : h.verts) {
          if (std::binary_search(g.verts.begin(), g.verts.end(), v)) continue;
          if (!(height(g.pl, v) > -eps_)) return false;
        }
        return true;
      };
      return close(ga, gb) || close(gb, ga);
    }
  }

  void unite(int x, int y) {
    x = find(x);
    y = find(y);
    if (x == y) return;
    Group& gx = groups_[sz(x)];
    Group& gy = groups_[sz(y)];
    std::vector<int> vs;
    std::set_union(gx.verts.begin(), gx.verts.end(), gy.verts.begin(), gy.verts.end(),
                   std::back_inserter(vs));
    gx.verts = std::move(vs);
    if (!gy.splits.empty()) {
      std::vector<int> sp;
      std::set_union(gx.splits.begin(), gx.splits.end(), gy.splits.begin(), gy.splits.end(),
                     std::back_inserter(sp));
      gx.splits = std::move(sp);
    }
    if constexpr (!exact) gx.area = Vec3<T>(gx.area + gy.area);
    if (gx.degenerate && !gy.degenerate) gx.pl = gy.pl;
    gx.degenerate = gx.degenerate && gy.degenerate;
    parent_[sz(y)] = x;
    refit(gx);
  }

  std::optional<ConvexPolyhedron<T>> merge_and_build(std::vector<int>& reject) {
    std::vector<int> live;
    for (std::size_t f = 0; f < tris_.size(); ++f)
      if (tris_[f].alive) live.push_back(static_cast<int>(f));
    parent_.assign(tris_.size(), 0);
    std::iota(parent_.begin(), parent_.end(), 0);
    if constexpr (!exact) {
      star_.assign(q_.size(), {});
      for (int f : live)
        for (int v : tris_[sz(f)].v) star_[sz(v)].push_back(f);
    }
    groups_.assign(tris_.size(), Group{});
    for (int f : live) {
      const Tri& t = tris_[sz(f)];
      Group& g = groups_[sz(f)];
      g.verts = {t.v[0], t.v[1], t.v[2]};
      std::sort(g.verts.begin(), g.verts.end());
      g.pl = t.pl;
      g.degenerate = is_zero(t.pl.normal);
      if (nomerge_[sz(f)] != 0) g.splits = {nomerge_[sz(f)]};
      if constexpr (!exact) g.area = T(2) * number_traits<T>::sqrt(tri_area2(t)) * t.pl.normal;
    }
    // Plane merges until nothing changes; then zero-area triangles join a
    // neighbouring face, and if any did, plane merges again: a zero-area
    // triangle between two coplanar faces kept them apart, and once it has
    // joined one of them they are adjacent (left unmerged, validation would
    // refuse the pair and the clean-up would drop a real corner).
    for (bool joined = true; joined;) {
      joined = false;
      for (bool changed = true; changed;) {
        changed = false;
        for (int f : live) {
          for (int i = 0; i < 3; ++i) {
            const int x = find(f), y = find(tris_[sz(f)].nb[sz(i)]);
            if (x == y || groups_[sz(x)].degenerate || groups_[sz(y)].degenerate) continue;
            if (split_apart(groups_[sz(x)], groups_[sz(y)])) continue;
            if (coplanar(groups_[sz(x)], groups_[sz(y)]) && !strands_vertex(x, y)) {
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
          if (!groups_[sz(find(f))].degenerate) continue;
          const Tri& t = tris_[sz(f)];
          int li = 0;
          T ll(-1);
          for (int i = 0; i < 3; ++i) {
            const T l = squared_norm(Vec3<T>(Q(t.v[sz((i + 1) % 3)]) - Q(t.v[sz(i)])));
            if (l > ll) {
              ll = l;
              li = i;
            }
          }
          int target = find(t.nb[sz(li)]);
          if (groups_[sz(target)].degenerate) {
            for (int i = 0; i < 3; ++i)
              if (!groups_[sz(find(t.nb[sz(i)]))].degenerate) target = find(t.nb[sz(i)]);
          }
          if (!groups_[sz(target)].degenerate) {
            unite(target, find(f));
            changed = true;
            joined = true;
          }
        }
      }
    }
    for (int f : live) {
      if (groups_[sz(find(f))].degenerate)
        throw std::logic_error("convex_hull: a zero-area face could not be merged (a bug)");
    }
    return extract(live, reject);
  }

  // ---- loops, clean-up, output ---------------------------------------------------

  std::optional<ConvexPolyhedron<T>> extract(const std::vector<int>& live, std::vector<int>& reject) {
    // boundary edges of each group
    std::unordered_map<int, std::vector<std::pair<int, int>>> bnd;  // group -> (from, to)
    std::vector<int> roots;
    for (int f : live) {
      const int g = find(f);
      auto [it, fresh] = bnd.try_emplace(g);
      if (fresh) roots.push_back(g);
      const Tri& t = tris_[sz(f)];
      for (int i = 0; i < 3; ++i)
        if (find(t.nb[sz(i)]) != g) it->second.emplace_back(t.v[sz(i)], t.v[sz((i + 1) % 3)]);
    }
    std::sort(roots.begin(), roots.end());
    bool collapsed = roots.size() < 4;
    for (int g : roots) collapsed = collapsed || bnd[g].empty();
    if (collapsed) {
      // Float only: everything merged into fewer than 4 faces, so the set is
      // flat within the merge tolerance although the simplex test did not
      // see it: build the flat polygon instead.
      if constexpr (exact) throw std::logic_error("convex_hull: exact hull collapsed (a bug)");
      return polygon(active_, base_normal_, reject);
    }
    std::vector<std::vector<int>> loops;
    std::vector<int> loop_group;
    for (int g : roots) {
      const auto& edges = bnd[g];
      std::unordered_map<int, int> next;
      for (const auto& [u, v] : edges) {
        if (!next.emplace(u, v).second) reject.push_back(u);  // pinched loop
      }
      if (!reject.empty()) continue;
      // the loop through the first edge; any other edges form extra loops
      std::vector<int> loop;
      const int start = edges.front().first;
      int cur = start;
      do {
        loop.push_back(cur);
        cur = next.at(cur);
      } while (cur != start && loop.size() <= edges.size());
      if (loop.size() != edges.size()) {
        // a face with a hole: reject the vertices of the other loops
        std::vector<int> sorted = loop;
        std::sort(sorted.begin(), sorted.end());
        for (const auto& e : edges)
          if (!std::binary_search(sorted.begin(), sorted.end(), e.first)) reject.push_back(e.first);
        continue;
      }
      loops.push_back(std::move(loop));
      loop_group.push_back(g);
    }
    if (!reject.empty()) {
      if constexpr (exact) throw std::logic_error("convex_hull: a merged face is not a disk (a bug)");
      return std::nullopt;
    }
    // Vertices on only two faces lie in the middle of an edge: drop them.
    std::unordered_map<int, int> degree;
    for (const auto& l : loops)
      for (int v : l) ++degree[v];
    if constexpr (!exact) {
      // ... unless a repair round pinned them (they were far from the hull
      // without them) and they are more than far_tol * eps from the segment
      // between their neighbours: then the two faces met at a fold, merged
      // within eps over a real corner (on a needle or thin slab every face
      // is within eps of every vertex: the tip of a needle, a third of its
      // length, was lost this way).  The less planar of the two faces it is
      // on (fold_choice) is split back into its triangles (which may not
      // merge again) and the faces merged again.
      // Every split marks more triangles, so this terminates; a face that
      // cannot be split any more drops the vertex.
      std::map<int, std::vector<int>> folds;  // stranded pinned vertex -> its groups
      for (std::size_t li = 0; li < loops.size(); ++li) {
        const auto& l = loops[li];
        const std::size_t n = l.size();
        for (std::size_t i = 0; i < n; ++i) {
          if (degree[l[i]] >= 3 || !pinned_[sz(l[i])]) continue;
          std::size_t a = (i + n - 1) % n, b = (i + 1) % n;
          while (a != i && degree[l[a]] < 3) a = (a + n - 1) % n;
          while (b != i && degree[l[b]] < 3) b = (b + 1) % n;
          if (a == i || b == i) continue;
          if (segment_distance(l[i], l[a], l[b]) > far_tol * to_double(eps_))
            folds[l[i]].push_back(loop_group[li]);
        }
      }
      if (split_groups(live, fold_choice(live, folds))) {
        reject.clear();
        return merge_and_build(reject);
      }
    }
    for (auto& l : loops) {
      std::vector<int> kept;
      for (int v : l)
        if (degree[v] >= 3) kept.push_back(v);
      l = std::move(kept);
    }
    // Every corner strictly convex; otherwise reject the middle of the three
    // points (it is within tolerance of the segment of the other two).  The
    // other two are its witnesses: a point is not rejected in a round where
    // it witnesses another rejection, nor when one of its own witnesses is
    // rejected (two near-duplicate points at a real corner each fail the
    // corner test with the other as the middle; rejecting both would lose
    // the corner).  Such rejections wait for the next round; the first
    // failing corner of a round is always rejected, so rounds still progress.
    std::vector<char> rejected(q_.size(), 0), witness(q_.size(), 0);
    [[maybe_unused]] int pinned_fallback = -1;
    for (int r : reject) rejected[sz(r)] = 1;
    for (std::size_t li = 0; li < loops.size(); ++li) {
      const auto& l = loops[li];
      const Group& g = groups_[sz(loop_group[li])];
      const std::size_t n = l.size();
      if (n < 3) {
        for (int v : l) {
          reject.push_back(v);
          rejected[sz(v)] = 1;
        }
        if (reject.empty()) throw std::logic_error("convex_hull: empty face (a bug)");
        continue;
      }
      for (std::size_t i = 0; i < n; ++i) {
        const int pa = l[(i + n - 1) % n], pb = l[i], pc = l[(i + 1) % n];
        const Vec3<T> e1(Q(pb) - Q(pa)), e2(Q(pc) - Q(pb));
        const T turn = dot(g.pl.normal, cross(e1, e2));
        bool ok;
        if constexpr (exact) {
          ok = turn > T(0);
          if (turn < T(0) && !is_zero(cross(e1, e2)))
            throw std::logic_error("convex_hull: reflex corner in an exact hull (a bug)");
        } else {
          ok = turn > eps_ * std::max(length(e1), length(e2));
        }
        if (ok) continue;
        // the point opposite the longest side of triangle (pa, pb, pc)
        const T lab = squared_norm(e1), lbc = squared_norm(e2), lca = squared_norm(Vec3<T>(Q(pa) - Q(pc)));
        int mid = pb;
        if (lab >= lbc && lab >= lca) mid = pc;
        if (lbc >= lab && lbc >= lca) mid = pa;
        if (lca >= lab && lca >= lbc) mid = pb;
        const int w1 = mid == pa ? pb : pa, w2 = mid == pc ? pb : pc;
        if (witness[sz(mid)] || rejected[sz(w1)] || rejected[sz(w2)] || rejected[sz(mid)]) continue;
        if constexpr (!exact) {
          // a point a repair round pinned (it was far from the hull without
          // it) is rejected only if nothing else is
          if (pinned_[sz(mid)]) {
            if (pinned_fallback < 0) pinned_fallback = mid;
            continue;
          }
        }
        rejected[sz(mid)] = 1;
        witness[sz(w1)] = witness[sz(w2)] = 1;
        reject.push_back(mid);
      }
    }
    if (reject.empty() && pinned_fallback >= 0) reject.push_back(pinned_fallback);
    if (!reject.empty()) {
      std::sort(reject.begin(), reject.end());
      reject.erase(std::unique(reject.begin(), reject.end()), reject.end());
      return std::nullopt;
    }
    if constexpr (!exact) {
      for (auto& l : loops) start_at_best_apex(l);
      // Adjacent faces that validation would see as coplanar are merged
      // (and the loops extracted again) rather than losing a vertex: the
      // smaller face's "least significant" vertex can be a real corner.
      // Every round merges two groups, so this terminates.
      //
      // A merged face that fails planarity or convexity as validation sees
      // it (a twisted sliver quad between two near-duplicate pairs, say) is
      // split back into its triangles, which may not merge again, rather
      // than losing a vertex.  Every split marks more triangles, so this
      // terminates too.
      std::vector<std::pair<int, int>> merges;
      std::vector<int> split;
      prevalidate(loops, reject, false, &merges, &loop_group, &split);
      std::vector<int> split_ids;
      for (int f : split) split_ids.push_back(loop_group[sz(f)]);
      if (split_groups(live, split_ids)) {
        reject.clear();
        return merge_and_build(reject);
      }
      if (!merges.empty()) {
        reject.clear();
        for (const auto& [f, g] : merges) unite(loop_group[sz(f)], loop_group[sz(g)]);
        return extract(live, reject);
      }
      if (!reject.empty()) return std::nullopt;
    }
    // Output: compact vertex numbering, original input coordinates.
    std::unordered_map<int, int> index;
    std::vector<Vec3<T>> verts;
    out_vertex_.assign(pts_.size(), 0);
    for (const auto& l : loops)
      for (int v : l) out_vertex_[sz(v)] = 1;
    std::vector<std::vector<int>> faces;
    for (const auto& l : loops) {
      std::vector<int> face;
      for (int v : l) {
        auto [it, fresh] = index.try_emplace(v, static_cast<int>(verts.size()));
        if (fresh) verts.push_back(in_[sz(pts_[sz(v)])]);
        face.push_back(it->second);
      }
      faces.push_back(std::move(face));
    }
    return finish([&] { return ConvexPolyhedron<T>::from_faces(std::move(verts), faces); });
  }

  // Float T: would merging groups x and y (roots) leave a vertex they share
  // on only two faces (so that it is dropped as the middle of an edge) while
  // it is more than far_tol * eps from the segment between its neighbours
  // along that edge?  On a needle or thin slab every face is within eps of
  // every vertex, and such merges folded faces over a real corner (the tip
  // of a needle, a third of its length).
  bool strands_vertex(int x, int y) {
    if constexpr (exact) {
      (void)x;
      (void)y;
      return false;
    } else {
      if (!any_pinned_) return false;
      const Group& gx = groups_[sz(x)];
      const Group& gy = groups_[sz(y)];
      std::vector<int> shared;
      std::set_intersection(gx.verts.begin(), gx.verts.end(), gy.verts.begin(), gy.verts.end(),
                            std::back_inserter(shared));
      auto group = [&](int t) {
        const int g = find(t);
        return g == y ? x : g;
      };
      for (int v : shared) {
        if (!pinned_[sz(v)]) continue;
        std::vector<int> gs;
        for (int t : star_[sz(v)]) gs.push_back(group(t));
        std::sort(gs.begin(), gs.end());
        gs.erase(std::unique(gs.begin(), gs.end()), gs.end());
        if (gs.size() == 1) return true;  // it would be inside a face
        if (gs.size() != 2) continue;
        // its neighbours along the boundary between the two faces
        std::vector<int> ends;
        for (int t : star_[sz(v)]) {
          const Tri& tr = tris_[sz(t)];
          for (int i = 0; i < 3; ++i) {
            const int u = tr.v[sz(i)], w = tr.v[sz((i + 1) % 3)];
            if (u != v) continue;
            if (group(t) != group(tr.nb[sz(i)])) ends.push_back(w);
          }
          for (int i = 0; i < 3; ++i) {
            const int u = tr.v[sz(i)], w = tr.v[sz((i + 1) % 3)];
            if (w != v) continue;
            if (group(t) != group(tr.nb[sz(i)])) ends.push_back(u);
          }
        }
        std::sort(ends.begin(), ends.end());
        ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
        if (ends.size() != 2) continue;
        if (segment_distance(v, ends[0], ends[1]) > far_tol * to_double(eps_)) return true;
      }
      return false;
    }
  }

  // Float T: which faces to split at folds (vertex -> the groups it is
  // on).  Of the two faces a stranded pinned vertex is on, only the one
  // that is less planar (the larger height of one of its vertices above or
  // below its fitted plane) is split, if it can be (two or more plain
  // unsplit triangles; else the other).  A vertex on two faces, while
  // being a corner of both, means one of them bends over it: on a slab,
  // the exactly planar bottom and a rim face merged from two triangles
  // within eps of each other's plane (they fold over the corner).
  // Splitting the planar face as well made its triangles unable to merge
  // again, and validation then saw them as coplanar neighbours, which cost
  // a corner each (7 of one set's 8 bottom corners).  If the less planar
  // face folds again after its split, the next pass finds it unsplittable
  // and splits the other, so no fold is left standing.
  std::vector<int> fold_choice(const std::vector<int>& live, const std::map<int, std::vector<int>>& folds) {
    std::vector<int> ids;
    if (folds.empty()) return ids;
    std::unordered_map<int, int> plain;  // group -> plain unsplit triangles
    for (int f : live) plain[find(f)] += !is_zero(tris_[sz(f)].pl.normal) && nomerge_[sz(f)] == 0;
    auto bend = [&](int g) {
      const Group& gr = groups_[sz(g)];
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
  bool split_groups(const std::vector<int>& live, std::vector<int> ids) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    if (ids.empty()) return false;
    std::unordered_map<int, std::vector<int>> members;  // group -> live triangles
    for (int f : live) members[find(f)].push_back(f);
    bool any_split = false;
    for (int g : ids) {
      std::vector<int>& m = members[g];
      int plain = 0;
      for (int t : m) plain += !is_zero(tris_[sz(t)].pl.normal) && nomerge_[sz(t)] == 0;
      if (plain < 2) continue;
      ++splits_;
      for (int t : m)
        if (nomerge_[sz(t)] == 0) nomerge_[sz(t)] = splits_;
      any_split = true;
    }
    return any_split;
  }

  // Euclidean distance of point v from the segment between points a and b
  // (double, on the local coordinates; exact conversion for float).
  double segment_distance(int v, int a, int b) const {
    const Vec3<double> x = vec_to_double(Q(v)), pa = vec_to_double(Q(a)), pb = vec_to_double(Q(b));
    const Vec3<double> e(pb - pa), ax(x - pa);
    const double l2 = squared_norm(e);
    const double t = l2 > 0 ? std::clamp(dot(ax, e) / l2, 0.0, 1.0) : 0.0;
    return std::sqrt(squared_norm(Vec3<double>(ax - t * e)));
  }

  // ---- float only: check what ConvexPolyhedron validation will check ----------
  //
  // Validation defines each face's plane by a vertex triple (the largest
  // triangle (0, j, k) of the loop, see convex_polyhedron.hpp) on the original
  // coordinates.  A face that is small or thin has a poorly determined plane,
  // and rounding can then put a far vertex above it.  Such faces are found
  // here, with half the validation tolerances, and the face's least
  // significant vertex (the one nearest the line through its neighbours) is
  // rejected, so the builder never hands validation a hull it would refuse.

  const Vec3<T>& X(int v) const { return in_[sz(pts_[sz(v)])]; }

  static std::array<int, 3> plane_triple(const std::vector<Vec3<T>>& pts) {
    const int n = static_cast<int>(pts.size());
    std::array<int, 3> best{0, 1, 2};
    if (n <= 16) {
      T best_area(-1);
      for (int j = 1; j + 1 < n; ++j)
        for (int k = j + 1; k < n; ++k) {
          const T a = squared_norm(cross(Vec3<T>(pts[sz(j)] - pts[0]), Vec3<T>(pts[sz(k)] - pts[0])));
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
  void start_at_best_apex(std::vector<int>& l) const {
    const std::size_t n = l.size();
    std::size_t best = 0;
    T best_s(-1);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3<T> e1(X(l[(i + n - 1) % n]) - X(l[i])), e2(X(l[(i + 1) % n]) - X(l[i]));
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
  int least_significant(const std::vector<int>& l) const {
    const std::size_t n = l.size();
    int best = l[0];
    T best_d(-1);
    bool best_pin = false;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3<T> a = Q(l[(i + n - 1) % n]), b = Q(l[(i + 1) % n]), v = Q(l[i]);
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
      // (a point a repair round pinned only if every vertex of the face is)
      const bool pin = !exact && pinned_[sz(l[i])];
      if (best_d < T(0) || (pin == best_pin ? d < best_d : best_pin)) {
        best_d = d;
        best = l[i];
        best_pin = pin;
      }
    }
    return best;
  }

  // Solids also get: merges, adjacent faces that validation would see as
  // coplanar (and not split apart); split, faces that fail only planarity,
  // convexity or a reflex corner (not a zero or sliver plane triangle).
  //
  // A face whose loop fails only because of where it starts (validation's
  // plane triple has its apex at the first vertex: for a twisted sliver
  // quad, one start gives a plane all four vertices are within tolerance of,
  // another does not) is started at the first corner that passes instead.
  void prevalidate(std::vector<std::vector<int>>& loops, std::vector<int>& reject, bool flat = false,
                   std::vector<std::pair<int, int>>* merges = nullptr,
                   const std::vector<int>* loop_group = nullptr, std::vector<int>* split = nullptr) {
    std::vector<int> used;
    for (const auto& l : loops) used.insert(used.end(), l.begin(), l.end());
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    Vec3<T> lo = X(used[0]), hi = X(used[0]);
    double max_abs = 0;
    for (int v : used)
      for (int c = 0; c < 3; ++c) {
        if (X(v)[c] < lo[c]) lo[c] = X(v)[c];
        if (X(v)[c] > hi[c]) hi[c] = X(v)[c];
        max_abs = std::max(max_abs, std::abs(to_double(X(v)[c])));
      }
    double d2 = 0;
    for (int c = 0; c < 3; ++c) {
      const double w = to_double(T(hi[c] - lo[c]));
      d2 += w * w;
    }
    const double ext = std::sqrt(d2);
    const T plan_tol = static_cast<T>(0.5 * Tolerances<T>::kPlanarity * ext);
    const T conv_tol = static_cast<T>(0.5 * Tolerances<T>::kConvexity * ext);
    const T copl_tol = static_cast<T>(2.0 * Tolerances<T>::kCoplanar / 4 * ext);
    std::vector<Plane<T>> planes;
    std::map<std::pair<int, int>, int> edge_face;
    for (std::size_t f = 0; f < loops.size(); ++f) {
      const auto& l = loops[f];
      for (std::size_t i = 0; i < l.size(); ++i)
        edge_face[{l[i], l[(i + 1) % l.size()]}] = static_cast<int>(f);
    }
    std::vector<char> bad(loops.size(), 0);
    for (std::size_t f = 0; f < loops.size(); ++f) {
      for (std::size_t rot = 0; rot < (flat ? 1 : loops[f].size()); ++rot) {
        std::vector<int> l = loops[f];
        std::rotate(l.begin(), l.begin() + static_cast<std::ptrdiff_t>(rot), l.end());
        std::vector<Vec3<T>> pts;
        for (int v : l) pts.push_back(X(v));
        auto t = plane_triple(pts);
        if (flat && f == 1) {  // the back face reuses the front triple, reversed
          std::vector<Vec3<T>> front;
          for (int v : loops[0]) front.push_back(X(v));
          const auto t0 = plane_triple(front);
          const std::size_t n = l.size();
          // loops[1] is loops[0] reversed: position i there is n-1-i here
          t = {static_cast<int>(n - 1 - sz(t0[0])), static_cast<int>(n - 1 - sz(t0[2])),
               static_cast<int>(n - 1 - sz(t0[1]))};
        }
        const Plane<T> pl = plane_through(pts[sz(t[0])], pts[sz(t[1])], pts[sz(t[2])]);
        if (rot == 0) planes.push_back(pl);
        auto h = [&](int v) { return T(dot(pl.normal, X(v)) - pl.offset); };
        bool ok = !is_zero(pl.normal);
        if constexpr (!exact) {  // (validation: aspect > sliver; here with a factor 2 margin)
          ok = ok && detail::triangle_aspect(pts[sz(t[0])], pts[sz(t[1])], pts[sz(t[2])]) >
                         2 * Tolerances<T>::kSliver;
        }
        const bool shape_ok = ok;
        for (int v : l) ok = ok && abs_of(h(v)) <= plan_tol;
        for (int v : used) ok = ok && h(v) <= conv_tol;
        // corners as validation sees them: no reflex turn about this normal
        const std::size_t n = l.size();
        for (std::size_t i = 0; i < n && ok; ++i) {
          const Vec3<T> ab(X(l[i]) - X(l[(i + n - 1) % n]));
          const Vec3<T> bc(X(l[(i + 1) % n]) - X(l[i]));
          const T lab = length(ab);
          ok = lab > T(0) && !(dot(pl.normal, cross(ab, bc)) < -(conv_tol * lab));
        }
        if (ok) {
          bad[f] = 0;
          loops[f] = std::move(l);
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
      std::erase_if(*split, [&](int f) { return !bad[sz(f)]; });
    }
    for (std::size_t f = 0; f < loops.size() && !flat; ++f) {
      if (bad[f]) continue;
      const auto& l = loops[f];
      for (std::size_t i = 0; i < l.size() && !bad[f]; ++i) {
        const int g = edge_face[{l[(i + 1) % l.size()], l[i]}];
        bool coplanar = true;
        for (int v : loops[sz(g)])
          coplanar = coplanar && abs_of(T(dot(planes[f].normal, X(v)) - planes[f].offset)) <= copl_tol;
        if (coplanar && merges != nullptr &&
            !split_apart(groups_[sz((*loop_group)[f])], groups_[sz((*loop_group)[sz(g)])])) {
          merges->emplace_back(static_cast<int>(f), g);
          break;
        }
        if (coplanar) bad[loops[f].size() <= loops[sz(g)].size() ? f : sz(g)] = 1;
      }
    }
    bool any = false;
    for (std::size_t f = 0; f < loops.size(); ++f) {
      if (!bad[f]) continue;
      any = true;
      reject.push_back(least_significant(loops[f]));
    }
    if (any && 16.0 * number_traits<T>::unit_roundoff * max_abs > Tolerances<T>::kPlanarity * ext) {
      throw InvalidInput(ErrorCode::BadScale,
                         "convex_hull: the points are up to " + std::to_string(max_abs) +
                             " from the origin, too far for " + std::string(number_traits<T>::name) +
                             " to resolve a shape of extent " + std::to_string(ext) +
                             " within the validation tolerance; build the hull near the origin and move it "
                             "with a RigidTransform, or use double");
    }
    std::sort(reject.begin(), reject.end());
    reject.erase(std::unique(reject.begin(), reject.end()), reject.end());
  }

  template <class F>
  static std::optional<ConvexPolyhedron<T>> finish(F&& make) {
    try {
      return make();
    } catch (const InvalidInput& e) {
      throw std::logic_error(std::string("convex_hull: the hull failed validation (a bug): ") + e.what());
    }
  }

  std::span<const Vec3<T>> in_;
  double extent_ = 0;
  Vec3<T> centre_;
  T eps_, flat_, weld_;
  std::vector<int> pts_;    // welded point -> input index
  std::vector<Vec3<T>> q_;  // welded point, local coordinates
  std::vector<Tri> tris_;
  std::vector<int> parent_;
  std::vector<int> active_;                     // the points of the current build
  std::array<int, 4> simplex_{-1, -1, -1, -1};  // the first build's initial simplex
  Vec3<T> base_normal_;                         // normal of its initial triangle
  std::vector<Group> groups_;
  std::vector<char> pinned_;  // float: points a repair round put back
  bool any_pinned_ = false;
  std::vector<char> out_vertex_;        // vertices of the last output
  std::vector<std::vector<int>> star_;  // float: vertex -> live triangles around it
  std::vector<int> nomerge_;            // triangle -> id of the face it was split from (0: none)
  int splits_ = 0;
  bool tent_ = true;  // float: may try tent_hull (not in the second build)
};

}  // namespace hull_detail

/// The convex hull of points (see the header comment for the guarantees).
/// Throws InvalidInput: NonFinite (naming the point), TooFewPoints (< 3
/// distinct points), Collinear, BadScale (float extent overflow).
template <Number T>
ConvexPolyhedron<T> convex_hull(std::span<const Vec3<T>> points) {
  return hull_detail::Builder<T>(points).run();
}

template <Number T>
ConvexPolyhedron<T> convex_hull(const std::vector<Vec3<T>>& points) {
  return convex_hull<T>(std::span<const Vec3<T>>(points.data(), points.size()));
}

}  // namespace sepax::reference
