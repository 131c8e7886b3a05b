// sepax/robust/robust_kernel_edges.hpp
//
// The edge-pair decisions of RobustKernel<T> (robust_kernel.hpp).
//   * arc_signs(), minkowski_face(), minkowski_faces(): the Minkowski-face
//     test of two arcs of the Gauss maps, filtered, exact within the bound
//     (one pair, or a batch over B's SIMD lanes);
//   * edges_parallel(): exact, decided by the unit axis's bound first;
//   * edge_pair_below(): a pair certainly below the best, without its axis;
//   * edge_separation() (O(1) form) and edge_separation_full() (projection
//     form, with its exact support checks, extremes() and all_on_side()).
// Built on robust_kernel_faces.hpp; robust_kernel.hpp builds on it.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include <sepax/robust/parallel.hpp>
#include <sepax/robust/robust_kernel_faces.hpp>
#include <sepax/edge_pair_rule_out.hpp>
#include <sepax/simd_lanes.hpp>

namespace sepax::robust::detail {

template <RobustFloat T>
class RobustEdgePairs : public RobustFaceQueries<T> {
  using Base = RobustFaceQueries<T>;

 protected:
  using Base::a_;
  using Base::axis_cache_;
  using Base::axis_side;
  using Base::b_;
  using Base::Base;
  using Base::cross_ratio_squared;
  using Base::diff;
  using Base::e_;
  using Base::edge_axis;
  using Base::edge_pair_sign;
  using Base::edge_value_error;
  using Base::fallbacks_;
  using Base::float_edge_axis;
  using Base::kMargin;
  using Base::kNoBound;
  using Base::lanes_;
  using Base::negate_if;
  using Base::normal_dot_sign_exact;
  using Base::pair_axis_side;
  using Base::projection_rule_;
  using Base::snap;
  using typename Base::EdgeAxis;
  using typename Base::P;

 public:
  ArcSigns arc_signs(int ea, int eb) const {
    // The per-edge arrays of ConvexPolyhedron: the same T values PlainKernel
    // computes (head - tail, the faces' normals), without indirections.
    const Vec3<T>& da = a_.edge_direction(ea);
    const Vec3<T>& db = b_.edge_direction(eb);
    // Branch-free like PlainKernel (the signs are unpredictable); one
    // well-predicted branch for "some sign is within its error bound".
    const T c = dot(b_.edge_normal(eb, 0), da);
    const T d = dot(b_.edge_normal(eb, 1), da);
    const T a = dot(a_.edge_normal(ea, 0), db);
    const T b = dot(a_.edge_normal(ea, 1), db);
    const T eb_ = e_.arc_b_t, ea_ = e_.arc_a_t;  // the bounds rounded up to T
    ArcSigns s;
    s.cba = (c > eb_) - (c < -eb_);
    s.dba = (d > eb_) - (d < -eb_);
    s.adc = (a < -ea_) - (a > ea_);
    s.bdc = (b < -ea_) - (b > ea_);
    // A sign is 0 exactly when |value| <= bound (or NaN): then decide exactly.
    if (s.cba * s.dba * s.adc * s.bdc == 0) [[unlikely]]
      resolve_arc_signs(s, ea, eb, c, d, a, b);
    return s;
  }

  /// == arc_signs(ea, eb).minkowski_face() (the same exact signs), deciding
  /// sign(cba), sign(dba) first -- filter, exact only within the bound -- and
  /// adc, bdc only when those two are strictly opposite.  Signs it does not
  /// need are not decided, so exact_fallbacks() counts fewer arc fallbacks
  /// than arc_signs would.  Inline when every needed sign is certain from the
  /// filter; any uncertain sign goes to minkowski_face_resolve.
  SEPAX_ROBUST_INLINE bool minkowski_face(int ea, int eb) const {
    const Vec3<T>& da = a_.edge_direction(ea);
    const T c = dot(b_.edge_normal(eb, 0), da);
    const T d = dot(b_.edge_normal(eb, 1), da);
    const T eb_ = e_.arc_b_t;
    // certainly on the same side (filtered signs both +1 or both -1): the
    // common case.  Comparisons with NaN are false, so NaN goes to the exact
    // stage like any value within the bound.  With lanes_ (both shapes
    // lanes_bounded: every normal and direction finite, |x| <= 2^60) c and d
    // are finite, and the test is min(c, d) > bound or max(c, d) < -bound
    // (as PlainKernel's, fewer operations than four comparisons).
    if (lanes_) {
      const T lo = d < c ? d : c;
      const T hi = c < d ? d : c;
      if ((lo > eb_) | (hi < -eb_)) return false;
    } else if (((c > eb_) & (d > eb_)) | ((c < -eb_) & (d < -eb_))) {
      return false;
    }
    if (!(((c > eb_) & (d < -eb_)) | ((c < -eb_) & (d > eb_)))) [[unlikely]]
      return minkowski_face_resolve(ea, eb);
    // cba = -dba, both certain
    const Vec3<T>& db = b_.edge_direction(eb);
    const T a = dot(a_.edge_normal(ea, 0), db);
    const T b = dot(a_.edge_normal(ea, 1), db);
    const T ea_ = e_.arc_a_t;
    const int adc = (a < -ea_) - (a > ea_);
    const int bdc = (b < -ea_) - (b > ea_);
    if (adc * bdc == 0) [[unlikely]]
      return minkowski_face_resolve(ea, eb);
    const int cba = c > eb_ ? 1 : -1;
    return adc * bdc < 0 && cba * bdc > 0;
  }

  /// Optional batched member (sat_kernel.hpp, HasMinkowskiFaces): the eb in
  /// [lo, hi) with minkowski_face(ea, eb), ascending.  A float pre-filter over
  /// B's lane arrays (simd_lanes.hpp, arc_candidates<true>) computes the same
  /// four values c, d, a, b as minkowski_face, for a few edges at once, and
  /// drops a pair only when both sign patterns of a crossing are certainly
  /// violated: some value is beyond the bound e_.arc_lane = max(e_.arc_a_t,
  /// e_.arc_b_t) >= the bound of each value (error_bounds.hpp: E_arc, rounded
  /// up to T) on the wrong side, so its exact sign is wrong as well.  A
  /// survivor whose four values are all beyond the bound with the crossing
  /// signs (all > bound or all < -bound: every exact sign is certain)
  /// crosses.  When every survivor of the batch is certain (the common case:
  /// the lanes report it as one flag), the survivors are the answer, with
  /// no per-pair code after the lanes (a second pass over them cost a
  /// mispredicted loop exit per edge of A).  Otherwise (some value within the
  /// bound, or NaN) every survivor goes through minkowski_face, which decides
  /// exactly (the certain ones cost it only its filters, which pass: their
  /// per-side bounds are <= e_.arc_lane).  So the result is exactly
  /// {eb : minkowski_face(ea, eb)}, with or without FMA contraction (the bound
  /// holds either way).  The lanes need both shapes lanes_bounded() (no
  /// overflow, no NaN); otherwise every pair takes minkowski_face.
  SEPAX_ROBUST_INLINE int minkowski_faces(int ea, int lo, int hi, int* out) const {
    if (lanes_) {
      bool uncertain;
      const int m = simd::arc_candidates<true>(b_, lo, hi, a_.edge_direction(ea), a_.edge_normal(ea, 0),
                                               a_.edge_normal(ea, 1), e_.arc_lane, out, &uncertain);
      if (!uncertain) [[likely]]
        return m;
      return minkowski_faces_resolve(ea, m, out);
    }
    int n = 0;
    for (int eb = lo; eb < hi; ++eb) {
      if (minkowski_face(ea, eb)) out[n++] = eb;
    }
    return n;
  }

  /// Exact: (head_A - tail_A) x (head_B - tail_B) == 0.  The edge pair's
  /// unit axis (edge_axis, which edge_separation needs next anyway) decides
  /// it first: a bounded axis (delta < kNoBound) means |Ñ| > 2q, q >= |Ñ - N|
  /// the bound of error_bounds.hpp's unit_error_from_ratio (Ñ = fl(ẽA x ẽB), N the exact
  /// cross product of the exact edge vectors), so |N| >= |Ñ| - q > 0: the
  /// edges are certainly not parallel.  (unit_error_from_ratio returns a
  /// finite delta only for q/|Ñ| < 1/2, computed with the (1+1e-6)^2 pad that
  /// covers the rounding of ρ; with or without FMA, as the axis bound.)
  /// Otherwise -- the T cross product tiny, zero or not finite, or too close
  /// to its error -- robust::parallel decides, as before; the degenerate axis
  /// is then not computed here (exact_edge_axis would be the costly path for
  /// exactly parallel edges, which robust::parallel decides cheaply).
  bool edges_parallel(int ea, int eb) const {
    if (ea != axis_cache_.ea || eb != axis_cache_.eb) {
      const Vec3<T> c = cross(a_.edge_direction(ea), b_.edge_direction(eb));
      const double r2 = cross_ratio_squared(a_.edge_direction(ea), b_.edge_direction(eb), c);
      if (std::isfinite(r2)) {
        axis_cache_.ea = ea;
        axis_cache_.eb = eb;
        axis_cache_.axis = float_edge_axis(c, r2);
      }
    }
    if (ea == axis_cache_.ea && eb == axis_cache_.eb && axis_cache_.axis.delta < kNoBound) return false;
    return robust::parallel(a_.vertex(a_.edge_tail(ea)), a_.vertex(a_.edge_head(ea)),
                            b_.vertex(b_.edge_tail(eb)), b_.vertex(b_.edge_head(eb)), &fallbacks_);
  }

  /// Optional member (sat_kernel.hpp, HasEdgePairBelow), float only: true
  /// when the edge pair's exact O(1) separation s* (the value edge_separation
  /// approximates, with axis_side's orientation) is certainly below
  /// best - best_err, hence below the exact separation of any feature whose
  /// value is best within best_err; false when that is not certain (which
  /// says nothing).  Exactly parallel edges always give false.  It decides
  /// from the T inputs in double, without the unit axis, its bound or an
  /// exact stage, so a pair that exact arithmetic would offer and reject
  /// costs about 40 instructions instead of edges_parallel, edge_separation
  /// and a comparison.  The bounds are error_bounds.hpp's "(pair prefilter)".
  bool edge_pair_below(int ea, int eb, T best, double best_err) const requires std::is_same_v<T, float> {
    // M = best_err - best > 0: the best's exact value is certainly negative
    // (the overlapping case); otherwise no decision.  NaN compares false.
    const double m = best_err - static_cast<double>(best);
    if (!(m > 0) || !lanes_) return false;
    const Vec3<T>& da = a_.edge_direction(ea);
    const Vec3<T>& db = b_.edge_direction(eb);
    const Vec3<T>& pa = a_.vertex(a_.edge_tail(ea));
    const Vec3<T>& pb = b_.vertex(b_.edge_tail(eb));
    const Vec3<T>& ca = a_.centroid();
    const Vec3<T>& cb = b_.centroid();
    // Ĉ = fl_d(ẽA x ẽB): float products are exact in double.
    const double ax = da[0], ay = da[1], az = da[2], bx = db[0], by = db[1], bz = db[2];
    const double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    // v̂ = Ĉ . ŵ, ŵ = (pA - c̃A) + (c̃B - pB): axis_side's sum, unnormalised.
    auto wc = [&](int i) {
      return (static_cast<double>(pa[i]) - static_cast<double>(ca[i])) +
             (static_cast<double>(cb[i]) - static_cast<double>(pb[i]));
    };
    const double v = cx * wc(0) + cy * wc(1) + cz * wc(2);
    if (!(std::abs(v) > e_.pre_side)) return false;  // orientation not certain
    // t̂ = Ĉ . d̂, d̂ = pB - pA; σ̂ t̂ the oriented value times |Ĉ|.
    const double t = cx * (static_cast<double>(pb[0]) - static_cast<double>(pa[0])) +
                     cy * (static_cast<double>(pb[1]) - static_cast<double>(pa[1])) +
                     cz * (static_cast<double>(pb[2]) - static_cast<double>(pa[2]));
    const double y = (v < 0 ? t : -t) - e_.pre_value;  // -σ̂ t̂ - E_t
    const double n2 = cx * cx + cy * cy + cz * cz;
    return (y > 0) & (y * y > m * m * (n2 + e_.pre_norm_sq) * kMargin);
  }

  Separation<T> edge_separation(int ea, int eb) const {
    projection_rule_ = false;
    const EdgeAxis ax = edge_axis(ea, eb);
    const Vec3<T>& pa = a_.vertex(a_.edge_tail(ea));
    const Vec3<T>& pb = b_.vertex(b_.edge_tail(eb));
    // The orientation flips the axis's sign bits (the same n as -n, hence
    // PlainKernel's value, bit for bit) without a jump: the side is a coin
    // toss per pair (about half the Minkowski pairs flip), and the jump
    // mispredicted at the end of the pair's longest chains (the axis: sqrt,
    // divisions; its bound: division, sqrt).
    const bool flip = axis_side(ax, ea, eb) < 0;
    const Vec3<T> n(negate_if(ax.n[0], flip), negate_if(ax.n[1], flip), negate_if(ax.n[2], flip));
    return snap(dot(n, diff(pb, pa)), edge_value_error(ax.delta), Feature::edges(ea, eb));
  }

  /// Optional member (sat_kernel.hpp, HasEdgePairRuledOut): true only when
  /// edge_separation_full(ea, eb) would return nothing, its decisions being
  /// exact along n* = E_A x E_B: a wing of either edge certainly on each
  /// side (edge_pair_rule_out.hpp, ExactRuleOut).
  bool edge_pair_ruled_out(int ea, int eb) const {
    return rule_out_.ruled_out(a_, ea, b_, eb, [] { return std::array<double, 2>{}; });
  }

  std::optional<Separation<T>> edge_separation_full(int ea, int eb) const {
    projection_rule_ = true;
    const EdgeAxis ax = edge_axis(ea, eb);
    const Vec3<T>& n = ax.n;
    const double wa = e_.proj_abs_a + ax.delta * e_.extent_a * kMargin;
    const double wb = e_.proj_abs_b + ax.delta * e_.extent_b * kMargin;
    // Most pairs support neither orientation, and the neighbours of the
    // edges' endpoints show it (rule_out_by_neighbours) before any scan.
    bool may_plus = true, may_minus = true;
    rule_out_by_neighbours(a_, n, ea, wa, may_plus, may_minus);
    if (may_plus || may_minus) rule_out_by_neighbours(b_, n, eb, wb, may_minus, may_plus);
    if (!may_plus && !may_minus) return std::nullopt;
    Extremes ea_x = extremes(a_, n, a_.edge_tail(ea), a_.edge_head(ea));
    const bool a_max = may_plus && all_on_side(a_, ea_x, n, wa, +1, ea, eb);
    const bool a_min = may_minus && all_on_side(a_, ea_x, n, wa, -1, ea, eb);
    if (!a_max && !a_min) return std::nullopt;
    Extremes eb_x = extremes(b_, n, b_.edge_tail(eb), b_.edge_head(eb));
    const bool b_min = a_max && all_on_side(b_, eb_x, n, wb, -1, ea, eb);
    const bool b_max = a_min && all_on_side(b_, eb_x, n, wb, +1, ea, eb);
    const bool plus = a_max && b_min;   // +n from A to B
    const bool minus = a_min && b_max;  // -n from A to B
    if (!plus && !minus) return std::nullopt;
    const Separation<T> sp{T(eb_x.lo - ea_x.hi), T(1)};
    const Separation<T> sm{T(ea_x.lo - eb_x.hi), T(1)};
    if (plus && minus) {
      // Both shapes project to single values: sp* = -sm*, so sp >= sm iff
      // n*.(pB - pA) >= 0.
      const double e = edge_value_error(ax.delta);
      int s;
      if (static_cast<double>(sp.num) > e)
        s = 1;
      else if (static_cast<double>(sp.num) < -e)
        s = -1;
      else
        s = edge_pair_sign(ea, eb);
      return snap((s >= 0 ? sp : sm).num, edge_value_error(ax.delta), Feature::edges(ea, eb));
    }
    return snap((plus ? sp : sm).num, edge_value_error(ax.delta), Feature::edges(ea, eb));
  }

 protected:
  // The lane candidates out[0, m) of a batch with some uncertain pair, each
  // decided by minkowski_face (exact); the crossing ones kept, in order.
  SEPAX_ROBUST_COLD int minkowski_faces_resolve(int ea, int m, int* out) const {
    int n = 0;
    for (int i = 0; i < m; ++i) {
      if (minkowski_face(ea, out[i])) out[n++] = out[i];
    }
    return n;
  }

  // minkowski_face with some needed sign within its bound: the same sequence
  // (cba, dba, then adc, bdc only if cba, dba are strictly opposite), each
  // sign filtered and decided exactly when uncertain.
  SEPAX_ROBUST_COLD bool minkowski_face_resolve(int ea, int eb) const {
    const Vec3<T>& da = a_.edge_direction(ea);
    const T c = dot(b_.edge_normal(eb, 0), da);
    const T d = dot(b_.edge_normal(eb, 1), da);
    const T eb_ = e_.arc_b_t;
    int cba = (c > eb_) - (c < -eb_);
    int dba = (d > eb_) - (d < -eb_);
    if (cba * dba == 0) resolve_arc_signs_ba(cba, dba, ea, eb, c, d);
    if (!(cba * dba < 0)) return false;
    const Vec3<T>& db = b_.edge_direction(eb);
    const T a = dot(a_.edge_normal(ea, 0), db);
    const T b = dot(a_.edge_normal(ea, 1), db);
    const T ea_ = e_.arc_a_t;
    int adc = (a < -ea_) - (a > ea_);
    int bdc = (b < -ea_) - (b > ea_);
    if (adc * bdc == 0) resolve_arc_signs_dc(adc, bdc, ea, eb, a, b);
    return adc * bdc < 0 && cba * bdc > 0;
  }

  // The arc signs of a pair decided exactly.
  // The arc signs whose value was within the bound (or NaN), decided exactly.
  SEPAX_ROBUST_COLD void resolve_arc_signs(ArcSigns& s, int ea, int eb, T c, T d, T a, T b) const {
    if (!(std::fabs(c) > e_.arc_b_t)) s.cba = normal_dot_sign_exact(b_, b_.edge_face(eb, 0), a_, ea);
    if (!(std::fabs(d) > e_.arc_b_t)) s.dba = normal_dot_sign_exact(b_, b_.edge_face(eb, 1), a_, ea);
    if (!(std::fabs(a) > e_.arc_a_t)) s.adc = -normal_dot_sign_exact(a_, a_.edge_face(ea, 0), b_, eb);
    if (!(std::fabs(b) > e_.arc_a_t)) s.bdc = -normal_dot_sign_exact(a_, a_.edge_face(ea, 1), b_, eb);
  }

  // minkowski_face's halves of resolve_arc_signs (same exact predicates).
  SEPAX_ROBUST_COLD void resolve_arc_signs_ba(int& cba, int& dba, int ea, int eb, T c, T d) const {
    if (!(std::fabs(c) > e_.arc_b_t)) cba = normal_dot_sign_exact(b_, b_.edge_face(eb, 0), a_, ea);
    if (!(std::fabs(d) > e_.arc_b_t)) dba = normal_dot_sign_exact(b_, b_.edge_face(eb, 1), a_, ea);
  }

  SEPAX_ROBUST_COLD void resolve_arc_signs_dc(int& adc, int& bdc, int ea, int eb, T a, T b) const {
    if (!(std::fabs(a) > e_.arc_a_t)) adc = -normal_dot_sign_exact(a_, a_.edge_face(ea, 0), b_, eb);
    if (!(std::fabs(b) > e_.arc_a_t)) bdc = -normal_dot_sign_exact(a_, a_.edge_face(ea, 1), b_, eb);
  }

  struct Extremes {
    T lo, hi;              // over all vertices (the values PlainKernel computes)
    T lo_other, hi_other;  // over all vertices except the edge's endpoints
    T ref;                 // projection of the edge's tail
  };
  Extremes extremes(const P& p, const Vec3<T>& n, int tail, int head) const {
    // The other vertices in three runs around the edge's two endpoints (no
    // per-vertex mask), two selects each (minss/maxss, not jumps: whether a
    // vertex is a new extreme is a coin toss per vertex and pair, and the
    // brute force runs this loop twice per edge pair); the endpoints join
    // lo and hi at the end.  The same values as one loop over all vertices:
    // a minimum or maximum of the same fl(n.v) does not depend on the order.
    constexpr T kInf = std::numeric_limits<T>::infinity();
    Extremes x;
    x.lo_other = kInf;
    x.hi_other = -kInf;
    const auto run = [&](int from, int to) {
      for (int i = from; i < to; ++i) {
        const T h = dot(n, p.vertex(i));
        x.lo_other = h < x.lo_other ? h : x.lo_other;
        x.hi_other = h > x.hi_other ? h : x.hi_other;
      }
    };
    const int first = tail < head ? tail : head, second = tail < head ? head : tail;
    run(0, first);
    run(first + 1, second);
    run(second + 1, p.vertex_count());
    x.ref = dot(n, p.vertex(tail));
    const T h_head = dot(n, p.vertex(head));
    const T lo_edge = x.ref < h_head ? x.ref : h_head, hi_edge = x.ref > h_head ? x.ref : h_head;
    x.lo = lo_edge < x.lo_other ? lo_edge : x.lo_other;
    x.hi = hi_edge > x.hi_other ? hi_edge : x.hi_other;
    return x;
  }

  // The test of all_on_side on the vertices adjacent to the endpoints of p's
  // edge e only (the endpoints themselves excluded): a neighbour whose
  // projection exceeds the tail's by more than w (the bound on the error of
  // that difference, the one all_on_side uses) is exactly beyond the edge
  // along n*, which rules out the edge at p's maximum (at_max := false; at
  // p's minimum for a difference below -w).  all_on_side decides the same
  // (its extreme is at least as far, and the subtraction rounds
  // monotonically), and either way the decision is the exact one.  On a
  // convex shape a vertex that is not extreme along n has a neighbour farther
  // along n, so most edges off the extremes are ruled out here.
  void rule_out_by_neighbours(const P& p, const Vec3<T>& n, int e, double w, bool& at_max,
                              bool& at_min) const {
    const int tail = p.edge_tail(e), head = p.edge_head(e);
    const double ref = static_cast<double>(dot(n, p.vertex(tail)));
    for (const int v : {tail, head}) {
      for (const int h : p.vertex_half_edges(v)) {
        const int u = p.half_edge(P::twin(h)).origin;
        if (u == tail || u == head) continue;
        const double d = static_cast<double>(dot(n, p.vertex(u))) - ref;
        if (d > w) at_max = false;
        if (-d > w) at_min = false;
        if (!at_max && !at_min) return;
      }
    }
  }

  // dir = +1: every vertex v of p satisfies n*.(v - ref) <= 0 (the edge is at
  // p's maximum along n*); dir = -1: >= 0 (at its minimum).  The edge's own
  // endpoints are exactly at 0 (n* is orthogonal to both edges).
  bool all_on_side(const P& p, const Extremes& x, const Vec3<T>& n, double w, int dir, int ea, int eb) const {
    const double ext = static_cast<double>(dir > 0 ? x.hi_other : x.lo_other);
    const double dx = (ext - static_cast<double>(x.ref)) * dir;  // > 0: some vertex beyond
    if (dx < -w) return true;
    if (dx > w) return false;
    return all_on_side_resolve(p, x, n, w, dir, ea, eb);
  }

  SEPAX_ROBUST_COLD bool all_on_side_resolve(const P& p, const Extremes& x, const Vec3<T>& n, double w,
                                             int dir, int ea, int eb) const {
    const bool is_a = &p == &a_;
    const int tail = is_a ? a_.edge_tail(ea) : b_.edge_tail(eb);
    const int head = is_a ? a_.edge_head(ea) : b_.edge_head(eb);
    const Vec3<T>& ref = p.vertex(tail);
    for (int i = 0; i < p.vertex_count(); ++i) {
      if (i == tail || i == head) continue;
      const double d = (static_cast<double>(dot(n, p.vertex(i))) - static_cast<double>(x.ref)) * dir;
      if (d > w) return false;
      if (d < -w) continue;
      if (pair_axis_side(ea, eb, ref, p.vertex(i)) * dir > 0) return false;
    }
    return true;
  }

 private:
  mutable sepax::detail::EdgePairRuleOut<T, true> rule_out_;  // edge_pair_ruled_out's state
};

}  // namespace sepax::robust::detail
