// sat::gauss_map: hand-checked configurations (float, double) and the
// brute-force oracle on random poses.
#include <catch2/catch.hpp>

#include "sat_cases.hpp"

using namespace sepax;
using namespace sepax::test;

TEMPLATE_TEST_CASE("gauss map: hand-checked configurations", "[sat][gauss_map]", float, double) {
  for (const auto& c : known_cases<TestType>()) check_known(c, sat::gauss_map(c.a, c.b));
}

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

TEMPLATE_TEST_CASE("gauss map: early_out and stats", "[sat][gauss_map][stats]", float, double) {
  using T = TestType;
  const auto a = shapes::tetrahedron<T>(1.0);
  const auto overlapping = translated(a, v3<T>(0, 0, 1.75));
  const auto r = sat::gauss_map(a, overlapping);
  const auto bf = sat::brute_force(a, overlapping);
  CHECK_FALSE(r.early_out);
  CHECK(r.stats.face_axes == 8);
  CHECK(r.stats.edge_pairs == 36);
  // The arc test keeps exactly the pairs the brute force finds supported.
  CHECK(r.stats.minkowski_faces == bf.stats.minkowski_faces);
  CHECK(r.stats.minkowski_faces > 0);
  CHECK(r.stats.minkowski_faces < r.stats.edge_pairs);

  const auto separated = translated(a, v3<T>(0, 0, 2.5));
  const auto e = sat::gauss_map(a, separated, SatOptions{true});
  CHECK(e.early_out);
  CHECK_FALSE(e.overlap);
  CHECK(e.feature.type == FeatureType::EdgePair);
  CHECK(e.separation_as_double() > 0);
  CHECK(e.stats.face_axes == 8);
  CHECK(e.stats.edge_pairs <= 36);
  const auto f = sat::gauss_map(a, separated);
  CHECK_FALSE(f.early_out);
  CHECK(f.stats.edge_pairs == 36);
  CHECK(f.feature == sat::brute_force(a, separated).feature);
}

// Random rational poses of the shape zoo, evaluated in T: brute force and Gauss
// map must agree on the verdict and the feature.  In floating point two
// different features may legitimately win when their separations are within
// rounding of each other; such near-ties are counted and must stay rare, and
// the two separations must then agree to rounding.
TEMPLATE_TEST_CASE("gauss map agrees with brute force on random poses", "[sat][gauss_map][oracle]", float,
                   double) {
  using T = TestType;
  const auto shapes_ = zoo<T>();
  std::mt19937 rng(20130327);
  const double eps = number_traits<T>::unit_roundoff * 1e4;  // relative to the extents
  int pairs = 0, overlaps = 0, near_ties = 0, feature_mismatch = 0, verdict_mismatch = 0;
  for (int it = 0; it < 600; ++it) {
    const auto& sa = shapes_[static_cast<std::size_t>(it) % shapes_.size()];
    const auto& sb = shapes_[static_cast<std::size_t>(it / 7) % shapes_.size()];
    const auto a = apply_pose(sa, random_pose(rng, 8));
    const auto b = apply_pose(sb, random_pose(rng, 8));
    const auto bf = sat::brute_force(a, b);
    const auto gm = sat::gauss_map(a, b);
    ++pairs;
    overlaps += gm.overlap;
    const double tol = eps * (a.extent() + b.extent());
    const double d = std::abs(bf.separation_as_double() - gm.separation_as_double());
    INFO("pair " << it << ": bf " << to_string(bf.feature) << " " << bf.separation_as_double() << ", gm "
                 << to_string(gm.feature) << " " << gm.separation_as_double());
    CHECK(d <= tol);
    if (bf.overlap != gm.overlap) {
      ++verdict_mismatch;
      CHECK(std::abs(gm.separation_as_double()) <= tol);  // only at touching
    }
    if (!(bf.feature == gm.feature)) {
      if (d <= tol) {
        ++near_ties;
      } else {
        ++feature_mismatch;
      }
    }
  }
  INFO("pairs " << pairs << " overlapping " << overlaps << " near ties " << near_ties);
  CHECK(feature_mismatch == 0);
  CHECK(near_ties * 50 <= pairs);
  CHECK(verdict_mismatch * 100 <= pairs);
  // the sample must exercise both verdicts
  CHECK(overlaps > pairs / 10);
  CHECK(overlaps < pairs - pairs / 10);
}
