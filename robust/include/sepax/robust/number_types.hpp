// sepax/robust/number_types.hpp
//
// number_traits<T> (see sepax/number_traits.hpp) for the exact number types
// sepax is instantiated with:
//
// | T                          | exact | sqrt | normalises | note                                   |
// |----------------------------|-------|------|------------|----------------------------------------|
// | mpq_class (GMP C++)        | yes   | no   | no         | plain GMP rationals                    |
// | CGAL::Gmpq                 | yes   | no   | no         | CGAL's GMP rational                    |
// | CGAL::Lazy_exact_nt<ET>    | yes   | no   | no         | CGAL::Epeck::FT (interval filter + ET) |
// | CORE::Expr (CGAL's CORE)   | yes   | yes  | yes        | exact sqrt: normalised separations     |
//
// from_double is exact for all of them (a double is a dyadic rational).
// to_double is for reporting only; for the GMP rationals it is the nearest
// double (GMP's mpq_get_d, behind CGAL::Gmpq's too, truncates: every exact
// value printed one ulp towards zero, below the double run's).  Eigen::NumTraits for mpq_class is
// provided here (CGAL provides it for its own types).
#pragma once

#include <gmpxx.h>
#include <mpfr.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Lazy_exact_nt.h>
#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <type_traits>

#include <sepax/number_traits.hpp>
#include <sepax/plane.hpp>
#include <sepax/vec3.hpp>

namespace Eigen {
template <>
struct NumTraits<mpq_class> : GenericNumTraits<mpq_class> {
  typedef mpq_class Real;
  typedef mpq_class NonInteger;
  typedef mpq_class Nested;
  typedef mpq_class Literal;
  enum {
    IsInteger = 0,
    IsSigned = 1,
    IsComplex = 0,
    RequireInitialization = 1,
    ReadCost = 6,
    AddCost = 150,
    MulCost = 100
  };
  static inline Real epsilon() { return 0; }
  static inline Real dummy_precision() { return 0; }
  static inline int digits10() { return 0; }
};
}  // namespace Eigen

namespace sepax {

namespace detail {
/// The double nearest to q, ties to even (MPFR rounds the rational once to
/// 53 bits; only below 2^-1022, in double's subnormal range, is the result
/// rounded a second time).  Beyond double's range: +-infinity.  A q that is
/// a normal double (numerator of at most 53 bits over 2^z, z <= 1022, as
/// every value converted from a float or a double) is read without MPFR:
/// numerator and scaling are exact, so the value is the same.
inline double nearest_double(mpq_srcptr q) {
  const mpz_srcptr num = mpq_numref(q), den = mpq_denref(q);
  const mp_bitcnt_t z = mpz_scan1(den, 0);  // (den > 0)
  if (z <= 1022 && mpz_sizeinbase(den, 2) == z + 1 && mpz_sizeinbase(num, 2) <= 53)
    return std::ldexp(mpz_get_d(num), -static_cast<int>(z));
  mpfr_t f;
  mpfr_init2(f, 53);
  mpfr_set_q(f, q, MPFR_RNDN);
  const double d = mpfr_get_d(f, MPFR_RNDN);
  mpfr_clear(f);
  return d;
}

/// log2 of a rational's denominator den (> 0) when it is a power of two, std::nullopt otherwise.
inline std::optional<mp_bitcnt_t> power_of_two_exponent(mpz_srcptr den) {
  const mp_bitcnt_t z = mpz_scan1(den, 0);  // (den > 0)
  if (mpz_sizeinbase(den, 2) != z + 1) return std::nullopt;
  return z;
}

/// log2 of q's denominator when it is a power of two (q a dyadic rational, as every value converted from a
/// float or a double is), std::nullopt otherwise.
inline std::optional<mp_bitcnt_t> dyadic_shift(const mpq_class& q) {
  return power_of_two_exponent(mpq_denref(q.get_mpq_t()));
}

/// a . b evaluated in N, left to right, from at(v, j): coordinate j of vector v (0: a, 1: b).
template <class N, class At>
N dot_value(At at) {
  N s = at(0, 0) * at(1, 0);
  s = s + at(0, 1) * at(1, 1);
  s = s + at(0, 2) * at(1, 2);
  return s;
}

/// a.(p - q) evaluated in N from at(v, j): coordinate j of vector v (0: a, 1: p, 2: q).
template <class N, class At>
N difference_dot_value(At at) {
  N s = at(0, 0) * (at(1, 0) - at(2, 0));
  s = s + at(0, 1) * (at(1, 1) - at(2, 1));
  s = s + at(0, 2) * (at(1, 2) - at(2, 2));
  return s;
}

/// (a x b).(p - q) evaluated in N from at(v, j): coordinate j of vector v (0: a, 1: b, 2: p, 3: q).
template <class N, class At>
N height_value(At at) {
  N s(0);
  for (int j = 0; j < 3; ++j) {
    const int u = (j + 1) % 3, w = (j + 2) % 3;
    s = s + (at(0, u) * at(1, w) - at(0, w) * at(1, u)) * (at(2, j) - at(3, j));
  }
  return s;
}

/// Three rationals (a vector's coordinates), read in place.
using Mpq3 = std::array<mpq_srcptr, 3>;

/// e_i = log2(den(a_i) den(b_i)), i = 0, 1, 2, when all six denominators are powers of two (the terms
/// a_i b_i = num(a_i) num(b_i) / 2^e_i); false otherwise.
inline bool dyadic_term_exponents(const Mpq3& a, const Mpq3& b, mp_bitcnt_t (&e)[3]) {
  for (int i = 0; i < 3; ++i) {
    const std::optional<mp_bitcnt_t> ea = power_of_two_exponent(mpq_denref(a[i]));
    if (!ea) return false;
    const std::optional<mp_bitcnt_t> eb = power_of_two_exponent(mpq_denref(b[i]));
    if (!eb) return false;
    e[i] = *ea + *eb;
  }
  return true;
}

/// The sign of a . b = a_0 b_0 + a_1 b_1 + a_2 b_2 for rationals (a[i], b[i]), exact, in integers: the
/// sign mpq_class's dot gives, without the gcd each of its operations reduces by.  Denominators are > 0,
/// so the term a_i b_i has the sign of num(a_i) num(b_i):
///   1. no negative term: the sign is +1 if a term is positive, else 0; no positive term: -1;
///   2. all six denominators powers of two (a_i b_i = N_i / 2^e_i, N_i = num(a_i) num(b_i)): the sign of
///      sum N_i 2^(k - e_i), k = max e_i (the sum times 2^k > 0);
///   3. otherwise, with N_i as above and D_i = den(a_i) den(b_i) > 0: the sign of
///      N_0 D_1 D_2 + N_1 D_0 D_2 + N_2 D_0 D_1 (the sum times D_0 D_1 D_2 > 0).
inline int rational_dot_sign(const Mpq3& a, const Mpq3& b) {
  int positive = 0, negative = 0;
  for (int i = 0; i < 3; ++i) {
    const int s = mpz_sgn(mpq_numref(a[i])) * mpz_sgn(mpq_numref(b[i]));
    positive += s > 0;
    negative += s < 0;
  }
  if (negative == 0) return positive > 0 ? 1 : 0;
  if (positive == 0) return -1;
  thread_local mpz_class n[3], d[3], t, sum;  // (kept: no allocation once grown)
  mp_bitcnt_t e[3];
  const bool dyadic = dyadic_term_exponents(a, b, e);
  for (int i = 0; i < 3; ++i) mpz_mul(n[i].get_mpz_t(), mpq_numref(a[i]), mpq_numref(b[i]));
  if (dyadic) {
    const mp_bitcnt_t k = std::max({e[0], e[1], e[2]});
    mpz_mul_2exp(sum.get_mpz_t(), n[0].get_mpz_t(), k - e[0]);
    for (int i = 1; i < 3; ++i) {
      mpz_mul_2exp(t.get_mpz_t(), n[i].get_mpz_t(), k - e[i]);
      mpz_add(sum.get_mpz_t(), sum.get_mpz_t(), t.get_mpz_t());
    }
    return mpz_sgn(sum.get_mpz_t());
  }
  for (int i = 0; i < 3; ++i) mpz_mul(d[i].get_mpz_t(), mpq_denref(a[i]), mpq_denref(b[i]));
  mpz_mul(t.get_mpz_t(), d[1].get_mpz_t(), d[2].get_mpz_t());
  mpz_mul(sum.get_mpz_t(), n[0].get_mpz_t(), t.get_mpz_t());
  mpz_mul(t.get_mpz_t(), d[0].get_mpz_t(), d[2].get_mpz_t());
  mpz_addmul(sum.get_mpz_t(), n[1].get_mpz_t(), t.get_mpz_t());
  mpz_mul(t.get_mpz_t(), d[0].get_mpz_t(), d[1].get_mpz_t());
  mpz_addmul(sum.get_mpz_t(), n[2].get_mpz_t(), t.get_mpz_t());
  return mpz_sgn(sum.get_mpz_t());
}

/// q = m / 2^e in lowest terms (m = 0: 0 / 1), dividing out the common powers of two.
inline void set_dyadic(mpq_ptr q, mpz_srcptr m, mp_bitcnt_t e) {
  const mp_bitcnt_t s = mpz_sgn(m) == 0 ? e : std::min(e, mpz_scan1(m, 0));
  mpz_tdiv_q_2exp(mpq_numref(q), m, s);
  mpz_set_ui(mpq_denref(q), 1);
  mpz_mul_2exp(mpq_denref(q), mpq_denref(q), e - s);
}
inline void set_dyadic(mpq_class& q, const mpz_class& m, mp_bitcnt_t e) {
  set_dyadic(q.get_mpq_t(), m.get_mpz_t(), e);
}

/// The plane through a, b, c (normal (b - a) x (c - a), offset normal . a) when every coordinate is a dyadic
/// rational (its denominator a power of two, as for every coordinate converted from a float or a double),
/// computed in integers: the nine coordinates on one denominator 2^k (X = x 2^k), N = (B - A) x (C - A) and
/// N . A in mpz (no gcd), then normal = N / 2^(2k) and offset = N . A / 2^(3k) in lowest terms, dividing out
/// the common powers of two.  These are the values mpq_class's operations give (a rational's lowest terms
/// are unique), at a fraction of the cost: each mpq operation reduces its result by a gcd.  Written into
/// out (its numbers reused); false, out untouched, when a denominator is not a power of two.
inline bool dyadic_plane(Plane<mpq_class>& out, const Vec3<mpq_class>& a, const Vec3<mpq_class>& b,
                         const Vec3<mpq_class>& c) {
  const Vec3<mpq_class>* points[3] = {&a, &b, &c};
  mp_bitcnt_t shift[9];  // log2 of each denominator
  mp_bitcnt_t k = 0;
  for (int i = 0; i < 9; ++i) {
    const std::optional<mp_bitcnt_t> z = dyadic_shift((*points[i / 3])[i % 3]);
    if (!z) return false;
    shift[i] = *z;
    k = std::max(k, *z);
  }
  thread_local mpz_class x[9], u[3], w[3], n[3], off, t;  // (kept: no allocation once grown)
  for (int i = 0; i < 9; ++i)
    mpz_mul_2exp(x[i].get_mpz_t(), mpq_numref((*points[i / 3])[i % 3].get_mpq_t()), k - shift[i]);
  for (int j = 0; j < 3; ++j) {
    mpz_sub(u[j].get_mpz_t(), x[3 + j].get_mpz_t(), x[j].get_mpz_t());
    mpz_sub(w[j].get_mpz_t(), x[6 + j].get_mpz_t(), x[j].get_mpz_t());
  }
  for (int j = 0; j < 3; ++j) {  // n_j = u_{j+1} w_{j+2} - u_{j+2} w_{j+1}
    const int p = (j + 1) % 3, q = (j + 2) % 3;
    mpz_mul(n[j].get_mpz_t(), u[p].get_mpz_t(), w[q].get_mpz_t());
    mpz_mul(t.get_mpz_t(), u[q].get_mpz_t(), w[p].get_mpz_t());
    mpz_sub(n[j].get_mpz_t(), n[j].get_mpz_t(), t.get_mpz_t());
  }
  mpz_mul(off.get_mpz_t(), n[0].get_mpz_t(), x[0].get_mpz_t());
  for (int j = 1; j < 3; ++j) mpz_addmul(off.get_mpz_t(), n[j].get_mpz_t(), x[j].get_mpz_t());
  for (int j = 0; j < 3; ++j) set_dyadic(out.normal[j], n[j], 2 * k);
  set_dyadic(out.offset, off, 3 * k);
  return true;
}

/// out = a - b when both are dyadic rationals, in integers as dyadic_plane computes (both on the
/// denominator 2^k, k the larger shift; the numerators' difference; lowest terms by powers of two): the
/// value mpq_class's subtraction gives, without its gcd.  false (out untouched) when a denominator is not a
/// power of two.  out may be a or b.
inline bool dyadic_difference(mpq_class& out, const mpq_class& a, const mpq_class& b) {
  const std::optional<mp_bitcnt_t> za = dyadic_shift(a), zb = dyadic_shift(b);
  if (!za || !zb) return false;
  const mp_bitcnt_t k = std::max(*za, *zb);
  thread_local mpz_class x, y;  // (kept: no allocation once grown)
  mpz_mul_2exp(x.get_mpz_t(), mpq_numref(a.get_mpq_t()), k - *za);
  mpz_mul_2exp(y.get_mpz_t(), mpq_numref(b.get_mpq_t()), k - *zb);
  mpz_sub(x.get_mpz_t(), x.get_mpz_t(), y.get_mpz_t());
  set_dyadic(out, x, k);
  return true;
}

/// out = a . b = a_0 b_0 + a_1 b_1 + a_2 b_2 when all six are dyadic rationals, in integers: the terms
/// N_i / 2^e_i (N_i = num(a_i) num(b_i)) on the denominator 2^k, k = max e_i, summed, and the sum over 2^k
/// in lowest terms by powers of two (set_dyadic): the value mpq_class's dot gives (a rational's lowest
/// terms are unique), without its gcds.  false, out untouched, when a denominator is not a power of two.
inline bool dyadic_dot(mpq_ptr out, const Mpq3& a, const Mpq3& b) {
  mp_bitcnt_t e[3];
  if (!dyadic_term_exponents(a, b, e)) return false;
  const mp_bitcnt_t k = std::max({e[0], e[1], e[2]});
  thread_local mpz_class t, sum;  // (kept: no allocation once grown)
  mpz_mul(sum.get_mpz_t(), mpq_numref(a[0]), mpq_numref(b[0]));
  mpz_mul_2exp(sum.get_mpz_t(), sum.get_mpz_t(), k - e[0]);
  for (int i = 1; i < 3; ++i) {
    mpz_mul(t.get_mpz_t(), mpq_numref(a[i]), mpq_numref(b[i]));
    mpz_mul_2exp(t.get_mpz_t(), t.get_mpz_t(), k - e[i]);
    mpz_add(sum.get_mpz_t(), sum.get_mpz_t(), t.get_mpz_t());
  }
  set_dyadic(out, sum.get_mpz_t(), k);
  return true;
}

/// The sign of (a x b).(p - q) for rationals (three coordinates each), exact.  When all twelve are dyadic,
/// in integers: each of a, b and (p, q) on one denominator 2^k (A = a 2^ka, B = b 2^kb, D = (p - q) 2^kd,
/// integer vectors), the sign of (A x B).D, which is the sign times 2^(ka + kb + kd) > 0, with no gcd.
/// Otherwise with mpq_class's operations.
inline int rational_height_sign(const Mpq3& a, const Mpq3& b, const Mpq3& p, const Mpq3& q) {
  const Mpq3* vectors[4] = {&a, &b, &p, &q};
  mp_bitcnt_t shift[12];
  bool dyadic = true;
  for (int i = 0; i < 12 && dyadic; ++i) {
    const std::optional<mp_bitcnt_t> z = power_of_two_exponent(mpq_denref((*vectors[i / 3])[i % 3]));
    dyadic = z.has_value();
    if (dyadic) shift[i] = *z;
  }
  if (!dyadic) {  // (not sepax::dot: dot<mpq_class> is not to be instantiated before number_traits)
    const mpq_class h = height_value<mpq_class>(
        [&](int v, int j) { return mpq_class((*vectors[v])[static_cast<std::size_t>(j)]); });
    return sgn(h);
  }
  thread_local mpz_class x[9], c[3], t, h;  // A, B, D; A x B (kept: no allocation once grown)
  // the common exponent of a, of b, and of p and q together
  const mp_bitcnt_t k[3] = {std::max({shift[0], shift[1], shift[2]}),
                            std::max({shift[3], shift[4], shift[5]}),
                            std::max({shift[6], shift[7], shift[8], shift[9], shift[10], shift[11]})};
  for (int i = 0; i < 6; ++i)
    mpz_mul_2exp(x[i].get_mpz_t(), mpq_numref((*vectors[i / 3])[i % 3]), k[i / 3] - shift[i]);
  for (int j = 0; j < 3; ++j) {
    mpz_mul_2exp(x[6 + j].get_mpz_t(), mpq_numref(p[j]), k[2] - shift[6 + j]);
    mpz_mul_2exp(t.get_mpz_t(), mpq_numref(q[j]), k[2] - shift[9 + j]);
    mpz_sub(x[6 + j].get_mpz_t(), x[6 + j].get_mpz_t(), t.get_mpz_t());
  }
  for (int j = 0; j < 3; ++j) {  // c_j = A_{j+1} B_{j+2} - A_{j+2} B_{j+1}
    const int u = (j + 1) % 3, w = (j + 2) % 3;
    mpz_mul(c[j].get_mpz_t(), x[u].get_mpz_t(), x[3 + w].get_mpz_t());
    mpz_mul(t.get_mpz_t(), x[w].get_mpz_t(), x[3 + u].get_mpz_t());
    mpz_sub(c[j].get_mpz_t(), c[j].get_mpz_t(), t.get_mpz_t());
  }
  mpz_mul(h.get_mpz_t(), c[0].get_mpz_t(), x[6].get_mpz_t());
  for (int j = 1; j < 3; ++j) mpz_addmul(h.get_mpz_t(), c[j].get_mpz_t(), x[6 + j].get_mpz_t());
  return mpz_sgn(h.get_mpz_t());
}

struct exact_rational_traits {
  static constexpr bool is_exact = true;
  static constexpr bool has_sqrt = false;
  static constexpr bool normalizes = false;
  static constexpr double unit_roundoff = 0.0;
};
}  // namespace detail

template <>
struct number_traits<mpq_class> : detail::exact_rational_traits {
  static constexpr std::string_view name = "mpq";
  static mpq_class from_double(double d) { return mpq_class(d); }
  static double to_double(const mpq_class& x) { return detail::nearest_double(x.get_mpq_t()); }
  static bool is_finite(const mpq_class&) { return true; }
  /// plane_through's values in integers when the coordinates are dyadic (detail::dyadic_plane).
  static bool exact_plane(Plane<mpq_class>& out, const Vec3<mpq_class>& a, const Vec3<mpq_class>& b,
                          const Vec3<mpq_class>& c) {
    return detail::dyadic_plane(out, a, b, c);
  }
  /// out = a - b in integers when both are dyadic (detail::dyadic_difference).
  static bool exact_difference(mpq_class& out, const mpq_class& a, const mpq_class& b) {
    return detail::dyadic_difference(out, a, b);
  }
  /// out = a . b in integers when all six are dyadic (detail::dyadic_dot).
  static bool exact_dot(mpq_class& out, const Vec3<mpq_class>& a, const Vec3<mpq_class>& b) {
    return detail::dyadic_dot(out.get_mpq_t(), {a[0].get_mpq_t(), a[1].get_mpq_t(), a[2].get_mpq_t()},
                              {b[0].get_mpq_t(), b[1].get_mpq_t(), b[2].get_mpq_t()});
  }
  /// The sign of a . b in integers (detail::rational_dot_sign).
  static int dot_sign(const Vec3<mpq_class>& a, const Vec3<mpq_class>& b) {
    return detail::rational_dot_sign({a[0].get_mpq_t(), a[1].get_mpq_t(), a[2].get_mpq_t()},
                                     {b[0].get_mpq_t(), b[1].get_mpq_t(), b[2].get_mpq_t()});
  }
  /// The sign of (a x b).(p - q) in integers when dyadic (detail::rational_height_sign).
  static int height_sign(const Vec3<mpq_class>& a, const Vec3<mpq_class>& b, const Vec3<mpq_class>& p,
                         const Vec3<mpq_class>& q) {
    auto c = [](const Vec3<mpq_class>& v) {
      return detail::Mpq3{v[0].get_mpq_t(), v[1].get_mpq_t(), v[2].get_mpq_t()};
    };
    return detail::rational_height_sign(c(a), c(b), c(p), c(q));
  }
};

template <>
struct number_traits<CGAL::Gmpq> : detail::exact_rational_traits {
  static constexpr std::string_view name = "gmpq";
  static CGAL::Gmpq from_double(double d) { return CGAL::Gmpq(d); }
  static double to_double(const CGAL::Gmpq& x) { return detail::nearest_double(x.mpq()); }
  static bool is_finite(const CGAL::Gmpq&) { return true; }
  /// out = a . b in integers when all six are dyadic (detail::dyadic_dot), into a new Gmpq (out's
  /// number is shared by its copies, so it is replaced, not written).
  static bool exact_dot(CGAL::Gmpq& out, const Vec3<CGAL::Gmpq>& a, const Vec3<CGAL::Gmpq>& b) {
    CGAL::Gmpq s;
    if (!detail::dyadic_dot(s.mpq(), in_place(a), in_place(b))) return false;
    out = s;
    return true;
  }
  /// The sign of a . b in integers (detail::rational_dot_sign).
  static int dot_sign(const Vec3<CGAL::Gmpq>& a, const Vec3<CGAL::Gmpq>& b) {
    return detail::rational_dot_sign(in_place(a), in_place(b));
  }
  /// The sign of (a x b).(p - q) in integers when dyadic (detail::rational_height_sign).
  static int height_sign(const Vec3<CGAL::Gmpq>& a, const Vec3<CGAL::Gmpq>& b, const Vec3<CGAL::Gmpq>& p,
                         const Vec3<CGAL::Gmpq>& q) {
    return detail::rational_height_sign(in_place(a), in_place(b), in_place(p), in_place(q));
  }

 private:
  static detail::Mpq3 in_place(const Vec3<CGAL::Gmpq>& v) { return {v[0].mpq(), v[1].mpq(), v[2].mpq()}; }
};

template <class ET>
struct number_traits<CGAL::Lazy_exact_nt<ET>> : detail::exact_rational_traits {
  static constexpr std::string_view name = "epeck";
  static CGAL::Lazy_exact_nt<ET> from_double(double d) { return CGAL::Lazy_exact_nt<ET>(d); }
  static double to_double(const CGAL::Lazy_exact_nt<ET>& x) { return CGAL::to_double(x); }
  static bool is_finite(const CGAL::Lazy_exact_nt<ET>&) { return true; }
  using L = CGAL::Lazy_exact_nt<ET>;
  using I = CGAL::Interval_nt_advanced;  // valid inside Protect_FPU_rounding<true> (rounding upward)

  /// The sign of a . b: first from the coordinates' stored intervals (approx(), enclosures of the exact
  /// values), the dot product evaluated in interval arithmetic rounding upward, so the result encloses
  /// the exact a . b; a sign it decides (an interval excluding 0, or the point [0, 0]) is that of a . b.
  /// Otherwise from the exact values (exact(), evaluated and kept by Lazy_exact_nt as for any exact
  /// sign): in integers for a GMP rational ET (detail::rational_dot_sign), else ET's dot.  No lazy node is
  /// built, where dot(a, b) builds five.
  static int dot_sign(const Vec3<L>& a, const Vec3<L>& b) {
    const Vec3<L>* v[2] = {&a, &b};
    {
      CGAL::Protect_FPU_rounding<true> upward;
      const I s = detail::dot_value<I>([&](int i, int j) { return (*v[i])[j].approx(); });
      if (const std::optional<int> d = decided(s)) return *d;
    }
    if constexpr (kRational) {
      return detail::rational_dot_sign(exact_in_place(a), exact_in_place(b));
    } else {
      return sign_value(detail::dot_value<ET>([&](int i, int j) { return (*v[i])[j].exact(); }));
    }
  }

  /// The sign of a.(p - q): as dot_sign, the intervals first (the differences evaluated in interval
  /// arithmetic, rounding upward), then the exact values (ET's operations: a rare path).  No lazy node is
  /// built, where dot(a, p) < dot(a, q) builds ten.
  static int difference_dot_sign(const Vec3<L>& a, const Vec3<L>& p, const Vec3<L>& q) {
    const Vec3<L>* v[3] = {&a, &p, &q};
    {
      CGAL::Protect_FPU_rounding<true> upward;
      const I s = detail::difference_dot_value<I>([&](int i, int j) { return (*v[i])[j].approx(); });
      if (const std::optional<int> d = decided(s)) return *d;
    }
    return sign_value(detail::difference_dot_value<ET>([&](int i, int j) { return (*v[i])[j].exact(); }));
  }

  /// The sign of (a x b).(p - q): as dot_sign, the intervals first (the cross product and the difference
  /// evaluated in interval arithmetic, rounding upward), then the exact values (in integers for a GMP
  /// rational ET, detail::rational_height_sign; else ET's operations).
  static int height_sign(const Vec3<L>& a, const Vec3<L>& b, const Vec3<L>& p, const Vec3<L>& q) {
    const Vec3<L>* v[4] = {&a, &b, &p, &q};
    {
      CGAL::Protect_FPU_rounding<true> upward;
      const I s = detail::height_value<I>([&](int i, int j) { return (*v[i])[j].approx(); });
      if (const std::optional<int> d = decided(s)) return *d;
    }
    if constexpr (kRational) {
      return detail::rational_height_sign(exact_in_place(a), exact_in_place(b), exact_in_place(p),
                                          exact_in_place(q));
    } else {
      return sign_value(detail::height_value<ET>([&](int i, int j) { return (*v[i])[j].exact(); }));
    }
  }

 private:
  static constexpr bool kRational = std::is_same_v<ET, mpq_class> || std::is_same_v<ET, CGAL::Gmpq>;

  /// The sign of an exact value.
  static int sign_value(const ET& s) { return (s > ET(0)) - (s < ET(0)); }

  /// The sign of every value in the enclosure s when they all have one.
  static std::optional<int> decided(const I& s) {
    if (s.inf() > 0) return 1;
    if (s.sup() < 0) return -1;
    if (s.inf() == 0 && s.sup() == 0) return 0;
    return std::nullopt;
  }

  /// The exact values' rationals, read in place (kRational).
  static detail::Mpq3 exact_in_place(const Vec3<L>& v) {
    if constexpr (std::is_same_v<ET, mpq_class>) {
      return {v[0].exact().get_mpq_t(), v[1].exact().get_mpq_t(), v[2].exact().get_mpq_t()};
    } else {
      return {v[0].exact().mpq(), v[1].exact().mpq(), v[2].exact().mpq()};
    }
  }
};

}  // namespace sepax
