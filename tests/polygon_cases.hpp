// tests/polygon_cases.hpp: oracles for the 2D polygon SAT (shared by
// tests/core/polygon_sat_2d_test.cpp and tests/exact/polygon_sat_2d_exact_test.cpp).
#pragma once

#include <catch2/catch.hpp>

#include <sepax/polygon_sat_2d.hpp>

#include <random>
#include <vector>

namespace sepax::test2d {

template <class T>
Vec2<T> p2(double x, double y) {
  return Vec2<T>(from_double<T>(x), from_double<T>(y));
}

template <class T>
Polygon2<T> poly(std::initializer_list<std::pair<double, double>> pts) {
  std::vector<Vec2<T>> v;
  for (const auto& [x, y] : pts) v.push_back(p2<T>(x, y));
  return Polygon2<T>::from_vertices(std::move(v));
}

template <class T>
Polygon2<T> moved(const Polygon2<T>& p, const Vec2<T>& t) {
  std::vector<Vec2<T>> v;
  for (const auto& x : p.vertices()) v.push_back(Vec2<T>(x + t));
  return Polygon2<T>::from_vertices(std::move(v));
}

/// Brute-force separation: project BOTH polygons fully on every candidate
/// axis (A's edge normals, then B's, negated so the axis runs from A to B);
/// the maximum of (min over B - max over A), with the same tie-break.  Uses
/// neither support() nor offset().
template <class T>
std::pair<Separation<T>, Feature> projection_oracle(const Polygon2<T>& a, const Polygon2<T>& b) {
  Separation<T> best;
  Feature bf;
  bool has = false;
  const auto extent = [](const Polygon2<T>& p, const Vec2<T>& n, T& lo, T& hi, int& arg_lo) {
    lo = hi = dot2(n, p.vertex(0));
    arg_lo = 0;
    for (int i = 1; i < p.size(); ++i) {
      const T x = dot2(n, p.vertex(i));
      if (x < lo) {
        lo = x;
        arg_lo = i;
      }
      if (x > hi) hi = x;
    }
  };
  for (int side = 0; side < 2; ++side) {
    const Polygon2<T>& p = side == 0 ? a : b;
    for (int i = 0; i < p.size(); ++i) {
      const Vec2<T> n = side == 0 ? p.normal(i) : Vec2<T>(-p.normal(i));
      T alo, ahi, blo, bhi;
      int aarg, barg;
      extent(a, n, alo, ahi, aarg);
      extent(b, n, blo, bhi, barg);
      // the support feature: B's deepest vertex for A's edges, A's for B's
      // (along the B edge's own outward normal -n, A's lowest = highest on n)
      int amax = 0;
      for (int k = 1; k < a.size(); ++k)
        if (dot2(n, a.vertex(k)) > dot2(n, a.vertex(amax))) amax = k;
      const Separation<T> s{T(blo - ahi), sat2::norm2_of(n)};
      const Feature f = side == 0 ? Feature::face_a(i, barg) : Feature::face_b(amax, i);
      const int c = has ? compare(s, best) : 1;
      if (c > 0 || (c == 0 && precedes(f, bf))) {
        best = s;
        bf = f;
        has = true;
      }
    }
  }
  return {best, bf};
}

/// Geometric verdict oracle (exact for exact T): the polygons share a point iff
/// some vertex of one is inside-or-on the other or two edges intersect.
template <class T>
int orient(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c) {
  return sign_of(cross2(Vec2<T>(b - a), Vec2<T>(c - a)));
}

template <class T>
bool on_segment(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& p) {
  return orient(a, b, p) == 0 && std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
}

template <class T>
bool segments_meet(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c, const Vec2<T>& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

template <class T>
bool inside_or_on(const Polygon2<T>& p, const Vec2<T>& q) {
  for (int i = 0; i < p.size(); ++i)
    if (orient(p.vertex(i), p.vertex((i + 1) % p.size()), q) < 0) return false;
  return true;
}

template <class T>
bool geometric_overlap(const Polygon2<T>& a, const Polygon2<T>& b) {
  for (const auto& v : a.vertices())
    if (inside_or_on(b, v)) return true;
  for (const auto& v : b.vertices())
    if (inside_or_on(a, v)) return true;
  for (int i = 0; i < a.size(); ++i)
    for (int j = 0; j < b.size(); ++j)
      if (segments_meet(a.vertex(i), a.vertex((i + 1) % a.size()), b.vertex(j), b.vertex((j + 1) % b.size())))
        return true;
  return false;
}

/// A random convex polygon with 3..8 vertices exactly on a circle of radius r
/// around c: rational points ((1-t^2)/(1+t^2), 2t/(1+t^2)) for distinct
/// rational t = k/8 (k in -24..24) plus the point (-1, 0) sometimes, so the
/// polygon is strictly convex exactly; in float the same values rounded.
template <class T>
Polygon2<T> random_circle_polygon(std::mt19937& rng, const T& r, const Vec2<T>& c) {
  std::uniform_int_distribution<int> nd(3, 8), kd(-24, 24);
  const int n = nd(rng);
  std::vector<int> ks;
  while (static_cast<int>(ks.size()) < n) {
    const int k = kd(rng);
    bool dup = false;
    for (int x : ks) dup = dup || x == k;
    if (!dup) ks.push_back(k);
  }
  std::sort(ks.begin(), ks.end());  // t increasing = angle increasing in (-pi, pi): CCW
  std::vector<Vec2<T>> v;
  for (int k : ks) {
    const T t = T(from_double<T>(k) / T(8));
    const T d = T(T(1) + t * t);
    v.push_back(Vec2<T>(T(c[0] + r * T(T(1) - t * t) / d), T(c[1] + r * T(T(2) * t) / d)));
  }
  return Polygon2<T>::from_vertices(std::move(v));
}

}  // namespace sepax::test2d
