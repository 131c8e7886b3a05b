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

#include <sepax/number_traits.hpp>

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
/// rounded a second time).  Beyond double's range: +-infinity.
inline double nearest_double(mpq_srcptr q) {
  mpfr_t f;
  mpfr_init2(f, 53);
  mpfr_set_q(f, q, MPFR_RNDN);
  const double d = mpfr_get_d(f, MPFR_RNDN);
  mpfr_clear(f);
  return d;
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
