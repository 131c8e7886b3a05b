// sepax/robust/robust_kernel_faces.hpp
//
// The face queries of RobustKernel<T> (robust_kernel.hpp): the support vertex
// of the other shape below a face of one, exactly the exact kernel's.
//   * face_query_a/b(): float minimum and second minimum (SIMD lanes or a
//     scalar loop); unique beyond the support bound, else resolve_support();
//   * face_estimate_a/b(): the face's value without certifying its vertex;
//   * face_separation_a/b(): a vertex's height above a face;
//   * support_filter_a/b(), support_sign_a/b(): the traversal's filtered
//     comparison of two vertices below a face;
//   * side_query_a/b(): side axes of two flat shapes, exact.
// Built on robust_kernel_values.hpp; robust_kernel_edges.hpp builds on it.
#pragma once

#include <cmath>
#include <limits>

#include <sepax/robust/robust_kernel_values.hpp>
#include <sepax/simd_lanes.hpp>

namespace sepax::robust::detail {

template <RobustFloat T>
class RobustFaceQueries : public RobustValues<T> {
  using Base = RobustValues<T>;

 protected:
  using Base::a_;
  using Base::b_;
  using Base::Base;
  using Base::e_;
  using Base::face_pair_sign;
  using Base::fallbacks_;
  using Base::height;
  using Base::side_normal;
  using Base::snap;
  using Base::snap_exact;
  using Base::support_lanes_;
  using typename Base::P;

 public:
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

  /// Optional member (sat_kernel.hpp, HasEdgeWedge): vertex x of B strictly
  /// inside the wedge of edge e of A, exactly: sign((E x N_s).(x - tail)) for
  /// the exact edge E = head - tail and N_s the plane triple's cross product
  /// of edge_face(e, s), > 0 for s = 0 and < 0 for s = 1.  Each sign is
  /// filtered in T with E_wedge(A) (error_bounds.hpp, QueryBounds::wedge_a),
  /// exact beyond it.
  SEPAX_ROBUST_INLINE bool in_edge_wedge_a(int e, int x) const {
    const Vec3<T> c = wedge_cross(a_.edge_direction(e), b_.vertex(x), a_.vertex(a_.edge_tail(e)));
    return wedge_sign(e, 0, x, c) > 0 && wedge_sign(e, 1, x, c) < 0;
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

 protected:
  // c = fl(w x Ẽ), w = fl(x - tail), Ẽ the stored edge direction, written
  // out (sepax::cross is not always inlined): (E x n).w = n.(w x E), so one
  // cross product serves both faces.
  SEPAX_ROBUST_INLINE static Vec3<T> wedge_cross(const Vec3<T>& d, const Vec3<T>& x, const Vec3<T>& tail) {
    const T w0 = x[0] - tail[0], w1 = x[1] - tail[1], w2 = x[2] - tail[2];
    return Vec3<T>(T(w1 * d[2] - w2 * d[1]), T(w2 * d[0] - w0 * d[2]), T(w0 * d[1] - w1 * d[0]));
  }
  // sign((E x N_s).w) of in_edge_wedge_a: the T value fl(n_s.c) decides
  // beyond E_wedge(A) when finite, else the exact stage.
  SEPAX_ROBUST_INLINE int wedge_sign(int e, int s, int x, const Vec3<T>& c) const {
    const Vec3<T>& n = a_.edge_normal(e, s);
    const T v = n[0] * c[0] + n[1] * c[1] + n[2] * c[2];
    const double m = std::abs(static_cast<double>(v));
    if (m > e_.wedge_a && m <= std::numeric_limits<double>::max()) return v > T(0) ? 1 : -1;
    return wedge_sign_exact(e, s, x);
  }
  SEPAX_ROBUST_COLD int wedge_sign_exact(int e, int s, int x) const {
    ++fallbacks_;
    const auto& t = a_.face(a_.edge_face(e, s)).plane_vertices;
    const Vec3<T>& v0 = a_.vertex(t[0]);
    const auto n =
        robust::exact_cross(robust::exact_diff(a_.vertex(t[1]), v0), robust::exact_diff(a_.vertex(t[2]), v0));
    const Vec3<T>& tail = a_.vertex(a_.edge_tail(e));
    const auto d = robust::exact_diff(a_.vertex(a_.edge_head(e)), tail);
    return robust::exact_sign(
        robust::exact_dot(robust::exact_cross(d, n), robust::exact_diff(b_.vertex(x), tail)));
  }

  // Support vertex of q along -u (lowest index among the exactly lowest).
  SEPAX_ROBUST_COLD FaceQuery<T> side_query(const P& p, int e, const P& q, bool of_a) const {
    ++fallbacks_;
    const auto u = this->template side_normal_as<robust::ExactFloat>(p, e);
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

  // Support vertex of q along the inward normal of face f of p: the lowest
  // index among the vertices with exactly minimal N_f . v.
  // The float minimum and second minimum come from the same n.v values
  // either way: a few vertices at a time over q's lane arrays (simd_lanes.hpp;
  // shapes with more than kScalarSupportMax vertices, support_lanes_bounded), else
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
    if (support_lanes_ && nv > kScalarSupportMax) {
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
    if (support_lanes_ && nv > kScalarSupportMax) return simd::support_scan<false, false>(q, pl.normal).min;
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
      if (d > w)
        s = 1;
      else if (d < -w)
        s = -1;
      else
        s = robust::orient_sign(v0, v1, v0, v2, q.vertex(cur), q.vertex(i), &fallbacks_);
      if (s < 0) {
        cur = i;
        gcur = g;
      }
    }
    return cur;
  }
};

}  // namespace sepax::robust::detail
