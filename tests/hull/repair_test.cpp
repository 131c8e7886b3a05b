// hull/repair.hpp and the repair loop of convex_hull.hpp (build_hull): a repair pass that repeats the one
// before (Builder::repeats: the same result, the same points taken out by the clean-up, only points already
// pinned left out) ends the repairs.
// On the stress streams of tests/core/hull_point_sets.hpp, in float and double: the passes run to the
// end (kHullMaxRepairs, as build_hull ran them before it stopped at a repeat) choose the same polytope
// as build_hull, and every pass after a repeat repeats it again; the streams do contain repeats.
// A pass that goes on from its own triangles (a local removal) and whose result validation refuses builds
// from the start instead (Builder::finish, faces_of_local_surface).
#include <catch2/catch.hpp>

#include <sepax/convex_hull.hpp>

#include "core/hull_point_sets.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace {

using sepax::Vec3;
using sepax::hull::detail::Builder;
using sepax::hull::detail::RepairLog;

struct AllPasses {
  std::uint64_t digest = 0;  ///< of the chosen result
  int repeats = 0;           ///< passes that repeated the one before
  int repeated_again = 0;    ///< passes after a repeat that repeated it once more
  bool broke = false;        ///< a pass after a repeat that did not repeat it
};

// build_hull's loop without its stop at a repeat: every repair pass up to kHullMaxRepairs.
template <class T>
AllPasses all_passes(std::span<const Vec3<T>> points) {
  AllPasses r;
  Builder<T> b(points, true);
  b.check_input();
  b.weld();
  RepairLog<T> log;
  std::vector<int> pinned, last_outside;
  std::uint64_t last = 0;
  bool repeating = false;
  for (int pass = 0;; ++pass) {
    std::optional<sepax::ConvexPolyhedron<T>> hull = b.build_pass(log.nearest.has_value(), pinned);
    std::vector<int> outside;
    const std::uint64_t d = hull ? Builder<T>::digest(*hull) : 0;
    if (hull) b.measure(std::move(*hull), outside, log);
    if (repeating) {
      if (hull && d == last && outside == last_outside) {
        ++r.repeated_again;
      } else {
        r.broke = true;
      }
    }
    if (!hull || outside.empty() || pass == sepax::kHullMaxRepairs) {
      r.digest = Builder<T>::digest(b.choose_result(log));
      return r;
    }
    if (pass > 0 && b.repeats(d, last, outside)) {
      ++r.repeats;
      repeating = true;
    }
    last = d;
    last_outside = outside;
    b.pin(outside);
    pinned = outside;
  }
}

template <class T>
void check_stream(unsigned seed, int sets, int& repeats, int& repeated_again) {
  std::mt19937 rng(seed);
  for (int it = 0; it < sets; ++it) {
    const auto p = sepax::hull_sets::to_t<T>(sepax::hull_sets::random_point_set(rng, it % 9));
    const std::span<const Vec3<T>> s(p.data(), p.size());
    std::optional<std::uint64_t> built;
    try {
      built = Builder<T>::digest(sepax::hull::detail::build_hull<T>(s, true));
    } catch (const sepax::InvalidInput&) {
      CHECK_THROWS_AS(all_passes<T>(s), sepax::InvalidInput);
      continue;
    }
    const AllPasses all = all_passes<T>(s);
    INFO("seed " << seed << ", set " << it);
    CHECK(all.digest == *built);
    CHECK_FALSE(all.broke);
    repeats += all.repeats;
    repeated_again += all.repeated_again;
  }
}

}  // namespace

TEMPLATE_TEST_CASE("repair passes: a repeated pass ends them, and the result is the one all passes choose",
                   "[hull][repair]", float, double) {
  int repeats = 0, repeated_again = 0;
  for (unsigned seed : {1u, 2u}) check_stream<TestType>(seed, 700, repeats, repeated_again);
  // the streams contain sets whose repair passes repeat (else the test shows nothing)
  CHECK(repeats > 0);
  CHECK(repeated_again >= repeats);
}

// A set whose second repair pass's clean-up takes out a point the first pass kept, with the same result
// (tests/data/hull_repair_removal.pts, double): the third pass starts without that point and builds
// another hull, so the second pass is not a repeat (Builder::repeats) and the passes go on.
TEST_CASE("repair passes: a pass whose clean-up took out another point is not a repeat", "[hull][repair]") {
  const auto p =
      sepax::hull_sets::read_points(std::string(SEPAX_SOURCE_DIR) + "/tests/data/hull_repair_removal.pts");
  REQUIRE(p.size() == 60);
  const std::span<const Vec3<double>> s(p.data(), p.size());
  const AllPasses all = all_passes<double>(s);
  CHECK_FALSE(all.broke);
  CHECK(all.digest == Builder<double>::digest(sepax::hull::detail::build_hull<double>(s, true)));
}

// 200 000 points of the unit sphere in float (mt19937_64 seed 5, normalised normal triples: the
// generator of the benchmark's sphere sets, hull_sets::bench_point_set, with another seed): a local
// removal of the clean-up's rejected vertices leaves a vertex whose faces wind twice around it, which
// validation refuses (a vertex 1.2 above a face plane).  The build starts over instead, and every point
// is within the hull guarantee of the faces (a sample of the points against every face).
TEST_CASE("a local removal whose surface validation refuses is built again from the start",
          "[hull][repair]") {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> nd;
  std::vector<Vec3<float>> pts;
  while (pts.size() < 200000) {
    const double x = nd(rng), y = nd(rng), z = nd(rng), l = std::sqrt(x * x + y * y + z * z);
    if (l > 0)
      pts.emplace_back(static_cast<float>(x / l), static_cast<float>(y / l), static_cast<float>(z / l));
  }
  // (the sweep searching as far as the heights reach, without the walk towards each point: the path of the
  // build that meets the case)
  struct Restore {
    ~Restore() { sepax::hull::detail::sweep_walks.store(true); }
  } restore;
  sepax::hull::detail::sweep_walks.store(false);
  const std::size_t refusals = sepax::hull::detail::local_surface_refusals.load();
  std::optional<sepax::ConvexPolyhedron<float>> h;
  REQUIRE_NOTHROW(h.emplace(sepax::convex_hull<float>(pts)));
  CHECK(sepax::hull::detail::local_surface_refusals.load() > refusals);  // the case this test is for
  CHECK(h->vertex_count() > 90000);
  double worst = -1e300;
  for (std::size_t i = 0; i < pts.size(); i += 97)
    for (int f = 0; f < h->face_count(); ++f)
      worst =
          std::max(worst, static_cast<double>(sepax::dot(h->plane(f).normal, pts[i]) - h->plane(f).offset));
  CHECK(worst / (sepax::Tolerances<float>::kCoplanar * h->extent()) <= sepax::kHullOutsideBound);
}
