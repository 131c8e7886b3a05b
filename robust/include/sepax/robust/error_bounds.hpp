// sepax/robust/error_bounds.hpp
//
// The robust kernel's error model, in one place (RobustKernel's filters use
// nothing else):
//   1. ErrorConstants<T>: u, η, γ_k (gamma<T>), the (1 + 1e-6) margin, as
//      compile-time constants (the notation and what the margin covers: on
//      ErrorConstants).
//   2. Per-shape terms: the padded extent D_P, the normal error δ_P
//      (normal_error), the centroid error C_P (centroid_error).
//   3. The bound of a unit axis fl(normalize(fl(e1 x e2))) from its ratio
//      ρ = |ẽ1||ẽ2|/|Ñ| (unit_error_from_ratio), used for face normals (δ_P)
//      and for edge-pair axes (δ_e, per pair).
//   4. QueryBounds<T>: one named field per bound a query's filters compare
//      with, each computed in O(1) from the two shapes' terms, its derivation
//      on the field.
// Every bound holds with and without FMA contraction (contraction only
// removes roundings).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <type_traits>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/number_traits.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sepax {

/// The number types policy::Robust filters (its kernel's values are T's).
template <class T>
concept RobustFloat = std::is_same_v<T, float> || std::is_same_v<T, double>;

namespace robust {

/// γ_k = k u / (1 - k u), u the unit roundoff of T: the relative error bound
/// of k successive roundings (Higham, Lemma 3.1).
template <RobustFloat T>
constexpr double gamma(int k) {
  return rounding_gamma(k, number_traits<T>::unit_roundoff);
}

namespace detail {

/// sqrt of a double, the IEEE (correctly rounded) result as std::sqrt, but
/// inline: under -frounding-math GCC calls libm's sqrt for it.
inline double sqrt_d(double x) {
#if defined(__SSE2__)
  return _mm_cvtsd_f64(_mm_sqrt_sd(_mm_setzero_pd(), _mm_set_sd(x)));
#else
  return std::sqrt(x);
#endif
}

/// x < y ? x : y and x > y ? x : y as one minsd/maxsd (GCC compiles std::min
/// and std::max of converted floats to jumps, mispredicted about half the time
/// on the random order of two bounding boxes).  With a NaN operand they return
/// one of the operands, as std::min/max do.
inline double min_d(double x, double y) {
#if defined(__SSE2__)
  return _mm_cvtsd_f64(_mm_min_sd(_mm_set_sd(x), _mm_set_sd(y)));
#else
  return x < y ? x : y;
#endif
}
inline double max_d(double x, double y) {
#if defined(__SSE2__)
  return _mm_cvtsd_f64(_mm_max_sd(_mm_set_sd(x), _mm_set_sd(y)));
#else
  return x > y ? x : y;
#endif
}

/// The smallest T >= x, for comparisons in T against a double bound.  The
/// bounds are >= 0: the next T above a finite t >= 0 is the one whose bit
/// pattern is one more (max() goes to infinity, 0 to denorm_min), added
/// without a jump (whether the conversion rounded down is a coin toss per
/// bound) and without libm's nextafter.  x NaN: t is NaN and stays NaN.  A
/// negative t (never for these bounds) takes nextafter.
template <RobustFloat T>
T round_up(double x) {
  using Bits = std::conditional_t<std::is_same_v<T, float>, std::uint32_t, std::uint64_t>;
  const T t = static_cast<T>(x);
  if (!(t >= T(0))) [[unlikely]]
    return static_cast<double>(t) < x ? std::nextafter(t, std::numeric_limits<T>::infinity()) : t;
  return std::bit_cast<T>(
      static_cast<Bits>(std::bit_cast<Bits>(t) + static_cast<Bits>(static_cast<double>(t) < x)));
}

}  // namespace detail

/// The constants of T's rounding the bounds are built from.  sepax::robust is
/// compiled with -frounding-math (CGAL's flag), under which GCC does not fold
/// inexact constant arithmetic in ordinary expressions: γ_k, √2, √3 times the
/// margin would be recomputed (divisions, libm sqrt calls) on every use, per
/// edge pair.  As static constexpr members they are constant-evaluated (both
/// compilers must), rounded to nearest: the values the runtime expressions
/// would have (√2 and √3 are the correctly rounded std::numbers constants,
/// what std::sqrt(2.0) and std::sqrt(3.0) return).  Runtime code uses these
/// members, never the expressions.
///
/// Notation: M_P max |coordinate| of P (exact); D_P bbox diagonal of P; D bbox
/// diagonal of A ∪ B (|p - q| <= D for any two vertices); N_f the exact cross
/// product of face f's plane triple, n_f its stored unit normal.
/// Every bound is computed in double and multiplied by the margin (1 + 1e-6),
/// which covers the rounding of the bound computation itself (relative
/// 1e-15), the (1 + γ_4) factors for float (relative 3e-7) and the absolute
/// underflow terms of the normalisation (<= √3 η / |Ñ| with |Ñ|^2 >= 2^40 times
/// the smallest normal T, far below 1e-6 γ_4; smaller cross products get no
/// bound: always exact).  Overflow or NaN anywhere in a bound makes it infinite
/// or the comparison false: the decision goes exact.  FMA contraction only
/// removes roundings, so every bound holds with and without it.
template <RobustFloat T>
struct ErrorConstants {
  /// u, the unit roundoff of T.
  static constexpr double kU = number_traits<T>::unit_roundoff;
  /// η, the smallest subnormal of T (absolute error of an underflowing product).
  static constexpr double kEta = static_cast<double>(std::numeric_limits<T>::denorm_min());
  /// The pad of every bound: (1 + 1e-6), see the header.
  static constexpr double kMargin = 1.0 + 1e-6;
  static constexpr double kMargin2 = kMargin * kMargin;
  static constexpr double kG4 = gamma<T>(4);
  static constexpr double kG5 = gamma<T>(5);
  static constexpr double kG8 = gamma<T>(8);
  /// √3 (1 + 1e-6): |v|_2 <= √3 M for a vertex v, padded.
  static constexpr double kS3 = std::numbers::sqrt3 * kMargin;
  static constexpr double kG5S3 = kG5 * kS3;
  static constexpr double kG3S3x2 = 2 * gamma<T>(3) * kS3;
  /// √2 γ_5 + 3u, the rounding part of the wedge bound (QueryBounds::wedge_a).
  static constexpr double kWedgeRound = std::numbers::sqrt2 * kG5 + 3 * kU;
  /// q/|Ñ| = kUnitC ρ for a unit axis (unit_error_from_ratio).
  static constexpr double kUnitC = kG4 * std::numbers::sqrt2 / ((1 - kU) * (1 - kU));
  static constexpr double kUnitCM2 = kUnitC * kMargin * kMargin;
  /// δ of an axis with no useful bound: |n - n*| <= 2 (1 + γ_4) always.
  static constexpr double kNoBound = 2.5;
  /// Cross products with |Ñ|^2 at most this (in T units) risk underflow in
  /// the normalisation: no bound (ConvexPolyhedron::kNormalTinySquared).
  static constexpr double kTinySquared = static_cast<double>(std::numeric_limits<T>::min()) * 0x1p40;
  /// The pair prefilter's constants (QueryBounds, "pair prefilter"): u_d,
  /// κ = (2u + u^2)/(1 - u)^2, (1 + u)^2 (1 + 1e-6).
  static constexpr double kUd = 0x1p-53;
  static constexpr double kPreKappa = (2 * kU + kU * kU) / ((1 - kU) * (1 - kU));
  static constexpr double kPreK = (1 + kU) * (1 + kU) * kMargin;

  /// Bound δ on |n - N/|N|| for n = fl(normalize(Ñ)), Ñ = fl(ẽ1 x ẽ2), ẽ the
  /// rounded differences, from ρ = |ẽ1||ẽ2|/|Ñ| as computed (unpadded).
  /// Each component of Ñ meets 4 roundings per term (2 differences, product,
  /// subtraction): |Ñ - N| <= γ_4 |Q| <= γ_4 √2 |e1||e2| (Q_x = |e1_y e2_z| +
  /// |e1_z e2_y|, Σ Q_x^2 <= 2 |e1|^2 |e2|^2), plus √3 η for products that
  /// underflow.  Normalising: sqrt of a dot of squares has relative error
  /// <= γ_3/2 + u, the division u, so |n - Ñ/|Ñ|| <= γ_4; and |x/|x| - y/|y||
  /// <= 2|x - y|/|y|.  With q = γ_4 √2 |ẽ1||ẽ2|/(1-u)^2 + √3 η:
  ///   δ = γ_4 + 2 q / (|Ñ| - q)      (kNoBound, "always exact", if |Ñ| <= 2q).
  /// q/|Ñ| = kUnitC ρ, and both (1+1e-6) pads (of ρ and of q/|Ñ|) are in
  /// kUnitCM2, one product.  2x/(1 - x) is bounded without a division (a
  /// long-latency divsd per Minkowski pair): for 0 <= x < 1/2, (1 + 2x)(1 - x)
  /// = 1 + x(1 - 2x) >= 1, so x/(1 - x) <= x(1 + 2x), looser by at most 2x^2
  /// (x ~ 1e-7 for a well-conditioned axis).  Its own few roundings (relative
  /// 1e-16) are inside the margin.
  static double unit_error_from_ratio(double rho) {
    const double qr = kUnitCM2 * rho;
    if (!(qr < 0.5)) return kNoBound;
    return (kG4 + 2 * qr * (1 + 2 * qr)) * kMargin;
  }

  static double squared_norm_d(const Vec3<T>& v) {
    const double x = v[0], y = v[1], z = v[2];
    return x * x + y * y + z * z;
  }

  /// ρ^2 = |e1|^2 |e2|^2 / |c|^2 of a cross product c = fl(e1 x e2), or
  /// +infinity when |c|^2 <= kTinySquared or anything overflows (an overflow
  /// must not become a NaN, which every comparison would silently ignore).
  static double cross_ratio_squared(const Vec3<T>& e1, const Vec3<T>& e2, const Vec3<T>& c) {
    const double nc2 = squared_norm_d(c);
    if (!(nc2 > kTinySquared) || !std::isfinite(nc2)) return std::numeric_limits<double>::infinity();
    const double r2 = squared_norm_d(e1) / nc2 * squared_norm_d(e2);
    return std::isfinite(r2) ? r2 : std::numeric_limits<double>::infinity();
  }

  /// D_P, the shape's bbox diagonal padded for its own rounding (4u) and the
  /// margin.
  static double padded_extent(const ConvexPolyhedron<T>& p) { return p.extent() * (1.0 + 4 * kU) * kMargin; }

  /// δ_P = max_f δ_f over the faces of P, from ρ_P = max_f ρ_f, which
  /// ConvexPolyhedron computes once per shape on first use
  /// (normal_conditioning(): the same T differences and cross products of the
  /// plane triples, +infinity when some |Ñ|^2 <= kTinySquared or anything
  /// overflows, which gives kNoBound).  O(1) per query.
  static double normal_error(const ConvexPolyhedron<T>& p) {
    static_assert(ConvexPolyhedron<T>::kNormalTinySquared == kTinySquared);
    return unit_error_from_ratio(p.normal_conditioning());
  }

  /// C_P >= |c̃ - c|, c̃ the stored centroid (a sequential sum of V vertices
  /// and a division: V + 1 roundings per coordinate), c the exact vertex mean:
  /// √3 γ_{V+1} M_P.
  static double centroid_error(const ConvexPolyhedron<T>& p) {
    const double k = static_cast<double>(p.vertex_count()) + 1.0;
    if (!(k * kU < 0.25)) return std::numeric_limits<double>::infinity();
    return std::numbers::sqrt3 * gamma<T>(static_cast<int>(k)) * p.max_abs_coordinate() * kMargin2 + 4 * kEta;
  }
};

/// The error bounds of one query of A against B, computed once in O(1).
template <RobustFloat T>
struct QueryBounds : ErrorConstants<T> {
  using C = ErrorConstants<T>;

  /// D (padded): the diagonal of the bounding box of A ∪ B.
  double d = 0;
  /// D (1 + 1e-6), the factor of an edge pair's δ_e in its value bound.
  double d_margin = 0;
  /// D_A, D_B (padded_extent).
  double extent_a = 0, extent_b = 0;
  /// (face value) E_face(P), P's face against Q's vertex: h̃ = fl(fl(n.v) -
  /// fl(n.a)) vs h = N.(v - a)/|N|.  |fl(n.v) - n.v| <= γ_3 |n||v| <=
  /// γ_3 (1+γ_4) √3 M_Q, the same for n.a with M_P, |(n - N/|N|).(v - a)| <=
  /// δ_P D, the final subtraction <= u |h̃ + ...|:
  ///   E_face(P) = δ_P D + γ_5 √3 (M_P + M_Q) + 4η.
  double face_a = 0, face_b = 0;
  /// (support) W_P: two vertices v, w of Q compared along face f of P through
  /// g = fl(n.v): |(g_v - g_w) - (N/|N|).(v - w)| <= 2 γ_3 (1+γ_4) √3 M_Q +
  /// δ_P D_Q.  A scan keeps the minimum and the second minimum; more than W_P
  /// apart, the float argmin is the exact unique argmin, else the vertices
  /// within W_P of the minimum are compared exactly.  _t: rounded up to T.
  double support_a = 0, support_b = 0;
  T support_a_t = 0, support_b_t = 0;
  /// (arc sign) E_arc(P): fl(n_f . fl(head - tail)) vs (N/|N|).e for a face
  /// of P and an edge e of Q: (δ_P + γ_5) |e| + 2η <= (δ_P + γ_5) D_Q + 2η.
  /// _t: rounded up to T; arc_lane = max(arc_a_t, arc_b_t), the SIMD arc
  /// scan's one bound.
  double arc_a = 0, arc_b = 0;
  T arc_a_t = 0, arc_b_t = 0, arc_lane = 0;
  /// (edge value) the part of an edge pair's bound that does not depend on
  /// its axis: both the O(1) form fl(n.fl(pB - pA)) and the projection form
  /// fl(min_B fl(n.w) - max_A fl(n.v)) differ from σ (eA x eB).(pB - pA)/
  /// |eA x eB| by at most δ_e D + γ_8 (D + √3 (M_A + M_B)) (for the
  /// projection form, shift every projection by the common (n - n*).o, o the
  /// centre of the union bbox: the shift cancels in min - max, what remains
  /// is <= δ_e D/2 per side).  This field is γ_8 (D + √3 (M_A + M_B)) + 8η;
  /// the kernel adds δ_e d_margin per pair.
  double edge_abs = 0;
  /// (projection) the axis-independent part of a projection fl(n.v) of P's
  /// vertex: 2 γ_3 √3 M_P + 4η (the brute force's support band adds δ_e D_P).
  double proj_abs_a = 0, proj_abs_b = 0;
  /// (centroid side) C_A, C_B (centroid_error).  fl(n.fl(p - c̃)) vs
  /// n*.(p - c), c the exact mean: error <= (δ_e + γ_5)(D_P + C_P) + C_P.
  double centroid_a = 0, centroid_b = 0;
  /// axis_side's two terms summed, regrouped: (δ_e + γ_5) side_span +
  /// side_abs with side_span = (D_A + C_A + D_B + C_B)(1 + 1e-6) and
  /// side_abs = (C_A + C_B)(1 + 1e-6) + 8η (the regrouping's rounding is
  /// inside the margin).
  double side_span = 0, side_abs = 0;
  /// (pair prefilter) float T only (RobustKernel::edge_pair_below).  Products
  /// of floats are exact in double, and with both shapes lanes_bounded
  /// (|x| <= 2^60) nothing below overflows or underflows (every double
  /// product is >= 2^-298 in magnitude or zero).  u = 2^-24, u_d = 2^-53.
  /// Exact: N = eA x eB (exact edge vectors), w* = (pA - cA) + (cB - pB)
  /// (exact means), σ* = -1 if N.w* < 0 else +1 (axis_side's rule), t* =
  /// N.(pB - pA), and the pair's exact separation s* = σ* t*/|N|.  Computed
  /// in double from the T data: Ĉ = fl(ẽA x ẽB), v̂ = fl(Ĉ.ŵ), ŵ = fl((pA -
  /// c̃A) + (c̃B - pB)), t̂ = fl(Ĉ.d̂), d̂ = fl(pB - pA).
  ///  - |ẽ - e| <= u|e| per edge, so |ẽA x ẽB - N| <= (2u + u^2)|eA||eB| <=
  ///    κ |ẽA||ẽB|, κ = (2u + u^2)/(1 - u)^2; Ĉ rounds each component once:
  ///    |Ĉ - N| <= (κ + u_d) K =: ε_N with K = (1+u)^2 D_A D_B >= |ẽA||ẽB|
  ///    (|e| <= D_P), and |Ĉ| <= (1 + u_d) K.
  ///  - pre_value = E_t: |t̂ - t*| <= γ_3,d |Ĉ||d̂| + |Ĉ| u_d |d| + ε_N |d| <=
  ///    (κ + 8 u_d) K D (|d| <= D).
  ///  - pre_side = E_σ: |v̂ - N.w*| <= γ_3,d |Ĉ||ŵ| + |Ĉ||ŵ - w̃| +
  ///    |Ĉ|(C_A + C_B) + ε_N |w*| (w̃ the exact sum with the stored centroids:
  ///    |w̃ - w*| <= C_A + C_B; |ŵ - w̃| <= 2.0001 u_d S; |w*|, |w̃| <= S,
  ///    S = D_A + C_A + D_B + C_B) <= K ((C_A + C_B) + (κ + 8 u_d) S).
  ///    |v̂| > E_σ gives σ* = sign v̂.
  ///  - pre_norm_sq = Q: with M = best_err - best > 0 (the best's exact value
  ///    is >= -M): s* < -M holds if -σ̂ t̂ - E_t > M (|Ĉ| + ε_N), since
  ///    σ* t* <= σ̂ t̂ + E_t and |N| <= |Ĉ| + ε_N.  Both sides positive, so it
  ///    is tested squared, with (|Ĉ| + ε_N)^2 <= |Ĉ|^2 + Q, Q = ε_N (2 (1 +
  ///    u_d) K + ε_N): y = fl(-σ̂ t̂ - E_t) > 0 and fl(y y) > fl(M M (fl(Ĉ.Ĉ) +
  ///    Q)) (1+1e-6).  The computed sides are within (1 + 12 u_d) of the real
  ///    ones, far inside the margin.  Parallel edges (N = 0, t* = 0, |t̂| <=
  ///    E_t) never pass.  With FMA the products are exact anyway and the dot
  ///    products lose roundings, so the bounds hold either way.
  double pre_side = 0, pre_value = 0, pre_norm_sq = 0;
  /// (wedge) E_wedge(A), the traversal's wedge test (RobustKernel::
  /// in_edge_wedge_a): for an edge E = head - tail of A, a face f of A at the
  /// edge and a vertex x of B, ṽ = fl(n_f . fl(w̃ x Ẽ)) with Ẽ = fl(head -
  /// tail) (the stored edge direction), w̃ = fl(x - tail), all in T, against
  /// v = (N_f/|N_f|) . (w x E) = (E x N_f/|N_f|) . w, w = x - tail (its sign
  /// is sign((E x N_f) . w)).
  ///  - |Ẽ - E| <= u|E|, |w̃ - w| <= u|w| (one rounding per coordinate),
  ///    |n_f - N_f/|N_f|| <= δ_A (normal_error), |n_f| <= 1 + δ_A.
  ///  - |det(a, b, c)| <= |a||b||c|, so det(n, w̃, Ẽ) - det(n*, w, E) =
  ///    det(n, w̃, Ẽ - E) + det(n - n*, w̃, E) + det(n*, w̃ - w, E) is at most
  ///    |E||w| (u(1+u)(1+δ_A) + δ_A(1+u) + u).
  ///  - the evaluation: each of the three terms n_i (w̃_j Ẽ_k - w̃_k Ẽ_j)
  ///    meets at most 5 roundings (two products, the subtraction, the product
  ///    by n_i, two additions): error <= γ_5 Σ_i |n_i|(|w̃_j Ẽ_k| + |w̃_k Ẽ_j|)
  ///    <= √2 γ_5 |n||w̃||Ẽ| (Cauchy-Schwarz) <= √2 γ_5 (1+u)^2 (1+δ_A)|E||w|.
  ///  - underflow: the six products of w̃ x Ẽ add <= 2η per component, <= 2√3
  ///    η |n| (1+γ_3) after the product by n; the three final products <= 3η
  ///    (1+γ_2); subnormal additions are exact: <= 7η (|n| < 1.01).
  ///  - |E| <= D_A, |w| <= D (x and tail are in the bbox of A ∪ B); the (1+u)
  ///    factors (at most (1+u)^3) are inside the margin.
  ///   E_wedge(A) = ((√2 γ_5 + 3u)(1 + δ_A) + δ_A) D D_A (1 + 1e-6) + 8η.
  /// |ṽ| > E_wedge(A), ṽ finite, gives sign v = sign ṽ; an overflow anywhere in
  /// ṽ leaves it infinite or NaN, and the exact stage decides.  FMA
  /// contraction only removes roundings.
  double wedge_a = 0;

  QueryBounds(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b) {
    using robust::detail::max_d;
    using robust::detail::min_d;
    using robust::detail::round_up;
    const double ma = a.max_abs_coordinate(), mb = b.max_abs_coordinate();
    const double da = C::padded_extent(a), db = C::padded_extent(b);
    // min/max without jumps (min_d/max_d); no NaN in the bounds of a valid
    // shape, and with one the bound below is NaN or not as with std::min/max
    // (a NaN bound sends every decision to the exact stage).
    double d2 = 0;
    for (int c = 0; c < 3; ++c) {
      const double lo = min_d(a.bounds_min()[c], b.bounds_min()[c]);
      const double hi = max_d(a.bounds_max()[c], b.bounds_max()[c]);
      d2 += (hi - lo) * (hi - lo);
    }
    d = robust::detail::sqrt_d(d2) * C::kMargin;
    const double da_n = C::normal_error(a), db_n = C::normal_error(b);
    face_a = (da_n * d + C::kG5S3 * (ma + mb)) * C::kMargin + 4 * C::kEta;
    face_b = (db_n * d + C::kG5S3 * (ma + mb)) * C::kMargin + 4 * C::kEta;
    support_a = (C::kG3S3x2 * mb + da_n * db) * C::kMargin + 4 * C::kEta;  // B's vertices, A's faces
    support_b = (C::kG3S3x2 * ma + db_n * da) * C::kMargin + 4 * C::kEta;
    arc_a = (da_n + C::kG5) * db * C::kMargin + 2 * C::kEta;  // A's normals . B's edges
    arc_b = (db_n + C::kG5) * da * C::kMargin + 2 * C::kEta;
    arc_a_t = round_up<T>(arc_a);
    arc_b_t = round_up<T>(arc_b);
    support_a_t = round_up<T>(support_a);
    support_b_t = round_up<T>(support_b);
    edge_abs = C::kG8 * (d + C::kS3 * (ma + mb)) * C::kMargin + 8 * C::kEta;
    proj_abs_a = C::kG3S3x2 * ma * C::kMargin + 4 * C::kEta;
    proj_abs_b = C::kG3S3x2 * mb * C::kMargin + 4 * C::kEta;
    centroid_a = C::centroid_error(a);
    centroid_b = C::centroid_error(b);
    extent_a = da;
    extent_b = db;
    d_margin = d * C::kMargin;
    side_span = ((extent_a + centroid_a) + (extent_b + centroid_b)) * C::kMargin;
    side_abs = (centroid_a + centroid_b) * C::kMargin + 8 * C::kEta;
    if constexpr (std::is_same_v<T, float>) {
      // K = (1+u)^2 D_A D_B >= |ẽA||ẽB| (da, db are the padded D_A, D_B),
      // ε = κ + 8 u_d, ε_N = (κ + u_d) K.
      const double k = C::kPreK * da * db;
      const double en = (C::kPreKappa + C::kUd) * k;
      pre_value = (C::kPreKappa + 8 * C::kUd) * k * d * C::kMargin;
      pre_side = k * ((centroid_a + centroid_b) + (C::kPreKappa + 8 * C::kUd) * side_span) * C::kMargin;
      pre_norm_sq = en * (2 * k * (1 + C::kUd) + en) * C::kMargin;
    }
    arc_lane = arc_a_t < arc_b_t ? arc_b_t : arc_a_t;
    wedge_a = ((C::kWedgeRound * (1 + da_n) + da_n) * d * da) * C::kMargin + 8 * C::kEta;
  }
};

}  // namespace robust
}  // namespace sepax
