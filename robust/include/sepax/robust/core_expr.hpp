// sepax/robust/core_expr.hpp
//
// number_traits<CORE::Expr>: CGAL's CORE expression type as a sepax number
// type.  CORE::Expr is exact (it keeps the expression DAG and evaluates
// comparisons to whatever precision their sign needs, using separation bounds)
// and has an exact sqrt, so it is the one exact type with `normalizes = true`:
// the SATs normalise face normals and edge axes with sqrt, separations are
// true Euclidean distances (norm2 == 1), and every comparison is still exact.
// That makes it the reference for "the separation value itself", where the
// rationals only give it in squared form (num / sqrt(norm2)).
//
//   is_exact = true, has_sqrt = true, normalizes = true, unit_roundoff = 0.
//
// from_double is exact (CORE keeps the double as an exact constant); a NaN or
// infinity throws InvalidInput(NonFinite) instead of reaching CORE's error
// handler.  to_double is for reporting only.  Expressions grow with every
// operation, so CORE::Expr is slow: use it for verification, not for speed.
//
// Eigen::NumTraits<CORE::Expr> comes with <CGAL/CORE_Expr.h>.
#pragma once

#include <CGAL/CORE_Expr.h>

#include <cmath>
#include <string_view>

#include <gmpxx.h>

#include <sepax/error.hpp>
#include <sepax/number_traits.hpp>

namespace sepax {

template <>
struct number_traits<CORE::Expr> {
  static constexpr bool is_exact = true;
  static constexpr bool has_sqrt = true;
  static constexpr bool normalizes = true;
  static constexpr double unit_roundoff = 0.0;
  static constexpr std::string_view name = "core_expr";
  static CORE::Expr from_double(double d) {
    if (!std::isfinite(d)) throw InvalidInput(ErrorCode::NonFinite, "non-finite value given to CORE::Expr");
    return CORE::Expr(d);
  }
  static double to_double(const CORE::Expr& x) { return x.doubleValue(); }
  static CORE::Expr sqrt(const CORE::Expr& x) { return CORE::sqrt(x); }
  static bool is_finite(const CORE::Expr&) { return true; }
};

/// An exact rational as a CORE::Expr (for comparing mpq results with CORE ones).
inline CORE::Expr to_core_expr(const mpq_class& q) { return CORE::Expr(CORE::BigRat(q.get_mpq_t())); }

}  // namespace sepax
