// sepax/fuzz/classify.hpp
//
// The classification rules of the checking core (check.hpp), exposed so they
// can be tested on synthetic disagreements.  Exact values are Separation<mpq>
// (num / sqrt(norm2), see separation.hpp); float values are doubles (a float
// converts exactly); bounds come from error_bounds.hpp.
#pragma once

#include <gmpxx.h>

#include <sepax/fuzz/check.hpp>
#include <sepax/fuzz/error_bounds.hpp>
#include <sepax/robust/number_types.hpp>
#include <sepax/separation.hpp>

namespace sepax::fuzz {

using ExactSep = Separation<mpq_class>;

/// sign(r - value(s)), exactly.
int cmp_rational_sep(const mpq_class& r, const ExactSep& s);
/// |x - value(s)| <= bound, exactly (bound as the rational value of a double;
/// an infinite bound always holds).
bool within(double x, const ExactSep& s, double bound);
/// sign(value(x) - value(y) - b), exactly (rational comparisons only, see check.cpp).
int sign_sep_diff(const ExactSep& x, const ExactSep& y, const mpq_class& b);
/// |value(x) - value(y)| <= bound (bound as the rational value of a double; an
/// infinite bound always holds); equal values always hold.  Decided exactly.
bool close(const ExactSep& x, const ExactSep& y, double bound);

/// One sign a float configuration decided (float_sign) against the exact
/// quantity: agree / exact_zero / explained (|exact| <= bound) / unexplained.
/// exact_decisions: the configuration claims exact signs (robust policy): any
/// difference is unexplained.
Classification classify_sign(int float_sign, const ExactSep& exact, double bound, bool exact_decisions);

/// Overlap verdicts: a difference is exact_zero when the exact maximum
/// separation is exactly 0, explained when it is within `bound` of 0.
Classification classify_overlap(bool float_overlap, bool exact_overlap, const ExactSep& exact_max,
                                double bound, bool exact_decisions);

/// The reported separation sf against the exact optimum.  same_axis: the float
/// chose the exact optimum's axis (its bound is bf); otherwise a different
/// feature, and the combined bound bf + be applies (classified as a tie).
Classification classify_separation(double sf, const ExactSep& exact_max, bool same_axis, double bf, double be,
                                   bool exact_decisions);

/// Could the plain kernel of F have skipped the edge pair (da, db) as parallel
/// (error_bounds.hpp (6))?  outside: certainly not, the pair was measured;
/// inside: it may have been skipped; unknown: the guard against underflow /
/// overflow fails, nothing can be shown.  Decided exactly on the F values.
enum class ParallelBand { outside, inside, unknown };
template <class F>
ParallelBand parallel_band(const Vec3<F>& da, const Vec3<F>& db) {
  using Q = mpq_class;
  using PS = bounds::ParallelSkip<F>;
  const Vec3<Q> a = vec_cast<Q>(da), b = vec_cast<Q>(db);
  const Q a2 = squared_norm(a), b2 = squared_norm(b), c2 = squared_norm(cross(a, b));
  const Q t(PS::tol()), lo(PS::min_len2()), hi(PS::max_len2()), pmin(PS::min_p());
  if (a2 < lo || b2 < lo || a2 > hi || b2 > hi || Q(t * t * a2 * b2) < pmin) return ParallelBand::unknown;
  const Q K(PS::sine_bound());
  return c2 <= K * K * a2 * b2 ? ParallelBand::inside : ParallelBand::outside;
}

}  // namespace sepax::fuzz
