// Brute-force and Gauss-map SATs in exact arithmetic (mpq_class, CGAL::Gmpq,
// CGAL::Epeck::FT): the hand-checked cases of tests/sat_cases.hpp exactly, the
// brute-force oracle on random rational poses (feature, verdict and separation
// exactly equal), and invariance under exact scaling and translation.
#include <catch2/catch.hpp>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <sepax/robust/number_types.hpp>

#include <sepax/polygon_sat_2d.hpp>

#include "sat_cases.hpp"

using namespace sepax;
using namespace sepax::test;

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

TEMPLATE_TEST_CASE("exact: hand-checked configurations", "[sat][exact]", mpq_class, CGAL::Gmpq,
                   CGAL::Epeck::FT) {
  for (const auto& c : known_cases<TestType>()) {
    check_known(c, sat::brute_force(c.a, c.b));
    check_known(c, sat::gauss_map(c.a, c.b));
  }
}

template <class T>
void check_same(const SatResult<T>& x, const SatResult<T>& y) {
  CHECK(x.feature == y.feature);
  CHECK(x.overlap == y.overlap);
  CHECK(compare(x.separation, y.separation) == 0);
}

TEMPLATE_TEST_CASE("exact: Gauss map equals brute force on random rational poses", "[sat][exact][oracle]",
                   mpq_class, CGAL::Gmpq, CGAL::Epeck::FT) {
  using T = TestType;
  const auto shapes_ = zoo<T>();
  std::mt19937 rng(7);
  const int n = std::is_same_v<T, CGAL::Epeck::FT> ? 60 : 150;
  int overlaps = 0, edge_features = 0;
  for (int it = 0; it < n; ++it) {
    const auto a = apply_pose(shapes_[static_cast<std::size_t>(it) % shapes_.size()], random_pose(rng, 8));
    const auto b =
        apply_pose(shapes_[static_cast<std::size_t>(it / 7) % shapes_.size()], random_pose(rng, 8));
    const auto bf = sat::brute_force(a, b);
    const auto gm = sat::gauss_map(a, b);
    INFO("pair " << it << ": bf " << to_string(bf.feature) << ", gm " << to_string(gm.feature));
    check_same(bf, gm);
    // The Minkowski faces the arc test keeps are exactly those the projection finds.
    CHECK(bf.stats.minkowski_faces == gm.stats.minkowski_faces);
    overlaps += gm.overlap;
    edge_features += gm.feature.type == FeatureType::EdgePair;
  }
  CHECK(overlaps > n / 10);
  CHECK(overlaps < n - n / 10);
  CHECK(edge_features > 0);
}

// Scaling both shapes by s (about the origin) and moving both by the same
// offset changes no decision in exact arithmetic: the same features, and the
// separation scales by s exactly.  s = 1e-4 and 1e4 are the doubles nearest
// those values, converted exactly.
TEMPLATE_TEST_CASE("exact: tiny, huge and far-from-origin configurations give the same features",
                   "[sat][exact][scale]", mpq_class, CGAL::Gmpq, CGAL::Epeck::FT) {
  using T = TestType;
  const auto shapes_ = zoo<T>();
  std::mt19937 rng(11);
  const int n = std::is_same_v<T, CGAL::Epeck::FT> ? 12 : 30;
  const T zero(0);
  for (int it = 0; it < n; ++it) {
    const auto a = apply_pose(shapes_[static_cast<std::size_t>(it) % shapes_.size()], random_pose(rng, 6));
    const auto b =
        apply_pose(shapes_[static_cast<std::size_t>(it / 3) % shapes_.size()], random_pose(rng, 6));
    const auto ref = sat::gauss_map(a, b);
    for (const double s : {1e-4, 1e4}) {
      for (const double off : {0.0, 1e3}) {
        const T st = from_double<T>(s);
        const Vec3<T> o = v3<T>(off, -off, off);
        const auto as = scaled(a, st, o);
        const auto bs = scaled(b, st, o);
        INFO("pair " << it << " scale " << s << " offset " << off);
        for (const auto& r : {sat::gauss_map(as, bs), sat::brute_force(as, bs)}) {
          CHECK(r.feature == ref.feature);
          CHECK(r.overlap == ref.overlap);
          CHECK(compare(r.separation, Separation<T>{T(ref.separation.num * st), ref.separation.norm2}) == 0);
        }
      }
    }
    // far from the origin at scale 1
    const Vec3<T> far = v3<T>(1e3, 1e3, -1e3);
    const auto rf = sat::gauss_map(translated(a, far), translated(b, far));
    CHECK(rf.feature == ref.feature);
    CHECK(compare(rf.separation, ref.separation) == 0);
    (void)zero;
  }
}

// Coplanar flat shapes: the side axes (best_axis.hpp) separate them in their
// plane, exactly, also in a plane tilted by an exact rotation; the 2D SAT
// (sat2::coplanar_sat) gives the same verdict and the same separation.
TEMPLATE_TEST_CASE("exact: coplanar triangles with a gap, side axes", "[sat][exact][coplanar]", mpq_class,
                   CGAL::Epeck::FT) {
  using T = TestType;
  const auto c = coplanar_separated_triangles<T>();
  // 12/sqrt 5 (see tests/core/best_axis_test.cpp), a tie of SideA (A's edge
  // 1-2) and SideB (B's edge 0-2): SideA wins.
  const Separation<T> expected{T(12), T(5)};
  const auto rot = quaternion_rotation<T>(1, 2, 3, 4);
  const auto a = posed(c.a, rot, v3<T>(0.5, 0, 0)), b = posed(c.b, rot, v3<T>(0.5, 0, 0));
  bool tilted = false;
  for (const auto& [pa, pb] : {std::pair{c.a, c.b}, std::pair{a, b}}) {
    const auto r2 = sat2::coplanar_sat(pa, pb);
    CHECK_FALSE(r2.overlap);
    for (const auto& r : {sat::brute_force(pa, pb), sat::gauss_map(pa, pb)}) {
      CHECK_FALSE(r.overlap);
      CHECK(r.feature.type == FeatureType::SideA);
      CHECK(r.feature.a == edge_between(pa, 1, 2));
      CHECK(compare(r.separation, expected) == 0);
      // the 2D SAT measures in a projection of the plane: a distance only
      // when the plane is z = const
      if (!tilted) CHECK(compare(r.separation, r2.separation) == 0);
    }
    tilted = true;
  }
  // moved by 8 along x: exactly touching at the vertex (2,-2,0) -> overlap, 0
  const auto touching = posed(translated(c.a, v3<T>(4, 0, 0)), rot, v3<T>(0.5, 0, 0));
  const auto rt = sat::gauss_map(a, touching);
  CHECK(rt.overlap);
  CHECK(sign(rt.separation) == 0);
  CHECK(rt.feature.type == FeatureType::FaceA);
  CHECK(sat2::coplanar_sat(a, touching).overlap);
}
