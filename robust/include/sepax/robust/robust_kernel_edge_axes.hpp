// sepax/robust/robust_kernel_edge_axes.hpp
//
// The edge-pair axes of RobustKernel<T> (robust_kernel.hpp): the unit axis of
// two edges and its orientation, each with its error bound and exact fallback.
//   * edge_axis(): fl(normalize(dA x dB)), PlainKernel's axis, with its bound
//     delta (cached per pair; exact_edge_axis() when the T cross product fails);
//   * axis_side(), centroid_side(): which way the axis points, from the shapes'
//     exact vertex means (the exact kernel's rule), filtered, exact beside it;
//   * edge_sigma(): the orientation the current SAT's exact counterpart uses;
//   * side_normal_as(), side_normal(): the in-plane normals of a flat shape's
//     edges (side axes).
// Built on robust_kernel_state.hpp; robust_kernel_values.hpp builds on it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <sepax/robust/robust_kernel_state.hpp>

namespace sepax::robust::detail {

template <RobustFloat T>
class RobustEdgeAxes : public RobustKernelState<T> {
  using Base = RobustKernelState<T>;

 protected:
  using Base::a_;
  using Base::axis_cache_;
  using Base::b_;
  using Base::Base;
  using Base::cross_ratio_squared;
  using Base::diff;
  using Base::e_;
  using Base::edge_pair_sign;
  using Base::fallbacks_;
  using Base::kEta;
  using Base::kG5;
  using Base::kMargin;
  using Base::kNoBound;
  using Base::projection_rule_;
  using Base::unit_error_from_ratio;
  using typename Base::EdgeAxis;
  using typename Base::P;

 protected:
  // The unit axis of an edge pair, exactly as PlainKernel<T>::unoriented_axis,
  // with its error bound.  If the T cross product is zero or not finite (edges
  // parallel in T but not exactly), the axis is computed from the exact cross
  // product rounded to double (a value for reporting; every decision about it
  // then goes exact because delta is kNoBound).
  // compare()/sign()/axis()/error_bound() of a feature follow its
  // edges_parallel/edge_separation calls: the cache hit is inline (it was an
  // out-of-line call, twice per Minkowski pair), the miss is not.
  SEPAX_ROBUST_INLINE EdgeAxis edge_axis(int ea, int eb) const {
    if (ea == axis_cache_.ea && eb == axis_cache_.eb) [[likely]]
      return axis_cache_.axis;
    return cache_edge_axis(ea, eb);
  }

  SEPAX_ROBUST_NOINLINE EdgeAxis cache_edge_axis(int ea, int eb) const {
    axis_cache_.ea = ea;
    axis_cache_.eb = eb;
    axis_cache_.axis = compute_edge_axis(ea, eb);
    return axis_cache_.axis;
  }

  EdgeAxis compute_edge_axis(int ea, int eb) const {
    const Vec3<T>& da = a_.edge_direction(ea);
    const Vec3<T>& db = b_.edge_direction(eb);
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
  // r2 = cross_ratio_squared(dA, dB, c).  Where c.c leaves T's safe range
  // (c finite, as r2 is, but c.c overflowing T: float edges beyond about 4e9)
  // c is first scaled by a power of two (scaled_unit).
  static EdgeAxis float_edge_axis(const Vec3<T>& c, double r2) {
    EdgeAxis ax;
    const T s = squared_norm(c);
    if (sepax::detail::safe_squared_norm(s)) [[likely]] {
      const T len = std::sqrt(s);
      ax.n = Vec3<T>(c[0] / len, c[1] / len, c[2] / len);
    } else {
      ax.n = scaled_unit(c);
    }
    ax.delta = unit_error_from_ratio(robust::detail::sqrt_d(r2));
    return ax;
  }

  // c / |c| for a finite c != 0 whose c.c leaves T's safe range: c 2^-e with
  // its largest |component| in [1, 2), then normalised.  The bound of
  // unit_error_from_ratio still holds: the scaling is exact except for
  // components it makes subnormal (an absolute error below 2^-148 against a
  // largest component >= 1), and the normalisation's roundings are relative,
  // as in range; that 2^-148 is far inside the bound's (1 + 1e-6) pad.
  SEPAX_ROBUST_COLD static Vec3<T> scaled_unit(const Vec3<T>& c) {
    const T m = sepax::detail::max_abs2(c, c);
    if (!(m > T(0) && m <= std::numeric_limits<T>::max())) return Vec3<T>(T(0), T(0), T(0));
    const Vec3<T> cs = sepax::detail::scale_pow2(c, sepax::detail::pow2_exponent(m));
    const T len = std::sqrt(squared_norm(cs));
    return Vec3<T>(cs[0] / len, cs[1] / len, cs[2] / len);
  }

  // The T cross product is zero or not finite: the axis from the exact cross
  // product rounded to double, no bound (out of line: it keeps the hot path's
  // frame small).
  SEPAX_ROBUST_COLD EdgeAxis exact_edge_axis(int ea, int eb) const {
    EdgeAxis ax;
    const auto ce =
        robust::exact_cross(robust::exact_diff(a_.vertex(a_.edge_head(ea)), a_.vertex(a_.edge_tail(ea))),
                            robust::exact_diff(b_.vertex(b_.edge_head(eb)), b_.vertex(b_.edge_tail(eb))));
    int scale = 0;  // (the exact cross product may leave double's range: scaled into it)
    const std::array<double, 3> cs = robust::approx_scaled(ce, scale);
    Vec3<double> cd(cs[0], cs[1], cs[2]);
    const double m = std::max({std::fabs(cd[0]), std::fabs(cd[1]), std::fabs(cd[2])});
    if (m > 0) cd /= m;
    const double len = cd.norm();
    ax.n = len > 0 ? Vec3<T>(static_cast<T>(cd[0] / len), static_cast<T>(cd[1] / len),
                             static_cast<T>(cd[2] / len))
                   : Vec3<T>(T(0), T(0), T(0));
    ax.delta = kNoBound;
    return ax;
  }

  // sign of n* . (p.vertex(v) - exact mean of p's vertices), n* = eA x eB.
  // PlainKernel<mpq_class> orients an edge-pair axis by the exact vertex
  // means.  The float centroids need not be strictly inside (sliver shapes,
  // and off the plane of a flat shape), so the exact fallbacks use the exact
  // means: sign sum_v n*.(p - v) = sign (V n*.p - n*.sum v).
  int centroid_side(const P& p, int v, const EdgeAxis& ax, double cerr, double extent, int ea, int eb) const {
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
    if (s == 0) [[unlikely]]
      return axis_side_exact(ea, eb);
    return s;
  }

  // sign( V_A V_B n*.(pA - pB) + V_A n*.Sum(B) - V_B n*.Sum(A) ): the rule
  // above multiplied by V_A V_B > 0, exactly.
  SEPAX_ROBUST_COLD int axis_side_exact(int ea, int eb) const {
    ++fallbacks_;
    using robust::ExactFloat;
    const auto n =
        robust::exact_cross(robust::exact_diff(a_.vertex(a_.edge_head(ea)), a_.vertex(a_.edge_tail(ea))),
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
    const auto n =
        robust::exact_cross(robust::exact_diff(a_.vertex(a_.edge_head(ea)), a_.vertex(a_.edge_tail(ea))),
                            robust::exact_diff(b_.vertex(b_.edge_head(eb)), b_.vertex(b_.edge_tail(eb))));
    std::array<ExactFloat, 3> sum{ExactFloat(0), ExactFloat(0), ExactFloat(0)};
    for (const auto& w : p.vertices()) {
      for (int c = 0; c < 3; ++c) sum[c] = sum[c] + robust::exact(static_cast<double>(w[c]));
    }
    const std::array<ExactFloat, 3> pv{robust::exact(static_cast<double>(p.vertex(v)[0])),
                                       robust::exact(static_cast<double>(p.vertex(v)[1])),
                                       robust::exact(static_cast<double>(p.vertex(v)[2]))};
    const ExactFloat val =
        ExactFloat(p.vertex_count()) * robust::exact_dot(n, pv) - robust::exact_dot(n, sum);
    return robust::exact_sign(val);
  }

  // The orientation (+1/-1) of the edge pair's axis that the current SAT's
  // exact counterpart uses.  A separation value does not say which
  // orientation its SAT chose, so compare()/sign() recompute it from the
  // feature: the O(1) form (edge_separation, Gauss map, traversal) uses
  // axis_side, no flip when zero; the projection form (edge_separation_full,
  // brute force) uses s_A if non-zero, else the sign of n*.(centroid(B) - pB),
  // else the sign of n*.(pB - pA) (+1 when zero), which is exactly the
  // orientation its exact support checks select.  A kernel serves one SAT
  // run; it remembers which of the two forms that run used (projection_rule_).
  int edge_sigma(int ea, int eb) const {
    const EdgeAxis ax = edge_axis(ea, eb);
    if (!projection_rule_) return axis_side(ax, ea, eb) < 0 ? -1 : 1;
    const int sa = centroid_side(a_, a_.edge_tail(ea), ax, e_.centroid_a, e_.extent_a, ea, eb);
    if (sa != 0) return sa;
    const int sb = -centroid_side(b_, b_.edge_tail(eb), ax, e_.centroid_b, e_.extent_b, ea, eb);
    if (sb != 0) return sb;
    return edge_pair_sign(ea, eb) < 0 ? -1 : 1;
  }

  // Side axes (see side_query_a).
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
    const Vec3<T>& d = p.edge_direction(e);
    const Vec3<T>& n = p.edge_normal(e, 0);
    const Vec3<double> dd(d[0], d[1], d[2]), nd(n[0], n[1], n[2]);
    Vec3<double> u = scaled_cross(dd, nd);  // scale-safe: vec3.hpp
    const double len = u.norm();
    if (len > 0) u /= len;
    return Vec3<T>(static_cast<T>(u[0]), static_cast<T>(u[1]), static_cast<T>(u[2]));
  }
};

}  // namespace sepax::robust::detail
