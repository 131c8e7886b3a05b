// The 2D polygon SAT (float, double): validation, support, hand-checked
// configurations, and the projection/geometry oracles on random polygons.
#include <catch2/catch.hpp>

#include <sepax/sat_gauss_map.hpp>
#include <sepax/shapes.hpp>

#include "polygon_cases.hpp"

using namespace sepax;
using namespace sepax::test2d;

namespace {
template <class T>
ErrorCode error_of(std::initializer_list<std::pair<double, double>> pts) {
  try {
    (void)poly<T>(pts);
  } catch (const InvalidInput& e) {
    return e.code();
  }
  FAIL("no exception");
  return ErrorCode::Parse;
}
}  // namespace

TEMPLATE_TEST_CASE("polygon2: validation names the problem", "[sat2d]", float, double) {
  using T = TestType;
  CHECK(error_of<T>({{0, 0}, {1, 0}}) == ErrorCode::TooFewPoints);
  CHECK(error_of<T>({{0, 0}, {1, 0}, {1, 0}, {0, 1}}) == ErrorCode::DegenerateFace);            // duplicate
  CHECK(error_of<T>({{0, 0}, {0, 1}, {1, 1}, {1, 0}}) == ErrorCode::InwardFaces);               // clockwise
  CHECK(error_of<T>({{0, 0}, {2, 0}, {1, 0.25}, {2, 2}, {0, 2}}) == ErrorCode::NonConvexFace);  // reflex
  CHECK(error_of<T>({{0, 0}, {1, 1}, {2, 2}}) == ErrorCode::DegenerateFace);  // collinear: no area
  // pentagram: turns left at every corner but winds twice
  CHECK(error_of<T>({{1, 0}, {-0.809, 0.588}, {0.309, -0.951}, {0.309, 0.951}, {-0.809, -0.588}}) ==
        ErrorCode::NonConvexFace);
  CHECK(error_of<T>({{0, 0}, {1, 0}, {std::nan(""), 1}}) == ErrorCode::NonFinite);
  try {
    (void)poly<T>({{0, 0}, {0, 1}, {1, 0}});
    FAIL("clockwise accepted");
  } catch (const InvalidInput& e) {
    CHECK(std::string(e.what()).find("clockwise") != std::string::npos);
  }
  CHECK_NOTHROW(poly<T>({{0, 0}, {1, 0}, {0, 1}}));
}

TEMPLATE_TEST_CASE("polygon2: support and normals", "[sat2d]", float, double) {
  using T = TestType;
  const auto sq = poly<T>({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
  CHECK(sq.support(p2<T>(1, 0.5)) == 2);
  CHECK(sq.support(p2<T>(-1, -0.5)) == 0);
  CHECK(sq.support(p2<T>(1, 0)) == 1);  // tie between 1 and 2: lowest index
  CHECK(sq.normal(0) == p2<T>(0, -1));  // edge 0 runs along -y side
  CHECK(sq.normal(1) == p2<T>(1, 0));
  CHECK(sq.offset(1) == T(1));
}

TEMPLATE_TEST_CASE("polygon2: hand-checked configurations", "[sat2d]", float, double) {
  using T = TestType;
  const auto sq = poly<T>({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});  // edges: 0 -y, 1 +x, 2 +y, 3 -x
  SECTION("overlapping squares: A's +x edge and B's -x edge tie at -1/2: A first") {
    const auto r = sat2::polygon_sat(sq, moved(sq, p2<T>(1.5, 0.25)));
    CHECK(r.overlap);
    CHECK(r.feature == Feature::face_a(1, 0));
    CHECK(r.separation_as_double() == -0.5);
    CHECK(r.axis == p2<T>(1, 0));
  }
  SECTION("separated: +y edge, separation 1/4") {
    const auto b = moved(sq, p2<T>(0.5, 2.25));
    const auto r = sat2::polygon_sat(sq, b);
    CHECK_FALSE(r.overlap);
    CHECK(r.feature == Feature::face_a(2, 0));
    CHECK(r.separation_as_double() == 0.25);
    CHECK_FALSE(sat2::overlap(sq, b));
    const auto e = sat2::polygon_sat(sq, b, true);
    CHECK(e.early_out);
    CHECK_FALSE(e.overlap);
  }
  SECTION("exactly touching at a corner: overlap, separation exactly 0") {
    const auto r = sat2::polygon_sat(sq, moved(sq, p2<T>(2, 2)));
    CHECK(r.overlap);
    CHECK(r.separation_as_double() == 0.0);
    CHECK(r.feature == Feature::face_a(1, 0));
    CHECK(sat2::overlap(sq, moved(sq, p2<T>(2, 2))));
  }
  SECTION("vertex of a diamond into an edge: the diamond's edges are worse") {
    const auto d = poly<T>({{0, -1}, {1, 0}, {0, 1}, {-1, 0}});
    const auto b = moved(d, p2<T>(0, 1.75));  // lowest vertex (0) at y = 0.75
    const auto r = sat2::polygon_sat(sq, b);
    CHECK(r.overlap);
    CHECK(r.feature == Feature::face_a(2, 0));
    CHECK(r.separation_as_double() == -0.25);
    const auto s = sat2::polygon_sat(b, sq);  // swapped: B's edge, A's vertex
    CHECK(s.feature == Feature::face_b(0, 2));
    CHECK(s.separation_as_double() == -0.25);
    CHECK(s.axis == p2<T>(0, -1));
  }
  SECTION("triangle: FaceB wins when B's edge separates more") {
    const auto t = poly<T>({{0, 0}, {4, 0}, {0, 4}});
    const auto b = moved(t, p2<T>(-4, -4.5));  // its hypotenuse x+y = -4.5 - ... below-left of sq
    const auto r = sat2::polygon_sat(sq, b);
    const auto o = projection_oracle(sq, b);
    CHECK(r.feature == o.second);
    CHECK(compare(r.separation, o.first) == 0);
    CHECK(r.feature.type == FeatureType::FaceB);
    CHECK(r.feature.b == 1);  // the hypotenuse
  }
}

TEMPLATE_TEST_CASE("polygon2: SAT agrees with the projection and geometry oracles", "[sat2d][oracle]", float,
                   double) {
  using T = TestType;
  std::mt19937 rng(2013);
  std::uniform_int_distribution<int> cd(-20, 20);
  int overlaps = 0, n = 0;
  for (int it = 0; it < 400; ++it) {
    const T ra = T(from_double<T>(1 + it % 3) / T(2));
    const auto a = random_circle_polygon<T>(rng, ra, p2<T>(0, 0));
    const auto b = random_circle_polygon<T>(rng, T(1), p2<T>(cd(rng) / 8.0, cd(rng) / 8.0));
    const auto r = sat2::polygon_sat(a, b);
    const auto o = projection_oracle(a, b);
    const double tol = 1e3 * number_traits<T>::unit_roundoff * (a.extent() + b.extent());
    INFO("case " << it << ": " << to_string(r.feature) << " " << r.separation_as_double() << " oracle "
                 << to_string(o.second) << " " << to_double(o.first));
    CHECK(r.separation_as_double() == Approx(to_double(o.first)).margin(tol));
    if (!(r.feature == o.second)) CHECK(std::abs(r.separation_as_double() - to_double(o.first)) <= tol);
    CHECK(r.overlap == sat2::overlap(a, b));
    if (std::abs(r.separation_as_double()) > tol) CHECK(r.overlap == geometric_overlap(a, b));
    overlaps += r.overlap;
    ++n;
  }
  CHECK(overlaps > n / 10);
  CHECK(overlaps < n - n / 10);
}

// The case the 3D SATs cannot decide (docs/sat.md): coplanar flat shapes.
TEMPLATE_TEST_CASE("coplanar_sat decides coplanar polygons in their plane", "[sat2d][coplanar]", float,
                   double) {
  using T = TestType;
  const auto v = [](double x, double y, double z) { return vec_from_double<T>(Vec3<double>(x, y, z)); };
  // a tilted plane x + y + 2z = 2 (exactly representable points)
  const auto t1 = ConvexPolyhedron<T>::polygon({v(2, 0, 0), v(0, 2, 0), v(0, 0, 1)});
  const auto far =
      ConvexPolyhedron<T>::polygon({v(4, 2, -2), v(6, 0, -2), v(6, 2, -3)});  // same plane, apart
  const auto near = ConvexPolyhedron<T>::polygon({v(1, 1, 0), v(3, 1, -1), v(1, 3, -1)});  // shares (1,1,0)
  const auto inside = ConvexPolyhedron<T>::polygon({v(0.5, 0.5, 0.5), v(1, 0.5, 0.25), v(0.5, 1, 0.25)});
  // (the 3D SAT says "touching" here in exact arithmetic; in float it depends on rounding)
  const auto r = sat2::coplanar_sat(t1, far);
  CHECK_FALSE(r.overlap);
  CHECK(r.separation_as_double() > 0);
  CHECK(sat2::coplanar_sat(t1, near).overlap);
  CHECK(sat2::coplanar_sat(t1, near).separation_as_double() == 0.0);  // touching at a vertex
  CHECK(sat2::coplanar_sat(t1, inside).overlap);
  CHECK(sat2::coplanar_sat(inside, t1).overlap);
  // features use 3D indices: an edge of A (or B) and a vertex of the other
  const auto f = r.feature;
  if (f.type == FeatureType::FaceA) {
    CHECK(f.a >= 0);
    CHECK(f.a < t1.edge_count());
  } else {
    CHECK(f.b >= 0);
    CHECK(f.b < far.edge_count());
  }
  CHECK_THROWS_AS(sat2::coplanar_sat(t1, ConvexPolyhedron<T>::polygon({v(0, 0, 0), v(1, 0, 0), v(0, 1, 0)})),
                  std::invalid_argument);
  CHECK_THROWS_AS(sat2::coplanar_sat(shapes::cube<T>(1.0), t1), std::invalid_argument);
}
