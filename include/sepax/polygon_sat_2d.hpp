// sepax/polygon_sat_2d.hpp
//
// The separating axis test between two convex polygons in the plane, as in the
// 2D part of Gregorius' GDC 2013 talk, over any sepax number type T:
//   Polygon2<T>     a validated convex polygon, vertices counter-clockwise.
//                   Edge i runs from vertex i to vertex i+1 (mod n); its
//                   outward normal is (e.y, -e.x): unit length when T
//                   normalises (float, double, CORE::Expr), the exact
//                   unnormalised vector for rationals.
//   support(d)      the vertex with the largest projection on d (the lowest
//                   index among exact ties).
//   face_query      over A's edges: the edge plane, the support vertex of B
//                   along the inward normal, and its signed height above the
//                   edge line; returns the edge of maximum height.
//   sat2::polygon_sat(A, B)   both face queries: the candidate of maximum
//                   separation, with feature and separation; overlap iff it
//                   is <= 0 (touching polygons overlap).
//   sat2::overlap(A, B)       early-out verdict only.
//   sat2::coplanar_sat(A, B)  two flat ConvexPolyhedra in one plane, decided
//                   in the plane (the case the 3D SATs report as touching).
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "convex_polyhedron.hpp"
#include "error.hpp"
#include "feature.hpp"
#include "number_traits.hpp"
#include "separation.hpp"
#include "tolerances.hpp"
#include "vec3.hpp"

namespace sepax {

/// a.x*b.y - a.y*b.x (the z of the 3D cross product), fixed evaluation order.
template <class T>
inline T cross2(const Vec2<T>& a, const Vec2<T>& b) {
  return T(a[0] * b[1] - a[1] * b[0]);
}

template <class T>
inline T dot2(const Vec2<T>& a, const Vec2<T>& b) {
  return T(a[0] * b[0] + a[1] * b[1]);
}

template <Number T>
class Polygon2 {
 public:
  using Scalar = T;

  Polygon2() = default;

  /// Validate and build; vertices counter-clockwise.  Throws InvalidInput for:
  /// fewer than 3 vertices (TooFewPoints), NaN/infinity (NonFinite), a repeated
  /// vertex (DegenerateFace), clockwise order (InwardFaces), a reflex or (in
  /// exact arithmetic) collinear corner, or a loop that winds more than once
  /// (NonConvexFace).  For float/double the convexity check uses the relative
  /// tolerance Tolerances<T>::kConvexity of tolerances.hpp.
  static Polygon2 from_vertices(std::vector<Vec2<T>> vertices) {
    Polygon2 p;
    p.v_ = std::move(vertices);
    p.validate();
    p.compute_normals();
    return p;
  }

  int size() const { return static_cast<int>(v_.size()); }
  const Vec2<T>& vertex(int i) const { return v_[static_cast<std::size_t>(i)]; }
  const std::vector<Vec2<T>>& vertices() const { return v_; }
  /// vertex(i+1) - vertex(i)
  Vec2<T> edge(int i) const { return Vec2<T>(vertex((i + 1) % size()) - vertex(i)); }
  /// Outward normal of edge i (unit iff T normalises).
  const Vec2<T>& normal(int i) const { return n_[static_cast<std::size_t>(i)]; }
  /// normal(i) . x == offset(i) on edge i's line.
  T offset(int i) const { return dot2(normal(i), vertex(i)); }
  /// Bounding-box diagonal as a double: the scale of the relative tolerances.
  double extent() const { return extent_; }

  /// Index of the vertex with the largest projection on d (lowest index on ties).
  int support(const Vec2<T>& d) const {
    int best = 0;
    T best_p = dot2(d, v_[0]);
    for (int i = 1; i < size(); ++i) {
      const T p = dot2(d, vertex(i));
      if (p > best_p) {
        best_p = p;
        best = i;
      }
    }
    return best;
  }

 private:
  [[noreturn]] static void fail(ErrorCode c, const std::string& m) { throw InvalidInput(c, "polygon: " + m); }

  void validate() {
    const int n = size();
    if (n < 3) fail(ErrorCode::TooFewPoints, "needs at least 3 vertices, got " + std::to_string(n));
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 2; ++c)
        if (!number_traits<T>::is_finite(vertex(i)[c]))
          fail(ErrorCode::NonFinite, "vertex " + std::to_string(i) + " has a non-finite coordinate");
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < i; ++j)
        if (vertex(i) == vertex(j))
          fail(ErrorCode::DegenerateFace,
               "vertices " + std::to_string(j) + " and " + std::to_string(i) + " are the same point");
    Vec2<T> lo = v_[0], hi = v_[0];
    for (const auto& p : v_)
      for (int c = 0; c < 2; ++c) {
        if (p[c] < lo[c]) lo[c] = p[c];
        if (p[c] > hi[c]) hi[c] = p[c];
      }
    const double dx = to_double(T(hi[0] - lo[0])), dy = to_double(T(hi[1] - lo[1]));
    extent_ = std::sqrt(dx * dx + dy * dy);
    if constexpr (!number_traits<T>::is_exact) {
      double m = 0;
      for (const auto& p : v_) m = std::max({m, std::abs(to_double(p[0])), std::abs(to_double(p[1]))});
      if (!number_traits<T>::is_finite(static_cast<T>(m * m * 4.0)))
        fail(ErrorCode::BadScale, "coordinates up to " + format_number(m) + " overflow " +
                                      std::string(number_traits<T>::name) + " in edge products");
    }
    // Orientation: twice the signed area, exact for exact T.
    T area2(0);
    for (int i = 0; i < n; ++i) area2 = area2 + cross2(vertex(i), vertex((i + 1) % n));
    if (!(area2 > T(0))) {
      if (area2 < T(0)) fail(ErrorCode::InwardFaces, "vertices are clockwise: list them counter-clockwise");
      fail(ErrorCode::DegenerateFace, "zero area (all vertices on one line)");
    }
    // Every vertex on the inner side of every edge line (catches reflex corners
    // and loops that wind twice, like a pentagram, which turn left everywhere).
    for (int i = 0; i < n; ++i) {
      const Vec2<T> e = edge(i);
      T tol(0);
      if constexpr (!number_traits<T>::is_exact) {
        tol = static_cast<T>(Tolerances<T>::kConvexity * extent_) * number_traits<T>::sqrt(dot2(e, e));
      }
      for (int j = 0; j < n; ++j) {
        if (j == i || j == (i + 1) % n) continue;
        const T side = cross2(e, Vec2<T>(vertex(j) - vertex(i)));  // > 0: left (inside)
        bool bad;
        if constexpr (number_traits<T>::is_exact) {
          bad = !(side > T(0));
        } else {
          bad = side < -tol;
        }
        if (bad)
          fail(ErrorCode::NonConvexFace,
               "not convex: vertex " + std::to_string(j) +
                   (number_traits<T>::is_exact ? " is not strictly left of edge " : " is right of edge ") +
                   std::to_string(i) + " (" + std::to_string(i) + "->" + std::to_string((i + 1) % n) + ")");
      }
    }
  }

  void compute_normals() {
    n_.clear();
    for (int i = 0; i < size(); ++i) {
      const Vec2<T> e = edge(i);
      Vec2<T> m(e[1], T(-e[0]));
      if constexpr (number_traits<T>::normalizes) {
        const T len = number_traits<T>::sqrt(dot2(m, m));
        m = Vec2<T>(T(m[0] / len), T(m[1] / len));
      }
      n_.push_back(m);
    }
  }

  std::vector<Vec2<T>> v_;
  std::vector<Vec2<T>> n_;
  double extent_ = 0;
};

namespace sat2 {

/// The best edge of `a` against `b`: maximum height of b's support vertex
/// (along -normal) above the edge line.  Ties: the lowest edge index.
template <class T>
struct FaceQuery2 {
  Separation<T> separation;
  int edge = -1;
  int support_vertex = -1;
};

template <Number T>
T norm2_of(const Vec2<T>& n) {
  if constexpr (number_traits<T>::normalizes) {
    (void)n;
    return T(1);
  } else {
    return dot2(n, n);
  }
}

/// Height of b's support vertex above edge i of a.
template <Number T>
FaceQuery2<T> edge_query(const Polygon2<T>& a, int i, const Polygon2<T>& b) {
  const Vec2<T>& n = a.normal(i);
  const int s = b.support(Vec2<T>(-n));
  return FaceQuery2<T>{Separation<T>{T(dot2(n, b.vertex(s)) - a.offset(i)), norm2_of(n)}, i, s};
}

template <Number T>
FaceQuery2<T> face_query(const Polygon2<T>& a, const Polygon2<T>& b) {
  FaceQuery2<T> best = edge_query(a, 0, b);
  for (int i = 1; i < a.size(); ++i) {
    const auto q = edge_query(a, i, b);
    if (compare(q.separation, best.separation) > 0) best = q;
  }
  return best;
}

template <class T>
struct Sat2Result {
  /// No separating axis: the polygons share at least one point (touching counts).
  bool overlap = false;
  /// face_a(edge of A, support vertex of B) or face_b(support vertex of A, edge of B).
  Feature feature;
  Separation<T> separation;
  /// The axis from A to B: unit when T normalises, else separation.norm2 long.
  Vec2<T> axis = Vec2<T>(T(0), T(0));
  /// Stopped at the first separating axis (early_out).
  bool early_out = false;
  double separation_as_double() const { return sepax::to_double(separation); }
};

/// The 2D SAT.  early_out: stop at the first separating edge normal.
/// The candidate axes of two convex polygons are the edge normals of A and of
/// B (the edge normals of A - B), so this test is complete in 2D.  Results
/// reuse the 3D vocabulary: Feature::face_a(edge of A, support vertex of B),
/// Feature::face_b(support vertex of A, edge of B), Separation<T> (exact
/// comparison in squared form for rationals) and the tie-break of feature.hpp
/// (equal separations: A's edges before B's, lower index first).
template <Number T>
Sat2Result<T> polygon_sat(const Polygon2<T>& a, const Polygon2<T>& b, bool early_out = false) {
  Sat2Result<T> r;
  bool has = false;
  const auto consider = [&](const Separation<T>& s, const Feature& f, const Vec2<T>& axis) {
    const int c = has ? compare(s, r.separation) : 1;
    if (c > 0 || (c == 0 && precedes(f, r.feature))) {
      r.separation = s;
      r.feature = f;
      r.axis = axis;
      has = true;
    }
  };
  for (int i = 0; i < a.size(); ++i) {
    const auto q = edge_query(a, i, b);
    consider(q.separation, Feature::face_a(i, q.support_vertex), a.normal(i));
    if (early_out && sign(q.separation) > 0) {
      r.early_out = true;
      break;
    }
  }
  if (!r.early_out) {
    for (int i = 0; i < b.size(); ++i) {
      const auto q = edge_query(b, i, a);
      consider(q.separation, Feature::face_b(q.support_vertex, i), Vec2<T>(-b.normal(i)));
      if (early_out && sign(q.separation) > 0) {
        r.early_out = true;
        break;
      }
    }
  }
  r.overlap = sign(r.separation) <= 0;
  return r;
}

/// True iff the polygons share a point (Gregorius' Overlap(): two face queries).
template <Number T>
bool overlap(const Polygon2<T>& a, const Polygon2<T>& b) {
  if (sign(face_query(a, b).separation) > 0) return false;
  return sign(face_query(b, a).separation) <= 0;
}

// ---- coplanar flat shapes ---------------------------------------------------
//
// The 3D SATs cannot separate two double-sided polygons lying in one plane
// with a gap between them (their Minkowski difference is flat; see
// docs/sat.md).  coplanar_sat decides that case in the plane: both polygons
// are projected by dropping the coordinate in which A's normal is largest
// (an affine bijection of the plane, exact for exact T), and the 2D SAT runs
// there.  The verdict is exact for exact T; the separation's SIGN is
// meaningful, its value is measured in the projected coordinates (not a 3D
// distance).  Features use the 3D indices: face_a(a, b) means "the in-plane
// normal of A's (undirected) edge a, support vertex b of B"; face_b likewise.

/// Face 0 of a flat shape as a CCW polygon in the projection dropping
/// coordinate `drop`; loop[i] is the 3D vertex index of polygon vertex i.
template <Number T>
Polygon2<T> project_flat(const ConvexPolyhedron<T>& p, int drop, std::vector<int>* loop = nullptr) {
  std::vector<int> l = p.face_vertices(0);
  if (!(p.plane(0).normal[drop] > T(0))) std::reverse(l.begin(), l.end());
  const int u = (drop + 1) % 3, w = (drop + 2) % 3;
  std::vector<Vec2<T>> v;
  for (int i : l) v.push_back(Vec2<T>(p.vertex(i)[u], p.vertex(i)[w]));
  if (loop) *loop = l;
  return Polygon2<T>::from_vertices(std::move(v));
}

/// 2D SAT of two flat shapes in one plane (throws std::invalid_argument if
/// either is not flat or they are not coplanar: exactly for exact T, within
/// Tolerances<T>::kCoplanar of the extent for float T).
template <Number T>
Sat2Result<T> coplanar_sat(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b) {
  if (!a.is_flat() || !b.is_flat())
    throw std::invalid_argument("coplanar_sat: both shapes must be flat polygons");
  const Plane<T>& pl = a.plane(0);
  T tol(0);
  if constexpr (!number_traits<T>::is_exact)
    tol = static_cast<T>(Tolerances<T>::kCoplanar * std::max(a.extent(), b.extent()));
  for (const auto& v : b.vertices())
    if (abs_of(T(dot(pl.normal, v) - pl.offset)) > tol)
      throw std::invalid_argument("coplanar_sat: the two polygons are not in one plane");
  int drop = 0;
  for (int c = 1; c < 3; ++c)
    if (abs_of(pl.normal[c]) > abs_of(pl.normal[drop])) drop = c;
  std::vector<int> la, lb;
  const Polygon2<T> pa = project_flat(a, drop, &la);
  const Polygon2<T> pb = project_flat(b, drop, &lb);
  Sat2Result<T> r = polygon_sat(pa, pb);
  const auto edge3 = [](const ConvexPolyhedron<T>& p, const std::vector<int>& l, int i) {
    const int x = l[static_cast<std::size_t>(i)],
              y = l[static_cast<std::size_t>((i + 1) % static_cast<int>(l.size()))];
    for (int e = 0; e < p.edge_count(); ++e)
      if ((p.edge_tail(e) == x && p.edge_head(e) == y) || (p.edge_tail(e) == y && p.edge_head(e) == x))
        return e;
    return -1;
  };
  if (r.feature.type == FeatureType::FaceA) {
    r.feature = Feature::face_a(edge3(a, la, r.feature.a), lb[static_cast<std::size_t>(r.feature.b)]);
  } else {
    r.feature = Feature::face_b(la[static_cast<std::size_t>(r.feature.a)], edge3(b, lb, r.feature.b));
  }
  return r;
}

}  // namespace sat2
}  // namespace sepax
