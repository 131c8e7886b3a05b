// sepax/edge_pair_rule_out.hpp
//
// The brute force's first test of an edge pair (ea, eb), float and double:
// is c = eA x eB certainly not the normal of a face of the Minkowski
// difference A - B?  Most pairs are not, and the kernels' own test
// (edge_separation_full: a unit axis, projections, the neighbours of the
// edges' endpoints) costs several hundred instructions to say so.
//   1. the wings (edge_wings, rule_out_wings): the vertex before each endpoint
//      in the edge's two faces, both neighbours of the edge;
//   2. their heights c.(w - tail) in double: A's first as dB.m, m = (w -
//      tail) x dA kept per edge of A (across_verdict: no cross product per
//      pair), then as c.(w - tail) (side_verdict);
//   3. the bound beyond which a height's sign is the one the kernel's test
//      sees: PlainRuleOut (the plain kernel's rounded unit axis and support
//      tolerance) or ExactRuleOut (the robust kernel's exact axis);
//   4. the pair is ruled out when the wings rule out both orientations of c
//      (EdgePairRuleOut::ruled_out): +c needs A's edge at A's maximum and B's
//      at B's minimum, -c the opposite.
// A pair ruled out here is one the kernel's edge_separation_full rejects (or
// one edges_parallel skips), so the brute force's result and counters do not
// change; a pair not ruled out goes to the kernel's test as before.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

#include "convex_polyhedron.hpp"
#include "number_traits.hpp"
#include "vec3.hpp"

namespace sepax::detail {

/// An edge's endpoints and its two wings (any vertex of the shape would be a
/// valid witness; these two are the ones whose heights split the circle of
/// directions orthogonal to the edge at the normals of its two faces).
struct EdgeWings {
  int tail, head;
  int wing0;  ///< the vertex before the tail in the face of half-edge 2e
  int wing1;  ///< the vertex before the head in the face of half-edge 2e + 1
};

/// The wings of edge e of p.
template <Number T>
EdgeWings edge_wings(const ConvexPolyhedron<T>& p, int e) {
  const HalfEdge& h0 = p.half_edge(2 * e);
  const HalfEdge& h1 = p.half_edge(2 * e + 1);
  return EdgeWings{h0.origin, h1.origin, p.half_edge(h0.prev).origin, p.half_edge(h1.prev).origin};
}

/// fl_d(p - q), one subtraction per coordinate in double.
template <class F>
Vec3<double> difference_d(const Vec3<F>& p, const Vec3<F>& q) {
  return Vec3<double>(static_cast<double>(p[0]) - static_cast<double>(q[0]),
                      static_cast<double>(p[1]) - static_cast<double>(q[1]),
                      static_cast<double>(p[2]) - static_cast<double>(q[2]));
}

/// The plain kernel's test (PlainKernel<T>::edge_separation_full, T = float or
/// double) sees the pair through n = fl(normalise(fl(dA x dB))) (dA, dB the
/// stored edge directions, unoriented_axis), projections e0 = fl(n.tail) and
/// h = fl(n.w), and the support tolerance t of w's shape: it rules out the
/// edge at the maximum when e0 < fl(h - t) (at the minimum when e0 >
/// fl(h + t)), by the neighbours or by the full scan (whose extreme is at
/// least as far, and the rounding is monotone).  Bound, with u the unit
/// roundoff of T, u_d that of double, c = dA x dB exact, ĉ = c/|c|, R =
/// √3 max|coordinate| of the shape (|w|, |tail| <= R):
///  - fl(dA x dB) = c + δ, |δ| <= √2 γ_2 |dA||dB| (each component: two
///    products and a difference, or an FMA; Cauchy-Schwarz); normalising
///    adds a relative γ_4 per component (the squared norm γ_3, its square
///    root and the division), so |n - ĉ| <= ε_n = 2ρ + γ_4, ρ = |δ|/|c|
///    (|x/|x| - y/|y|| <= 2|x - y|/|y|), and |n| <= 1 + ε_n;
///  - |fl(n.x) - ĉ.x| <= (ε_n + γ_3 (1 + ε_n)) |x| for x = w, tail;
///  - fl(h - t) >= h - t - u (|h| + t), |h| <= (1 + ε_n)(1 + γ_3) R.
/// So ĉ.(w - tail) > t (1 + u) + R K1 + ρ R K2, K1 = 2 γ_4 (1 + γ_3) + 2 γ_3 +
/// u (1 + γ_3)(1 + γ_4), K2 = 4 (1 + γ_3) + 2 u (1 + γ_3), gives e0 < fl(h -
/// t) (and -ĉ.(w - tail) above it gives e0 > fl(h + t)).  Times |c|, with ρ
/// |c| = √2 γ_2 |dA||dB|: c.(w - tail) > |c| (t (1 + u) + R K1) + √2 γ_2
/// |dA||dB| R K2.  The height is computed in double: c_d = fl_d(dA x dB) is
/// within √2 γ_2,d |dA||dB| of c (exact products for float), w - tail within
/// u_d per coordinate, the dot product γ_3,d; |w - tail| <= 2R; so
/// |fl_d(c.(w - tail)) - c.(w - tail)| <= (√2 γ_2,d |dA||dB| + γ_4,d |c|) 2R
/// (1 + u_d), and |c| <= |c_d| + √2 γ_2,d |dA||dB| (1 + γ_2,d).  The bound
/// (constants()) adds these and a factor 1 + 1e-6 that covers the (1 + γ_d)
/// factors, the rounding of the bound itself and underflow: while |c_d| >=
/// kMinScale and R >= kMinScale, each subnormal result adds at most 2^-150
/// (float; 2^-1075 double), below 2^-60 of the bound's R K1 term.  Larger
/// shapes than kMaxCoordinate (double: products of three coordinates would
/// overflow) are not ruled out here.  FMA contraction only removes roundings,
/// so the bound holds with it on or off.
template <class T>
struct PlainRuleOut {
  static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>);
  static constexpr double kU = number_traits<T>::unit_roundoff;
  static constexpr double kUd = number_traits<double>::unit_roundoff;
  /// Smallest |c_d| and R (coordinate units) the underflow argument covers.
  static constexpr double kMinScale = std::is_same_v<T, float> ? 0x1p-60 : 0x1p-500;
  /// Largest |coordinate| of a shape the filter takes (double: 2^240, so that
  /// products of three coordinate differences stay finite).
  static constexpr double kMaxCoordinate = std::is_same_v<T, float> ? 0x1p128 : 0x1p240;
  static constexpr double kK1 = 2 * rounding_gamma(4, kU) * (1 + rounding_gamma(3, kU)) +
                                2 * rounding_gamma(3, kU) +
                                kU * (1 + rounding_gamma(3, kU)) * (1 + rounding_gamma(4, kU));
  static constexpr double kK2 = 4 * (1 + rounding_gamma(3, kU)) + 2 * kU * (1 + rounding_gamma(3, kU));
  static constexpr double kSqrt2 = 1.4142135623730951;  // (rounded up: 1.41421356237309504...)
  static constexpr double kOnePlusU = 1 + kU;
  static constexpr double kMarginFactor = 1 + 1e-6;
  static constexpr double kTwoG4d = 2 * rounding_gamma(4, kUd);
  static constexpr double kSqrt2G2d = kSqrt2 * rounding_gamma(2, kUd);
  static constexpr double kSqrt2G2K2 = kSqrt2 * rounding_gamma(2, kU) * kK2;
  static constexpr double kTwoSqrt2G2d = 2 * kSqrt2 * rounding_gamma(2, kUd);

  /// The bound on c_d.(w - tail) for a shape with largest |coordinate|
  /// max_abs and support tolerance t is cn x + l2 y, cn = |c_d|, l2 =
  /// |dA||dB| (both in double): x = (1 + 1e-6)(t (1 + u) + R K1 + 2 γ_4,d R),
  /// y = (1 + 1e-6)(√2 γ_2,d (t (1 + u) + R K1) + √2 γ_2 R K2 + 2 √2 γ_2,d R)
  /// (the terms above, regrouped).  Outside the covered range x = +infinity
  /// (no decision).  The constants are constexpr: with -frounding-math
  /// (CGAL's builds) the compiler would not fold them.
  static void constants(double max_abs, double t, double& x, double& y) {
    const double r = 1.7320508075688774 * max_abs;  // √3 (rounded up)
    if (!(r >= kMinScale && max_abs <= kMaxCoordinate)) {
      x = std::numeric_limits<double>::infinity();
      y = 0;
      return;
    }
    const double tt = t * kOnePlusU + r * kK1;
    x = kMarginFactor * (tt + r * kTwoG4d);
    y = kMarginFactor * (kSqrt2G2d * tt + r * kSqrt2G2K2 + r * kTwoSqrt2G2d);
  }

  /// The bound without |c| (across_verdict: A's wings' heights as dB.m, m =
  /// fl_d((w - tail) x dA), no cross product per pair).  With L = |dA|_1
  /// |dB|_1 >= |dA||dB| >= |c|, the condition above is implied by c.(w -
  /// tail) > L (t (1 + u) + R K1 + √2 γ_2 R K2).  The height fl_d(dB.m) is
  /// the triple product det(dA, dB, w - tail) through its six monomials dB_i
  /// (w - tail)_j dA_k, each with at most five roundings (two in m, the
  /// product by dB_i, two additions; FMA contraction removes some) and one
  /// more in w - tail (exact for float coordinates of nearby binades): it
  /// is within (γ_5,d (1 + u_d) + u_d) G L
  /// <= 7 u_d G L of c.(w - tail), G = 2 max|coordinate| >= |w - tail|_∞.
  /// So the bound is L z + kAcrossUnderflow, z = (1 + 1e-6)(t (1 + u) + R K1
  /// + √2 γ_2 R K2 + 7 u_d G) (the factor covers the rounding of L and of
  /// the bound); kAcrossUnderflow covers subnormal intermediates (double:
  /// each at most 2^-1075 off, at most three per component of m, each
  /// multiplied by |dB_i| <= 2 kMaxCoordinate = 2^241, and five in the dot
  /// product: below 2^-829; float: no intermediate is subnormal).  The
  /// kernel's own arithmetic needs |c_d| >= kMinScale: a height above the
  /// bound gives |c| > L K1 / 2 (|w - tail| < 2R), so |c_d| > L K1 / 4 and
  /// the bound is asked only while L >= kMinAcross = 4 kMinScale / K1.
  /// Outside the covered range z = +infinity (no decision).
  static double across_constant(double max_abs, double t) {
    const double r = 1.7320508075688774 * max_abs;  // √3 (rounded up)
    if (!(r >= kMinScale && max_abs <= kMaxCoordinate)) return std::numeric_limits<double>::infinity();
    return kMarginFactor * (t * kOnePlusU + r * kK1 + r * kSqrt2G2K2 + 2 * max_abs * kAcrossHeightError);
  }
  static constexpr double kAcrossHeightError = 7 * kUd;
  static_assert(kAcrossHeightError > rounding_gamma(5, kUd) * (1 + kUd) + kUd);
  static constexpr double kAcrossUnderflow = 0x1p-800;
  static constexpr double kMinAcross = 4 * kMinScale / kK1;
  static_assert(kK1 / 4 >= kSqrt2G2d);  // |c_d| >= |c| - √2 γ_2,d L > L K1 / 4
};

/// The robust kernel's test (RobustKernel::edge_separation_full) decides
/// exactly along n* = E_A x E_B, E = head - tail exact: it rules out the edge
/// at its shape's maximum exactly when some vertex w has n*.(w - tail) > 0
/// (at the minimum: < 0).  The height is evaluated in double from Ẽ =
/// fl_d(head - tail) and fl_d(w - tail) (one rounding per coordinate each),
/// then the three differences of products, the products by the coordinates
/// of w - tail and two additions (at most five roundings per term, with or
/// without FMA): the computed value is within γ_8,d Σ_i |D_i| (|E_A,j E_B,k| +
/// |E_A,k E_B,j|) <= γ_8,d |D|_∞ |E_A|_1 |E_B|_1 of n*.D, |D|_∞ <= 2
/// max|coordinate| = G.  The same holds for A's heights evaluated as
/// Ẽ_B.fl_d(D x Ẽ_A) (across_verdict): the same six monomials, each with at
/// most eight roundings (three in the inputs, two in the cross product, the
/// product by Ẽ_B,i, two additions).  The bound is l1 k + z, l1 =
/// fl_d(|Ẽ_A|_1 |Ẽ_B|_1) (or fl_d(fl_d(|Ẽ_A|_1 k) |Ẽ_B|_1)):
/// k = 16 u_d G (> γ_8,d G with the rounding of the bound's own products);
/// z covers underflow, for double only (products of float coordinates in
/// double never underflow): each subnormal product is at most 2^-1075 off,
/// then multiplied by a coordinate difference of at most G (in the across
/// order: at most three per component of the cross product, multiplied by
/// |Ẽ_B,i| <= G, and five more), so z = 2^-1000 (G + 1), a normal number
/// (subnormal operands cost a hundred cycles each).
/// Shapes beyond kMaxCoordinate are not ruled out here (k = +infinity).
template <class T>
struct ExactRuleOut {
  static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>);
  static constexpr double kUd = number_traits<double>::unit_roundoff;
  static constexpr double kMaxCoordinate = std::is_same_v<T, float> ? 0x1p128 : 0x1p240;
  static constexpr double kSixteenUd = 16 * kUd;

  /// The constants k and z of a shape whose largest |coordinate| is max_abs.
  static void constants(double max_abs, double& k, double& z) {
    if (!(max_abs <= kMaxCoordinate)) {
      k = std::numeric_limits<double>::infinity();
      z = 0;
      return;
    }
    const double g = 2 * max_abs;
    k = kSixteenUd * g;
    z = std::is_same_v<T, double> ? 0x1p-1000 * (g + 1) : 0.0;
  }
};

/// One edge as the rule-out reads it, in double: its direction, its wings
/// relative to its tail, and the norms the bounds take.
struct RuleOutEdge {
  Vec3<double> dir;               ///< PlainRuleOut: the stored direction; ExactRuleOut: fl_d(head - tail)
  Vec3<double> wing0, wing1;      ///< fl_d(wing - tail)
  Vec3<double> across0, across1;  ///< fl_d(wing_i x dir): d.across_i = (dir x d).wing_i (across_verdict)
  double norm = 0;                ///< PlainRuleOut: fl_d(|dir|); ExactRuleOut: fl_d(|dir|_1)
  double norm1 = 0;               ///< fl_d(|dir|_1)
};

/// fl_d(|d|_1).
inline double l1_norm(const Vec3<double>& d) { return std::abs(d[0]) + std::abs(d[1]) + std::abs(d[2]); }

/// The direction of edge e of p and its 1-norm (RuleOutEdge::dir, norm1);
/// kExact: ExactRuleOut's.
template <bool kExact, class T>
void rule_out_direction(const ConvexPolyhedron<T>& p, int e, RuleOutEdge& r) {
  if constexpr (kExact) {
    r.dir = difference_d(p.vertex(p.edge_head(e)), p.vertex(p.edge_tail(e)));
  } else {
    r.dir = vec_to_double(p.edge_direction(e));
  }
  r.norm1 = l1_norm(r.dir);
}

/// The norm PlainRuleOut's bound takes, fl_d(|dir|) (ExactRuleOut: |dir|_1).
template <bool kExact>
void rule_out_norm(RuleOutEdge& r) {
  r.norm = kExact ? r.norm1 : std::sqrt(r.dir.dot(r.dir));
}

/// The wings of edge e of p relative to its tail (RuleOutEdge::wing0, wing1).
template <class T>
void rule_out_wings(const ConvexPolyhedron<T>& p, int e, RuleOutEdge& r) {
  const EdgeWings w = edge_wings(p, e);
  const Vec3<T>& tail = p.vertex(w.tail);
  r.wing0 = difference_d(p.vertex(w.wing0), tail);
  r.wing1 = difference_d(p.vertex(w.wing1), tail);
}

/// The wings' verdict on one edge along c with the bound b: a height above b
/// puts a vertex beyond the edge (not at the maximum), below -b (not at the
/// minimum).  NaN decides nothing.
struct SideVerdict {
  bool not_max = false, not_min = false;
};

/// fl_d(c.d): a wing's height, d = fl_d(wing - tail).
inline double wing_height(const Vec3<double>& c, const Vec3<double>& d) {
  return c[0] * d[0] + c[1] * d[1] + c[2] * d[2];
}

inline SideVerdict side_verdict(const RuleOutEdge& e, const Vec3<double>& c, double b) {
  const double h0 = wing_height(c, e.wing0), h1 = wing_height(c, e.wing1);
  return SideVerdict{h0 > b || h1 > b, h0 < -b || h1 < -b};
}

/// The same verdict for edge e along c = e.dir x d from its wings' heights
/// d.across_i (the bound: PlainRuleOut::across_constant, ExactRuleOut).
inline SideVerdict across_verdict(const RuleOutEdge& e, const Vec3<double>& d, double b) {
  const double h0 = wing_height(d, e.across0), h1 = wing_height(d, e.across1);
  return SideVerdict{h0 > b || h1 > b, h0 < -b || h1 < -b};
}

/// Steps 2-4 for a kernel of the pair (A, B), kExact: ExactRuleOut (robust
/// kernel) or PlainRuleOut (plain kernel).  Keeps the data of the last edge of
/// A asked (the brute force asks every edge of B for one edge of A in turn)
/// and the shapes' bound constants, so a pair costs the axis, A's two heights
/// and, when A's wings leave an orientation open, B's.  No allocation.
template <class T, bool kExact>
class EdgePairRuleOut {
 public:
  /// true only when the kernel's test rejects (ea, eb).  tolerances():
  /// the shapes' support tolerances {t_A, t_B} (PlainRuleOut), asked on the
  /// first call only.
  template <class Tolerances>
  [[gnu::always_inline]] bool ruled_out(const ConvexPolyhedron<T>& a, int ea, const ConvexPolyhedron<T>& b,
                                        int eb, Tolerances&& tolerances) const {
    if (ea != ea_) [[unlikely]] {
      if (ea_ < 0) init(a, b, tolerances);
      load_edge_a(a, ea);
      ea_ = ea;
    }
    RuleOutEdge eb_data;
    rule_out_direction<kExact>(b, eb, eb_data);
    // A's wings across eB: no cross product (most pairs end here)
    SideVerdict va;
    if (kExact || edge_a_.norm1 * eb_data.norm1 >= PlainRuleOut<T>::kMinAcross) {
      va = across_verdict(edge_a_, eb_data.dir, across_a_ * eb_data.norm1 + across_slack_);
      if (va.not_max && va.not_min) return true;
    }
    return ruled_out_along_c(b, eb, eb_data, va);
  }

 private:
  // the rest of ruled_out: c = dA x dB, (plain) A's wings along c with the
  // bound that takes |c| (finer for nearly parallel edges), B's wings
  [[gnu::noinline]] bool ruled_out_along_c(const ConvexPolyhedron<T>& b, int eb, RuleOutEdge& eb_data,
                                           SideVerdict va) const {
    const Vec3<double> c = cross(edge_a_.dir, eb_data.dir);
    rule_out_norm<kExact>(eb_data);
    double bound_b;
    if constexpr (kExact) {
      bound_b = edge_a_.norm * eb_data.norm * xb_ + yb_;
    } else {
      const double cn = std::sqrt(c.dot(c)), l2 = edge_a_.norm * eb_data.norm;
      if (!(cn >= PlainRuleOut<T>::kMinScale)) return false;
      const SideVerdict v = side_verdict(edge_a_, c, cn * xa_ + l2 * ya_);
      va.not_max = va.not_max || v.not_max;
      va.not_min = va.not_min || v.not_min;
      if (va.not_max && va.not_min) return true;
      bound_b = cn * xb_ + l2 * yb_;
    }
    rule_out_wings(b, eb, eb_data);
    const SideVerdict vb = side_verdict(eb_data, c, bound_b);
    // +c needs A's edge at A's maximum and B's at B's minimum; -c the opposite
    return (va.not_max || vb.not_min) && (va.not_min || vb.not_max);
  }

  template <class Tolerances>
  void init(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b, Tolerances& tolerances) const {
    if constexpr (!kExact) {
      const std::array<double, 2> t = tolerances();
      PlainRuleOut<T>::constants(a.max_abs_coordinate(), t[0], xa_, ya_);
      PlainRuleOut<T>::constants(b.max_abs_coordinate(), t[1], xb_, yb_);
      za_ = PlainRuleOut<T>::across_constant(a.max_abs_coordinate(), t[0]);
      across_slack_ = PlainRuleOut<T>::kAcrossUnderflow;
    } else {
      (void)tolerances;
      ExactRuleOut<T>::constants(a.max_abs_coordinate(), xa_, ya_);
      ExactRuleOut<T>::constants(b.max_abs_coordinate(), xb_, yb_);
      za_ = xa_;
      across_slack_ = ya_;
    }
  }

  // edge ea of a into edge_a_: direction, norms, wings, their cross products
  // with the direction, and the across bound's factor
  [[gnu::noinline]] void load_edge_a(const ConvexPolyhedron<T>& a, int ea) const {
    rule_out_direction<kExact>(a, ea, edge_a_);
    rule_out_norm<kExact>(edge_a_);
    rule_out_wings(a, ea, edge_a_);
    edge_a_.across0 = cross(edge_a_.wing0, edge_a_.dir);
    edge_a_.across1 = cross(edge_a_.wing1, edge_a_.dir);
    across_a_ = edge_a_.norm1 * za_;
  }

  mutable int ea_ = -1;                               // the edge of A edge_a_ holds (-1: none yet)
  mutable RuleOutEdge edge_a_;                        // (uninitialised until the first call)
  mutable double xa_ = 0, ya_ = 0, xb_ = 0, yb_ = 0;  // the bounds' constants of A and B
  mutable double za_ = 0;                             // the across bound's constant of A (ExactRuleOut: xa_)
  mutable double across_slack_ = 0;  // its absolute term (PlainRuleOut: kAcrossUnderflow; exact: ya_)
  mutable double across_a_ = 0;      // fl_d(|dA|_1 za_) for the edge in edge_a_
};

}  // namespace sepax::detail
