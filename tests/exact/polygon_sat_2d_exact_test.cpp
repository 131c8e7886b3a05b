// The 2D polygon SAT in exact arithmetic (mpq_class, CGAL::Gmpq,
// CGAL::Epeck::FT): exact validation, exact agreement with the projection and
// geometry oracles (touching included), and double vs exact on the same inputs.
#include <catch2/catch.hpp>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <sepax/robust/number_types.hpp>

#include "polygon_cases.hpp"

using namespace sepax;
using namespace sepax::test2d;

TEMPLATE_TEST_CASE("polygon2 exact: collinear corners are rejected exactly", "[sat2d][exact]", mpq_class,
                   CGAL::Gmpq, CGAL::Epeck::FT) {
  using T = TestType;
  try {
    (void)poly<T>({{0, 0}, {1, 0}, {2, 0}, {1, 1}});
    FAIL("collinear corner accepted");
  } catch (const InvalidInput& e) {
    CHECK(e.code() == ErrorCode::NonConvexFace);
  }
  // 0.1 is not 1/10 as a double; exactly converted, this corner is still convex
  CHECK_NOTHROW(poly<T>({{0, 0}, {1, 0}, {1, 1}, {0.1, 1}}));
}

TEMPLATE_TEST_CASE("polygon2 exact: SAT == oracles on random rational polygons", "[sat2d][exact][oracle]",
                   mpq_class, CGAL::Gmpq, CGAL::Epeck::FT) {
  using T = TestType;
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> cd(-16, 16);
  const int n = std::is_same_v<T, CGAL::Epeck::FT> ? 80 : 250;
  int overlaps = 0, touching = 0;
  for (int it = 0; it < n; ++it) {
    const auto a = random_circle_polygon<T>(rng, T(1), p2<T>(0, 0));
    // (y drawn before x, in separate statements: the order of two draws in
    // one argument list is unspecified -- gcc and clang differ -- and the
    // touching count below depends on the sequence)
    const double cy = cd(rng) / 8.0;
    const double cx = cd(rng) / 8.0;
    auto b = random_circle_polygon<T>(rng, T(1), p2<T>(cx, cy));
    if (it % 4 == 0) {
      // make them exactly touch: move b along A's best axis by -separation
      // when that is rational (axis-aligned edge normals), else keep b.
      const auto r0 = sat2::polygon_sat(a, b);
      const Vec2<T>& ax = r0.axis;
      if (ax[0] == T(0) || ax[1] == T(0)) {
        const T len2 = T(ax[0] * ax[0] + ax[1] * ax[1]);
        const T s = T(r0.separation.num / len2);  // num / |ax|^2 * ax = sep * unit axis
        b = moved(b, Vec2<T>(T(-s * ax[0]), T(-s * ax[1])));
      }
    }
    const auto r = sat2::polygon_sat(a, b);
    const auto o = projection_oracle(a, b);
    INFO("case " << it << ": " << to_string(r.feature) << " oracle " << to_string(o.second));
    CHECK(r.feature == o.second);
    CHECK(compare(r.separation, o.first) == 0);
    CHECK(r.overlap == geometric_overlap(a, b));
    CHECK(r.overlap == sat2::overlap(a, b));
    overlaps += r.overlap;
    touching += sign(r.separation) == 0;
  }
  CHECK(overlaps > n / 10);
  CHECK(overlaps < n - n / 10);
  CHECK(touching > 0);
}

TEST_CASE("polygon2: double and exact agree on the same (exactly converted) inputs",
          "[sat2d][exact][float]") {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> cd(-16, 16);
  int same_feature = 0, n = 0;
  for (int it = 0; it < 300; ++it) {
    const auto ad = random_circle_polygon<double>(rng, 1.0, p2<double>(0, 0));
    const double cy = cd(rng) / 8.0;  // (sequenced: see above)
    const double cx = cd(rng) / 8.0;
    const auto bd = random_circle_polygon<double>(rng, 1.0, p2<double>(cx, cy));
    const auto conv = [](const Polygon2<double>& p) {
      std::vector<Vec2<mpq_class>> v;
      for (const auto& x : p.vertices()) v.push_back(Vec2<mpq_class>(mpq_class(x[0]), mpq_class(x[1])));
      return Polygon2<mpq_class>::from_vertices(std::move(v));
    };
    const auto a = conv(ad), b = conv(bd);
    const auto rd = sat2::polygon_sat(ad, bd);
    const auto rq = sat2::polygon_sat(a, b);
    const double tol = 1e-12;
    INFO("case " << it << ": double " << to_string(rd.feature) << " " << rd.separation_as_double() << ", mpq "
                 << to_string(rq.feature) << " " << rq.separation_as_double());
    CHECK(rd.separation_as_double() == Approx(rq.separation_as_double()).margin(tol));
    if (std::abs(rq.separation_as_double()) > tol) CHECK(rd.overlap == rq.overlap);
    same_feature += rd.feature == rq.feature;
    ++n;
  }
  CHECK(same_feature * 100 >= n * 98);
}
