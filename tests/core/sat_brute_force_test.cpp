// sat::brute_force on hand-checked configurations (float, double), the
// tie-break rule, early_out and stats.  The exact-type versions of the same
// cases are in tests/exact/sat_exact_test.cpp.
#include <catch2/catch.hpp>

#include "sat_cases.hpp"

using namespace sepax;
using namespace sepax::test;

TEMPLATE_TEST_CASE("brute force: hand-checked configurations", "[sat][brute_force]", float, double) {
  for (const auto& c : known_cases<TestType>()) check_known(c, sat::brute_force(c.a, c.b));
}

TEST_CASE("feature order: FaceA < FaceB < EdgePair, then by index", "[sat][feature]") {
  CHECK(precedes(Feature::face_a(0, 7), Feature::face_a(1, 0)));
  CHECK_FALSE(precedes(Feature::face_a(1, 0), Feature::face_a(0, 7)));
  // the support vertex is not part of the order
  CHECK_FALSE(precedes(Feature::face_a(2, 0), Feature::face_a(2, 5)));
  CHECK_FALSE(precedes(Feature::face_a(2, 5), Feature::face_a(2, 0)));
  CHECK(precedes(Feature::face_a(9, 0), Feature::face_b(0, 0)));
  CHECK(precedes(Feature::face_b(9, 0), Feature::face_b(0, 1)));  // by B's face, not the vertex
  CHECK(precedes(Feature::face_b(0, 99), Feature::edges(0, 0)));
  CHECK(precedes(Feature::edges(0, 5), Feature::edges(1, 0)));
  CHECK(precedes(Feature::edges(1, 0), Feature::edges(1, 1)));
  CHECK_FALSE(precedes(Feature::edges(1, 1), Feature::edges(1, 1)));
}

TEMPLATE_TEST_CASE("brute force: tie-break prefers A's faces, then B's, then edges",
                   "[sat][brute_force][tie]", float, double) {
  using T = TestType;
  // Box on box, exactly touching: A's top face, B's bottom face and the crossing
  // top/bottom edge pairs all give exactly 0.
  const auto a = shapes::cube<T>(1.0);
  const auto b = translated(a, v3<T>(0, 0, 2));
  const auto ab = sat::brute_force(a, b);
  CHECK(ab.feature == Feature::face_a(1, 0));
  CHECK(ab.separation_as_double() == 0.0);
  CHECK(ab.overlap);
  // Swapped: A's bottom face (0) is the same plane; still FaceA, support vertex
  // = lowest index among B's top vertices 4..7.
  const auto ba = sat::brute_force(b, a);
  CHECK(ba.feature == Feature::face_a(0, 4));
  // Rotating A by a quarter turn about z keeps its faces in the same planes,
  // so the same face of A still wins (face indices, not positions, decide).
  const auto qa = posed(a, Mat3<T>{T(0), T(-1), T(0), T(1), T(0), T(0), T(0), T(0), T(1)}, v3<T>(0, 0, 0));
  CHECK(sat::brute_force(qa, b).feature == Feature::face_a(1, 0));
}

TEMPLATE_TEST_CASE("brute force: early_out and stats", "[sat][brute_force][stats]", float, double) {
  using T = TestType;
  const auto a = shapes::cube<T>(1.0);
  const auto b = shapes::tetrahedron<T>(1.0);
  SECTION("full scan counts every candidate") {
    const auto r = sat::brute_force(a, translated(b, v3<T>(0.5, 0.25, 0)));
    CHECK_FALSE(r.early_out);
    CHECK(r.stats.face_axes == a.face_count() + b.face_count());
    CHECK(r.stats.edge_pairs == a.edge_count() * b.edge_count());
    CHECK(r.stats.minkowski_faces > 0);
    CHECK(r.stats.minkowski_faces <= r.stats.edge_pairs);
    CHECK(r.stats.exact_fallbacks == 0);
  }
  SECTION("early_out stops at the first separating face axis") {
    // Separated along +x: A's faces are visited in order -z, +z, -y, +y, -x, +x.
    const auto bx = translated(b, v3<T>(3, 0, 0));
    const auto full = sat::brute_force(a, bx);
    const auto r = sat::brute_force(a, bx, SatOptions{true});
    CHECK_FALSE(full.overlap);
    CHECK_FALSE(r.overlap);
    CHECK(r.early_out);
    CHECK(r.stats.face_axes == 6);
    CHECK(r.feature == Feature::face_a(5, full.feature.b));
    CHECK(r.stats.edge_pairs == 0);
  }
  SECTION("early_out on an edge axis") {
    // Crossed tetrahedra separated along z by 1/2: no face axis separates.
    const auto bz = translated(b, v3<T>(0, 0, 2.5));
    const auto r = sat::brute_force(b, bz, SatOptions{true});
    CHECK_FALSE(r.overlap);
    CHECK(r.early_out);
    CHECK(r.feature.type == FeatureType::EdgePair);
    CHECK(r.separation_as_double() > 0);
    CHECK(r.stats.face_axes == 8);
    CHECK(r.stats.edge_pairs <= 36);
  }
  SECTION("early_out changes nothing when the shapes overlap") {
    const auto bo = translated(b, v3<T>(0.5, 0, 0));
    const auto full = sat::brute_force(a, bo);
    const auto r = sat::brute_force(a, bo, SatOptions{true});
    CHECK(full.overlap);
    CHECK(r.overlap);
    CHECK_FALSE(r.early_out);
    CHECK(r.feature == full.feature);
    CHECK(r.separation_as_double() == full.separation_as_double());
  }
}
