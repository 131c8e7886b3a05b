// sepax/robust/robust_kernel.hpp
//
// policy::Robust and RobustKernel<T> (T = float or double): the SAT kernel whose
// VALUES are the plain float/double values of PlainKernel<T> and whose every
// DECISION is exact.
//
// Contract.  For float/double polyhedra A, B, a SAT run with policy::Robust
// makes exactly the decisions that PlainKernel<mpq_class> makes on the exact
// images ConvexPolyhedron<mpq_class>::convert_from(A), convert_from(B):
// the same support vertices (lowest index among the exactly deepest), arc
// signs, parallel edges, edge-axis orientations, brute-force support checks,
// comparisons and signs.  Hence the same feature, the same overlap verdict and
// the same sign of separation.  The separation VALUE and the axis are the
// float/double numbers PlainKernel<T> computes for that feature, except that a
// value whose sign is wrong (|value| within its error bound, exact sign
// different) is replaced by 0 (exact zero) or by the exact separation rounded
// to T: a returned separation always has the exact sign.
//
// How.  Each decision first compares the plain value with an error bound
// derived from per-query constants (below), and falls back to an exact
// evaluation from the vertex coordinates (orientation.hpp, parallel.hpp,
// separation_compare.hpp) only when |value| <= bound.  Argmin/argmax keep the
// few candidates within the bound and resolve them exactly.
//
// Error bounds: error_bounds.hpp.  Per query, O(1) from terms each
// ConvexPolyhedron computes once (with its planes: max_abs_coordinate, extent,
// bounds, centroid; on first use: normal_conditioning), no allocation:
// QueryBounds<T>, one named field per bound with its derivation (face value,
// support, arc sign, edge value, projection, centroid side, pair prefilter);
// per edge pair, the unit axis bound δ_e (unit_error_from_ratio).
//
// Centroids.  PlainKernel<mpq_class> orients an edge-pair axis (O(1) form) by
// the sign of n*.(pA - cA) + n*.(cB - pB), cA and cB the exact vertex means
// (axis_side).  For a Minkowski edge pair of exactly convex shapes both terms
// are positive, but the float centroids need not be strictly inside (sliver
// shapes, and off the plane of a flat shape), and on inputs convex only within
// tolerance the terms can differ in sign, so the exact fallbacks use the
// exact means: sign Σ_v n*.(p - v) = sign (V n*.p - n*.Σ v).
//
// Edge-pair orientation in compare()/sign().  A separation value does not say
// which orientation its SAT chose, so the kernel recomputes it from the
// feature: the O(1) form (edge_separation, Gauss map, traversal) uses
// axis_side (above), no flip when zero; the projection form
// (edge_separation_full, brute force) uses s_A if non-zero, else the sign of
// n*.(centroid(B) - pB), else the sign of n*.(pB - pA) (+1 when zero), which is
// exactly the orientation its exact support checks select.  A kernel serves one
// SAT run; it remembers which of the two forms that run used.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <type_traits>

#include <sepax/plain_kernel.hpp>
#include <sepax/robust/error_bounds.hpp>
#include <sepax/robust/exact_float.hpp>
#include <sepax/robust/orientation.hpp>
#include <sepax/robust/parallel.hpp>
#include <sepax/robust/separation_compare.hpp>
#include <sepax/sat_kernel.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

/// The SAT loops' per-pair and per-face fast paths: inlined into the loop even
/// when the inliner's size heuristics would not (their exact stages are out of
/// line).  SEPAX_ROBUST_NOINLINE: a rare slow path kept out of such a loop
/// (not cold: the brute force takes it on every edge pair).
#if defined(__GNUC__) || defined(__clang__)
#define SEPAX_ROBUST_INLINE [[gnu::always_inline]]
#define SEPAX_ROBUST_NOINLINE [[gnu::noinline]]
#else
#define SEPAX_ROBUST_INLINE
#define SEPAX_ROBUST_NOINLINE
#endif

namespace sepax {

namespace policy {
/// float/double values, every decision by a filtered exact predicate.
struct Robust {};
}  // namespace policy

template <RobustFloat T>
class RobustKernel : robust::ErrorConstants<T> {
 public:
  using FT = T;
  /// Every decision is exact (sat_kernel.hpp, exact_decisions_v).
  static constexpr bool kExactDecisions = true;

  RobustKernel(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b)
      : a_(a), b_(b), e_(a, b), lanes_(a.lanes_bounded() && b.lanes_bounded()) {}

  const ConvexPolyhedron<T>& a() const { return a_; }
  const ConvexPolyhedron<T>& b() const { return b_; }

  SEPAX_ROBUST_INLINE FaceQuery<T> face_query_a(int f) const {
    FaceQuery<T> q = face_query(a_, f, b_, e_.support_a, e_.support_a_t);
    q.separation = snap(q.separation.num, e_.face_a, Feature::face_a(f, q.support_vertex));
    return q;
  }
  SEPAX_ROBUST_INLINE FaceQuery<T> face_query_b(int f) const {
    FaceQuery<T> q = face_query(b_, f, a_, e_.support_b, e_.support_b_t);
    q.separation = snap(q.separation.num, e_.face_b, Feature::face_b(q.support_vertex, f));
    return q;
  }

  /// Optional members (sat_kernel.hpp, HasFaceEstimate): face f's value
  /// without certifying its support vertex, for the face scan's skip test
  /// (best_axis.hpp, BestAxis::certainly_below).  The value is
  /// fl(m - offset), m the minimum over the other shape's vertices v of
  /// g_v = fl(n.v) (a min-only scan: no argmin, no second minimum); face_query
  /// reports the same value when its support vertex is the float argmin.
  /// Its error against the face's exact separation h* = min_v h(v) (h(v) =
  /// N.(v - a)/|N|, the exact support vertex's height) is at most E_face,
  /// e_.face_a (error_bounds.hpp, QueryBounds::face_a, which bounds
  /// |fl(g_v - offset) - h(v)| for every vertex v, with or without FMA):
  /// with u the vertex attaining m and w an exact argmin,
  ///   h* <= h(u) <= fl(m - offset) + E_face, and, since g_w >= m and
  ///   rounding is monotone, fl(m - offset) <= fl(g_w - offset) <= h* + E_face.
  /// No exact stage runs here.
  SEPAX_ROBUST_INLINE FaceEstimate<T> face_estimate_a(int f) const {
    const Plane<T>& pl = a_.plane(f);
    return FaceEstimate<T>{Separation<T>{T(support_min(pl, b_) - pl.offset), T(1)}, e_.face_a};
  }
  SEPAX_ROBUST_INLINE FaceEstimate<T> face_estimate_b(int f) const {
    const Plane<T>& pl = b_.plane(f);
    return FaceEstimate<T>{Separation<T>{T(support_min(pl, a_) - pl.offset), T(1)}, e_.face_b};
  }

  // Side axes (both shapes flat; best_axis.hpp).  No filter: the case is
  // rare (two double-sided polygons) and small, so the support vertex
  // and every decision on a side feature are exact (value_error is infinite
  // for SideA/SideB, so compare and sign always take the exact stage).  The
  // value is the float height along the normalised side normal, carrying the
  // exact sign (snap_exact).
  FaceQuery<T> side_query_a(int e) const { return side_query(a_, e, b_, true); }
  FaceQuery<T> side_query_b(int e) const { return side_query(b_, e, a_, false); }

  Separation<T> face_separation_a(int f, int vb) const {
    return snap(height(a_.plane(f), b_.vertex(vb)).num, e_.face_a, Feature::face_a(f, vb));
  }
  Separation<T> face_separation_b(int f, int va) const {
    return snap(height(b_.plane(f), a_.vertex(va)).num, e_.face_b, Feature::face_b(va, f));
  }

  // ---- the traversal's filtered support comparisons (optional members) ----
  // Two vertices u, v of B below face f of A are compared through
  // g = fl(n_f . p) (the support scan's values): |(g_u - g_v) - (N/|N|).(u - v)|
  // <= W_A (e_.support_a, "(support)" in error_bounds.hpp).  support_filter_a() is
  // W_A rounded up to T, so a T comparison is enough: rounding is monotone and
  // -W is a T value, so fl(g_u - g_v) < -W implies g_u - g_v < -W (exactly),
  // hence N.(u - v) < 0; likewise > W.  FMA contraction inside the dot products
  // only removes roundings (γ_3 still bounds them); the subtraction has no
  // product to contract with.  Within the filter (or NaN) the caller asks
  // support_sign_*, the exact sign.

  /// W_A rounded up to T: bound on the error of fl(n_f.u) - fl(n_f.v), f a face
  /// of A, u, v vertices of B.
  T support_filter_a() const { return e_.support_a_t; }
  /// W_B rounded up to T (faces of B, vertices of A).
  T support_filter_b() const { return e_.support_b_t; }
  /// Exact sign of N_f . (b_u - b_v), N_f the plane triple's cross product of
  /// face f of A: < 0 when vertex u of B is strictly deeper below f than v.
  /// Out of line (and cold: asked only within the filter): inlined, its
  /// orientation filter's registers made the traversal's climb loop spill on
  /// every step although it almost never runs.
  /// (d, the filtered difference, is not needed: sat_kernel.hpp, HasSupportFilter.)
  SEPAX_ROBUST_COLD int support_sign_a(int f, int u, int v, T /*d*/) const {
    return face_pair_sign(a_, f, b_.vertex(v), b_.vertex(u));
  }
  /// Exact sign of N_f . (a_u - a_v), f a face of B.
  SEPAX_ROBUST_COLD int support_sign_b(int f, int u, int v, T /*d*/) const {
    return face_pair_sign(b_, f, a_.vertex(v), a_.vertex(u));
  }

  /// The bound on |value - exact value| of a separation this kernel returns
  /// for feature f (face_separation_*, face_query_*, edge_separation): the
  /// bound compare() and sign() use.
  double error_bound(const Feature& f) const { return value_error(f); }

  /// compare() with both error bounds given (error_bound() of fx and fy, e.g.
  /// kept by the caller for its current best): the same filter and the same
  /// exact fallback, hence the same answer.
  /// The filter width of compare_bounded() for error bounds ex and ey: when
  /// x.num - y.num (in double) is beyond it, the exact comparison has that
  /// sign.
  double compare_width(double ex, double ey) const { return (ex + ey) * kMargin; }

  ///
  /// The filter comes before the test fx == fy (whose short-circuit jumps on
  /// the features' fields mispredicted several times per query): for one
  /// feature both values are within their bounds ex, ey of the same exact
  /// separation, so |x - y| <= ex + ey (in exact arithmetic; d and bound carry
  /// the (1+1e-6) margin of compare_width) and the filter never answers
  /// +-1 for it -- the features are compared only when the filter does not
  /// decide, as before for every pair of distinct features, with the same
  /// answer.
  int compare_bounded(const Separation<T>& x, const Feature& fx, double ex, const Separation<T>& y,
                      const Feature& fy, double ey) const {
    const double bound = compare_width(ex, ey);
    const double d = static_cast<double>(x.num) - static_cast<double>(y.num);
    if (d > bound) return 1;
    if (d < -bound) return -1;
    if (fx == fy) return 0;
    return compare_exact(fx, fy);
  }

  ArcSigns arc_signs(int ea, int eb) const {
    // The per-edge arrays of ConvexPolyhedron: the same T values PlainKernel
    // computes (head - tail, the faces' normals), without indirections.
    const Vec3<T>& da = a_.edge_dir(ea);
    const Vec3<T>& db = b_.edge_dir(eb);
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
    if (s.cba * s.dba * s.adc * s.bdc == 0) [[unlikely]] resolve_arc_signs(s, ea, eb, c, d, a, b);
    return s;
  }

  /// == arc_signs(ea, eb).minkowski_face() (the same exact signs), deciding
  /// sign(cba), sign(dba) first -- filter, exact only within the bound -- and
  /// adc, bdc only when those two are strictly opposite.  Signs it does not
  /// need are not decided, so exact_fallbacks() counts fewer arc fallbacks
  /// than arc_signs would.  Inline when every needed sign is certain from the
  /// filter; any uncertain sign goes to minkowski_face_resolve.
  SEPAX_ROBUST_INLINE bool minkowski_face(int ea, int eb) const {
    const Vec3<T>& da = a_.edge_dir(ea);
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
    const Vec3<T>& db = b_.edge_dir(eb);
    const T a = dot(a_.edge_normal(ea, 0), db);
    const T b = dot(a_.edge_normal(ea, 1), db);
    const T ea_ = e_.arc_a_t;
    const int adc = (a < -ea_) - (a > ea_);
    const int bdc = (b < -ea_) - (b > ea_);
    if (adc * bdc == 0) [[unlikely]] return minkowski_face_resolve(ea, eb);
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
      const int m = simd::arc_candidates<true>(b_, lo, hi, a_.edge_dir(ea), a_.edge_normal(ea, 0),
                                               a_.edge_normal(ea, 1), e_.arc_lane, out, &uncertain);
      if (!uncertain) [[likely]] return m;
      return minkowski_faces_resolve(ea, m, out);
    }
    int n = 0;
    for (int eb = lo; eb < hi; ++eb) {
      if (minkowski_face(ea, eb)) out[n++] = eb;
    }
    return n;
  }

 private:
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
    const Vec3<T>& da = a_.edge_dir(ea);
    const T c = dot(b_.edge_normal(eb, 0), da);
    const T d = dot(b_.edge_normal(eb, 1), da);
    const T eb_ = e_.arc_b_t;
    int cba = (c > eb_) - (c < -eb_);
    int dba = (d > eb_) - (d < -eb_);
    if (cba * dba == 0) resolve_arc_signs_ba(cba, dba, ea, eb, c, d);
    if (!(cba * dba < 0)) return false;
    const Vec3<T>& db = b_.edge_dir(eb);
    const T a = dot(a_.edge_normal(ea, 0), db);
    const T b = dot(a_.edge_normal(ea, 1), db);
    const T ea_ = e_.arc_a_t;
    int adc = (a < -ea_) - (a > ea_);
    int bdc = (b < -ea_) - (b > ea_);
    if (adc * bdc == 0) resolve_arc_signs_dc(adc, bdc, ea, eb, a, b);
    return adc * bdc < 0 && cba * bdc > 0;
  }

 public:
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
      const Vec3<T> c = cross(a_.edge_dir(ea), b_.edge_dir(eb));
      const double r2 = cross_ratio_squared(a_.edge_dir(ea), b_.edge_dir(eb), c);
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
  bool edge_pair_below(int ea, int eb, T best, double best_err) const
    requires std::is_same_v<T, float>
  {
    // M = best_err - best > 0: the best's exact value is certainly negative
    // (the overlapping case); otherwise no decision.  NaN compares false.
    const double m = best_err - static_cast<double>(best);
    if (!(m > 0) || !lanes_) return false;
    const Vec3<T>& da = a_.edge_dir(ea);
    const Vec3<T>& db = b_.edge_dir(eb);
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

  std::optional<Separation<T>> edge_separation_full(int ea, int eb) const {
    projection_rule_ = true;
    const EdgeAxis ax = edge_axis(ea, eb);
    const Vec3<T>& n = ax.n;
    Extremes ea_x = extremes(a_, n, a_.edge_tail(ea), a_.edge_head(ea));
    const double wa = e_.proj_abs_a + ax.delta * e_.extent_a * kMargin;
    const bool a_max = all_on_side(a_, ea_x, n, wa, +1, ea, eb);
    const bool a_min = all_on_side(a_, ea_x, n, wa, -1, ea, eb);
    if (!a_max && !a_min) return std::nullopt;
    Extremes eb_x = extremes(b_, n, b_.edge_tail(eb), b_.edge_head(eb));
    const double wb = e_.proj_abs_b + ax.delta * e_.extent_b * kMargin;
    const bool b_min = a_max && all_on_side(b_, eb_x, n, wb, -1, ea, eb);
    const bool b_max = a_min && all_on_side(b_, eb_x, n, wb, +1, ea, eb);
    const bool plus = a_max && b_min;    // +n from A to B
    const bool minus = a_min && b_max;   // -n from A to B
    if (!plus && !minus) return std::nullopt;
    const Separation<T> sp{T(eb_x.lo - ea_x.hi), T(1)};
    const Separation<T> sm{T(ea_x.lo - eb_x.hi), T(1)};
    if (plus && minus) {
      // Both shapes project to single values: sp* = -sm*, so sp >= sm iff
      // n*.(pB - pA) >= 0.
      const double e = edge_value_error(ax.delta);
      int s;
      if (static_cast<double>(sp.num) > e) s = 1;
      else if (static_cast<double>(sp.num) < -e) s = -1;
      else s = edge_pair_sign(ea, eb);
      return snap((s >= 0 ? sp : sm).num, edge_value_error(ax.delta), Feature::edges(ea, eb));
    }
    return snap((plus ? sp : sm).num, edge_value_error(ax.delta), Feature::edges(ea, eb));
  }

  // The filter first, then fx == fy: see compare_bounded.
  int compare(const Separation<T>& x, const Feature& fx, const Separation<T>& y, const Feature& fy) const {
    const double bound = (value_error(fx) + value_error(fy)) * kMargin;
    const double d = static_cast<double>(x.num) - static_cast<double>(y.num);
    if (d > bound) return 1;
    if (d < -bound) return -1;
    if (fx == fy) return 0;
    return compare_exact(fx, fy);
  }

  int sign(const Separation<T>& x, const Feature& f) const {
    const double v = static_cast<double>(x.num);
    const double e = value_error(f);
    if (v > e) return 1;
    if (v < -e) return -1;
    return exact_value_sign(f);
  }

  /// Optional member (sat_kernel.hpp, HasCompareMargin): the exact sign of
  /// (f's exact separation - m), m >= 0 a finite double (SatOptions::margin).
  /// Filter: |x - exact| <= value_error(f) = e, and d = fl(x - m) in double
  /// (one subtraction of two doubles: nothing to contract) is within
  /// 2^-53 |x - m| of x - m, so |d| > e (1 + 1e-6) decides the sign (as
  /// compare_bounded).  Otherwise exactly: f's separation polynomials
  /// against m / sqrt(1) (robust::compare_exact).
  int compare_margin(const Separation<T>& x, const Feature& f, double m) const {
    const double e = value_error(f) * kMargin;
    const double d = static_cast<double>(x.num) - m;
    if (d > e) return 1;
    if (d < -e) return -1;
    return compare_margin_exact(f, m);
  }

  /// Largest error |n - n*| of a reported edge-pair axis (axis()), unitless
  /// (a chord of the unit sphere, about the angle in radians).  Beyond it the
  /// T unit axis is replaced by the exact direction (a few units of roundoff).
  static constexpr double kReportedAxisError = 0x1p-10;

  /// The feature's unit axis, from A to B.  An edge pair's axis is the T
  /// unit cross product (PlainKernel's) when its bound delta (|n - n*|, n*
  /// the exact unit direction) is at most kReportedAxisError; otherwise (edges
  /// nearly parallel, where the T cross product may point anywhere) it is the
  /// exact cross product's direction, rounded.  Its orientation is the exact
  /// one either way (edge_sigma).
  Vec3<T> axis(const Feature& f) const {
    switch (f.type) {
      case FeatureType::FaceA: return a_.plane(f.a).normal;
      case FeatureType::FaceB: return Vec3<T>(-b_.plane(f.b).normal);
      case FeatureType::EdgePair: {
        EdgeAxis ax = edge_axis(f.a, f.b);
        const int sigma = edge_sigma(f.a, f.b);
        if (!(ax.delta <= kReportedAxisError)) ax = exact_edge_axis(f.a, f.b);
        return sigma < 0 ? Vec3<T>(-ax.n) : ax.n;
      }
      case FeatureType::SideA: return side_normal(a_, f.a);
      case FeatureType::SideB: return Vec3<T>(-side_normal(b_, f.b));
    }
    return Vec3<T>(T(0), T(0), T(0));
  }

  /// Decisions that needed the exact stage (ExactFloat evaluations).
  std::int64_t exact_fallbacks() const { return fallbacks_; }

 private:
  using P = ConvexPolyhedron<T>;
  using C = robust::ErrorConstants<T>;
  using C::kEta;
  using C::kG5;
  using C::kMargin;
  using C::kNoBound;
  using C::kPreK;
  using C::kPreKappa;
  using C::kU;
  using C::kUd;
  using C::cross_ratio_squared;
  using C::unit_error_from_ratio;

  struct EdgeAxis {
    Vec3<T> n;      // fl(normalize(dA x dB)), unoriented (as PlainKernel)
    double delta;   // bound on |n - n*/|n*||
  };

  struct Extremes {
    T lo, hi;               // over all vertices (the values PlainKernel computes)
    T lo_other, hi_other;   // over all vertices except the edge's endpoints
    T ref;                  // projection of the edge's tail
  };

  // neg ? -v : v (the sign bit flipped: -v, as unary minus), without a jump.
  static T negate_if(T v, bool neg) {
    using Bits = std::conditional_t<std::is_same_v<T, float>, std::uint32_t, std::uint64_t>;
    constexpr int kSignShift = static_cast<int>(sizeof(T)) * 8 - 1;
    return std::bit_cast<T>(static_cast<Bits>(std::bit_cast<Bits>(v) ^ (static_cast<Bits>(neg) << kSignShift)));
  }

  // p - q, one subtraction per coordinate: the value of Vec3<T>(p - q), which
  // g++ -O3 compiled to an out-of-line Eigen call (as PlainKernel::diff).
  static Vec3<T> diff(const Vec3<T>& p, const Vec3<T>& q) {
    return Vec3<T>(T(p[0] - q[0]), T(p[1] - q[1]), T(p[2] - q[2]));
  }

  static Separation<T> height(const Plane<T>& pl, const Vec3<T>& p) {
    return Separation<T>{T(dot(pl.normal, p) - pl.offset), T(1)};
  }

  // The unit axis of an edge pair, exactly as PlainKernel<T>::unoriented_axis,
  // with its error bound.  If the T cross product is zero or not finite (edges
  // parallel in T but not exactly), the axis is computed from the exact cross
  // product rounded to double (a value for reporting; every decision about it
  // then goes exact because delta is kNoBound).
  // compare()/sign()/axis()/error_bound() of a feature follow its
  // edges_parallel/edge_separation calls: the cache hit is inline (it was an
  // out-of-line call, twice per Minkowski pair), the miss is not.
  SEPAX_ROBUST_INLINE EdgeAxis edge_axis(int ea, int eb) const {
    if (ea == axis_cache_.ea && eb == axis_cache_.eb) [[likely]] return axis_cache_.axis;
    return cache_edge_axis(ea, eb);
  }

  SEPAX_ROBUST_NOINLINE EdgeAxis cache_edge_axis(int ea, int eb) const {
    axis_cache_.ea = ea;
    axis_cache_.eb = eb;
    axis_cache_.axis = compute_edge_axis(ea, eb);
    return axis_cache_.axis;
  }

  EdgeAxis compute_edge_axis(int ea, int eb) const {
    const Vec3<T>& da = a_.edge_dir(ea);
    const Vec3<T>& db = b_.edge_dir(eb);
    const Vec3<T> c = cross(da, db);
    const double r2 = cross_ratio_squared(da, db, c);
    EdgeAxis ax;
    if (std::isfinite(r2)) {
      ax = float_edge_axis(c, r2);
    } else {
      ax = exact_edge_axis(ea, eb);
    }
    return ax;
  }

  // The axis from the T cross product c = fl(dA x dB) and its finite ratio
  // r2 = cross_ratio_squared(dA, dB, c).
  static EdgeAxis float_edge_axis(const Vec3<T>& c, double r2) {
    EdgeAxis ax;
    const T len = std::sqrt(squared_norm(c));
    ax.n = Vec3<T>(c[0] / len, c[1] / len, c[2] / len);
    ax.delta = unit_error_from_ratio(robust::detail::sqrt_d(r2));
    return ax;
  }

  // The T cross product is zero or not finite: the axis from the exact cross
  // product rounded to double, no bound (out of line: it keeps the hot path's
  // frame small).
  SEPAX_ROBUST_COLD EdgeAxis exact_edge_axis(int ea, int eb) const {
    EdgeAxis ax;
    const auto ce = robust::exact_cross(
        robust::exact_diff(a_.vertex(a_.edge_head(ea)), a_.vertex(a_.edge_tail(ea))),
        robust::exact_diff(b_.vertex(b_.edge_head(eb)), b_.vertex(b_.edge_tail(eb))));
    Vec3<double> cd(robust::approx_double(ce[0]), robust::approx_double(ce[1]),
                    robust::approx_double(ce[2]));
    const double m = std::max({std::fabs(cd[0]), std::fabs(cd[1]), std::fabs(cd[2])});
    if (m > 0) cd /= m;
    const double len = cd.norm();
    ax.n = len > 0 ? Vec3<T>(static_cast<T>(cd[0] / len), static_cast<T>(cd[1] / len),
                             static_cast<T>(cd[2] / len))
                   : Vec3<T>(T(0), T(0), T(0));
    ax.delta = kNoBound;
    return ax;
  }

  // δ D (1+1e-6) + e_.edge_abs, with e_.d_margin = D (1+1e-6) summed once per
  // query (a reassociated product: its rounding is inside the margin).
  double edge_value_error(double delta) const { return delta * e_.d_margin + e_.edge_abs; }

  double value_error(const Feature& f) const {
    switch (f.type) {
      case FeatureType::FaceA: return e_.face_a;
      case FeatureType::FaceB: return e_.face_b;
      case FeatureType::EdgePair: return edge_value_error(edge_axis(f.a, f.b).delta);
      case FeatureType::SideA:
      case FeatureType::SideB: break;  // always exact (see side_query)
    }
    return std::numeric_limits<double>::infinity();
  }

  // ---- exact helpers (each call counts as a fallback when it runs exactly) ----

  // Past the value filter: interval arithmetic on the exact formula first
  // (separation_compare.hpp, stage 2), the exact numbers only if that cannot
  // decide (ties, overflow).  Both count as one fallback: a decision the
  // filter could not make.
  SEPAX_ROBUST_COLD int compare_margin_exact(const Feature& f, double m) const {
    ++fallbacks_;
    return robust::compare_exact(separation_poly<robust::ExactFloat>(f, sigma_of(f)),
                                 robust::ExactSeparation{robust::exact(m), robust::exact(1.0)});
  }

  SEPAX_ROBUST_COLD int compare_exact(const Feature& fx, const Feature& fy) const {
    ++fallbacks_;
    // The orientations first: edge_sigma computes in T and double, which
    // must not run in the interval stage's upward rounding mode.
    const int sx = sigma_of(fx), sy = sigma_of(fy);
    const int s = robust::compare_interval([&] { return separation_poly<robust::IntervalFloat>(fx, sx); },
                                           [&] { return separation_poly<robust::IntervalFloat>(fy, sy); });
    if (s != robust::kUncertain) return s;
    return robust::compare_exact(separation_poly<robust::ExactFloat>(fx, sx),
                                 separation_poly<robust::ExactFloat>(fy, sy));
  }

  // sign of N_f . (q1 - q0), N_f the plane triple's cross product of face f of p.
  int face_pair_sign(const P& p, int f, const Vec3<T>& q0, const Vec3<T>& q1) const {
    const auto& t = p.face(f).plane_vertices;
    const Vec3<T>& v0 = p.vertex(t[0]);
    return robust::orient_sign(v0, p.vertex(t[1]), v0, p.vertex(t[2]), q0, q1, &fallbacks_);
  }

  // sign of N_f . (p - v_i), N_f the plane triple's cross product.
  int face_sign(const P& p, int f, const Vec3<T>& q) const {
    const auto& t = p.face(f).plane_vertices;
    const Vec3<T>& v0 = p.vertex(t[0]);
    return robust::orient_sign(v0, p.vertex(t[1]), v0, p.vertex(t[2]), v0, q, &fallbacks_);
  }

  // sign of (eA x eB) . (pB - pA), pA, pB the edges' tails.
  int edge_pair_sign(int ea, int eb) const {
    return robust::orient_sign(a_.vertex(a_.edge_tail(ea)), a_.vertex(a_.edge_head(ea)),
                               b_.vertex(b_.edge_tail(eb)), b_.vertex(b_.edge_head(eb)),
                               a_.vertex(a_.edge_tail(ea)), b_.vertex(b_.edge_tail(eb)), &fallbacks_);
  }

  // sign of (eA x eB) . (q - p0) for a vertex q of either shape.
  int pair_axis_side(int ea, int eb, const Vec3<T>& p0, const Vec3<T>& q) const {
    return robust::orient_sign(a_.vertex(a_.edge_tail(ea)), a_.vertex(a_.edge_head(ea)),
                               b_.vertex(b_.edge_tail(eb)), b_.vertex(b_.edge_head(eb)), p0, q,
                               &fallbacks_);
  }

  // sign of n* . (p.vertex(v) - exact mean of p's vertices), n* = eA x eB.
  int centroid_side(const P& p, int v, const EdgeAxis& ax, double cerr, double extent, int ea,
                    int eb) const {
    const T o = dot(ax.n, diff(p.vertex(v), p.centroid()));
    const double e = ((ax.delta + kG5) * (extent + cerr) + cerr) * kMargin + 4 * kEta;
    if (static_cast<double>(o) > e) return 1;
    if (static_cast<double>(o) < -e) return -1;
    return centroid_side_exact(p, v, ea, eb);
  }

  // The orientation rule of PlainKernel::edge_axis (the O(1) form): the sign
  // of n*.(pA - cA) + n*.(cB - pB), cA and cB the exact vertex means, no flip
  // when zero.  For a Minkowski edge pair of exactly convex shapes both terms
  // are positive; on inputs convex only within tolerance they can differ in
  // sign, and then only the sum matches the exact kernel.  Filter: each term's
  // bound is centroid_side's, the double sum of two T values adds at most
  // 2^-52 (|oa| + |ob|); exact fallback otherwise.
  int axis_side(const EdgeAxis& ax, int ea, int eb) const {
    const T oa = dot(ax.n, diff(a_.vertex(a_.edge_tail(ea)), a_.centroid()));
    const T ob = dot(ax.n, diff(b_.centroid(), b_.vertex(b_.edge_tail(eb))));
    // The sum of the two per-side bounds ((δ + γ_5)(D_P + C_P) + C_P)(1+1e-6)
    // (centroid_side's), regrouped: (δ + γ_5) e_.side_span + e_.side_abs with the
    // per-query sums e_.side_span = (D_A + C_A + D_B + C_B)(1+1e-6) and
    // e_.side_abs = (C_A + C_B)(1+1e-6) + 8η (the regrouping's rounding is
    // inside the margin).
    const double sum = static_cast<double>(oa) + static_cast<double>(ob);
    const double e = (ax.delta + kG5) * e_.side_span + e_.side_abs +
                     0x1p-52 * (std::abs(static_cast<double>(oa)) + std::abs(static_cast<double>(ob)));
    // the filtered sign as a value (no jump on the sign itself, see
    // edge_separation); 0 (within the bound, or NaN) goes exact
    const int s = static_cast<int>(sum > e) - static_cast<int>(sum < -e);
    if (s == 0) [[unlikely]] return axis_side_exact(ea, eb);
    return s;
  }

  // sign( V_A V_B n*.(pA - pB) + V_A n*.Sum(B) - V_B n*.Sum(A) ): the rule
  // above multiplied by V_A V_B > 0, exactly.
  SEPAX_ROBUST_COLD int axis_side_exact(int ea, int eb) const {
    ++fallbacks_;
    using robust::ExactFloat;
    const auto n = robust::exact_cross(
        robust::exact_diff(a_.vertex(a_.edge_head(ea)), a_.vertex(a_.edge_tail(ea))),
        robust::exact_diff(b_.vertex(b_.edge_head(eb)), b_.vertex(b_.edge_tail(eb))));
    auto sum_of = [](const P& p) {
      std::array<ExactFloat, 3> sum{ExactFloat(0), ExactFloat(0), ExactFloat(0)};
      for (const auto& w : p.vertices()) {
        for (int c = 0; c < 3; ++c) sum[c] = sum[c] + robust::exact(static_cast<double>(w[c]));
      }
      return sum;
    };
    auto exact_point = [](const Vec3<T>& v) {
      return std::array<ExactFloat, 3>{robust::exact(static_cast<double>(v[0])),
                                       robust::exact(static_cast<double>(v[1])),
                                       robust::exact(static_cast<double>(v[2]))};
    };
    const ExactFloat va(a_.vertex_count()), vb(b_.vertex_count());
    const auto pa = exact_point(a_.vertex(a_.edge_tail(ea)));
    const auto pb = exact_point(b_.vertex(b_.edge_tail(eb)));
    const ExactFloat val = va * vb * (robust::exact_dot(n, pa) - robust::exact_dot(n, pb)) +
                           va * robust::exact_dot(n, sum_of(b_)) - vb * robust::exact_dot(n, sum_of(a_));
    return robust::exact_sign(val);
  }

  SEPAX_ROBUST_COLD int centroid_side_exact(const P& p, int v, int ea, int eb) const {
    ++fallbacks_;
    using robust::ExactFloat;
    const auto n = robust::exact_cross(
        robust::exact_diff(a_.vertex(a_.edge_head(ea)), a_.vertex(a_.edge_tail(ea))),
        robust::exact_diff(b_.vertex(b_.edge_head(eb)), b_.vertex(b_.edge_tail(eb))));
    std::array<ExactFloat, 3> sum{ExactFloat(0), ExactFloat(0), ExactFloat(0)};
    for (const auto& w : p.vertices()) {
      for (int c = 0; c < 3; ++c) sum[c] = sum[c] + robust::exact(static_cast<double>(w[c]));
    }
    const std::array<ExactFloat, 3> pv{robust::exact(static_cast<double>(p.vertex(v)[0])),
                                       robust::exact(static_cast<double>(p.vertex(v)[1])),
                                       robust::exact(static_cast<double>(p.vertex(v)[2]))};
    const ExactFloat val = ExactFloat(p.vertex_count()) * robust::exact_dot(n, pv) - robust::exact_dot(n, sum);
    return robust::exact_sign(val);
  }

  // The orientation (+1/-1) of the edge pair's axis that the current SAT's
  // exact counterpart uses (see the header).
  int edge_sigma(int ea, int eb) const {
    const EdgeAxis ax = edge_axis(ea, eb);
    if (!projection_rule_) return axis_side(ax, ea, eb) < 0 ? -1 : 1;
    const int sa = centroid_side(a_, a_.edge_tail(ea), ax, e_.centroid_a, e_.extent_a, ea, eb);
    if (sa != 0) return sa;
    const int sb = -centroid_side(b_, b_.edge_tail(eb), ax, e_.centroid_b, e_.extent_b, ea, eb);
    if (sb != 0) return sb;
    return edge_pair_sign(ea, eb) < 0 ? -1 : 1;
  }

  // A feature's separation polynomials in N (ExactFloat or, inside a
  // rounding scope, IntervalFloat), sigma = edge_sigma of an edge pair
  // (computed by the caller: no T arithmetic runs here).
  template <class N>
  robust::SeparationPoly<N> separation_poly(const Feature& f, int sigma) const {
    switch (f.type) {
      case FeatureType::FaceA: {
        const auto pts = a_.plane_points(f.a);
        return robust::face_separation_poly<N>(pts[0], pts[1], pts[2], b_.vertex(f.b));
      }
      case FeatureType::FaceB: {
        const auto pts = b_.plane_points(f.b);
        return robust::face_separation_poly<N>(pts[0], pts[1], pts[2], a_.vertex(f.a));
      }
      case FeatureType::SideA: {
        const auto u = side_normal_as<N>(a_, f.a);
        return {robust::exact_dot(u, robust::diff_as<N>(b_.vertex(f.b), a_.vertex(a_.edge_tail(f.a)))),
                robust::exact_dot(u, u)};
      }
      case FeatureType::SideB: {
        const auto u = side_normal_as<N>(b_, f.b);
        return {robust::exact_dot(u, robust::diff_as<N>(a_.vertex(f.a), b_.vertex(b_.edge_tail(f.b)))),
                robust::exact_dot(u, u)};
      }
      case FeatureType::EdgePair:
      default: {
        const int ea = f.a, eb = f.b;
        return robust::edge_separation_poly<N>(
            a_.vertex(a_.edge_tail(ea)), a_.vertex(a_.edge_head(ea)), b_.vertex(b_.edge_tail(eb)),
            b_.vertex(b_.edge_head(eb)), a_.vertex(a_.edge_tail(ea)), b_.vertex(b_.edge_tail(eb)), sigma);
      }
    }
  }

  int sigma_of(const Feature& f) const { return f.type == FeatureType::EdgePair ? edge_sigma(f.a, f.b) : 1; }

  robust::ExactSeparation exact_separation(const Feature& f) const {
    return separation_poly<robust::ExactFloat>(f, sigma_of(f));
  }

  // The exact sign of a feature's separation.
  int exact_value_sign(const Feature& f) const {
    switch (f.type) {
      case FeatureType::FaceA: return face_sign(a_, f.a, b_.vertex(f.b));
      case FeatureType::FaceB: return face_sign(b_, f.b, a_.vertex(f.a));
      case FeatureType::EdgePair: return edge_sigma(f.a, f.b) * edge_pair_sign(f.a, f.b);
      case FeatureType::SideA:
      case FeatureType::SideB: ++fallbacks_; return robust::exact_sign(exact_separation(f).num);
    }
    return 0;
  }

  // A returned value always has the exact sign.  When |v| <= bound the sign is
  // decided exactly; on a mismatch the value becomes 0 (exact zero) or the
  // exact separation rounded to T (±denorm_min if that underflows).  The new
  // value is still within `bound` of the exact one: with opposite signs,
  // |exact| <= bound - |v|.
  Separation<T> snap(T v, double bound, const Feature& f) const {
    if (std::fabs(static_cast<double>(v)) > bound) return Separation<T>{v, T(1)};
    return snap_exact(v, f);
  }

  SEPAX_ROBUST_COLD Separation<T> snap_exact(T v, const Feature& f) const {
    const int s = exact_value_sign(f);
    if (s == sign_of(v)) return Separation<T>{v, T(1)};
    if (s == 0) return Separation<T>{T(0), T(1)};
    const robust::ExactSeparation ex = exact_separation(f);
    const double num = robust::approx_double(ex.num), n2 = robust::approx_double(ex.norm2);
    T r = T(0);
    if (std::isfinite(num) && std::isfinite(n2) && n2 > 0) r = static_cast<T>(num / std::sqrt(n2));
    if (sign_of(r) != s) r = s > 0 ? std::numeric_limits<T>::denorm_min() : -std::numeric_limits<T>::denorm_min();
    return Separation<T>{r, T(1)};
  }

  // ---- side axes (see side_query_a) ----

  // u = (head - tail) x N, N the plane triple's cross product of the face of
  // half-edge 2e: the polygon's in-plane outward normal of edge e, exactly.
  template <class N>
  static std::array<N, 3> side_normal_as(const P& p, int e) {
    const auto t = p.plane_points(p.edge_face(e, 0));
    const auto n = robust::exact_cross(robust::diff_as<N>(t[1], t[0]), robust::diff_as<N>(t[2], t[0]));
    return robust::exact_cross(robust::diff_as<N>(p.vertex(p.edge_head(e)), p.vertex(p.edge_tail(e))), n);
  }

  // The same direction in T, unit (reporting and float values only).
  static Vec3<T> side_normal(const P& p, int e) {
    const Vec3<T>& d = p.edge_dir(e);
    const Vec3<T>& n = p.edge_normal(e, 0);
    const Vec3<double> dd(d[0], d[1], d[2]), nd(n[0], n[1], n[2]);
    Vec3<double> u = scaled_cross(dd, nd);  // scale-safe: vec3.hpp
    const double len = u.norm();
    if (len > 0) u /= len;
    return Vec3<T>(static_cast<T>(u[0]), static_cast<T>(u[1]), static_cast<T>(u[2]));
  }

  // Support vertex of q along -u (lowest index among the exactly lowest).
  SEPAX_ROBUST_COLD FaceQuery<T> side_query(const P& p, int e, const P& q, bool of_a) const {
    ++fallbacks_;
    const auto u = side_normal_as<robust::ExactFloat>(p, e);
    const Vec3<T>& t = p.vertex(p.edge_tail(e));
    int best = 0;
    robust::ExactFloat m = robust::exact_dot(u, robust::exact_diff(q.vertex(0), t));
    for (int i = 1; i < q.vertex_count(); ++i) {
      robust::ExactFloat h = robust::exact_dot(u, robust::exact_diff(q.vertex(i), t));
      if (robust::exact_sign(h - m) < 0) {
        m = h;
        best = i;
      }
    }
    const T v = dot(side_normal(p, e), Vec3<T>(q.vertex(best) - t));
    const Feature f = of_a ? Feature::side_a(e, best) : Feature::side_b(best, e);
    return FaceQuery<T>{snap_exact(v, f), best};
  }

  // ---- decisions ----

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

  SEPAX_ROBUST_COLD int normal_dot_sign_exact(const P& p, int f, const P& q, int ei) const {
    const auto& t = p.face(f).plane_vertices;
    const Vec3<T>& v0 = p.vertex(t[0]);
    // N.e = ((v1 - v0) x (v2 - v0)) . e = det[e, v1 - v0, v2 - v0]
    return robust::orient_sign(q.vertex(q.edge_tail(ei)), q.vertex(q.edge_head(ei)), v0, p.vertex(t[1]),
                               v0, p.vertex(t[2]), &fallbacks_);
  }

  // Support vertex of q along the inward normal of face f of p: the lowest
  // index among the vertices with exactly minimal N_f . v.
  // The float minimum and second minimum come from the same n.v values
  // either way: a few vertices at a time over q's lane arrays (simd_lanes.hpp;
  // shapes with more than kScalarSupportMax vertices, lanes_bounded), else
  // the scalar loop.
  static constexpr int kScalarSupportMax = 4;
  // w: W_P of error_bounds.hpp's "(support)"; wt: W_P rounded up to T (the
  // uniqueness check in T: see below).
  SEPAX_ROBUST_INLINE FaceQuery<T> face_query(const P& p, int f, const P& q, double w, T wt) const {
    const Plane<T>& pl = p.plane(f);
    const auto& vs = q.vertices();
    const int nv = static_cast<int>(vs.size());
    int best = 0;
    T m, second;
    if (lanes_ && nv > kScalarSupportMax) {
      const simd::Support<T> s = simd::support_scan<true>(q, pl.normal);
      best = s.index;
      m = s.min;
      second = s.second;
    } else {
      m = dot(pl.normal, vs[0]);
      second = std::numeric_limits<T>::infinity();
      for (int i = 1; i < nv; ++i) {
        // branch-free minimum and second minimum (selects, not jumps)
        const T h = dot(pl.normal, vs[static_cast<std::size_t>(i)]);
        const bool lt = h < m;
        second = lt ? m : (h < second ? h : second);
        best = lt ? i : best;
        m = lt ? h : m;
      }
    }
    T hb = m;  // n.v at best (the value PlainKernel reports)
    // Unique beyond the bound: second - m > W, checked in T.  Rounding is
    // monotone and wt >= W is a T value, so fl(second - m) > wt implies
    // second - m > wt >= W (a subtraction: nothing to contract).  An
    // overflow to +inf is an exact difference beyond wt as well; NaN fails
    // the test.  Two conversions to double less per face than the check in
    // double; it fails wherever that one did (and within a rounding of the
    // bound a little more often: those faces take resolve_support, exact).
    if (!(T(second - m) > wt)) [[unlikely]] {
      best = resolve_support(p, f, q, m, w);
      hb = dot(pl.normal, vs[static_cast<std::size_t>(best)]);
    }
    return FaceQuery<T>{Separation<T>{T(hb - pl.offset), T(1)}, best};
  }

  // The minimum of g_v = fl(n.v) over q's vertices, n face f's normal
  // (face_estimate_*): the minimum face_query's scans find, from the same
  // values, without its argmin and second minimum.
  SEPAX_ROBUST_INLINE T support_min(const Plane<T>& pl, const P& q) const {
    const auto& vs = q.vertices();
    const int nv = static_cast<int>(vs.size());
    if (lanes_ && nv > kScalarSupportMax) return simd::support_scan<false, false>(q, pl.normal).min;
    T m = dot(pl.normal, vs[0]);
    for (int i = 1; i < nv; ++i) {
      const T h = dot(pl.normal, vs[static_cast<std::size_t>(i)]);
      m = h < m ? h : m;
    }
    return m;
  }

  SEPAX_ROBUST_COLD int resolve_support(const P& p, int f, const P& q, T m, double w) const {
    const Plane<T>& pl = p.plane(f);
    const auto& t = p.face(f).plane_vertices;
    const Vec3<T>& v0 = p.vertex(t[0]);
    const Vec3<T>& v1 = p.vertex(t[1]);
    const Vec3<T>& v2 = p.vertex(t[2]);
    int cur = -1;
    T gcur = T(0);
    for (int i = 0; i < q.vertex_count(); ++i) {
      const T g = dot(pl.normal, q.vertex(i));
      if (static_cast<double>(g) - static_cast<double>(m) > w) continue;  // exactly above the minimum
      if (cur < 0) {
        cur = i;
        gcur = g;
        continue;
      }
      const double d = static_cast<double>(g) - static_cast<double>(gcur);
      int s;
      if (d > w) s = 1;
      else if (d < -w) s = -1;
      else s = robust::orient_sign(v0, v1, v0, v2, q.vertex(cur), q.vertex(i), &fallbacks_);
      if (s < 0) {
        cur = i;
        gcur = g;
      }
    }
    return cur;
  }

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

  // dir = +1: every vertex v of p satisfies n*.(v - ref) <= 0 (the edge is at
  // p's maximum along n*); dir = -1: >= 0 (at its minimum).  The edge's own
  // endpoints are exactly at 0 (n* is orthogonal to both edges).
  bool all_on_side(const P& p, const Extremes& x, const Vec3<T>& n, double w, int dir, int ea,
                   int eb) const {
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

  const P& a_;
  const P& b_;
  const robust::QueryBounds<T> e_;  // this query's error bounds (error_bounds.hpp)
  struct AxisCache {
    int ea = -1, eb = -1;
    EdgeAxis axis;
  };
  mutable AxisCache axis_cache_;
  bool lanes_ = false;  // both shapes lanes_bounded(): the SIMD scans apply
  mutable std::int64_t fallbacks_ = 0;
  mutable bool projection_rule_ = false;
};

template <RobustFloat T>
struct kernel_for<policy::Robust, T> {
  using type = RobustKernel<T>;
};

/// For exact number types every decision is already exact: Robust is Plain.
template <ExactNumber T>
struct kernel_for<policy::Robust, T> {
  using type = PlainKernel<T>;
};

}  // namespace sepax
