// sepax/simd_ops.hpp
//
// Lane operations for the SIMD loops (simd_lanes.hpp, the plane pass of
// convex_polyhedron_derived.hpp): Lanes<T> holds 4 floats or 2 doubles with
// baseline SSE2 (no -march=native, no -ffast-math), one value otherwise
// (no SSE2, or SEPAX_NO_SIMD).  Every operation is the IEEE operation of the
// scalar code, correctly rounded per lane (sqrt and division included), so a
// lane computes bit for bit what the scalar expression does; dot3 keeps
// dot()'s order.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#if defined(__SSE2__) && !defined(SEPAX_NO_SIMD)
#include <emmintrin.h>
#define SEPAX_SIMD_SSE2 1
#endif

/// Inline the per-group bodies into their loops (GCC otherwise outlines a
/// lambda called from two places).
#if defined(__GNUC__) || defined(__clang__)
#define SEPAX_SIMD_INLINE __attribute__((always_inline))
#else
#define SEPAX_SIMD_INLINE
#endif

namespace sepax::simd {

/// f(0), f(1), ..., f(N - 1), written out (GCC leaves short loops whose
/// bodies store to arrays rolled).
template <int N, class F>
SEPAX_SIMD_INLINE inline void unrolled(F&& f) {
  [&]<int... I>(std::integer_sequence<int, I...>) SEPAX_SIMD_INLINE { (f(I), ...); }
  (std::make_integer_sequence<int, N>{});
}

/// Lane operations: V holds `width` values of T, M a per-lane mask.
///
/// Every lane evaluates exactly the operation sequence of the scalar code it
/// replaces -- dot(a, b) = (a0*b0 + a1*b1) + a2*b2, left to right, in T -- so
/// the values are bit-identical to PlainKernel's (IEEE operations are the
/// same in a vector lane).  Under FMA contraction (-march=native
/// -ffp-contract=fast) the compiler may fuse differently here and in the scalar
/// code: plain float/double decisions may then differ between the two paths
/// on inputs within rounding of a tie, as plain float decisions already differ
/// between builds.  The robust kernel only uses these values in filters whose
/// bounds hold with and without contraction.
///
template <class T>
struct Lanes {  // portable fallback: one lane
  using V = T;
  using M = bool;
  static constexpr int width = 1;
  static V load(const T* p) { return *p; }
  static V set1(T x) { return x; }
  static V iota(T base) { return base; }
  static void store(T* p, V v) { *p = v; }
  /// p[3i], p[3i + 1], p[3i + 2] = lane i of x, y, z: `width` points
  /// interleaved (an array of Vec3<T>), copies of the lanes' values.
  static void store_xyz(T* p, V x, V y, V z) { p[0] = x, p[1] = y, p[2] = z; }
  /// Lane i of x, y, z = p[i][0], p[i][1], p[i][2]: `width` points of three
  /// contiguous T each (a Vec3<T>), nothing read beyond them.
  static void load_xyz(const T* const* p, V& x, V& y, V& z) { x = p[0][0], y = p[0][1], z = p[0][2]; }
  /// p[4i], ..., p[4i + 3] = lane i of a, b, c, d: `width` records of four T
  /// (a Plane<T>: normal, offset), copies of the lanes' values.
  static void store_abcd(T* p, V a, V b, V c, V d) { p[0] = a, p[1] = b, p[2] = c, p[3] = d; }
  static V add(V a, V b) { return a + b; }
  static V sub(V a, V b) { return a - b; }
  static V mul(V a, V b) { return a * b; }
  static V div(V a, V b) { return a / b; }
  static V sqrt(V a) { return std::sqrt(a); }
  static V abs(V a) { return std::abs(a); }
  static V neg(V a) { return -a; }
  static M lt(V a, V b) { return a < b; }
  static M gt(V a, V b) { return a > b; }
  static M ge(V a, V b) { return a >= b; }
  static M le(V a, V b) { return a <= b; }
  static M mand(M a, M b) { return a && b; }
  static M mor(M a, M b) { return a || b; }
  static V select(M m, V a, V b) { return m ? a : b; }
  static V min_lt(V h, V m) { return h < m ? h : m; }  // h if h < m, else m
  static V max_gt(V h, V m) { return h > m ? h : m; }  // h if h > m, else m
  static M eq(V a, V b) { return a == b; }
  static V hmin(V v) { return v; }  // the minimum over the lanes, in every lane
  static V hmax(V v) { return v; }  // the maximum over the lanes, in every lane
  static unsigned bits(M m) { return m ? 1u : 0u; }
  static T first(V v) { return v; }
};

#if defined(SEPAX_SIMD_SSE2)
template <>
struct Lanes<float> {
  using V = __m128;
  using M = __m128;
  static constexpr int width = 4;
  static V load(const float* p) { return _mm_loadu_ps(p); }
  static V set1(float x) { return _mm_set1_ps(x); }
  static V iota(float base) { return _mm_setr_ps(base, base + 1.0f, base + 2.0f, base + 3.0f); }
  static void store(float* p, V v) { _mm_storeu_ps(p, v); }
  // (x0 y0 z0 x1) (y1 z1 x2 y2) (z2 x3 y3 z3) from two unpacks and six shuffles
  static void store_xyz(float* p, V x, V y, V z) {
    const V lo = _mm_unpacklo_ps(x, y);                                       // x0 y0 x1 y1
    const V hi = _mm_unpackhi_ps(x, y);                                       // x2 y2 x3 y3
    const V zx = _mm_shuffle_ps(z, lo, _MM_SHUFFLE(2, 2, 0, 0));              // z0 z0 x1 x1
    const V yz = _mm_shuffle_ps(lo, z, _MM_SHUFFLE(1, 1, 3, 3));              // y1 y1 z1 z1
    const V zx3 = _mm_shuffle_ps(z, hi, _MM_SHUFFLE(2, 2, 2, 2));             // z2 z2 x3 x3
    const V yz3 = _mm_shuffle_ps(hi, z, _MM_SHUFFLE(3, 3, 3, 3));             // y3 y3 z3 z3
    _mm_storeu_ps(p, _mm_shuffle_ps(lo, zx, _MM_SHUFFLE(2, 0, 1, 0)));        // x0 y0 z0 x1
    _mm_storeu_ps(p + 4, _mm_shuffle_ps(yz, hi, _MM_SHUFFLE(1, 0, 2, 0)));    // y1 z1 x2 y2
    _mm_storeu_ps(p + 8, _mm_shuffle_ps(zx3, yz3, _MM_SHUFFLE(2, 0, 2, 0)));  // z2 x3 y3 z3
  }
  // x and y from one 8-byte load per point, z from one 4-byte load each
  static void load_xyz(const float* const* p, V& x, V& y, V& z) {
    auto xy = [](const float* q) {  // q[0] q[1] 0 0 (through memcpy: no float read as double)
      double d;
      std::memcpy(&d, q, sizeof d);
      return _mm_castpd_ps(_mm_set_sd(d));
    };
    const V a = _mm_unpacklo_ps(xy(p[0]), xy(p[1]));                             // x0 x1 y0 y1
    const V b = _mm_unpacklo_ps(xy(p[2]), xy(p[3]));                             // x2 x3 y2 y3
    x = _mm_movelh_ps(a, b);                                                     // x0 x1 x2 x3
    y = _mm_movehl_ps(b, a);                                                     // y0 y1 y2 y3
    const V za = _mm_unpacklo_ps(_mm_load_ss(p[0] + 2), _mm_load_ss(p[1] + 2));  // z0 z1 0 0
    const V zb = _mm_unpacklo_ps(_mm_load_ss(p[2] + 2), _mm_load_ss(p[3] + 2));  // z2 z3 0 0
    z = _mm_movelh_ps(za, zb);
  }
  // the 4x4 transpose: record i is lane i of a, b, c, d
  static void store_abcd(float* p, V a, V b, V c, V d) {
    const V ab0 = _mm_unpacklo_ps(a, b);  // a0 b0 a1 b1
    const V ab1 = _mm_unpackhi_ps(a, b);  // a2 b2 a3 b3
    const V cd0 = _mm_unpacklo_ps(c, d);  // c0 d0 c1 d1
    const V cd1 = _mm_unpackhi_ps(c, d);  // c2 d2 c3 d3
    _mm_storeu_ps(p, _mm_movelh_ps(ab0, cd0));
    _mm_storeu_ps(p + 4, _mm_movehl_ps(cd0, ab0));
    _mm_storeu_ps(p + 8, _mm_movelh_ps(ab1, cd1));
    _mm_storeu_ps(p + 12, _mm_movehl_ps(cd1, ab1));
  }
  static V add(V a, V b) { return _mm_add_ps(a, b); }
  static V sub(V a, V b) { return _mm_sub_ps(a, b); }
  static V mul(V a, V b) { return _mm_mul_ps(a, b); }
  static V div(V a, V b) { return _mm_div_ps(a, b); }
  static V sqrt(V a) { return _mm_sqrt_ps(a); }
  static V abs(V a) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), a); }  // the sign bit cleared
  static V neg(V a) { return _mm_xor_ps(_mm_set1_ps(-0.0f), a); }     // the sign bit flipped (as -x)
  static M lt(V a, V b) { return _mm_cmplt_ps(a, b); }
  static M gt(V a, V b) { return _mm_cmpgt_ps(a, b); }
  static M ge(V a, V b) { return _mm_cmpge_ps(a, b); }
  static M le(V a, V b) { return _mm_cmple_ps(a, b); }
  static M mand(M a, M b) { return _mm_and_ps(a, b); }
  static M mor(M a, M b) { return _mm_or_ps(a, b); }
  static V select(M m, V a, V b) { return _mm_or_ps(_mm_and_ps(m, a), _mm_andnot_ps(m, b)); }
  // minps(a, b) = a < b ? a : b and maxps(a, b) = a > b ? a : b, per lane
  static V min_lt(V h, V m) { return _mm_min_ps(h, m); }
  static V max_gt(V h, V m) { return _mm_max_ps(h, m); }
  static M eq(V a, V b) { return _mm_cmpeq_ps(a, b); }
  static V hmin(V v) {  // no NaN: min over the lanes, in every lane
    v = _mm_min_ps(v, _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm_min_ps(v, _mm_shuffle_ps(v, v, _MM_SHUFFLE(1, 0, 3, 2)));
  }
  static V hmax(V v) {  // no NaN: max over the lanes, in every lane
    v = _mm_max_ps(v, _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm_max_ps(v, _mm_shuffle_ps(v, v, _MM_SHUFFLE(1, 0, 3, 2)));
  }
  /// Lane c of s (c < 3) += coordinate c of the points (x_i, y_i, z_i),
  /// i = 0 ... 3 in turn: per lane the scalar additions s_c + p_i[c] in index
  /// order (lane 3 adds zeros).
  static void add_points(V& s, V x, V y, V z) {
    const V z0 = _mm_setzero_ps();
    const V xy0 = _mm_unpacklo_ps(x, y);   // x0 y0 x1 y1
    const V xy1 = _mm_unpackhi_ps(x, y);   // x2 y2 x3 y3
    const V zz0 = _mm_unpacklo_ps(z, z0);  // z0 0 z1 0
    const V zz1 = _mm_unpackhi_ps(z, z0);  // z2 0 z3 0
    s = _mm_add_ps(s, _mm_movelh_ps(xy0, zz0));
    s = _mm_add_ps(s, _mm_movehl_ps(zz0, xy0));
    s = _mm_add_ps(s, _mm_movelh_ps(xy1, zz1));
    s = _mm_add_ps(s, _mm_movehl_ps(zz1, xy1));
  }
  static unsigned bits(M m) { return static_cast<unsigned>(_mm_movemask_ps(m)); }
  static float first(V v) { return _mm_cvtss_f32(v); }
  /// The rows of the column-major 3x3 matrix at m (9 floats, none read
  /// beyond): lane i of row k is m[k + 3 i], lane 3 zero.
  static void rows3x3(const float* m, V& r0, V& r1, V& r2) {
    const V c0 = _mm_loadu_ps(m);                                  // m0 m1 m2 m3
    const V c1 = _mm_loadu_ps(m + 3);                              // m3 m4 m5 m6
    const V c5 = _mm_loadu_ps(m + 5);                              // m5 m6 m7 m8
    const V c2 = _mm_shuffle_ps(c5, c5, _MM_SHUFFLE(3, 3, 2, 1));  // m6 m7 m8 m8
    const V z = _mm_setzero_ps();
    const V lo01 = _mm_unpacklo_ps(c0, c1);  // m0 m3 m1 m4
    const V hi01 = _mm_unpackhi_ps(c0, c1);  // m2 m5 m3 m6
    const V lo2 = _mm_unpacklo_ps(c2, z);    // m6 0 m7 0
    const V hi2 = _mm_unpackhi_ps(c2, z);    // m8 0 m8 0
    r0 = _mm_movelh_ps(lo01, lo2);           // m0 m3 m6 0
    r1 = _mm_movehl_ps(lo2, lo01);           // m1 m4 m7 0
    r2 = _mm_movelh_ps(hi01, hi2);           // m2 m5 m8 0
  }
  /// Stores lanes 0-2 of c0, c1, c2 as the columns of the column-major 3x3
  /// matrix at m (9 floats, none written beyond).
  static void store_cols3x3(float* m, V c0, V c1, V c2) {
    _mm_storeu_ps(m, c0);      // m0-m2 (m3 written again below)
    _mm_storeu_ps(m + 3, c1);  // m3-m5 (m6 written again below)
    // (c1[2], c2[0], c2[1], c2[2]) at m + 5
    const V c2r = _mm_shuffle_ps(c2, c2, _MM_SHUFFLE(2, 1, 0, 0));
    _mm_storeu_ps(m + 5, _mm_move_ss(c2r, _mm_shuffle_ps(c1, c1, _MM_SHUFFLE(2, 2, 2, 2))));
  }
  /// p[0], p[1], p[2] in lanes 0-2, lane 3 zero (3 floats read).
  static V load3(const float* p) {
    double d;  // p[0] p[1] through memcpy: no float read as double
    std::memcpy(&d, p, sizeof d);
    return _mm_movelh_ps(_mm_castpd_ps(_mm_set_sd(d)), _mm_load_ss(p + 2));
  }
  /// Stores lanes 0-2 of v at p (3 floats).
  static void store3(float* p, V v) {
    _mm_storel_pi(reinterpret_cast<__m64*>(p), v);
    _mm_store_ss(p + 2, _mm_movehl_ps(v, v));
  }
};

template <>
struct Lanes<double> {
  using V = __m128d;
  using M = __m128d;
  static constexpr int width = 2;
  static V load(const double* p) { return _mm_loadu_pd(p); }
  static V set1(double x) { return _mm_set1_pd(x); }
  static V iota(double base) { return _mm_setr_pd(base, base + 1.0); }
  static void store(double* p, V v) { _mm_storeu_pd(p, v); }
  // (x0 y0) (z0 x1) (y1 z1)
  static void store_xyz(double* p, V x, V y, V z) {
    _mm_storeu_pd(p, _mm_unpacklo_pd(x, y));
    _mm_storeu_pd(p + 2, _mm_shuffle_pd(z, x, 2));
    _mm_storeu_pd(p + 4, _mm_unpackhi_pd(y, z));
  }
  static void load_xyz(const double* const* p, V& x, V& y, V& z) {
    const V a = _mm_loadu_pd(p[0]), b = _mm_loadu_pd(p[1]);  // x y of each point
    x = _mm_unpacklo_pd(a, b);
    y = _mm_unpackhi_pd(a, b);
    z = _mm_unpacklo_pd(_mm_load_sd(p[0] + 2), _mm_load_sd(p[1] + 2));
  }
  static void store_abcd(double* p, V a, V b, V c, V d) {
    _mm_storeu_pd(p, _mm_unpacklo_pd(a, b));
    _mm_storeu_pd(p + 2, _mm_unpacklo_pd(c, d));
    _mm_storeu_pd(p + 4, _mm_unpackhi_pd(a, b));
    _mm_storeu_pd(p + 6, _mm_unpackhi_pd(c, d));
  }
  static V add(V a, V b) { return _mm_add_pd(a, b); }
  static V sub(V a, V b) { return _mm_sub_pd(a, b); }
  static V mul(V a, V b) { return _mm_mul_pd(a, b); }
  static V div(V a, V b) { return _mm_div_pd(a, b); }
  static V sqrt(V a) { return _mm_sqrt_pd(a); }
  static V abs(V a) { return _mm_andnot_pd(_mm_set1_pd(-0.0), a); }  // the sign bit cleared
  static V neg(V a) { return _mm_xor_pd(_mm_set1_pd(-0.0), a); }     // the sign bit flipped (as -x)
  static M lt(V a, V b) { return _mm_cmplt_pd(a, b); }
  static M gt(V a, V b) { return _mm_cmpgt_pd(a, b); }
  static M ge(V a, V b) { return _mm_cmpge_pd(a, b); }
  static M le(V a, V b) { return _mm_cmple_pd(a, b); }
  static M mand(M a, M b) { return _mm_and_pd(a, b); }
  static M mor(M a, M b) { return _mm_or_pd(a, b); }
  static V select(M m, V a, V b) { return _mm_or_pd(_mm_and_pd(m, a), _mm_andnot_pd(m, b)); }
  static V min_lt(V h, V m) { return _mm_min_pd(h, m); }
  static V max_gt(V h, V m) { return _mm_max_pd(h, m); }
  static M eq(V a, V b) { return _mm_cmpeq_pd(a, b); }
  static V hmin(V v) { return _mm_min_pd(v, _mm_shuffle_pd(v, v, 1)); }
  static V hmax(V v) { return _mm_max_pd(v, _mm_shuffle_pd(v, v, 1)); }
  static unsigned bits(M m) { return static_cast<unsigned>(_mm_movemask_pd(m)); }
  static double first(V v) { return _mm_cvtsd_f64(v); }
};
#endif

/// Whether the N bytes at a and at b are equal (memcmp(a, b, N) == 0; N a
/// multiple of 16): with SSE2 16 bytes at a time, written out.
template <std::size_t N>
inline bool equal_bytes(const void* a, const void* b) {
  static_assert(N % 16 == 0);
#if defined(SEPAX_SIMD_SSE2)
  const auto* p = static_cast<const unsigned char*>(a);
  const auto* q = static_cast<const unsigned char*>(b);
  auto eq = [&](std::size_t k) {
    return _mm_cmpeq_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p + k)),
                          _mm_loadu_si128(reinterpret_cast<const __m128i*>(q + k)));
  };
  __m128i all = eq(0);
  [&]<std::size_t... K>(std::index_sequence<K...>) { ((all = _mm_and_si128(all, eq(16 * (K + 1)))), ...); }
  (std::make_index_sequence<N / 16 - 1>{});
  return _mm_movemask_epi8(all) == 0xFFFF;
#else
  return std::memcmp(a, b, N) == 0;
#endif
}

/// out[i] = x_i*x_i + y_i*y_i + z_i*z_i in double, left to right, for the
/// Lanes<T>::width lanes of x, y, z (each value converted to double first,
/// exactly): what `double(x)*double(x) + double(y)*double(y) + ...` gives
/// lane by lane.
template <class T>
inline void squared_norms_in_double(typename Lanes<T>::V x, typename Lanes<T>::V y, typename Lanes<T>::V z,
                                    double* out) {
#if defined(SEPAX_SIMD_SSE2)
  if constexpr (std::is_same_v<T, float>) {
    auto sum = [](__m128d a, __m128d b, __m128d c) {
      return _mm_add_pd(_mm_add_pd(_mm_mul_pd(a, a), _mm_mul_pd(b, b)), _mm_mul_pd(c, c));
    };
    auto hi = [](__m128 v) { return _mm_cvtps_pd(_mm_movehl_ps(v, v)); };
    _mm_storeu_pd(out, sum(_mm_cvtps_pd(x), _mm_cvtps_pd(y), _mm_cvtps_pd(z)));
    _mm_storeu_pd(out + 2, sum(hi(x), hi(y), hi(z)));
  } else if constexpr (std::is_same_v<T, double>) {
    _mm_storeu_pd(out, _mm_add_pd(_mm_add_pd(_mm_mul_pd(x, x), _mm_mul_pd(y, y)), _mm_mul_pd(z, z)));
  } else
#endif
  {  // one lane
    const double a = static_cast<double>(x), b = static_cast<double>(y), c = static_cast<double>(z);
    *out = a * a + b * b + c * c;
  }
}

/// A dot product per lane, in dot()'s order: (x*bx + y*by) + z*bz.
template <class L>
inline typename L::V dot3(typename L::V x, typename L::V y, typename L::V z, typename L::V bx,
                          typename L::V by, typename L::V bz) {
  return L::add(L::add(L::mul(x, bx), L::mul(y, by)), L::mul(z, bz));
}

/// The bounds of points added a SIMD group at a time (posing's vertex
/// groups): per lane the lowest and the highest x, y and z, compared as the
/// scalar loops compare (min_lt / max_gt: of equal values the first stays),
/// and whether every |coordinate| added was at most `limit` (false for NaN).
template <class T>
struct LaneBounds {
  using L = Lanes<T>;
  using V = typename L::V;
  using M = typename L::M;

  /// No point yet: lowest +infinity, highest -infinity, every lane within.
  explicit LaneBounds(T limit)
      : lo{L::set1(kInf), L::set1(kInf), L::set1(kInf)},
        hi{L::set1(-kInf), L::set1(-kInf), L::set1(-kInf)},
        limit_(L::set1(limit)),
        within_(L::le(limit_, limit_)) {}

  /// Lane i of x, y, z is one more point of lane i.
  SEPAX_SIMD_INLINE void add(V x, V y, V z) {
    within_ = L::mand(within_, L::mand(L::le(L::abs(x), limit_),
                                       L::mand(L::le(L::abs(y), limit_), L::le(L::abs(z), limit_))));
    lo[0] = L::min_lt(x, lo[0]), lo[1] = L::min_lt(y, lo[1]), lo[2] = L::min_lt(z, lo[2]);
    hi[0] = L::max_gt(x, hi[0]), hi[1] = L::max_gt(y, hi[1]), hi[2] = L::max_gt(z, hi[2]);
  }

  /// Every coordinate added was within the limit (and none was NaN).
  bool within() const { return L::bits(within_) == (1u << L::width) - 1; }

  /// The lowest and highest coordinates over every lane into out_lo,
  /// out_hi (hmin / hmax: exact for values that are not NaN; a zero's sign
  /// is that of one of the lanes' zeros, not necessarily the first point's
  /// in the order added); returns whether none of the six is zero.  At
  /// least one group added.
  bool reduce(T (&out_lo)[3], T (&out_hi)[3]) const {
    const V zero = L::set1(T(0));
    M zeros = L::lt(zero, zero);  // no lane
    unrolled<3>([&](int c) SEPAX_SIMD_INLINE {
      const V l = L::hmin(lo[c]), h = L::hmax(hi[c]);
      zeros = L::mor(zeros, L::mor(L::eq(l, zero), L::eq(h, zero)));
      out_lo[c] = L::first(l);
      out_hi[c] = L::first(h);
    });
    return L::bits(zeros) == 0;
  }

  V lo[3];  ///< per lane, the lowest x, y, z added (+infinity before any)
  V hi[3];  ///< per lane, the highest x, y, z added (-infinity before any)

 private:
  static constexpr T kInf = std::numeric_limits<T>::infinity();
  V limit_;   ///< |coordinate| limit, in every lane
  M within_;  ///< per lane: every coordinate so far within limit_
};

}  // namespace sepax::simd
