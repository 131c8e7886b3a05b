// sepax/convex_polyhedron_derived.hpp
//
// ConvexPolyhedron<T>'s derived data (convex_polyhedron.hpp declares the
// class), recomputed from the vertices and the topology whenever they change:
//   * compute_derived(): the planes from the plane triples, then the rest;
//   * compute_edge_data(): per-edge directions (an array);
//   * compute_lanes(): the same values one array per coordinate (SIMD scans);
//   * compute_bounds(): bounds, centroid, extent, max |coordinate|;
//   * compute_normal_conditioning(), NormalConditioningScan: the shape's term
//     of the robust kernel's normal error bound;
//   * height(), height_tolerance(): a point above a face plane, and the
//     tolerance in those units.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "convex_polyhedron.hpp"
#include "simd_ops.hpp"

namespace sepax {

// The planes from the plane triples, then everything after them.  With
// eager_conditioning (float/double), normal_conditioning() is computed in
// the same pass (compute_planes).
template <Number T>
inline void ConvexPolyhedron<T>::compute_derived(bool eager_conditioning, bool with_bounds) {
  compute_planes(eager_conditioning);
  compute_edge_data();
  if (with_bounds) compute_bounds();
}

// The planes from the plane triples.  With eager_conditioning
// (float/double), normal_conditioning() is computed in the same pass from
// the plane triples' differences and cross products (the value
// compute_normal_conditioning() gives, bit for bit: the same expressions
// and the same scan, NormalConditioningScan); otherwise it is reset (computed
// on first use).  Returns, for float/double, whether every normal component
// is within 2^60 in magnitude (compute_lanes' bound; false for NaN) and
// whether every offset is finite, tested without a branch per value.
// Float/double with SIMD: plane_groups first, the scalar loop for the rest.
template <Number T>
inline typename ConvexPolyhedron<T>::PlanesInRange ConvexPolyhedron<T>::compute_planes(
    bool eager_conditioning) {
  const auto nf = static_cast<std::size_t>(topology_.face_count());
  if (planes_.size() != nf) planes_.resize(nf);  // (a call even when it has nothing to do)
  [[maybe_unused]] NormalConditioningScan scan;
  [[maybe_unused]] const bool cond =
      eager_conditioning && (std::is_same_v<T, float> || std::is_same_v<T, double>);
  PlanesInRange in_range;
  [[maybe_unused]] bool nb = true, of = true;
  std::size_t f = 0;
  if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
    if (nf > 2) f = plane_groups(cond ? &scan : nullptr, nb, of);
  }
  for (; f < nf; ++f) {
    if (f == 1 && nf == 2) {
      // Flat shape: the back face's plane is exactly the front one negated.
      // That is what plane_through on the reversed triple gives in exact
      // arithmetic and in plain IEEE arithmetic (a*b - c*d is antisymmetric);
      // under FMA contraction (-march=native -ffp-contract=fast) it is not,
      // and the "exactly opposite normals" invariant broke (tests/fma).
      planes_[1] = Plane<T>{Vec3<T>(-planes_[0].normal), T(-planes_[0].offset)};
      continue;
    }
    derive_plane(static_cast<int>(f), cond ? &scan : nullptr);
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) planes_in_range(planes_[f], nb, of);
  }
  normal_conditioning_.reset();  // new coordinates: computed again on first use
  if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
    if (cond) normal_conditioning_.store(scan.result());
    in_range.normals_bounded = nb;  // the back face of a flat shape: the front one negated
    in_range.offsets_finite = of;
  }
  return in_range;
}

// compute_planes' range tests of one plane (float/double): ANDs into nb
// whether every normal component is within 2^60 in magnitude (false for NaN)
// and the normal is not 0 (a plane triple that rounded to collinear points:
// check_plane_normals), and into of whether the offset is finite.  (Only
// the faces plane_groups leaves come here: its lanes' normals are non-zero,
// their c.c being above 2^40 min.)
template <Number T>
[[gnu::always_inline]] inline void ConvexPolyhedron<T>::planes_in_range(const Plane<T>& pl, bool& nb,
                                                                        bool& of) {
  const T big = T(0x1p60);
  nb &= std::abs(pl.normal[0]) <= big && std::abs(pl.normal[1]) <= big && std::abs(pl.normal[2]) <= big;
  nb &= pl.normal[0] != T(0) || pl.normal[1] != T(0) || pl.normal[2] != T(0);
  of &= std::abs(pl.offset) <= std::numeric_limits<T>::max();
}

// compute_planes for faces [0, k W), W = simd::Lanes<T>::width (4 floats or
// 2 doubles with SSE2; 0 faces without SIMD), k W the largest multiple of W
// up to the face count, W faces at a time: each lane evaluates
// plane_of_triple's operations in its order (the differences, the cross
// product, c.c left to right, sqrt, three divisions, the offset left to
// right), each correctly rounded as in a scalar register, so every plane and
// every scan term is bit for bit plane_of_triple's (under FMA contraction
// the caveat of simd_ops.hpp).  A group with a lane whose c.c leaves the
// safe range (plane_of_triple then rescales the cross product) is computed
// face by face by plane_of_triple.  The scan gets the faces in index order;
// nb and of get compute_planes' range tests (the normals of the lanes pass
// nb's by construction, below).  Returns k W.
// (inlined into compute_planes, its one caller)
template <Number T>
[[gnu::always_inline]] inline std::size_t ConvexPolyhedron<T>::plane_groups(NormalConditioningScan* scan,
                                                                            bool& nb, bool& of) {
  using L = simd::Lanes<T>;
  constexpr int W = L::width;
  if constexpr (W == 1) {
    (void)scan, (void)nb, (void)of;
    return 0;
  } else {
    using V = typename L::V;
    const std::size_t done = static_cast<std::size_t>(topology_.face_count()) / W * W;
    const V vmax = L::set1(std::numeric_limits<T>::max());
    const V vtiny = L::set1(std::numeric_limits<T>::min() * T(0x1p40));  // safe_squared_norm's
    auto ok_o = L::le(vmax, vmax);                                       // every lane true
    constexpr unsigned all = (1u << W) - 1;
    static_assert(sizeof(Vec3<T>) == 3 * sizeof(T) && sizeof(Plane<T>) == 4 * sizeof(T),
                  "load_xyz reads a Vec3<T> as three contiguous T, store_abcd writes a Plane<T> as four");
    for (std::size_t base = 0; base < done; base += W) {
      const T* q[3][W];  // v0, v1, v2 of each lane's plane triple
      simd::unrolled<W>([&](int i) SEPAX_SIMD_INLINE {
        const auto& t = topology_.faces()[base + static_cast<std::size_t>(i)].plane_vertices;
        q[0][i] = vertices_[static_cast<std::size_t>(t[0])].data();
        q[1][i] = vertices_[static_cast<std::size_t>(t[1])].data();
        q[2][i] = vertices_[static_cast<std::size_t>(t[2])].data();
      });
      V a0, a1, a2, b0, b1, b2, d0, d1, d2;
      L::load_xyz(q[0], a0, a1, a2);
      L::load_xyz(q[1], b0, b1, b2);
      L::load_xyz(q[2], d0, d1, d2);
      const V u0 = L::sub(b0, a0), u1 = L::sub(b1, a1), u2 = L::sub(b2, a2);
      const V w0 = L::sub(d0, a0), w1 = L::sub(d1, a1), w2 = L::sub(d2, a2);
      const V c0 = L::sub(L::mul(u1, w2), L::mul(u2, w1));
      const V c1 = L::sub(L::mul(u2, w0), L::mul(u0, w2));
      const V c2 = L::sub(L::mul(u0, w1), L::mul(u1, w0));
      const V s = L::add(L::add(L::mul(c0, c0), L::mul(c1, c1)), L::mul(c2, c2));
      if (L::bits(L::mand(L::le(s, vmax), L::gt(s, vtiny))) != all) [[unlikely]] {
        for (int i = 0; i < W; ++i) {
          const int f = static_cast<int>(base) + i;
          planes_[static_cast<std::size_t>(f)] = plane_of_triple(f, scan);
          planes_in_range(planes_[static_cast<std::size_t>(f)], nb, of);
        }
        continue;
      }
      const V len = L::sqrt(s);  // > 0: s is in the safe range
      const V n0 = L::div(c0, len), n1 = L::div(c1, len), n2 = L::div(c2, len);
      const V off = L::add(L::add(L::mul(n0, a0), L::mul(n1, a1)), L::mul(n2, a2));
      // nb needs no test here: every term of s is >= 0 and rounding is
      // monotone, so s >= fl(c_i c_i) (1 - u)^2 >= c_i^2 (1 - u)^3 (or c_i^2
      // is below the normal range, far below s > 2^40 min), len = fl(sqrt
      // s) >= |c_i| (1 - u)^(5/2) and |n_i| <= (1 + u) (1 - u)^(-5/2) < 2,
      // fused or not: no lane here has a normal component beyond 2^60
      ok_o = L::mand(ok_o, L::le(L::abs(off), vmax));
      L::store_abcd(planes_[base].normal.data(), n0, n1, n2, off);  // W planes: normal, offset
      if (scan != nullptr) {
        alignas(16) double sq[3][W];  // |u|^2, |w|^2, |c|^2 in double, x*x + y*y + z*z
        simd::squared_norms_in_double<T>(u0, u1, u2, sq[0]);
        simd::squared_norms_in_double<T>(w0, w1, w2, sq[1]);
        simd::squared_norms_in_double<T>(c0, c1, c2, sq[2]);
        if constexpr (std::is_same_v<T, float>) {
          // add_squares on finite u, w and c (s is in the safe range: an
          // infinite or NaN component of u or w makes one of c, and so s,
          // infinite or NaN): every square of a float is below 2^256 in
          // double, so |c|^2 and |u|^2 |w|^2 are finite and only the tiny
          // test of `bad` can fail.  The products and that test per lane;
          // then add_ratio's comparison of every lane with the running
          // maximum the group starts from (the same products, rounded the
          // same), and only if some lane is larger, the running maximum
          // face by face in index order (when none is, add_ratio would
          // keep that maximum through the whole group).
          using LD = simd::Lanes<double>;
          alignas(16) double num[W];
          const auto tiny = LD::set1(kNormalTinySquared);
          const auto wnum = LD::set1(scan->wnum), wden = LD::set1(scan->wden);
          auto above = LD::le(tiny, tiny);
          unsigned larger = 0;
          for (int h = 0; h < W; h += LD::width) {
            const auto n = LD::mul(LD::load(sq[0] + h), LD::load(sq[1] + h));
            const auto nc2 = LD::load(sq[2] + h);
            LD::store(num + h, n);
            above = LD::mand(above, LD::gt(nc2, tiny));
            larger |= LD::bits(LD::gt(LD::mul(n, wden), LD::mul(wnum, nc2)));
          }
          scan->bad |= LD::bits(above) != (1u << LD::width) - 1;
          if (larger != 0)
            for (int i = 0; i < W; ++i) scan->add_ratio(num[i], sq[2][i]);
        } else {
          for (int i = 0; i < W; ++i) scan->add_squares(sq[0][i], sq[1][i], sq[2][i]);
        }
      }
    }
    of &= L::bits(ok_o) == all;
    return done;
  }
}

// Everything after the planes: per-edge arrays and lanes.  Reuses the
// arrays' capacity.
template <Number T>
inline void ConvexPolyhedron<T>::compute_edge_data() {
  // per-edge directions
  const auto ne = static_cast<std::size_t>(edge_count());
  edge_dirs_.resize(ne);
  for (std::size_t e = 0; e < ne; ++e) derive_edge_direction(e);
  compute_lanes();
}

// (inlined: the posed queries derive every edge of B' per query)
template <Number T>
[[gnu::always_inline]] inline void ConvexPolyhedron<T>::derive_edge_direction(std::size_t e) {
  const HalfEdge& h0 = topology_.half_edges()[2 * e];
  const HalfEdge& h1 = topology_.half_edges()[2 * e + 1];
  if constexpr (HasExactDifference<T>) {
    assign_difference(edge_dirs_[e], vertex(h1.origin), vertex(h0.origin));
  } else {
    edge_dirs_[e] = Vec3<T>(vertex(h1.origin) - vertex(h0.origin));
  }
}

namespace detail {

/// The first steps of plane_of_triple on three points (float or double):
/// p0 (a), e1 = p1 - p0 (u), e2 = p2 - p0 (w), c = e1 x e2 and s = c.c
/// summed left to right, each operation as plane_of_triple does it.
template <class T>
struct TripleCross {
  T a0, a1, a2;
  T u0, u1, u2;
  T w0, w1, w2;
  T c0, c1, c2;
  T s;
};

template <class T>
[[gnu::always_inline]] inline TripleCross<T> triple_cross(const T* p0, const T* p1, const T* p2) {
  TripleCross<T> r;
  r.a0 = p0[0], r.a1 = p0[1], r.a2 = p0[2];
  r.u0 = p1[0] - r.a0, r.u1 = p1[1] - r.a1, r.u2 = p1[2] - r.a2;
  r.w0 = p2[0] - r.a0, r.w1 = p2[1] - r.a1, r.w2 = p2[2] - r.a2;
  r.c0 = r.u1 * r.w2 - r.u2 * r.w1, r.c1 = r.u2 * r.w0 - r.u0 * r.w2, r.c2 = r.u0 * r.w1 - r.u1 * r.w0;
  T s = r.c0 * r.c0;
  s = s + r.c1 * r.c1;
  s = s + r.c2 * r.c2;
  r.s = s;
  return r;
}

/// The last steps of plane_of_triple: the normal n / sqrt(s) (n unchanged
/// where sqrt(s) is 0), s = n.n, and the offset dot(normal, a) left to
/// right.
template <class T>
[[gnu::always_inline]] inline Plane<T> unit_plane(T n0, T n1, T n2, T s, T a0, T a1, T a2) {
  const T len = std::sqrt(s);
  if (len > T(0)) n0 = n0 / len, n1 = n1 / len, n2 = n2 / len;
  T off = n0 * a0;
  off = off + n1 * a1;
  off = off + n2 * a2;
  return Plane<T>{Vec3<T>(n0, n1, n2), off};
}

}  // namespace detail

// The plane of face f through its plane triple (v0, v1, v2), with scan (if
// not null) given the face's term of normal_conditioning().  The values of
// plane_through(v0, v1, v2) and of NormalConditioningScan::add(e1, e2, c),
// bit for bit: e1 = v1 - v0, e2 = v2 - v0, c = cross(e1, e2), the normal
// c / sqrt(c.c) (scaled_cross's rescaled c where c.c leaves the safe range),
// the offset dot(n, v0), every dot product left to right as dot() evaluates
// it.  Float/double on scalars (the Vec3 expressions cost a third more here,
// the hottest loop of posing); other T through plane_through_cross.  Every
// plane a ConvexPolyhedron stores is computed here (compute_planes,
// derive_rigid_part); its scalar steps are detail::triple_cross and
// detail::unit_plane, which code deriving a plane from three posed points
// outside a ConvexPolyhedron calls too.  Inlined into its loops (as a call
// it cost a fifth more per face).
template <Number T>
[[gnu::always_inline]] inline Plane<T> ConvexPolyhedron<T>::plane_of_triple(
    int f, NormalConditioningScan* scan) const {
  const auto& t = topology_.faces()[static_cast<std::size_t>(f)].plane_vertices;
  if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
    const detail::TripleCross<T> x =
        detail::triple_cross(vertex(t[0]).data(), vertex(t[1]).data(), vertex(t[2]).data());
    T n0 = x.c0, n1 = x.c1, n2 = x.c2;
    T s = x.s;
    if (!detail::safe_squared_norm(s)) [[unlikely]] {
      const Vec3<T> n =
          scaled_cross(Vec3<T>(x.u0, x.u1, x.u2), Vec3<T>(x.w0, x.w1, x.w2), Vec3<T>(x.c0, x.c1, x.c2));
      n0 = n[0], n1 = n[1], n2 = n[2];
      s = n0 * n0;
      s = s + n1 * n1;
      s = s + n2 * n2;
    }
    if (scan != nullptr) {
      auto sq = [](double x0, double x1, double x2) { return x0 * x0 + x1 * x1 + x2 * x2; };
      scan->add_squares(sq(x.u0, x.u1, x.u2), sq(x.w0, x.w1, x.w2), sq(x.c0, x.c1, x.c2));
    }
    return detail::unit_plane(n0, n1, n2, s, x.a0, x.a1, x.a2);
  } else {
    (void)scan;
    return plane_through(vertex(t[0]), vertex(t[1]), vertex(t[2]));
  }
}

template <Number T>
inline void ConvexPolyhedron<T>::derive_plane(int f, NormalConditioningScan* scan) {
  const auto k = static_cast<std::size_t>(f);
  if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
    planes_[k] = plane_of_triple(f, scan);
  } else {  // into the plane's numbers (plane_of_triple's values)
    (void)scan;
    const auto& t = topology_.faces()[k].plane_vertices;
    assign_plane_through(planes_[k], vertex(t[0]), vertex(t[1]), vertex(t[2]));
  }
}

// From the vertices alone: bounds, centroid, extent, max |coordinate|.
template <Number T>
inline void ConvexPolyhedron<T>::compute_bounds() {
  Vec3<T> sum(T(0), T(0), T(0));
  bmin_ = bmax_ = vertices_.empty() ? sum : vertices_[0];
  for (const auto& v : vertices_) {
    for (int c = 0; c < 3; ++c) {
      sum[c] += v[c];  // in place: no new number for exact T (the same sum)
      if (v[c] < bmin_[c]) bmin_[c] = v[c];
      if (v[c] > bmax_[c]) bmax_[c] = v[c];
    }
  }
  finish_bounds(sum);
}

// compute_bounds() after its pass over the vertices: bmin_, bmax_ are set
// and sum is the sequential sum of the vertices (from zero, in index order).
template <Number T>
[[gnu::always_inline]] inline void ConvexPolyhedron<T>::finish_bounds(const Vec3<T>& sum) {
  const T n = from_double<T>(static_cast<double>(vertices_.size()));  // exact for any count < 2^53
  if (!vertices_.empty()) centroid_ = Vec3<T>(sum[0] / n, sum[1] / n, sum[2] / n);
  // per coordinate in order, written out (a loop over the coordinates was not
  // unrolled): the widths, d2 = w0^2 + w1^2 + w2^2 left to right, the
  // largest |bound|
  max_abs_ = 0;
  auto width = [&](int c) {
    max_abs_ = std::max({max_abs_, std::abs(to_double(bmin_[c])), std::abs(to_double(bmax_[c]))});
    return to_double(T(bmax_[c] - bmin_[c]));
  };
  const std::array<double, 3> w{width(0), width(1), width(2)};
  double d2 = w[0] * w[0];
  d2 += w[1] * w[1];
  d2 += w[2] * w[2];
  extent_ = std::sqrt(d2);
  if (!detail::safe_squared_norm(d2)) {
    // Widths beyond about 1e+-154 (double T): the same diagonal through
    // widths scaled by a power of two (bit for bit the unscaled value where
    // that does not overflow or underflow).  Stays infinite if a width is.
    const double m = std::max({w[0], w[1], w[2]});
    if (m > 0 && m <= std::numeric_limits<double>::max()) {
      const int e = std::ilogb(m);
      double s2 = 0;
      for (const double wc : w) s2 += std::ldexp(wc, -e) * std::ldexp(wc, -e);
      extent_ = std::ldexp(std::sqrt(s2), e);
    }
  }
  if constexpr (std::is_floating_point_v<T>) {
    // The vertex sum overflows long before the coordinates do (n vertices
    // near max/n): then the centroid is the sum of the vertices scaled by a
    // power of two, divided by n and scaled back -- bit for bit the plain
    // formula's value wherever that one does not overflow.
    if (!vertices_.empty() && !(sum.cwiseAbs().maxCoeff() <= std::numeric_limits<T>::max())) {
      const int e = detail::pow2_exponent(static_cast<T>(max_abs_));
      Vec3<T> s(T(0), T(0), T(0));
      for (const auto& v : vertices_) s = Vec3<T>(s + detail::scale_pow2(v, e));
      centroid_ = detail::scale_pow2(Vec3<T>(s[0] / n, s[1] / n, s[2] / n), -e);
    }
  }
}

// ρ_P of normal_conditioning(), for the robust kernel's δ_P (derivation in
// robust/error_bounds.hpp, unit_error_from_ratio: δ_f = γ_4 + 2q/(|Ñ| - q) with
// q/|Ñ| = γ_4 √2 ρ_f/(1-u)^2 per face, so the worst face is the one with the
// largest ρ_f = |ẽ1||ẽ2|/|Ñ|).  ẽ1 = fl(v_j - v_i), ẽ2 = fl(v_k - v_i),
// Ñ = fl(ẽ1 x ẽ2) in T, as plane_through computes them (see there for the
// range where it rescales).  The bound only uses |Ñ| to bound the exact |N|
// from below (|N| >= |Ñ| - q), so any evaluation of the cross product with
// |Ñ - N| <= q will do, contracted or not.  "Tiny": |Ñ|^2 <=
// kNormalTinySquared = 2^40 min(T) (normalisation underflow; the kernel's
// margin covers what remains above it, see robust_kernel.hpp).  The back
// face of a flat shape is skipped: its normal is exactly the front one
// negated (compute_derived) and its exact N is -N_front, so its δ is the
// front face's.  This is the loop RobustKernel ran over every face of both
// shapes on every query (normal_error) until it moved here.
template <Number T>
inline double ConvexPolyhedron<T>::compute_normal_conditioning() const {
  if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
    NormalConditioningScan scan;
    const int nf = is_flat() ? 1 : face_count();
    for (int f = 0; f < nf; ++f) {
      const auto& t = face(f).plane_vertices;
      const Vec3<T>& v0 = vertex(t[0]);
      const Vec3<T> e1(vertex(t[1]) - v0), e2(vertex(t[2]) - v0);
      scan.add(e1, e2, Vec3<T>(cross(e1, e2)));
    }
    return scan.result();
  } else {
    return std::numeric_limits<double>::infinity();
  }
}

// The scan of compute_normal_conditioning() over the plane triples (v0, v1,
// v2), one face at a time, given ẽ1 = fl(v1 - v0), ẽ2 = fl(v2 - v0) and
// Ñ = fl(ẽ1 x ẽ2) in T (cross()); their squares in double.
template <Number T>
struct ConvexPolyhedron<T>::NormalConditioningScan {
  // float: the maximum of r2 = |ẽ1|^2 |ẽ2|^2 / |Ñ|^2 without a division or
  // a finiteness test per face: the maximum fraction num/den is tracked by
  // cross multiplication.  Every factor is a double square of a float
  // (<= 3 * 2^256), so num * den < 2^1024 cannot overflow; an infinite or
  // NaN difference or cross product, or a tiny |Ñ|, sets `bad`.  The one
  // division and sqrt at the end round once each (relative 2^-53, inside
  // the kernel's margin).
  // double: the squares can overflow, so one ratio per face, infinite when
  // not finite (never NaN, which a maximum would skip).
  double wnum = 0, wden = 1, worst = 0;
  bool bad = false;

  void add(const Vec3<T>& e1, const Vec3<T>& e2, const Vec3<T>& n) {
    auto sq = [](const Vec3<T>& v) {
      const double x = v[0], y = v[1], z = v[2];
      return x * x + y * y + z * z;
    };
    add_squares(sq(e1), sq(e2), sq(n));
  }
  // add() given |ẽ1|^2, |ẽ2|^2 and |Ñ|^2 in double (x*x + y*y + z*z).
  void add_squares(double e1sq, double e2sq, double nc2) {
    if constexpr (std::is_same_v<T, float>) {
      const double num = e1sq * e2sq;
      bad |= !(nc2 > kNormalTinySquared && nc2 <= std::numeric_limits<double>::max() &&
               num <= std::numeric_limits<double>::max());
      add_ratio(num, nc2);
    } else {
      double r2 = std::numeric_limits<double>::infinity();
      if (nc2 > kNormalTinySquared && std::isfinite(nc2)) {
        r2 = e1sq / nc2 * e2sq;
        if (!std::isfinite(r2)) r2 = std::numeric_limits<double>::infinity();
      }
      if (r2 > worst) worst = r2;
    }
  }
  // float: the running maximum's step for num = |ẽ1|^2 |ẽ2|^2 over nc2
  // (add_squares after its test of `bad`).
  void add_ratio(double num, double nc2) {
    const bool larger = num * wden > wnum * nc2;
    wnum = larger ? num : wnum;
    wden = larger ? nc2 : wden;
  }
  double result() const {
    if constexpr (std::is_same_v<T, float>) {
      if (bad) return std::numeric_limits<double>::infinity();
      return std::sqrt(wnum / wden);
    } else {
      return std::sqrt(worst);
    }
  }
};

// The lane arrays from the per-edge arrays and the vertices, each value
// written once (only the padding is zeroed).  lanes_bounded_: every lane
// value and every plane normal has |x| <= 2^60 (false for NaN).  The edge
// normal lanes are copies (or negations) of plane normals and the padding
// is zero, so that is: every plane normal, edge direction and vertex
// coordinate; tested without a branch per value.
template <Number T>
inline void ConvexPolyhedron<T>::compute_lanes() {
  lane_edge_stride_ = lane_vertex_stride_ = 0;
  lanes_bounded_ = support_lanes_bounded_ = false;
  if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
    size_lanes();
    const auto vs = static_cast<std::size_t>(lane_vertex_stride_);
    const auto nv = static_cast<std::size_t>(vertex_count());
    bool ok = write_edge_lanes();
    const T big = T(0x1p60);
    T* const lv = lanes_.data() + 9 * static_cast<std::size_t>(lane_edge_stride_);
    for (std::size_t v = 0; v < nv; ++v) {
      for (std::size_t c = 0; c < 3; ++c) {
        const T x = vertices_[v][static_cast<int>(c)];
        lv[c * vs + v] = x;
        ok &= std::abs(x) <= big;
      }
    }
    for (std::size_t c = 0; c < 3; ++c) std::fill(lv + c * vs + nv, lv + (c + 1) * vs, T(0));
    for (const auto& pl : planes_) {
      for (int c = 0; c < 3; ++c) ok &= std::abs(pl.normal[c]) <= big;
    }
    lanes_bounded_ = support_lanes_bounded_ = ok;
  } else {
    lanes_.clear();
  }
}

// Float/double: the lane strides for the current counts, and lanes_ sized
// for them (9 edge arrays, then 3 vertex arrays; values not written).
template <Number T>
inline void ConvexPolyhedron<T>::size_lanes() {
  auto padded = [](int n) { return (n + kLanePad - 1) / kLanePad * kLanePad; };
  lane_edge_stride_ = padded(edge_count());
  lane_vertex_stride_ = padded(vertex_count());
  lanes_.resize(9 * static_cast<std::size_t>(lane_edge_stride_) +
                3 * static_cast<std::size_t>(lane_vertex_stride_));
}

// Float/double, lanes_ sized (size_lanes): the 9 edge lane arrays from the
// per-edge arrays, the padding zeroed.  Returns whether every edge
// direction component has |x| <= 2^60 (false for NaN).
template <Number T>
inline bool ConvexPolyhedron<T>::write_edge_lanes() {
  const auto es = static_cast<std::size_t>(lane_edge_stride_);
  const auto ne = static_cast<std::size_t>(edge_count());
  T* const l = lanes_.data();
  const T big = T(0x1p60);
  bool ok = true;
  for (std::size_t e = 0; e < ne; ++e) {
    const Vec3<T>& n0 = edge_normal(static_cast<int>(e), 0);
    const Vec3<T>& n1 = edge_normal(static_cast<int>(e), 1);
    const Vec3<T>& d = edge_dirs_[e];
    for (std::size_t c = 0; c < 3; ++c) {
      l[c * es + e] = n0[static_cast<int>(c)];
      l[(3 + c) * es + e] = T(-n1[static_cast<int>(c)]);
      l[(6 + c) * es + e] = d[static_cast<int>(c)];
      ok &= std::abs(d[static_cast<int>(c)]) <= big;
    }
  }
  for (std::size_t k = 0; k < 9; ++k) std::fill(l + k * es + ne, l + (k + 1) * es, T(0));
  return ok;
}

// Signed distance-like value of p above plane f: exact N.(p - v_i) for exact
// T; the Euclidean signed distance for normalising T.
template <Number T>
inline T ConvexPolyhedron<T>::height(int f, const Vec3<T>& p) const {
  const auto& pl = plane(f);
  return T(dot(pl.normal, p) - pl.offset);
}

// Tolerance in height() units for a relative tolerance rel.
template <Number T>
inline T ConvexPolyhedron<T>::height_tolerance(double rel) const {
  if constexpr (number_traits<T>::is_exact) {
    (void)rel;
    return T(0);
  } else {
    return static_cast<T>(rel * extent_);
  }
}

}  // namespace sepax
