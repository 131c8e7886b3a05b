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
// to_double is for reporting only.  Eigen::NumTraits for mpq_class is
// provided here (CGAL provides it for its own types).
#pragma once

#include <gmpxx.h>

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
  static double to_double(const mpq_class& x) { return x.get_d(); }
  static bool is_finite(const mpq_class&) { return true; }
};

template <>
struct number_traits<CGAL::Gmpq> : detail::exact_rational_traits {
  static constexpr std::string_view name = "gmpq";
  static CGAL::Gmpq from_double(double d) { return CGAL::Gmpq(d); }
  static double to_double(const CGAL::Gmpq& x) { return CGAL::to_double(x); }
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
