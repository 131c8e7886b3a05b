#include <catch2/catch.hpp>

#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/shapes.hpp>

using namespace sepax;

TEST_CASE("box on box: face contact, depth and feature", "[sat][gauss_map]") {
  const auto a = shapes::cube<double>(1.0);
  std::vector<Vec3<double>> moved;
  for (const auto& v : a.vertices()) moved.push_back(v + Vec3<double>(0, 0, 1.75));
  const auto b = a.with_vertices(moved);
  for (const auto& r : {sat::gauss_map(a, b), sat::brute_force(a, b)}) {
    CHECK(r.overlap);
    CHECK(r.feature.type == FeatureType::FaceA);
    CHECK(r.feature.a == 1);  // +z face of A
    CHECK(r.separation_as_double() == Approx(-0.25));
    CHECK(r.axis.isApprox(Vec3<double>(0, 0, 1)));
  }
}
