// CGAL's interval filter (behind CGAL::Epeck::FT and CGAL's filtered
// predicates) rounds outward under the compiler in use.  With GCC the
// CGAL::CGAL target adds -frounding-math; with clang it adds nothing (clang 14
// has no reliable -frounding-math for this), and CGAL instead hides the
// operands from constant folding and from moves across rounding-mode changes
// with asm barriers (CGAL/FPU.h, IA_opacify).  CGAL checks this only in debug
// builds (an assertion); this test checks it in the build type we ship, for
// runtime and compile-time-constant operands.
#include <catch2/catch.hpp>

#include <CGAL/Interval_nt.h>
#include <gmpxx.h>

#include <sepax/robust/number_types.hpp>

namespace {

// inf <= exact <= sup, and the interval is not a point (exact is not a double)
void check_encloses(const CGAL::Interval_nt<>& x, const mpq_class& exact) {
  CHECK(x.inf() < x.sup());
  CHECK(mpq_class(x.inf()) <= exact);
  CHECK(exact <= mpq_class(x.sup()));
}

}  // namespace

TEST_CASE("CGAL intervals round outward (with or without -frounding-math)", "[robust][number_types]") {
  using I = CGAL::Interval_nt<>;
  // runtime operands
  volatile double one = 1.0, ten = 10.0, a = 1.1, b = 10.1;
  check_encloses(I(one) / I(ten), mpq_class(1, 10));
  check_encloses(I(a) * I(b), mpq_class(1.1) * mpq_class(10.1));
  check_encloses(-(I(-a) * I(b)), mpq_class(1.1) * mpq_class(10.1));
  const I r2 = CGAL::sqrt(I(static_cast<double>(ten) / 5));
  CHECK(r2.inf() < r2.sup());
  CHECK(mpq_class(r2.inf()) * mpq_class(r2.inf()) <= 2);
  CHECK(mpq_class(r2.sup()) * mpq_class(r2.sup()) >= 2);
  // compile-time constants: the case constant folding (in round-to-nearest)
  // would break
  check_encloses(I(1.0) / I(10.0), mpq_class(1, 10));
  check_encloses(I(1.1) * I(10.1), mpq_class(1.1) * mpq_class(10.1));
  check_encloses(-(I(-1.1) * I(10.1)), mpq_class(1.1) * mpq_class(10.1));
  check_encloses(I(0.1) + I(0.2), mpq_class(0.1) + mpq_class(0.2));
}

TEST_CASE("Epeck::FT decides signs exactly near zero", "[robust][number_types]") {
  using FT = CGAL::Epeck::FT;
  // 3 * 0.1 - 0.3 (of the doubles 0.1 and 0.3) is exactly 2^-55 (double
  // arithmetic gives 2^-54); 3 * 0.1 - 0.1 - 0.1 - 0.1 is exactly 0 (double
  // arithmetic gives 2^-55)
  CHECK(CGAL::sign(FT(0.1) * FT(3) - FT(0.3)) == CGAL::POSITIVE);
  CHECK(CGAL::sign(FT(0.1) * FT(3) - FT(0.1) - FT(0.1) - FT(0.1)) == CGAL::ZERO);
  CHECK(CGAL::sign(FT(1) / FT(3) * FT(3) - FT(1)) == CGAL::ZERO);
  CHECK(FT(1) / FT(10) * FT(10) == FT(1));
}
