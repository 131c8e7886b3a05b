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
#include <cmath>
#include <optional>

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

/// log2 of q's denominator when it is a power of two (q a dyadic rational, as every value converted from a
/// float or a double is), std::nullopt otherwise.
inline std::optional<mp_bitcnt_t> dyadic_shift(const mpq_class& q) {
  const mpz_srcptr den = mpq_denref(q.get_mpq_t());
  const mp_bitcnt_t z = mpz_scan1(den, 0);  // (den > 0)
  if (mpz_sizeinbase(den, 2) != z + 1) return std::nullopt;
  return z;
}

/// q = m / 2^e in lowest terms (m = 0: 0 / 1), dividing out the common powers of two.
inline void set_dyadic(mpq_class& q, const mpz_class& m, mp_bitcnt_t e) {
  const mp_bitcnt_t s = mpz_sgn(m.get_mpz_t()) == 0 ? e : std::min(e, mpz_scan1(m.get_mpz_t(), 0));
  mpz_tdiv_q_2exp(mpq_numref(q.get_mpq_t()), m.get_mpz_t(), s);
  mpz_set_ui(mpq_denref(q.get_mpq_t()), 1);
  mpz_mul_2exp(mpq_denref(q.get_mpq_t()), mpq_denref(q.get_mpq_t()), e - s);
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
};

template <>
struct number_traits<CGAL::Gmpq> : detail::exact_rational_traits {
  static constexpr std::string_view name = "gmpq";
  static CGAL::Gmpq from_double(double d) { return CGAL::Gmpq(d); }
  static double to_double(const CGAL::Gmpq& x) { return detail::nearest_double(x.mpq()); }
  static bool is_finite(const CGAL::Gmpq&) { return true; }
};

template <class ET>
struct number_traits<CGAL::Lazy_exact_nt<ET>> : detail::exact_rational_traits {
  static constexpr std::string_view name = "epeck";
  static CGAL::Lazy_exact_nt<ET> from_double(double d) { return CGAL::Lazy_exact_nt<ET>(d); }
  static double to_double(const CGAL::Lazy_exact_nt<ET>& x) { return CGAL::to_double(x); }
  static bool is_finite(const CGAL::Lazy_exact_nt<ET>&) { return true; }
};

}  // namespace sepax
