// SatCache: replaying poses along smooth rigid paths, a cached query equals a
// fresh query at every step (full queries: identical results; early-out
// queries: the same verdict, and a hit reports a separating feature with the
// separation the SATs compute for it).
#include <catch2/catch.hpp>

#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_cache.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/sat_traversal.hpp>
#include <sepax/shapes.hpp>

#include "traversal_shapes.hpp"

using namespace sepax;
using test::V3;

namespace {

// One rigid path: B turns about a fixed axis and slides along a line through A.
struct Path {
  V3 axis, from, to;
  double turns;
  Eigen::Matrix3d rotation(double s) const {
    return Eigen::AngleAxisd(turns * 6.283185307179586 * s, axis).toRotationMatrix();
  }
  V3 position(double s) const { return (1 - s) * from + s * to; }
};

template <class Run>
void replay(const ConvexPolyhedron<double>& a, const ConvexPolyhedron<double>& b0, const Path& path,
            int steps, Run run, std::int64_t& hits, std::int64_t& separated_steps) {
  SatCache<double> full_cache, eo_cache;
  for (int i = 0; i <= steps; ++i) {
    const double s = static_cast<double>(i) / steps;
    const auto b = test::moved(b0, path.rotation(s), path.position(s));
    PlainKernel<double> k(a, b);
    const auto fresh = run(k, SatOptions{});
    const auto fresh_eo = run(k, SatOptions{.early_out = true});
    const auto cached = sat::cached_with(k, full_cache, {}, run);
    INFO("step " << i << ": fresh " << to_string(fresh.feature) << " cached " << to_string(cached.feature));
    CHECK(cached.feature == fresh.feature);
    CHECK(compare(cached.separation, fresh.separation) == 0);
    CHECK(cached.overlap == fresh.overlap);
    CHECK(cached.axis == fresh.axis);
    const std::int64_t hits_before = eo_cache.hits;
    const auto eo = sat::cached_with(k, eo_cache, {.early_out = true}, run);
    const bool hit = eo_cache.hits > hits_before;
    if (!hit) {
      // a miss returns exactly the SAT's own early-out result
      CHECK(eo.feature == fresh_eo.feature);
      CHECK(compare(eo.separation, fresh_eo.separation) == 0);
    }
    CHECK(eo.overlap == fresh.overlap);
    CHECK(eo.overlap == fresh_eo.overlap);
    if (fresh.overlap) {
      // no axis separates: the cache cannot hit and the SAT's own result is returned
      CHECK(eo.feature == fresh.feature);
      CHECK(compare(eo.separation, fresh.separation) == 0);
    } else {
      ++separated_steps;
      CHECK(eo.early_out);
      CHECK(sign(eo.separation) > 0);
      if (hit) {
        // a hit reports the feature with the separation the kernel computes for it now
        const auto ev = sat::reevaluate(k, eo.feature);
        REQUIRE(ev);
        CHECK(ev->first == eo.feature);
        CHECK(compare(ev->second, eo.separation) == 0);
      }
      // and never more than the maximum separation (up to rounding: the brute
      // force measures edge axes by projection, the O(1) form rounds differently)
      CHECK(eo.separation_as_double() <= fresh.separation_as_double() + 1e-12);
    }
  }
  hits += eo_cache.hits;
}

}  // namespace

TEST_CASE("cached queries equal fresh queries along smooth paths (double, every SAT)", "[cache]") {
  std::mt19937_64 rng(99);
  const auto a = test::sphere_hull(rng, 24);
  const std::vector<ConvexPolyhedron<double>> bs{shapes::cube<double>(0.5), test::sphere_hull(rng, 16, 0.6),
                                                 shapes::regular_polygon<double>(6, 0.7),
                                                 shapes::prism<double>(10, 0.4, 0.6)};
  std::int64_t hits = 0, separated = 0;
  for (const auto& b0 : bs) {
    const GaussMapWalk wa(a), wb(b0);
    for (int p = 0; p < 4; ++p) {
      const Path path{test::random_unit(rng), V3(-3, 0.2 * p, 0.1), V3(3, -0.1 * p, 0.3), 0.5 + 0.25 * p};
      replay(
          a, b0, path, 120, [&](auto& k, const SatOptions& o) { return sat::traversal_with(k, wa, wb, o); },
          hits, separated);
      replay(
          a, b0, path, 40, [](auto& k, const SatOptions& o) { return sat::gauss_map_with(k, o); }, hits,
          separated);
      replay(
          a, b0, path, 15, [](auto& k, const SatOptions& o) { return sat::brute_force_with(k, o); }, hits,
          separated);
    }
  }
  CHECK(separated > 0);
  CHECK(hits > separated / 2);  // smooth paths: the cached feature mostly still separates
}

TEST_CASE("a stale or foreign cache never changes the answer", "[cache]") {
  const auto a = shapes::cube<double>(1.0);
  const auto b = test::moved(shapes::tetrahedron<double>(0.5), Eigen::Matrix3d::Identity(), V3(3, 0, 0));
  auto run = [](auto& k, const SatOptions& o) { return sat::gauss_map_with(k, o); };
  const auto fresh = sat::gauss_map(a, b);
  for (const Feature f : {Feature::face_a(99, 0), Feature::face_b(0, -1), Feature::edges(1000, 2),
                          Feature::edges(0, 0), Feature::face_a(0, 3), Feature::face_b(7, 2)}) {
    SatCache<double> cache;
    cache.valid = true;
    cache.feature = f;
    const auto r = sat::cached(cache, a, b, run);
    CHECK(r.feature == fresh.feature);
    CHECK(compare(r.separation, fresh.separation) == 0);
    SatCache<double> c2 = cache;
    c2.feature = f;
    const auto eo = sat::cached(c2, a, b, run, {.early_out = true});
    CHECK(eo.overlap == fresh.overlap);
    CHECK(sign(eo.separation) > 0);
  }
}
