// sepax/plain_kernel.hpp
//
// PlainKernel<T>: the SAT kernel that evaluates everything in T.
//
// * Exact T (rationals, Epeck::FT): every value and decision is exact.  Axes
//   are unnormalised and separations compared in squared form (separation.hpp);
//   exactly parallel edges are skipped; the support check of the brute force
//   compares projections exactly.
// * float/double: plain rounding arithmetic, with the named tolerances of
//   tolerances.hpp (kParallel, kSupport).  This is the fast path the benchmark
//   measures and the fuzzer audits against exact arithmetic.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>

#include "edge_pair_rule_out.hpp"
#include "sat_kernel.hpp"
#include "simd_lanes.hpp"

namespace sepax {

template <Number T>
class PlainKernel {
 public:
  using FT = T;
  /// Decisions are exact only for an exact T (sat_kernel.hpp, exact_decisions_v).
  static constexpr bool kExactDecisions = number_traits<T>::is_exact;

  PlainKernel(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b)
      : a_(a),
        b_(b),
        lanes_(a.lanes_bounded() && b.lanes_bounded()),
        support_lanes_(a.support_lanes_bounded() && b.support_lanes_bounded()) {}

  const ConvexPolyhedron<T>& a() const { return a_; }
  const ConvexPolyhedron<T>& b() const { return b_; }

  FaceQuery<T> face_query_a(int f) const { return face_query(a_, f, b_, support_lanes_); }
  FaceQuery<T> face_query_b(int f) const { return face_query(b_, f, a_, support_lanes_); }

  // Side axes (both shapes flat, best_axis.hpp): the in-plane
  // outward normal u = (head - tail) x normal(edge_face(e, 0)) of edge e (the
  // face of half-edge 2e is on its left seen from outside, so u points out of
  // the polygon), and the other shape's support vertex along -u.
  FaceQuery<T> side_query_a(int e) const { return side_query(a_, e, b_); }
  FaceQuery<T> side_query_b(int e) const { return side_query(b_, e, a_); }

  Separation<T> face_separation_a(int f, int vb) const { return height(a_.plane(f), b_.vertex(vb)); }
  Separation<T> face_separation_b(int f, int va) const { return height(b_.plane(f), a_.vertex(va)); }

  /// Optional members (sat_kernel.hpp, HasSupportFilter), float and double:
  /// two vertices below a face are compared by their rounded projections
  /// fl(n.x), with no filter: within it (d = 0, or NaN) they are equal.
  T support_filter_a() const requires std::is_floating_point_v<T> { return T(0); }
  T support_filter_b() const requires std::is_floating_point_v<T> { return T(0); }
  int support_sign_a(int, int, int, T d) const requires std::is_floating_point_v<T> { return sign_of(d); }
  int support_sign_b(int, int, int, T d) const requires std::is_floating_point_v<T> { return sign_of(d); }

  // The arc test reads the per-edge arrays of ConvexPolyhedron (edge_direction,
  // edge_normal): the same T values as head - tail and the face planes'
  // normals, without the half-edge and face indirections.
  ArcSigns arc_signs(int ea, int eb) const {
    const Vec3<T>& da = a_.edge_direction(ea);
    const Vec3<T>& db = b_.edge_direction(eb);
    ArcSigns s;
    s.cba = sign_of_dot(b_.edge_normal(eb, 0), da);
    s.dba = sign_of_dot(b_.edge_normal(eb, 1), da);
    s.adc = -sign_of_dot(a_.edge_normal(ea, 0), db);
    s.bdc = -sign_of_dot(a_.edge_normal(ea, 1), db);
    return s;
  }

  /// == arc_signs(ea, eb).minkowski_face(), same products in the same order
  /// (bit-identical for float), stopping after cba, dba when they are not
  /// strictly opposite (most pairs).
  bool minkowski_face(int ea, int eb) const {
    const Vec3<T>& da = a_.edge_direction(ea);
    int cba;
    if constexpr (number_traits<T>::is_exact) {
      // signs only: T's dot_sign where it has one (vec3.hpp, sign_of_dot)
      cba = sign_of_dot(b_.edge_normal(eb, 0), da);
      if (!(cba * sign_of_dot(b_.edge_normal(eb, 1), da) < 0)) return false;
    } else {
      const T c = dot(b_.edge_normal(eb, 0), da);
      const T d = dot(b_.edge_normal(eb, 1), da);
      // sign_of(c) * sign_of(d) < 0 as min < 0 < max: the same answer for
      // every input (signed zeros give false, and so does a NaN in either
      // place: it is never selected as both the min and the max), fewer ops.
      const T lo = d < c ? d : c;
      const T hi = c < d ? d : c;
      if (!(lo < T(0) && T(0) < hi)) return false;
      cba = sign_of(c);
    }
    const Vec3<T>& db = b_.edge_direction(eb);
    const int adc = -sign_of_dot(a_.edge_normal(ea, 0), db);
    const int bdc = -sign_of_dot(a_.edge_normal(ea, 1), db);
    return adc * bdc < 0 && cba * bdc > 0;
  }

  /// Optional batched member (sat_kernel.hpp, HasMinkowskiFaces): the eb in
  /// [lo, hi) with minkowski_face(ea, eb), ascending, written to out; their
  /// number returned.  Float and double: all four products for a few edges of
  /// B at once over B's lane arrays (simd_lanes.hpp), the same values and the
  /// same decision as minkowski_face.  Shapes whose coordinates could overflow
  /// (not lanes_bounded) take the scalar test.  Exact T has no batched form.
  int minkowski_faces(int ea, int lo, int hi, int* out) const
      requires(std::is_same_v<T, float> || std::is_same_v<T, double>) {
    if (lanes_) {
      return simd::arc_candidates<false>(b_, lo, hi, a_.edge_direction(ea), a_.edge_normal(ea, 0),
                                         a_.edge_normal(ea, 1), T(0), out);
    }
    int n = 0;
    for (int eb = lo; eb < hi; ++eb) {
      if (minkowski_face(ea, eb)) out[n++] = eb;
    }
    return n;
  }

  /// Optional member (sat_kernel.hpp, HasEdgeWedge): vertex x of B strictly
  /// inside the wedge of edge e of A, from the signs of (E x n_s).w in T.
  /// Exact T: exact (the stored normals are positive multiples of the
  /// planes' normals).  Float and double: E is first scaled by a power of two
  /// to max |E_i| in [1, 2), so E x n (n unit) is O(1) and the product with w
  /// neither overflows nor underflows where w itself does not.
  bool in_edge_wedge_a(int e, int x) const {
    const Vec3<T>& w = b_.vertex(x);
    const Vec3<T>& tail = a_.vertex(a_.edge_tail(e));
    if constexpr (number_traits<T>::is_exact) {
      // n.((w - tail) x E) = (E x n).(w - tail): T's height signs (vec3.hpp)
      const Vec3<T>& d = a_.edge_direction(e);
      return sign_of_height(d, a_.edge_normal(e, 0), w, tail) > 0 &&
             sign_of_height(d, a_.edge_normal(e, 1), w, tail) < 0;
    } else {
      Vec3<T> d = a_.edge_direction(e);
      const T m = detail::max_abs2(d, d);
      if (!(m > T(0) && m <= std::numeric_limits<T>::max())) return false;  // no direction: no wedge
      d = detail::scale_pow2(d, detail::pow2_exponent(m));
      // (E x n).w = n.(w x E): one cross product for both faces
      const Vec3<T> c = cross(diff(w, tail), d);
      return sign_of(dot(a_.edge_normal(e, 0), c)) > 0 && sign_of(dot(a_.edge_normal(e, 1), c)) < 0;
    }
  }

  bool edges_parallel(int ea, int eb) const {
    const Vec3<T>& da = a_.edge_direction(ea);
    const Vec3<T>& db = b_.edge_direction(eb);
    const Vec3<T> n = cross(da, db);
    if constexpr (number_traits<T>::is_exact) {
      return is_zero(n);
    } else {
      const T tol = static_cast<T>(Tolerances<T>::kParallel);
      return nearly_parallel(da, db, tol);  // (scale-safe: vec3.hpp)
    }
  }

  Separation<T> edge_separation(int ea, int eb) const {
    Vec3<T> n = edge_axis(ea, eb);
    const Vec3<T>& pa = a_.vertex(a_.edge_tail(ea));
    const Vec3<T>& pb = b_.vertex(b_.edge_tail(eb));
    return Separation<T>{dot(n, diff(pb, pa)), norm2_of(n)};
  }

  std::optional<Separation<T>> edge_separation_full(int ea, int eb) const {
    if constexpr (number_traits<T>::is_exact) {
      return exact_edge_separation_full(ea, eb);
    } else {
      const Vec3<T> n = unoriented_axis(ea, eb);
      const T ta = support_tolerance(a_), tb = support_tolerance(b_);
      const T pa0 = dot(n, a_.vertex(a_.edge_tail(ea))), pa1 = dot(n, a_.vertex(a_.edge_head(ea)));
      const T pb0 = dot(n, b_.vertex(b_.edge_tail(eb))), pb1 = dot(n, b_.vertex(b_.edge_head(eb)));
      // Most pairs support neither orientation: the neighbours of the edges'
      // endpoints, then the scans, stop at the first vertex that rules out both
      // (rule_out_by_neighbours, project_supporting); the decision below is then
      // the one the complete extremes give.
      T min_a, max_a, min_b, max_b;
      bool may_plus = true, may_minus = true;
      rule_out_by_neighbours(a_, n, ea, pa0, pa1, ta, may_plus, may_minus);
      if (may_plus || may_minus) rule_out_by_neighbours(b_, n, eb, pb0, pb1, tb, may_minus, may_plus);
      if (!may_plus && !may_minus) return std::nullopt;
      if (!project_supporting(a_, n, pa0, pa1, ta, min_a, max_a, may_plus, may_minus)) return std::nullopt;
      if (!project_supporting(b_, n, pb0, pb1, tb, min_b, max_b, may_minus, may_plus)) return std::nullopt;
      // +n from A to B: A's edge at A's max, B's edge at B's min.
      const bool plus = pa0 >= max_a - ta && pa1 >= max_a - ta && pb0 <= min_b + tb && pb1 <= min_b + tb;
      // -n from A to B: A's edge at A's min, B's edge at B's max.
      const bool minus = pa0 <= min_a + ta && pa1 <= min_a + ta && pb0 >= max_b - tb && pb1 >= max_b - tb;
      if (!plus && !minus) return std::nullopt;
      const T n2 = norm2_of(n);
      const Separation<T> sp{T(min_b - max_a), n2};
      const Separation<T> sm{T(min_a - max_b), n2};
      if (plus && minus) return sepax::compare(sp, sm) >= 0 ? sp : sm;
      return plus ? sp : sm;
    }
  }

  /// Optional member (sat_kernel.hpp, HasEdgePairRuledOut), float and
  /// double: true only when edge_separation_full(ea, eb) would return
  /// nothing (edge_pair_rule_out.hpp: the wings' heights in double, with
  /// PlainRuleOut's bound on the rounded axis and the support tolerance).
  bool edge_pair_ruled_out(int ea, int eb) const requires std::is_floating_point_v<T> {
    return rule_out_.ruled_out(a_, ea, b_, eb, [&] {
      return std::array<double, 2>{static_cast<double>(support_tolerance(a_)),
                                   static_cast<double>(support_tolerance(b_))};
    });
  }

  /// Optional member (sat_kernel.hpp, HasEdgePairRuledOut), exact T: the
  /// same wings (edge_pair_rule_out.hpp, edge_wings), their heights' exact
  /// signs along c = eA x eB (sign_of_height: integers for the GMP rationals,
  /// an interval filter for Lazy_exact_nt).  A wing above its edge's tail
  /// rules out the edge at its shape's maximum along c, below it the minimum,
  /// as rule_out_by_neighbours does (the wings are neighbours of the edge's
  /// endpoints), so edge_separation_full returns nothing for a pair ruled out
  /// in both orientations.  (Parallel edges: c = 0 rules out nothing.)
  bool edge_pair_ruled_out(int ea, int eb) const requires number_traits<T>::is_exact {
    const Vec3<T>& da = a_.edge_direction(ea);
    const Vec3<T>& db = b_.edge_direction(eb);
    bool may_plus = true, may_minus = true;  // +c: A's edge at A's max, B's at B's min
    const detail::EdgeWings wa = detail::edge_wings(a_, ea);
    for (const int w : {wa.wing0, wa.wing1}) {
      const int h = sign_of_height(da, db, a_.vertex(w), a_.vertex(wa.tail));
      may_plus = may_plus && h <= 0;
      may_minus = may_minus && h >= 0;
    }
    if (!may_plus && !may_minus) return true;
    const detail::EdgeWings wb = detail::edge_wings(b_, eb);
    for (const int w : {wb.wing0, wb.wing1}) {
      const int h = sign_of_height(da, db, b_.vertex(w), b_.vertex(wb.tail));
      may_plus = may_plus && h >= 0;
      may_minus = may_minus && h <= 0;
      if (!may_plus && !may_minus) return true;
    }
    return false;
  }

  int compare(const Separation<T>& x, const Feature&, const Separation<T>& y, const Feature&) const {
    return sepax::compare(x, y);
  }
  int sign(const Separation<T>& x, const Feature&) const { return sepax::sign(x); }

  Vec3<T> axis(const Feature& f) const {
    switch (f.type) {
      case FeatureType::FaceA:
        return a_.plane(f.a).normal;
      case FeatureType::FaceB:
        return Vec3<T>(-b_.plane(f.b).normal);
      case FeatureType::EdgePair:
        return oriented_axis_for_report(f.a, f.b);
      case FeatureType::SideA:
        return side_normal(a_, f.a);
      case FeatureType::SideB:
        return Vec3<T>(-side_normal(b_, f.b));
    }
    return Vec3<T>(T(0), T(0), T(0));
  }

  /// The brute force's support tolerance for shape p (edge_separation_full):
  /// an edge endpoint within it of p's extreme projection counts as
  /// supporting.  Public for the fuzzer's model of it (error_bounds.hpp (9)).
  static T support_tolerance(const ConvexPolyhedron<T>& p) {
    if constexpr (number_traits<T>::is_exact) {
      (void)p;
      return T(0);
    } else {
      // The named relative tolerance, plus a rounding floor: a projection
      // fl(n.v) with |n| = 1 (itself rounded: |fl(n) - n| <= 3u) is off by at
      // most (gamma_3 + 3u)|v|_1 <= 7u*sqrt(3)*max|v_i| (first order), so two
      // projections of vertices of p differ from the exact difference by at
      // most 2*7*sqrt(3)u*max|v_i| < 25u*max|v_i| (kSupportRoundingSlack,
      // tolerances.hpp).  Without it, a small shape far from the origin
      // (rounding > support*extent) loses its supporting edges.
      const double u = number_traits<T>::unit_roundoff;
      return static_cast<T>(Tolerances<T>::kSupport * p.extent() +
                            kSupportRoundingSlack * u * p.max_abs_coordinate());
    }
  }

  /// Optional member (sat_kernel.hpp, HasCompareMargin): sign of (s - m).
  /// Exact T: exact (m converted exactly); float/double: s's value against m
  /// in double (exact comparison of the two numbers given).
  int compare_margin(const Separation<T>& s, const Feature&, double m) const {
    if constexpr (number_traits<T>::is_exact) {
      return sepax::compare(s, Separation<T>{from_double<T>(m), T(1)});
    } else {
      const double v = static_cast<double>(s.num);
      return (v > m) - (v < m);
    }
  }

  std::int64_t exact_fallbacks() const { return 0; }

 private:
  static constexpr int kScalarSupportMax = 4;  // measured: the lanes win from 8 vertices on
  static FaceQuery<T> face_query(const ConvexPolyhedron<T>& p, int f, const ConvexPolyhedron<T>& q,
                                 bool lanes) {
    const Plane<T>& pl = p.plane(f);
    return support_below(pl.normal, pl.offset, q, lanes);
  }

  // Lowest vertex of q along n (first index among equal heights), and its
  // height n.v - offset.  lanes: q's vertex lanes may be used
  // (support_lanes_bounded of q and of the shape n comes from).
  static FaceQuery<T> support_below(const Vec3<T>& n, const T& offset, const ConvexPolyhedron<T>& q,
                                    [[maybe_unused]] bool lanes) {
    const auto& vs = q.vertices();
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
      if (lanes && q.vertex_count() > kScalarSupportMax) {
        // The scalar loop below, a few vertices at a time (simd_lanes.hpp):
        // the same n.v values, the same lowest-index argmin.  (For a handful
        // of vertices the scalar loop is cheaper than merging the lanes.)
        const simd::Support<T> s = simd::support_scan<false>(q, n);
        return FaceQuery<T>{Separation<T>{T(s.min - offset), norm2_of(n)}, s.index};
      }
    }
    if constexpr (HasDifferenceDotSign<T>) {
      // an exact type with a cheaper sign: the same argmin (the lowest index
      // among the exactly lowest) from signs of n.(v - best), one value
      int low = 0;
      for (int i = 1; i < static_cast<int>(vs.size()); ++i)
        if (sign_of_difference_dot(n, vs[static_cast<std::size_t>(i)], vs[static_cast<std::size_t>(low)]) < 0)
          low = i;
      return FaceQuery<T>{Separation<T>{T(dot(n, vs[static_cast<std::size_t>(low)]) - offset), norm2_of(n)},
                          low};
    }
    int best = 0;
    T best_h = dot(n, vs[0]);
    for (int i = 1; i < static_cast<int>(vs.size()); ++i) {
      const T h = dot(n, vs[static_cast<std::size_t>(i)]);
      if (h < best_h) {
        best_h = h;
        best = i;
      }
    }
    return FaceQuery<T>{Separation<T>{T(best_h - offset), norm2_of(n)}, best};
  }

  static Vec3<T> side_normal(const ConvexPolyhedron<T>& p, int e) {
    return normalized(scaled_cross(p.edge_direction(e), p.edge_normal(e, 0)));  // scale-safe: vec3.hpp
  }

  static FaceQuery<T> side_query(const ConvexPolyhedron<T>& p, int e, const ConvexPolyhedron<T>& q) {
    const Vec3<T> u = side_normal(p, e);
    return support_below(u, dot(u, p.vertex(p.edge_tail(e))), q, false);
  }

  static Separation<T> height(const Plane<T>& pl, const Vec3<T>& p) {
    return Separation<T>{T(dot(pl.normal, p) - pl.offset), norm2_of(pl.normal)};
  }

  // p - q, one subtraction per coordinate (the value of Vec3<T>(p - q), which
  // g++ -O2 did not always inline).
  static Vec3<T> diff(const Vec3<T>& p, const Vec3<T>& q) {
    return Vec3<T>(T(p[0] - q[0]), T(p[1] - q[1]), T(p[2] - q[2]));
  }

  static T norm2_of(const Vec3<T>& n) {
    if constexpr (number_traits<T>::normalizes) {
      (void)n;
      return T(1);
    } else {
      return squared_norm(n);
    }
  }

  static Vec3<T> normalized(const Vec3<T>& n) {
    if constexpr (number_traits<T>::normalizes) {
      const T len = number_traits<T>::sqrt(squared_norm(n));
      return Vec3<T>(n[0] / len, n[1] / len, n[2] / len);
    } else {
      return n;
    }
  }

  // eA x eB, normalised when T normalises (not oriented).
  Vec3<T> unoriented_axis(int ea, int eb) const {
    return normalized(scaled_cross(a_.edge_direction(ea), b_.edge_direction(eb)));
  }

  // eA x eB oriented from A to B (Gregorius' rule: for a Minkowski edge pair
  // the axis points out of A at eA and into B at eB, for any interior points).
  // Both tests are summed: n.(pA - cA) > 0 and n.(cB - pB) > 0 for a
  // Minkowski pair, so the sum has the same sign, and it stays well
  // conditioned when one shape is flat and n is (nearly) its plane normal --
  // there n.(p - c) is 0 up to rounding, and the float arc test can accept
  // such a pair by rounding; orienting by that shape alone then flipped the
  // separation's sign.  For exact T and solid shapes the result is unchanged.
  Vec3<T> edge_axis(int ea, int eb) const {
    Vec3<T> n = unoriented_axis(ea, eb);
    const Vec3<T>& pa = a_.vertex(a_.edge_tail(ea));
    const Vec3<T>& pb = b_.vertex(b_.edge_tail(eb));
    const T out_a = dot(n, diff(pa, a_.centroid()));
    const T in_b = dot(n, diff(b_.centroid(), pb));
    if (T(out_a + in_b) < T(0)) n = Vec3<T>(-n);
    return n;
  }

  Vec3<T> oriented_axis_for_report(int ea, int eb) const { return edge_axis(ea, eb); }

  // p's lowest and highest projections on n (lo, hi) while checking
  // whether p's edge, whose endpoints project to e0 and e1, can still be
  // within t of p's maximum (at_max) or minimum (at_min):
  // edge_separation_full accepts it there when e0, e1 >= fl(hi - t) (resp.
  // <= fl(lo + t)).  Rounding is monotone, so fl(hi - t) is the largest
  // fl(h - t) over the projections h: one vertex with e0 or e1 < fl(h - t)
  // rules out the maximum (resp. > fl(h + t) the minimum).  Returns false,
  // with lo and hi incomplete, as soon as both are ruled out.  (A NaN h rules
  // out nothing here, nor updates lo or hi; the complete test decides.)
  static bool project_supporting(const ConvexPolyhedron<T>& p, const Vec3<T>& n, const T& e0, const T& e1,
                                 const T& t, T& lo, T& hi, bool& at_max, bool& at_min) {
    lo = hi = dot(n, p.vertex(0));
    for (int i = 0; i < p.vertex_count(); ++i) {
      const T h = dot(n, p.vertex(i));
      if (h < lo) lo = h;
      if (h > hi) hi = h;
      rule_out(h, e0, e1, t, at_max, at_min);
      if (!at_max && !at_min) return false;
    }
    return true;
  }

  // One projection h of p's vertices against p's edge's endpoint projections
  // e0, e1 (project_supporting): rules out the maximum when e0 or e1 <
  // fl(h - t), the minimum when e0 or e1 > fl(h + t).  (Exact T decides by
  // signs: exact_edge_separation_full.)
  static void rule_out(const T& h, const T& e0, const T& e1, const T& t, bool& at_max, bool& at_min) {
    const T below = T(h - t), above = T(h + t);
    at_max = at_max && !(e0 < below || e1 < below);
    at_min = at_min && !(e0 > above || e1 > above);
  }

  // edge_separation_full for exact T, by signs (t = 0).  Along n = dA x dB
  // (unoriented_axis) an edge's endpoints are at one height, so a vertex w
  // rules out its shape's maximum when n.(w - tail) > 0 and its minimum when
  // n.(w - tail) < 0: sign_of_height, which builds no value for a type with
  // the hook.  The vertices are asked in the order of the float path (the
  // endpoints' neighbours, then every vertex, A before B), stopping when
  // both orientations are out; the complete scans decide the orientations
  // the float path's extremes decide (t = 0), and the value is its min_b -
  // max_a = n.(tail_B - tail_A) (+n) or min_a - max_b (-n).
  std::optional<Separation<T>> exact_edge_separation_full(int ea, int eb) const {
    const Vec3<T>& da = a_.edge_direction(ea);
    const Vec3<T>& db = b_.edge_direction(eb);
    const Vec3<T>& tail_a = a_.vertex(a_.edge_tail(ea));
    const Vec3<T>& tail_b = b_.vertex(b_.edge_tail(eb));
    bool a_max = true, a_min = true, b_max = true, b_min = true;
    // +n: A's edge at A's maximum and B's at B's minimum; -n the opposite
    auto open = [&] { return (a_max && b_min) || (a_min && b_max); };
    auto side = [&](const Vec3<T>& w, const Vec3<T>& tail, bool& at_max, bool& at_min) {
      const int s = sign_of_height(da, db, w, tail);
      at_max = at_max && s <= 0;
      at_min = at_min && s >= 0;
    };
    auto neighbours = [&](const ConvexPolyhedron<T>& p, int e, const Vec3<T>& tail, bool& at_max,
                          bool& at_min) {
      // (rule_out_by_neighbours' walk; written out there, where a shared
      // visitor cost the float brute force 6 % more instructions)
      for (const int v : {p.edge_tail(e), p.edge_head(e)})
        for (const int h : p.vertex_half_edges(v)) {
          side(p.vertex(p.half_edge(ConvexPolyhedron<T>::twin(h)).origin), tail, at_max, at_min);
          if (!open()) return false;
        }
      return true;
    };
    auto scan = [&](const ConvexPolyhedron<T>& p, const Vec3<T>& tail, bool& at_max, bool& at_min) {
      for (const Vec3<T>& w : p.vertices()) {
        side(w, tail, at_max, at_min);
        if (!open()) return false;
      }
      return true;
    };
    if (!neighbours(a_, ea, tail_a, a_max, a_min) || !neighbours(b_, eb, tail_b, b_max, b_min) ||
        !scan(a_, tail_a, a_max, a_min) || !scan(b_, tail_b, b_max, b_min))
      return std::nullopt;
    const bool plus = a_max && b_min, minus = a_min && b_max;
    const Vec3<T> n = unoriented_axis(ea, eb);
    const T gap = T(dot(n, tail_b) - dot(n, tail_a));  // +n: min_b - max_a
    const Separation<T> sp{gap, norm2_of(n)};
    const Separation<T> sm{T(-gap), sp.norm2};
    if (plus && minus) return sepax::compare(sp, sm) >= 0 ? sp : sm;
    return plus ? sp : sm;
  }

  // project_supporting's test on the vertices adjacent to the endpoints of
  // p's edge e only.  On a convex shape a vertex that is not extreme along n
  // has a neighbour farther along n, so an edge off the extremes is almost
  // always ruled out here, after a few projections instead of a scan.  The
  // tests are those of the scan, on a subset of its vertices, so a pair this
  // rules out is one the scan would rule out.
  static void rule_out_by_neighbours(const ConvexPolyhedron<T>& p, const Vec3<T>& n, int e, const T& e0,
                                     const T& e1, const T& t, bool& at_max, bool& at_min) {
    for (const int v : {p.edge_tail(e), p.edge_head(e)}) {
      for (const int h : p.vertex_half_edges(v)) {
        rule_out(dot(n, p.vertex(p.half_edge(ConvexPolyhedron<T>::twin(h)).origin)), e0, e1, t, at_max,
                 at_min);
        if (!at_max && !at_min) return;
      }
    }
  }

  const ConvexPolyhedron<T>& a_;
  const ConvexPolyhedron<T>& b_;
  bool lanes_;          // both shapes lanes_bounded(): the SIMD scans apply
  bool support_lanes_;  // both shapes support_lanes_bounded(): the support scans apply
  mutable detail::EdgePairRuleOut<T, false> rule_out_;  // edge_pair_ruled_out's state
};

template <Number T>
struct kernel_for<policy::Plain, T> {
  using type = PlainKernel<T>;
};

}  // namespace sepax
