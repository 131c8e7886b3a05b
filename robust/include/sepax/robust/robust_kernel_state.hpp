// sepax/robust/robust_kernel_state.hpp
//
// The root layer of RobustKernel<T> (robust_kernel.hpp): what one query keeps,
// and the exact predicates every other layer falls back to.
//   * the two shapes, this query's error bounds (QueryBounds<T>,
//     error_bounds.hpp: O(1) per query from terms each ConvexPolyhedron
//     computes once, one named field per bound beside its derivation), the
//     edge-axis cache and the exact-fallback counter;
//   * the T helpers shared by the layers (negate_if, diff, height);
//   * the orientation predicates (orientation.hpp) of a face against two
//     points, of an edge pair against a point, of a face normal against an
//     edge: exact signs, each counting a fallback when it runs exactly.
// Layers built on it, in order: robust_kernel_edge_axes.hpp,
// robust_kernel_values.hpp, robust_kernel_faces.hpp, robust_kernel_edges.hpp.
#pragma once

#include <cstdint>
#include <type_traits>

#include <sepax/plain_kernel.hpp>
#include <sepax/robust/error_bounds.hpp>
#include <sepax/robust/exact_float.hpp>
#include <sepax/robust/orientation.hpp>
#include <sepax/sat_kernel.hpp>

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

namespace sepax::robust::detail {

template <RobustFloat T>
class RobustKernelState : protected ErrorConstants<T> {
 public:
  const ConvexPolyhedron<T>& a() const { return a_; }
  const ConvexPolyhedron<T>& b() const { return b_; }

  /// Decisions that needed the exact stage (ExactFloat evaluations).
  std::int64_t exact_fallbacks() const { return fallbacks_; }

 protected:
  RobustKernelState(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b)
      : a_(a),
        b_(b),
        e_(a, b),
        lanes_(a.lanes_bounded() && b.lanes_bounded()),
        support_lanes_(a.support_lanes_bounded() && b.support_lanes_bounded()) {}

  using P = ConvexPolyhedron<T>;
  using C = robust::ErrorConstants<T>;
  using C::cross_ratio_squared;
  using C::kEta;
  using C::kG5;
  using C::kMargin;
  using C::kNoBound;
  using C::kPreK;
  using C::kPreKappa;
  using C::kU;
  using C::kUd;
  using C::unit_error_from_ratio;

  struct EdgeAxis {
    Vec3<T> n;     // fl(normalize(dA x dB)), unoriented (as PlainKernel)
    double delta;  // bound on |n - n*/|n*||
  };

  // neg ? -v : v (the sign bit flipped: -v, as unary minus), without a jump.
  static T negate_if(T v, bool neg) {
    using Bits = std::conditional_t<std::is_same_v<T, float>, std::uint32_t, std::uint64_t>;
    constexpr int kSignShift = static_cast<int>(sizeof(T)) * 8 - 1;
    return std::bit_cast<T>(
        static_cast<Bits>(std::bit_cast<Bits>(v) ^ (static_cast<Bits>(neg) << kSignShift)));
  }

  // p - q, one subtraction per coordinate: the value of Vec3<T>(p - q), which
  // g++ -O3 compiled to an out-of-line Eigen call (as PlainKernel::diff).
  static Vec3<T> diff(const Vec3<T>& p, const Vec3<T>& q) {
    return Vec3<T>(T(p[0] - q[0]), T(p[1] - q[1]), T(p[2] - q[2]));
  }

  static Separation<T> height(const Plane<T>& pl, const Vec3<T>& p) {
    return Separation<T>{T(dot(pl.normal, p) - pl.offset), T(1)};
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
                               b_.vertex(b_.edge_tail(eb)), b_.vertex(b_.edge_head(eb)), p0, q, &fallbacks_);
  }

  SEPAX_ROBUST_COLD int normal_dot_sign_exact(const P& p, int f, const P& q, int ei) const {
    const auto& t = p.face(f).plane_vertices;
    const Vec3<T>& v0 = p.vertex(t[0]);
    // N.e = ((v1 - v0) x (v2 - v0)) . e = det[e, v1 - v0, v2 - v0]
    return robust::orient_sign(q.vertex(q.edge_tail(ei)), q.vertex(q.edge_head(ei)), v0, p.vertex(t[1]), v0,
                               p.vertex(t[2]), &fallbacks_);
  }

  const P& a_;
  const P& b_;
  const robust::QueryBounds<T> e_;  // this query's error bounds (error_bounds.hpp)
  struct AxisCache {
    int ea = -1, eb = -1;
    EdgeAxis axis;
  };
  mutable AxisCache axis_cache_;
  bool lanes_ = false;          // both shapes lanes_bounded(): the SIMD scans apply
  bool support_lanes_ = false;  // both shapes support_lanes_bounded(): the support scans apply
  mutable std::int64_t fallbacks_ = 0;
  mutable bool projection_rule_ = false;
};

}  // namespace sepax::robust::detail
