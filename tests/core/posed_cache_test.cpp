// Warm starts (SatCache with the posed queries): along coherent pose
// sequences (resting, sliding, rolling) the cached query returns exactly the
// fresh query's result; foreign and stale caches are harmless.
#include <random>

#include <catch2/catch.hpp>

#include <sepax/prepared_shape.hpp>

#include "core/posed_cases.hpp"

using namespace sepax;
using namespace sepax::test;

TEMPLATE_TEST_CASE("warm posed queries equal fresh ones along coherent sequences (plain)", "[posed][cache]",
                   float, double) {
  using T = TestType;
  std::mt19937_64 rng(1821);
  const auto shapes = local_shapes<T>(rng);
  CHECK(check_warm_sequences<policy::Plain>(shapes, 40) == 7 * 7 * 3 * 3 * 40);
}

TEST_CASE("a cache from another pair or of stale shapes is harmless", "[posed][cache]") {
  std::mt19937_64 rng(1822);
  const auto shapes = local_shapes<double>(rng);
  std::vector<PreparedShape<double>> prepared;
  for (const auto& s : shapes) prepared.emplace_back(s);
  SatCache<double> foreign;
  for (int q = 0; q < 400; ++q) {
    const std::size_t i = rng() % shapes.size(), j = rng() % shapes.size();
    const auto pa = random_pose<double>(rng, 1.2), pb = random_pose<double>(rng, 1.2);
    for (SatAlgorithm alg : kSatAlgorithms) {
      const auto fresh = sat::run(alg, prepared[i], pa, prepared[j], pb);
      // the cache last held some other pair (and a random feature now and then)
      if (q % 7 == 0) {
        foreign.valid = true;
        foreign.feature = Feature::edges(static_cast<int>(rng() % 40) - 3, static_cast<int>(rng() % 40));
      }
      const auto warm = sat::run(alg, prepared[i], pa, prepared[j], pb, SatOptions{}, &foreign);
      REQUIRE(warm.feature == fresh.feature);
      require_same_separation(warm.separation, fresh.separation);
      REQUIRE(warm.overlap == fresh.overlap);
    }
  }
}

TEMPLATE_TEST_CASE("warm early-out answers decided on a partial posed B equal those on the full B (plain)",
                   "[posed][cache]", float, double) {
  using T = TestType;
  std::mt19937_64 rng(1825);
  const auto shapes = local_shapes<T>(rng);
  const WarmCounts n = check_warm_against_reference<policy::Plain>(shapes, rng, 3, [](auto&&...) {});
  check_every_warm_path_taken(n);
}
