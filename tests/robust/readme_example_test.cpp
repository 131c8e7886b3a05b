// The API example of README.md, verbatim where it can be, with its comments
// turned into assertions: the README must not promise what the code does not do.
#include <catch2/catch.hpp>

#include <sepax/contact_manifold.hpp>
#include <sepax/robust/number_types.hpp>
#include <sepax/robust/robust_kernel.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/sat_traversal.hpp>
#include <sepax/shapes.hpp>

using namespace sepax;

TEST_CASE("README: double-sided triangle lying on a box face", "[readme]") {
  const auto box = shapes::box<double>(1.0, 1.0, 0.5);
  // A double-sided triangle lying on the box's top face (z = 0.5).
  const auto tri = shapes::triangle<double>({-0.5, -0.5, 0.5}, {0.5, -0.5, 0.5}, {0.0, 0.5, 0.5});

  const SatResult<double> r = sat::gauss_map(box, tri);  // policy::Plain, double
  CHECK(r.overlap);
  CHECK(r.feature == Feature::face_a(1, 0));
  CHECK(r.separation_as_double() == 0.0);
  CHECK(r.axis == Vec3<double>(0, 0, 1));
  const ContactManifold<double> m = contact_manifold(box, tri, r);
  CHECK(m.size() == 3);
  for (const auto& p : m.points) CHECK(p.depth() == 0.0);

  const auto r_robust = sat::traversal<policy::Robust>(box, tri);  // float values, exact decisions
  const auto ea = ConvexPolyhedron<mpq_class>::convert_from(box);  // the exact image: same
  const auto eb = ConvexPolyhedron<mpq_class>::convert_from(tri);  // combinatorics, exact planes
  const auto r_exact = sat::brute_force(ea, eb);                   // exact feature and separation
  CHECK(r_exact.overlap);
  CHECK(sign(r_exact.separation) == 0);
  CHECK(r_exact.feature == r.feature);
  CHECK(r_robust.feature == r_exact.feature);
  CHECK(r_robust.overlap == r_exact.overlap);
}
