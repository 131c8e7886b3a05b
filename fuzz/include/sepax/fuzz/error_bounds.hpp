// sepax/fuzz/error_bounds.hpp
//
// Forward error bounds of the plain float/double kernel (plain_kernel.hpp), used
// by the fuzzer to classify a float/exact disagreement as "explained": the
// exact value lies within the bound of the float computation.  One function
// per computation of the kernel, each derived on the function (notation and
// FMA: on gamma):
//   (1) unit face normal          delta_normal       (6) parallel-edge skip  ParallelSkip
//   (2) arc triple product        arc_bound          (7) side axes           delta_side, side_bound
//   (3) face separation           face_bound         (8) edge-axis orientation  orientation_bound
//   (4) Gauss-map edge separation edge_bound         (9) brute-force support    support_band_width
//   (5) brute-force projection    projection_bound
// This derivation is independent of the robust kernel's (it is the check of
// the plain kernel; robust/include/sepax/robust/error_bounds.hpp derives the
// robust filters' bounds) and uses the same notation: u, gamma_k (there
// robust::gamma<T>(k)), delta for the error of a unit normal or axis (there
// δ_P, δ_e), B_face and B_arc for the face value and arc sign (there
// QueryBounds::face_a/b, arc_a/b).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/number_traits.hpp>
#include <sepax/tolerances.hpp>
#include <sepax/vec3.hpp>

namespace sepax::fuzz::bounds {

/// Notation.  F is float or double, u = number_traits<F>::unit_roundoff (2^-24,
/// 2^-53), gamma_k = k u / (1 - k u).  All inputs (vertex coordinates) are exact
/// F values; the exact quantity is what PlainKernel<mpq> computes from the same
/// vertices.  Every bound below holds with or without FMA contraction: an FMA
/// rounds once where the separate multiply-add rounds twice, and every step
/// below is charged for the separate roundings (e.g. a 3-term dot product is
/// charged gamma_3 on sum |x_i y_i|, which also covers fma(x2,y2,fma(x1,y1,x0 y0))).
///
/// The bounds are evaluated in double.  Their own rounding is covered by the
/// final factor (1 + 2^-30), far above the ~10 double roundings involved.  The
/// exact length |N_e| enters only as a lower bound (a slightly shrunk double).
inline double gamma(int k, double u) { return k * u / (1.0 - k * u); }

inline constexpr double kSlack = 1.0 + 0x1p-30;

template <class F>
inline double u_of() {
  return number_traits<F>::unit_roundoff;
}

template <class F>
inline Vec3<double> d(const Vec3<F>& v) {
  return Vec3<double>(double(v[0]), double(v[1]), double(v[2]));
}

inline double norm(const Vec3<double>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
inline double abs_dot(const Vec3<double>& a, const Vec3<double>& b) {
  return std::abs(a[0] * b[0]) + std::abs(a[1] * b[1]) + std::abs(a[2] * b[2]);
}
inline Vec3<double> abs_cross(const Vec3<double>& a, const Vec3<double>& b) {
  const Vec3<double> x = a.cwiseAbs(), y = b.cwiseAbs();
  return Vec3<double>(x[1] * y[2] + x[2] * y[1], x[2] * y[0] + x[0] * y[2], x[0] * y[1] + x[1] * y[0]);
}

/// (1) Unit face normal.  Plane triple p0, p1, p2 (exact F values).
///       a = fl(p1 - p0), b = fl(p2 - p0):   |a - a_e| <= u |a_e|  (componentwise)
///       N = fl(a x b), per component fl(a1 b2 - a2 b1):
///         |N_x - (a x b)_x| <= gamma_2 (|a1 b2| + |a2 b1|)
///         |(a x b)_x - (a_e x b_e)_x| <= (2u + u^2)(|a1e b2e| + |a2e b1e|)
///       With C_x = |a1||b2| + |a2||b1| (from the rounded a, b; |a_e| <= |a|/(1-u)):
///         ||N - N_e|| <= gamma_5 ||C||                                        (eN)
///       n = fl(N / fl(sqrt(fl(N.N)))): fl(N.N) = N.N (1 + th_3), the sqrt and the
///       division add one rounding each, so ||n - N/|N| || <= gamma_4.
///       ||N/|N| - N_e/|N_e| || <= 2 ||N - N_e|| / |N_e|.
///     => delta_n = ||n - n_e|| <= gamma_4 + 2 gamma_5 ||C|| / |N_e|.
///       ||C|| / |N_e| >= 1 is the conditioning of the triangle (1/sin of its angle at p0).
///
/// (1)/(4): bound on ||n - n_e|| for the normalised rounded cross product of
/// the rounded vectors a, b (as F computed them); exact_len_lo <= |N_e|.
template <class F>
inline double delta_normal(const Vec3<F>& a, const Vec3<F>& b, double exact_len_lo) {
  if (!(exact_len_lo > 0)) return std::numeric_limits<double>::infinity();
  const double u = u_of<F>();
  const double c = norm(abs_cross(d(a), d(b)));
  return (gamma(4, u) + 2.0 * gamma(5, u) * c / exact_len_lo) * kSlack;
}

/// (2) Triple product of the arc test: t = fl(n . d), d = fl(head - tail) an edge of
///     the other shape; exact value t_e = n_e . d_e (sign = sign(N_e . d_e)).
///       |fl(n.d) - n.d| <= gamma_3 sum|n_i||d_i|
///       |n.d - n_e.d_e| <= ||n - n_e|| ||d|| + ||n_e|| ||d - d_e|| <= (delta_n + gamma_1) ||d||
///     => B_arc = gamma_3 sum|n_i||d_i| + (delta_n + gamma_1) ||d||.
///
/// (2) arc triple product n . d.
template <class F>
inline double arc_bound(const Vec3<F>& n, const Vec3<F>& dir, double delta_n) {
  const double u = u_of<F>();
  const Vec3<double> nd = d(n), dd = d(dir);
  return (gamma(3, u) * abs_dot(nd, dd) + (delta_n + gamma(1, u)) * norm(dd)) * kSlack;
}

/// (3) Face separation (height of a vertex v above face f): s = fl(fl(n.v) - fl(n.p0))
///     (offset = n.p0 is stored by plane_through); exact s_e = n_e . (v - p0).
///       |fl(n.v) - n.v| <= gamma_3 sum|n_i||v_i|, same for p0; the subtraction
///       rounds once: <= u (|fl(n.v)| + |fl(n.p0)|);  |n.(v-p0) - n_e.(v-p0)| <= delta_n ||v - p0||.
///     => B_face(v) = gamma_3 (1+u) (sum|n||v| + sum|n||p0|) + u (|n.v| + |n.p0|) + delta_n ||v - p0||.
///     The face query is a minimum over v: |min fl - min exact| <= max_v B_face(v).
///     Far from the origin this grows with |v| and |p0|: the kernel really does
///     compute the offset in absolute coordinates.
///
/// (3) height of v above the face with rounded unit normal n and plane point p0.
template <class F>
inline double face_bound(const Vec3<F>& n, const Vec3<F>& p0, const Vec3<F>& v, double delta_n) {
  const double u = u_of<F>();
  const Vec3<double> nd = d(n), pd = d(p0), vd = d(v);
  const double dots = abs_dot(nd, vd) + abs_dot(nd, pd);
  return (gamma(3, u) * (1 + u) * dots + u * (1 + gamma(3, u)) * dots + delta_n * norm(vd - pd)) * kSlack;
}

/// (4) Edge separation of the Gauss map (O(1)): dA = fl(hA - tA), dB = fl(hB - tB),
///     N = fl(dA x dB), n = N/|N| rounded as in (1) (same derivation, with C from
///     |dA|, |dB|: here ||C|| / |N_e| is 1/sin of the angle between the edges),
///     w = fl(pB - pA), s = fl(n . w);  exact s_e = n_e . (pB - pA).
///     => B_edge = gamma_3 sum|n_i||w_i| + (delta_n + gamma_1) ||w||.
///     (The orientation of the axis is a sign decided on the centroid; a flipped
///     orientation is not covered by this bound and shows up as a disagreement.)
///
/// (4) O(1) edge separation: n the rounded unit axis, w = fl(pB - pA).
template <class F>
inline double edge_bound(const Vec3<F>& n, const Vec3<F>& w, double delta_n) {
  return arc_bound<F>(n, w, delta_n);
}

/// (5) Edge separation of the brute force (projection): s = fl(min_B fl(n.v) -
///     max_A fl(n.v)); every projection is off by at most
///     gamma_3 sum|n||v| + delta_n ||v|| (n as in (4)), the subtraction rounds once:
///     => B_proj = 2 max_v (gamma_3 sum|n||v| + delta_n ||v||) + u (|min_B| + |max_A|) (1 + gamma_1).
///
/// (5) one projection n . v of the brute force.
template <class F>
inline double projection_bound(const Vec3<F>& n, const Vec3<F>& v, double delta_n) {
  const double u = u_of<F>();
  const Vec3<double> nd = d(n), vd = d(v);
  return (gamma(3, u) * abs_dot(nd, vd) + delta_n * norm(vd)) * kSlack;
}

/// (6) The parallel-edge skip of the plain kernel (plain_kernel.hpp edges_parallel):
///       parallel  <=>  !( fl(N.N) > fl(fl(fl(t t) fl(da.da)) fl(db.db)) ),
///     N = fl(da x db), t = (F)Tolerances<F>::kParallel, and da, db the edge
///     directions the kernel stores (exact F values).  The SATs skip such a
///     pair, so a float run can miss an exact winner there.  What a "parallel"
///     answer implies about the exact values of da, db:
///     Standard model with gradual underflow, eta = half the smallest subnormal
///     of F (2^-150, 2^-1075): a product rounds to x y (1 + d) + e, |d| <= u,
///     |e| <= eta; sums and differences underflow exactly.
///       |N_i - (da x db)_i| <= gamma_2 C_i + 2 eta,   ||C|| <= sqrt(2) |da||db|
///         (C_x = |a1 b2| + |a2 b1|; sum_x C_x^2 <= 2 |da|^2 |db|^2 by Cauchy-Schwarz)
///       fl(N.N) >= (1 - gamma_3) |N|^2 - 3 eta            (a sum of squares)
///       fl(da.da) <= (1 + gamma_3) |da|^2 + 3 eta, likewise db; t t rounds once
///       right side <= P (1 + gamma_9) + eta fl(db.db)(1 + u) + eta,  P = t^2 |da|^2 |db|^2.
///     Guard (checked exactly): |da|^2, |db|^2 >= 2^80 eta and P >= 2^50 eta, so
///     every eta term is below 2^-24 of what it is added to (e.g. eta |db|^2 / P
///     = eta / (t^2 |da|^2) <= 2^-26 for both float and double tolerances);
///     and |da|^2, |db|^2 <= 2^50 (float) / 2^500 (double): nothing overflows.
///     Then "parallel" gives (1 - gamma_3)|N|^2 <= P (1 + gamma_9)(1 + 2^-23), and
///       |da x db| <= |N| + sqrt(2) gamma_2 |da||db| + 4 eta
///     => sin(da, db) = |da x db| / (|da||db|) <= K_F,
///        K_F = ( t sqrt((1 + gamma_9)(1 + 2^-23) / (1 - gamma_3)) + sqrt(2) gamma_2 ) (1 + 2^-23).
///     The fuzzer decides |da x db|^2 <= K_F^2 |da|^2 |db|^2 exactly (classify.hpp
///     parallel_band): when it fails, the plain kernel certainly measured the
///     pair; when it holds, the kernel may have skipped it.  K_F = 1.0016864e-4
///     for float (t = (float)1e-4 = 0.99999997e-4; the sqrt(2) gamma_2 term is
///     the 0.17%) and 1.0000002e-8 for double (t = 1e-8).
///
/// (6) The parallel skip: the tolerance t the kernel uses, the sine bound
/// K_F, and the guard limits on squared lengths (derived above).
template <class F>
struct ParallelSkip {
  static double tol() { return double(static_cast<F>(Tolerances<F>::kParallel)); }
  static double sine_bound() {
    const double u = u_of<F>(), t = tol();
    return (t * std::sqrt((1 + gamma(9, u)) * (1 + 0x1p-23) / (1 - gamma(3, u))) +
            std::sqrt(2.0) * gamma(2, u)) *
           (1 + 0x1p-23) * kSlack;
  }
  // eta = 2^-150 (float), 2^-1075 (double); the guard limits 2^80 eta, 2^50 eta.
  static constexpr bool is_float = sizeof(F) == 4;
  static double min_len2() { return is_float ? 0x1p-70 : 0x1p-995; }
  static double min_p() { return is_float ? 0x1p-100 : 0x1p-1025; }
  static double max_len2() { return is_float ? 0x1p50 : 0x1p500; }
};
/// (7) Side axis of edge e of a flat shape (two flat shapes, best_axis.hpp):
///     plain:  u = n(fl(d x n)) with d = fl(head - tail), n the face's unit
///             normal (delta_n from (1)), n(.) the rounded normalisation;
///             value fl(fl(u.v) - fl(u.t)), t the edge's tail: (3) with u for n;
///     robust: u computed in double and rounded to F, value fl(u . fl(v - t)):
///             (2)/(4) with u for n.
///     Exact: u_e = d_e x N_e / |d_e x N_e| (N_e the plane triple's normal).
///       ||fl(d x n) - d x n|| <= gamma_2 ||C||, C = |d| x |n| componentwise;
///       ||d x n - d_e x n_e|| <= (||d - d_e|| ||n|| + ||d_e|| ||n - n_e||)
///                             <= (u + delta_n)(1 + gamma_4) ||d|| / (1 - u)  =: e_dn
///       (||n|| <= 1 + gamma_4, ||d_e|| <= ||d|| / (1 - u));
///       |d_e x n_e| >= |d x n| - e_dn >= lo := |w|(1 - 2^-50) - e_dn, w = d x n
///       evaluated in double;
///     => delta_u = gamma_4 + 2 (gamma_2 ||C|| + e_dn) / lo   (as in (1)),
///        B_side(v) = max(B_face(v) with u, B_edge(v - t) with u).
///
/// (7) ||u - u_e|| for the side axis of an edge d with face unit normal n.
template <class F>
inline double delta_side(const Vec3<F>& dir, const Vec3<F>& n, double delta_n) {
  const double u = u_of<F>();
  const Vec3<double> dd = d(dir), nd = d(n);
  const double e_dn = (u + delta_n) * (1 + gamma(4, u)) * norm(dd) / (1 - u);
  const double lo = norm(cross(dd, nd)) * (1 - 0x1p-50) - e_dn;
  if (!(lo > 0)) return std::numeric_limits<double>::infinity();
  return (gamma(4, u) + 2.0 * (gamma(2, u) * norm(abs_cross(dd, nd)) + e_dn) / lo) * kSlack;
}

/// (7) a side-axis height of v (unit side normal u, edge tail t), for the
/// plain and the robust evaluation.
template <class F>
inline double side_bound(const Vec3<F>& uvec, const Vec3<F>& t, const Vec3<F>& v, double delta_u) {
  return std::max(face_bound<F>(uvec, t, v, delta_u), edge_bound<F>(uvec, Vec3<F>(v - t), delta_u));
}

/// (7) the bound of the side axis of edge e of p against every vertex of q
/// (the side query's minimum), delta_n the bound (1) of edge_face(e, 0)'s normal.
template <class F>
inline double side_axis_bound(const ConvexPolyhedron<F>& p, int e, const ConvexPolyhedron<F>& q,
                              double delta_n) {
  const Vec3<F>& dir = p.edge_direction(e);
  const Vec3<F>& n = p.edge_normal(e, 0);
  const double du = delta_side<F>(dir, n, delta_n);
  Vec3<F> uv = cross(dir, n);
  const F len = std::sqrt(squared_norm(uv));
  uv = Vec3<F>(uv[0] / len, uv[1] / len, uv[2] / len);
  const Vec3<F>& t = p.vertex(p.edge_tail(e));
  double m = 0;
  for (const auto& v : q.vertices()) m = std::max(m, side_bound<F>(uv, t, v, du));
  return m;
}

/// (8) Orientation of the Gauss-map edge axis (plain_kernel.hpp edge_axis):
///     float: n the rounded unit axis of (4) (delta_n), c~ the stored centroid of
///     each shape, wa = fl(pA - c~A), wb = fl(c~B - pB), oa = fl(n . wa),
///     ib = fl(n . wb), S = fl(oa + ib); the axis is negated iff S < 0.
///     exact: S_e = n_e . ((pA - cA) + (cB - pB)), cA, cB the exact vertex means
///     (PlainKernel<mpq>); negated iff S_e < 0.  A float orientation differs
///     from the exact one only if |S_e| <= |S - S_e|, so only if |S_e| <= B_or:
///       centroid (convex_polyhedron.hpp: a sequential sum of V vertices, one
///       division by V): per coordinate |c~ - c| <= gamma_{V-1} sum|v| / V +
///       u |s~| / V <= (gamma_{V-1} + u (1 + gamma_{V-1})) M <= gamma_V M, M the
///       largest |coordinate|:   ||c~ - c|| <= sqrt(3) gamma_V M =: E_c
///       (the overflow path scales by powers of two: the same bound);
///       |wa - (pA - c~A)| <= u |pA - c~A| <= u |wa| / (1 - u) componentwise, so
///       ||wa - (pA - cA)|| <= u ||wa|| / (1 - u) + E_cA;
///       |oa - n . wa| <= gamma_3 sum|n||wa|;
///       |n . wa - n_e . (pA - cA)| <= delta_n ||wa|| + ||wa - (pA - cA)||  (||n_e|| = 1);
///       the same for B;  |S - (oa + ib)| <= u (|oa| + |ib|)
///         <= u (1 + gamma_3) (sum|n||wa| + sum|n||wb|);
///     => B_or = (gamma_3 + u (1 + gamma_3)) (sum|n||wa| + sum|n||wb|)
///               + (delta_n + u / (1 - u)) (||wa|| + ||wb||) + E_cA + E_cB + 8 eta
///     (eta = half the smallest subnormal of F: one per rounded product that
///     may underflow, six products and the centroid divisions, padded to 8;
///     evaluated with the smallest subnormal, >= eta).  The
///     fuzzer decides |S_e| <= B_or exactly, as (N_e . X)^2 <= B_or^2 |N_e|^2
///     with N_e = dA_e x dB_e and X = (pA - cA) + (cB - pB) (classify.hpp):
///     outside this band a flipped float orientation is unexplained.
///
/// (8) ||c~ - c|| for the stored centroid of p (sequential sum, one division).
template <class F>
inline double centroid_error(const ConvexPolyhedron<F>& p) {
  return std::sqrt(3.0) * gamma(p.vertex_count(), u_of<F>()) * p.max_abs_coordinate() * kSlack;
}

/// (8) the orientation bound B_or: n the rounded unit axis, wa = fl(pA - c~A),
/// wb = fl(c~B - pB), delta_n from (4), ca, cb from centroid_error.
template <class F>
inline double orientation_bound(const Vec3<F>& n, const Vec3<F>& wa, const Vec3<F>& wb, double delta_n,
                                double ca, double cb) {
  const double u = u_of<F>();
  const double eta = double(std::numeric_limits<F>::denorm_min());  // >= eta
  const Vec3<double> nd = d(n), ad = d(wa), bd = d(wb);
  const double dots = abs_dot(nd, ad) + abs_dot(nd, bd);
  return ((gamma(3, u) + u * (1 + gamma(3, u))) * dots + (delta_n + u / (1 - u)) * (norm(ad) + norm(bd)) +
          ca + cb + 8 * eta) *
         kSlack;
}

/// (9) The brute force's support check (plain_kernel.hpp edge_separation_full):
///     along the unit axis n of (4) (unoriented), orientation "+" is accepted iff
///     both endpoints p of eA have fl(n.p) >= fl(max_A - t_A) and both endpoints
///     q of eB have fl(n.q) <= fl(min_B + t_B), max_A = max over A of fl(n.v),
///     min_B likewise, t_P = PlainKernel::support_tolerance(P) (an F value);
///     "-" is the same with A and B's roles of max and min swapped.  Every
///     projection is within P_S of the exact n_e . v (P_S = max over the shape's
///     vertices of (5)'s per-projection bound), and the subtraction rounds once,
///     so with g = max_e - n_e . p >= 0 the exact depth of an endpoint below its
///     shape's exact extreme:
///       accepted  =>  g <= t + 2 P_S + u (|max~| + t)           ("possible")
///     |max~| the float extreme's magnitude.  The exact brute force accepts only
///     g = 0.  A float run that accepts a pair the exact one rejects is
///     explained when every endpoint passes "possible", decided exactly as
///     (N_e . (v_max - p))^2 <= T^2 |N_e|^2 (classify.hpp support_band).
///
/// (9) the half-width of the "possible" support band of one shape:
/// t + 2 P_S + u (|max~| + t), with t the kernel's support tolerance
/// (PlainKernel::support_tolerance), ps = P_S and extreme = |max~| (or |min~|).
template <class F>
inline double support_band_width(double t, double ps, double extreme) {
  const double u = u_of<F>();
  return (t + 2 * ps + u * (extreme + t)) * kSlack;
}

/// A lower bound on sqrt(x) for a double x that approximates an exact value to
/// within a relative 2^-52 (to_double of an exact square length).
inline double sqrt_lower(double x) {
  if (!(x > 0)) return 0;
  return std::sqrt(x * (1 - 0x1p-50)) * (1 - 0x1p-50);
}

}  // namespace sepax::fuzz::bounds
