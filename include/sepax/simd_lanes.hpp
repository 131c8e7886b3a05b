// sepax/simd_lanes.hpp
//
// The two hot loops of the Gauss-map SAT over the lane arrays of
// ConvexPolyhedron (one array per coordinate), a few edges or vertices at a
// time with baseline SSE2 (4 floats or 2 doubles per instruction; no
// -march=native, no -ffast-math); without SSE2, or with SEPAX_NO_SIMD, one
// lane at a time.  Every lane computes bit for bit what the scalar code does
// (Lanes, simd_ops.hpp: the operations and the contraction caveat).
//   arc_candidates  the Minkowski-face (arc crossing) test of one edge of A
//                   against a range of edges of B (exact plain decisions, or
//                   the pairs a filter does not certainly reject);
//   support_scan    argmin over a shape's vertices of n.v, with the minimum
//                   (and the second smallest value for the robust filter).
// Both need ConvexPolyhedron::lanes_bounded() of the shapes they read (no
// value can overflow, none is NaN); callers check it once per query and use
// their scalar code otherwise.
#pragma once

#include <bit>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "convex_polyhedron.hpp"
#include "simd_ops.hpp"

namespace sepax::simd {

/// Minkowski-face test of edge ea of A against the edges eb in [lo, hi) of B
/// (lo a multiple of the lane width, e.g. of kMinkowskiBatch).  Writes the accepted eb to
/// out in increasing order and returns their number (out needs hi - lo
/// entries).  With, per pair, the four values PlainKernel::arc_signs signs
///   c = n_B0(eb).d_A(ea)   d = n_B1(eb).d_A(ea)   a = n_A0(ea).d_B(eb)   b = n_A1(ea).d_B(eb)
/// (n_P0, n_P1 the normals of the edge's faces on sides 0 and 1, d_P its
/// direction), the arcs cross iff sign(c) = sign(a) = -sign(d) = -sign(b) != 0
/// (ArcSigns::minkowski_face with cba = sign c, dba = sign d, adc = -sign a,
/// bdc = -sign b: cba*dba < 0, adc*bdc < 0 and cba*bdc > 0).  The lanes
/// compute d' = (-n_B1).d_A = -d and b' = (-n_A1).d_B = -b (negation is exact
/// and commutes with rounding), so the test is: all four of c, a, d', b'
/// positive, or all four negative.  Needs lanes_bounded() of A and B (no NaN).
///  * kFilter = false: accept iff min(c, a, d', b') > 0 or max(...) < 0:
///    exactly the scalar decision on these values (zeros reject).
///  * kFilter = true, with `bound` >= the error bound of each of the four
///    values (beyond it a value's sign is certain): accept unless each pattern
///    has a value certainly of the wrong sign, i.e. unless min < -bound and
///    max > bound.  A superset of the pairs the exact test accepts, written
///    as eb like the exact ones.  *uncertain is set to whether some accepted
///    pair is not certainly crossing (neither min > bound: all four certainly
///    positive, nor max < -bound: all certainly negative), i.e. has a value
///    within the bound: only then does the caller need its exact test, on
///    the accepted pairs (uncertain must not be null).  The flag is ORed
///    over the groups with an accepted lane only, inside the jump that skips
///    the other groups' emit (no extra jump, no per-pair code); padding lanes
///    are left out.
template <bool kFilter, class T>
SEPAX_SIMD_INLINE inline int arc_candidates(const ConvexPolyhedron<T>& b, int lo, int hi, const Vec3<T>& da,
                                            const Vec3<T>& na0, const Vec3<T>& na1, T bound, int* out,
                                            bool* uncertain = nullptr) {
  using L = Lanes<T>;
  using V = typename L::V;
  constexpr int W = L::width;
  const T* n0x = b.lane_edge(0);
  const T* n0y = b.lane_edge(1);
  const T* n0z = b.lane_edge(2);
  const T* n1x = b.lane_edge(3);  // -n_B1
  const T* n1y = b.lane_edge(4);
  const T* n1z = b.lane_edge(5);
  const T* dx = b.lane_edge(6);
  const T* dy = b.lane_edge(7);
  const T* dz = b.lane_edge(8);
  const V ax = L::set1(da[0]), ay = L::set1(da[1]), az = L::set1(da[2]);
  const V p0x = L::set1(na0[0]), p0y = L::set1(na0[1]), p0z = L::set1(na0[2]);
  const V p1x = L::set1(T(-na1[0])), p1y = L::set1(T(-na1[1])), p1z = L::set1(T(-na1[2]));
  const V lo_lim = L::set1(kFilter ? T(-bound) : T(0));
  const V hi_lim = L::set1(kFilter ? bound : T(0));
  // one group of W pairs: the accepted lanes among `live` as bits.  kFilter:
  // the accepted lanes that are not certain are added to `unc`; computed only
  // for a group with some accepted lane (the jump is the one that skips the
  // group's emit: most groups have none, and then cost what the plain test
  // costs).
  unsigned unc = 0;
  auto group = [&](std::size_t i, [[maybe_unused]] unsigned live) SEPAX_SIMD_INLINE {
    const V c = dot3<L>(L::load(n0x + i), L::load(n0y + i), L::load(n0z + i), ax, ay, az);
    const V d = dot3<L>(L::load(n1x + i), L::load(n1y + i), L::load(n1z + i), ax, ay, az);
    const V a = dot3<L>(L::load(dx + i), L::load(dy + i), L::load(dz + i), p0x, p0y, p0z);
    const V e = dot3<L>(L::load(dx + i), L::load(dy + i), L::load(dz + i), p1x, p1y, p1z);
    const V mn = L::min_lt(L::min_lt(c, a), L::min_lt(d, e));
    const V mx = L::max_gt(L::max_gt(c, a), L::max_gt(d, e));
    if constexpr (!kFilter) {
      return L::bits(L::mor(L::gt(mn, lo_lim), L::lt(mx, hi_lim)));
    } else {
      // not (min < -bound and max > bound), i.e. min >= -bound or max <=
      // bound: no value is NaN (lanes_bounded, the precondition), so the
      // negation is exact and costs what the plain test costs.
      const unsigned bits = L::bits(L::mor(L::ge(mn, lo_lim), L::le(mx, hi_lim))) & live;
      // certain: min > bound or max < -bound
      if (bits != 0) unc |= bits & ~L::bits(L::mor(L::gt(mn, hi_lim), L::lt(mx, lo_lim)));
      return bits;
    }
  };
  int n = 0;
  auto emit = [&](unsigned m, int g) SEPAX_SIMD_INLINE {
    while (m != 0) {
      out[n++] = g + std::countr_zero(m);
      m &= m - 1;
    }
  };
  constexpr unsigned kAll = (1u << W) - 1u;
  const int full = lo + (hi - lo) / W * W;
  for (int g = lo; g < full; g += W) {
    const unsigned m = group(static_cast<std::size_t>(g), kAll);
    if (m != 0) emit(m, g);
  }
  if (full < hi) {  // the last, partial group: padding lanes masked out
    const unsigned live = (1u << (hi - full)) - 1u;
    emit(group(static_cast<std::size_t>(full), live) & live, full);
  }
  if constexpr (kFilter) *uncertain = unc != 0;
  return n;
}

/// Result of support_scan.
template <class T>
struct Support {
  int index = 0;    // kIndex: lowest index among the minima of n.v (else 0)
  T min = T(0);     // n.v at index
  T second = T(0);  // kSecond: the smallest n.v over the other vertices (+inf if none)
};

/// argmin over the vertices v of q of dot(n, v), the lowest index among equal
/// minima: the vertex PlainKernel's scalar loop `if (h < best) best = h`
/// selects.  kSecond also keeps the smallest value over the other vertices
/// (equal to min when the minimum is attained twice).  kIndex = false keeps
/// the minimum alone (index is 0; not with kSecond): the same minimum, fewer
/// operations per group.  Per lane: the smallest value, the first index
/// attaining it, and the second smallest value; the lanes are merged at the
/// end.  Needs support_lanes_bounded() of q and a finite n with |n_i| <= 2^60 (no
/// NaN); vertex counts up to 2^24 (indices are kept exactly as T).
template <bool kSecond, bool kIndex = true, class T>
SEPAX_SIMD_INLINE inline Support<T> support_scan(const ConvexPolyhedron<T>& q, const Vec3<T>& n) {
  static_assert(kIndex || !kSecond, "the second minimum needs the argmin's lane");
  using L = Lanes<T>;
  using V = typename L::V;
  using M = typename L::M;
  constexpr int W = L::width;
  const int nv = q.vertex_count();
  const T* x = q.lane_vertex(0);
  const T* y = q.lane_vertex(1);
  const T* z = q.lane_vertex(2);
  const V nx = L::set1(n[0]), ny = L::set1(n[1]), nz = L::set1(n[2]);
  const V inf = L::set1(std::numeric_limits<T>::infinity());
  V m1 = inf, m2 = inf;
  V idx = L::set1(T(0));
  V cur = L::iota(T(0));
  const V step = L::set1(T(W));
  auto visit = [&](V h) SEPAX_SIMD_INLINE {
    if constexpr (!kIndex) {
      m1 = L::min_lt(h, m1);
    } else {
      const M lt = L::lt(h, m1);
      // the larger of (h, m1), if below m2.  min_lt(m2, t) rather than
      // min_lt(t, m2): the same value (no NaN; on equal values the two differ
      // at most in the sign of a zero, which no caller can see: it only
      // subtracts and compares), and minps can then write m2's register in
      // place (one register copy less per group).
      if constexpr (kSecond) m2 = L::min_lt(m2, L::max_gt(h, m1));
      idx = L::select(lt, cur, idx);
      m1 = L::min_lt(h, m1);
      cur = L::add(cur, step);
    }
  };
  const int full = nv / W * W;
  for (int g = 0; g < full; g += W) {
    const auto i = static_cast<std::size_t>(g);
    visit(dot3<L>(L::load(x + i), L::load(y + i), L::load(z + i), nx, ny, nz));
  }
  if (full < nv) {  // the last, partial group: padding lanes become +inf
    const auto i = static_cast<std::size_t>(full);
    const V h = dot3<L>(L::load(x + i), L::load(y + i), L::load(z + i), nx, ny, nz);
    // !kIndex: cur is not advanced by visit; these lanes' indices are full + j
    const V at = kIndex ? cur : L::iota(static_cast<T>(full));
    visit(L::select(L::lt(at, L::set1(static_cast<T>(nv))), h, inf));
  }
  // merge the lanes: the minimum, then the lowest index among the lanes holding it
  Support<T> r;
  const V mn = L::hmin(m1);
  if constexpr (!kIndex) {
    r.min = L::first(mn);
    return r;
  }
  const M at_min = L::eq(m1, mn);
  const V best = L::hmin(L::select(at_min, idx, inf));
  r.min = L::first(mn);
  r.index = static_cast<int>(L::first(best));
  if (r.min == std::numeric_limits<T>::infinity())
    r.index = 0;  // every value +inf (never with bounded lanes)
  if constexpr (kSecond) {
    // the best lane contributes its second value, every other lane its first
    const M best_lane = L::mand(at_min, L::eq(idx, best));
    r.second = L::first(L::hmin(L::select(best_lane, m2, m1)));
  }
  return r;
}

}  // namespace sepax::simd
