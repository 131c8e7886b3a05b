// sepax/robust/robust_kernel_values.hpp
//
// The separation values of RobustKernel<T> (robust_kernel.hpp): their error
// bounds and the exact decisions about them.
//   * value_error(), error_bound(): the bound on |value - exact value| of a
//     feature's separation (error_bounds.hpp);
//   * compare(), compare_bounded(), sign(), compare_margin(): the filter on the
//     plain values first, the exact stage (interval, then ExactFloat, on the
//     feature's separation polynomials) only within it;
//   * snap(): a returned value always carries the exact sign.
// Built on robust_kernel_edge_axes.hpp; robust_kernel_faces.hpp builds on it.
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include <sepax/robust/robust_kernel_edge_axes.hpp>
#include <sepax/robust/separation_compare.hpp>

namespace sepax::robust::detail {

template <RobustFloat T>
class RobustValues : public RobustEdgeAxes<T> {
  using Base = RobustEdgeAxes<T>;

 protected:
  using Base::a_;
  using Base::b_;
  using Base::Base;
  using Base::e_;
  using Base::edge_axis;
  using Base::edge_pair_sign;
  using Base::edge_sigma;
  using Base::face_sign;
  using Base::fallbacks_;
  using Base::kMargin;

 public:
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

 protected:
  // δ D (1+1e-6) + e_.edge_abs, with e_.d_margin = D (1+1e-6) summed once per
  // query (a reassociated product: its rounding is inside the margin).
  double edge_value_error(double delta) const { return delta * e_.d_margin + e_.edge_abs; }

  double value_error(const Feature& f) const {
    switch (f.type) {
      case FeatureType::FaceA:
        return e_.face_a;
      case FeatureType::FaceB:
        return e_.face_b;
      case FeatureType::EdgePair:
        return edge_value_error(edge_axis(f.a, f.b).delta);
      case FeatureType::SideA:
      case FeatureType::SideB:
        break;  // always exact (see side_query)
    }
    return std::numeric_limits<double>::infinity();
  }

  // Exact helpers (each call counts as a fallback when it runs exactly).
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
        const auto u = this->template side_normal_as<N>(a_, f.a);
        return {robust::exact_dot(u, robust::diff_as<N>(b_.vertex(f.b), a_.vertex(a_.edge_tail(f.a)))),
                robust::exact_dot(u, u)};
      }
      case FeatureType::SideB: {
        const auto u = this->template side_normal_as<N>(b_, f.b);
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
      case FeatureType::FaceA:
        return face_sign(a_, f.a, b_.vertex(f.b));
      case FeatureType::FaceB:
        return face_sign(b_, f.b, a_.vertex(f.a));
      case FeatureType::EdgePair:
        return edge_sigma(f.a, f.b) * edge_pair_sign(f.a, f.b);
      case FeatureType::SideA:
      case FeatureType::SideB:
        ++fallbacks_;
        return robust::exact_sign(exact_separation(f).num);
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
    // num / sqrt(norm2) with both scaled into double's range by powers of two
    // (at large or small scales either leaves it; norm2's scale is a multiple of
    // 2 x 960, so its square root is a power of two too)
    int scale_num = 0, scale_n2 = 0;
    const double num = robust::approx_scaled(std::array<robust::ExactFloat, 1>{ex.num}, scale_num)[0];
    const double n2 = robust::approx_scaled(std::array<robust::ExactFloat, 1>{ex.norm2}, scale_n2)[0];
    T r = T(0);
    if (std::isfinite(num) && std::isfinite(n2) && n2 > 0)
      r = static_cast<T>(std::ldexp(num / std::sqrt(n2), scale_num - scale_n2 / 2));
    if (sign_of(r) != s)
      r = s > 0 ? std::numeric_limits<T>::denorm_min() : -std::numeric_limits<T>::denorm_min();
    return Separation<T>{r, T(1)};
  }
};

}  // namespace sepax::robust::detail
