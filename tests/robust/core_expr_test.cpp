// CORE::Expr as a sepax number type: exact, with exact sqrt, normalising.  The
// SATs must pick the same features as with mpq, and the normalised separation
// must be the exact distance: equal to the mpq squared form when squared.
#include <catch2/catch.hpp>
#include <sepax/robust/core_expr.hpp>
#include <sepax/robust/number_types.hpp>

#include "sat_cases.hpp"

using namespace sepax;
using namespace sepax::test;
using Expr = CORE::Expr;

static_assert(Number<Expr>);
static_assert(ExactNumber<Expr>);
static_assert(SqrtNumber<Expr>);
static_assert(number_traits<Expr>::normalizes);

TEST_CASE("core_expr: traits", "[core_expr]") {
  CHECK(from_double<Expr>(0.1) == Expr(0.1));
  CHECK(from_double<Expr>(0.1) != Expr(1) / Expr(10));  // the double, exactly
  CHECK(number_traits<Expr>::sqrt(Expr(2)) * number_traits<Expr>::sqrt(Expr(2)) == Expr(2));
  CHECK_THROWS_AS(from_double<Expr>(std::nan("")), InvalidInput);
  CHECK(to_double(Expr(1) / Expr(3)) == Approx(1.0 / 3.0));
  CHECK(to_core_expr(mpq_class(1, 3)) * Expr(3) == Expr(1));
}

TEST_CASE("core_expr: box at a rational offset: the separation is exactly the distance", "[core_expr][sat]") {
  const auto a = shapes::cube<Expr>(1.0);
  const Expr third = Expr(1) / Expr(3);
  const auto b = translated(a, Vec3<Expr>(Expr(0), Expr(0), Expr(Expr(2) - third)));
  for (const auto& r : {sat::brute_force(a, b), sat::gauss_map(a, b)}) {
    CHECK(r.overlap);
    CHECK(r.feature == Feature::face_a(1, 0));
    CHECK(r.separation.norm2 == Expr(1));
    CHECK(r.separation.num == -third);
    CHECK((r.axis == Vec3<Expr>(Expr(0), Expr(0), Expr(1))));
  }
  const auto apart = translated(a, Vec3<Expr>(Expr(0), Expr(0), Expr(Expr(2) + third)));
  const auto s = sat::gauss_map(a, apart);
  CHECK_FALSE(s.overlap);
  CHECK(s.separation.num == third);
}

TEST_CASE("core_expr: hand-checked configurations (irrational separations exactly)", "[core_expr][sat]") {
  for (const auto& c : known_cases<Expr>()) {
    check_known(c, sat::brute_force(c.a, c.b));
    check_known(c, sat::gauss_map(c.a, c.b));
  }
}

TEST_CASE("core_expr: triangle across a box edge: separation^2 == the mpq squared form", "[core_expr][sat]") {
  const auto ce = known_cases<Expr>();
  const auto cq = known_cases<mpq_class>();
  REQUIRE(ce.size() == cq.size());
  int irrational = 0;
  for (std::size_t i = 0; i < ce.size(); ++i) {
    const auto re = sat::gauss_map(ce[i].a, ce[i].b);
    const auto rq = sat::gauss_map(cq[i].a, cq[i].b);
    INFO(ce[i].name);
    CHECK(re.feature == rq.feature);
    CHECK(sign(re.separation) == sign(rq.separation));
    const mpq_class sq = rq.separation.num * rq.separation.num / rq.separation.norm2;
    CHECK(re.separation.num * re.separation.num == to_core_expr(sq));
    irrational += rq.separation.norm2 != 1 && ce[i].name.find("edge") != std::string::npos;
  }
  CHECK(irrational > 0);
}

TEST_CASE("core_expr: same features as mpq on random rational poses", "[core_expr][sat][oracle]") {
  const auto ze = zoo<Expr>();
  const auto zq = zoo<mpq_class>();
  std::mt19937 rng(3);
  for (int it = 0; it < 16; ++it) {
    const auto pa = random_pose(rng, 8), pb = random_pose(rng, 8);
    const std::size_t ia = static_cast<std::size_t>(it) % ze.size(),
                      ib = static_cast<std::size_t>(it / 3) % ze.size();
    const auto ae = apply_pose(ze[ia], pa), be = apply_pose(ze[ib], pb);
    const auto aq = apply_pose(zq[ia], pa), bq = apply_pose(zq[ib], pb);
    const auto rq = sat::gauss_map(aq, bq);
    INFO("pair " << it << ": mpq " << to_string(rq.feature));
    for (const auto& re : {sat::brute_force(ae, be), sat::gauss_map(ae, be)}) {
      CHECK(re.feature == rq.feature);
      CHECK(re.overlap == rq.overlap);
      const mpq_class sq = rq.separation.num * rq.separation.num / rq.separation.norm2;
      CHECK(re.separation.num * re.separation.num == to_core_expr(sq));
      CHECK(sign(re.separation) == sign(rq.separation));
    }
  }
}
