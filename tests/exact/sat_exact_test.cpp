#include <catch2/catch.hpp>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <sepax/robust/number_types.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/shapes.hpp>

using namespace sepax;

TEMPLATE_TEST_CASE("exact box on box", "[sat][exact]", mpq_class, CGAL::Gmpq, CGAL::Epeck::FT) {
  using T = TestType;
  const auto a = shapes::cube<T>(1.0);
  std::vector<Vec3<T>> moved;
  for (const auto& v : a.vertices()) moved.push_back(Vec3<T>(v + Vec3<T>(T(0), T(0), T(2))));
  const auto b = a.with_vertices(moved);
  const auto r = sat::gauss_map(a, b);
  CHECK(r.overlap);  // exactly touching
  CHECK(sign(r.separation) == 0);
  CHECK(r.feature == Feature::face_a(1, 0));
  CHECK(r.feature == sat::brute_force(a, b).feature);
}
