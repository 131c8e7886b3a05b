// best_axis.hpp: the side axes of two flat shapes (scan_side_axes), as every
// SAT sees them.  The known cases (sat_cases.hpp: gap in the plane, facing
// edges, touching at a vertex) are checked with each SAT's own test; here: the
// SATs agree with each other and with the 2D SAT on random coplanar polygons,
// side axes are looked at only when both shapes are flat, early out, and the
// cache.
#include <catch2/catch.hpp>

#include <sepax/convex_hull.hpp>
#include <sepax/polygon_sat_2d.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_cache.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/sat_traversal.hpp>

#include <random>

#include <Eigen/Geometry>

#include "sat_cases.hpp"

using namespace sepax;
using namespace sepax::test;

namespace {

// A random convex polygon in the plane z = z0: the hull of n integer points
// in [x0, x0 + 8] x [y0, y0 + 8] (a flat ConvexPolyhedron; nullopt when the
// points are collinear).
template <class T>
std::optional<ConvexPolyhedron<T>> random_polygon(std::mt19937& rng, int n, int x0, int y0, int z0) {
  std::uniform_int_distribution<int> d(0, 8);
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < n; ++i) pts.push_back(v3<T>(x0 + d(rng), y0 + d(rng), z0));
  try {
    auto p = convex_hull<T>(pts);
    if (!p.is_flat()) return std::nullopt;
    return p;
  } catch (const InvalidInput&) {
    return std::nullopt;
  }
}

}  // namespace

TEMPLATE_TEST_CASE("side axes: coplanar triangles with a gap are separated by every SAT", "[sat][side]",
                   float, double) {
  using T = TestType;
  const auto c = coplanar_separated_triangles<T>();
  // A = (-2,-2), (2,-2), (0,2); B = A + (10, 0).  A's edge (2,-2)-(0,2) has
  // outward normal (2,1)/sqrt 5; B's lowest vertex along it is (8,-2) at
  // 12/sqrt 5.  B's edge (8,-2)-(10,2), normal (-2,1)/sqrt 5, gives the same
  // 12/sqrt 5 (A's vertex (2,-2)): SideA wins the tie in exact arithmetic.
  const double expected = 12 / std::sqrt(5.0);
  const GaussMapWalk wa(c.a), wb(c.b);
  for (const auto& r :
       {sat::brute_force(c.a, c.b), sat::gauss_map(c.a, c.b), sat::traversal(c.a, wa, c.b, wb)}) {
    INFO(to_string(r.feature));
    CHECK_FALSE(r.overlap);
    CHECK((r.feature.type == FeatureType::SideA || r.feature.type == FeatureType::SideB));
    CHECK(r.separation_as_double() == Approx(expected).epsilon(1e-5));
    CHECK(r.stats.side_axes == c.a.edge_count() + c.b.edge_count());
    const Vec3<double> ax = vec_to_double(r.axis);
    CHECK(ax.normalized().dot(Vec3<double>(1, 0, 0)) > 0.8);  // points from A towards B
  }
}

TEMPLATE_TEST_CASE("side axes: only for two flat shapes", "[sat][side]", float, double) {
  using T = TestType;
  const auto tri = shapes::triangle<T>(v3<T>(0, 0, 0), v3<T>(2, 0, 0), v3<T>(0, 2, 0));
  // parallel planes, directly above: the side axes are looked at, the face
  // axis (1 along z) wins
  const auto up = translated(tri, v3<T>(0, 0, 1));
  for (const auto& r : {sat::brute_force(tri, up), sat::gauss_map(tri, up)}) {
    CHECK(r.stats.side_axes == 6);
    CHECK_FALSE(r.overlap);
    CHECK(r.feature.type == FeatureType::FaceA);
    CHECK(r.separation_as_double() == 1);
  }
  // parallel planes, beside: the gap in the plane (1) is larger than the
  // distance of the planes (1/4): a side axis wins
  const auto beside = translated(tri, v3<T>(3, 0, T(1) / T(4)));
  const auto rs = sat::gauss_map(tri, beside);
  CHECK(rs.feature.type == FeatureType::SideB);
  CHECK(rs.separation_as_double() == 1);
  // a triangle lying on a box's top face, beside it (B not flat): no side axes
  const auto box = shapes::box<T>(1, 1, 1);
  const auto on_top = translated(tri, v3<T>(3, 0, 1));
  for (const auto& r : {sat::brute_force(box, on_top), sat::gauss_map(box, on_top)}) {
    CHECK(r.stats.side_axes == 0);
    CHECK_FALSE(r.overlap);
  }
  // the box's side faces separate the triangle beside it
  const auto r = sat::gauss_map(box, on_top);
  CHECK(r.feature.type == FeatureType::FaceA);
  CHECK(r.separation_as_double() == 2);
}

TEMPLATE_TEST_CASE("side axes: random coplanar polygons, every SAT agrees with the 2D SAT", "[sat][side]",
                   float, double) {
  using T = TestType;
  std::mt19937 rng(20261121);
  std::uniform_int_distribution<int> off(-10, 10), cnt(3, 9);
  int separated = 0, touching = 0, tested = 0;
  for (int it = 0; it < 400; ++it) {
    const int z = off(rng);
    const auto a = random_polygon<T>(rng, cnt(rng), 0, 0, z);
    const auto b = random_polygon<T>(rng, cnt(rng), off(rng), off(rng), z);
    if (!a || !b) continue;
    ++tested;
    const auto r2 = sat2::coplanar_sat(*a, *b);
    const GaussMapWalk wa(*a), wb(*b);
    const auto rb = sat::brute_force(*a, *b);
    const auto rg = sat::gauss_map(*a, *b);
    const auto rt = sat::traversal(*a, wa, *b, wb);
    INFO("case " << it << ": brute " << to_string(rb.feature) << " " << rb.separation_as_double() << ", 2D "
                 << sepax::to_double(r2.separation));
    // integer data in one plane: every height along the normal is exactly 0,
    // so the SATs take the side axes and agree exactly
    CHECK(rb.stats.side_axes == a->edge_count() + b->edge_count());
    CHECK(rb.overlap == r2.overlap);
    CHECK(rg.overlap == rb.overlap);
    CHECK(rt.overlap == rb.overlap);
    CHECK(rg.feature == rb.feature);
    CHECK(rt.feature == rb.feature);
    CHECK(rg.separation_as_double() == rb.separation_as_double());
    CHECK(rt.separation_as_double() == rb.separation_as_double());
    if (!rb.overlap) {
      ++separated;
      CHECK((rb.feature.type == FeatureType::SideA || rb.feature.type == FeatureType::SideB));
      CHECK(rb.separation_as_double() == Approx(sepax::to_double(r2.separation)).epsilon(1e-5));
    } else if (rb.separation_as_double() == 0) {
      ++touching;
    }
  }
  CHECK(tested > 300);
  CHECK(separated > 50);  // the generator makes both verdicts
  CHECK(tested - separated > 50);
  (void)touching;
}

TEMPLATE_TEST_CASE("side axes: a rotated coplanar pair, rounded to T", "[sat][side]", float, double) {
  using T = TestType;
  // Rounded rotated coordinates put B's vertices off A's plane by rounding:
  // the side axes still see the gap.
  const auto c = coplanar_separated_triangles<double>();
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.7, Vec3<double>(1, 2, 3).normalized()).toRotationMatrix();
  auto pose = [&](const ConvexPolyhedron<double>& p) {
    std::vector<Vec3<T>> vs;
    for (const auto& v : p.vertices())
      vs.push_back(vec_from_double<T>(Vec3<double>(rot * v + Vec3<double>(3, -1, 2))));
    return ConvexPolyhedron<T>::polygon(vs);
  };
  const auto a = pose(c.a), b = pose(c.b);
  const double expected = 12 / std::sqrt(5.0);
  const GaussMapWalk wa(a), wb(b);
  for (const auto& r : {sat::brute_force(a, b), sat::gauss_map(a, b), sat::traversal(a, wa, b, wb)}) {
    CHECK_FALSE(r.overlap);
    CHECK(r.stats.side_axes > 0);
    CHECK(r.separation_as_double() == Approx(expected).epsilon(1e-4));
  }
}

TEMPLATE_TEST_CASE("side axes: early out and the cache", "[sat][side]", float, double) {
  using T = TestType;
  const auto c = coplanar_separated_triangles<T>();
  SatOptions eo;
  eo.early_out = true;
  for (const auto& r : {sat::brute_force(c.a, c.b, eo), sat::gauss_map(c.a, c.b, eo)}) {
    CHECK_FALSE(r.overlap);
    CHECK(r.early_out);
    CHECK((r.feature.type == FeatureType::SideA || r.feature.type == FeatureType::SideB));
  }
  // the cache re-checks a side feature first, and keeps the fresh answers
  SatCache<T> cache;
  auto run = [](auto& k, const SatOptions& o) { return sat::gauss_map_with(k, o); };
  const auto first = sat::cached(cache, c.a, c.b, run, eo);
  const auto moved = translated(c.b, v3<T>(1, 0, 0));
  const auto second = sat::cached(cache, c.a, moved, run, eo);
  CHECK(cache.hits == 1);
  CHECK_FALSE(second.overlap);
  CHECK(second.feature.type == first.feature.type);
  CHECK(second.separation_as_double() > first.separation_as_double());
  // moved into overlap: the cached side feature no longer separates; the
  // fresh early-out query decides
  const auto into = translated(c.b, v3<T>(-8, 0, 0));
  const auto third = sat::cached(cache, c.a, into, run, eo);
  CHECK(third.overlap);
  CHECK(third.overlap == sat::gauss_map(c.a, into).overlap);
  // lifted off the plane by 1/4: the side axis still separates (a hit)
  SatCache<T> cache2;
  (void)sat::cached(cache2, c.a, c.b, run, eo);
  const auto lifted = translated(c.b, v3<T>(0, 0, T(1) / T(4)));
  const auto fourth = sat::cached(cache2, c.a, lifted, run, eo);
  CHECK(cache2.hits == 1);
  CHECK_FALSE(fourth.overlap);
  CHECK((fourth.feature.type == FeatureType::SideA || fourth.feature.type == FeatureType::SideB));
}

// scan_face_axes asks a kernel with face estimates (sat_kernel.hpp,
// HasFaceEstimate: RobustKernel, tests/robust/robust_kernel_test.cpp) for the
// certified face query only where it can matter; plain and exact kernels have
// none and certify every face, as before.
TEST_CASE("face estimates: plain kernels certify every face", "[sat][estimate]") {
  STATIC_REQUIRE(!HasFaceEstimate<PlainKernel<float>>);
  STATIC_REQUIRE(!HasFaceEstimate<PlainKernel<double>>);
}
