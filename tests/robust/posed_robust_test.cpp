// Posed queries under policy::Robust and in exact types: the posed query is
// bit for bit the pre-posed query on (A, posed(B, X)); the robust decisions
// are the exact decisions on that input (the mpq SAT on its exact image, and
// the robust SAT on transformed(B, X), which has the same vertices and exact
// planes); exact rational poses stay exact (the world-frame exact answer);
// margins decided exactly at ties.
#include <random>

#include <catch2/catch.hpp>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <sepax/prepared_shape.hpp>
#include <sepax/robust/number_types.hpp>
#include <sepax/robust/robust_kernel.hpp>

#include "core/posed_cases.hpp"

using namespace sepax;
using namespace sepax::test;

namespace {

/// Shapes and poses that make exact ties: boxes resting face on face,
/// rotated about the contact normal, and random poses.
template <Number T, class Check>
void on_pose_pairs(std::mt19937_64& rng, int random_poses, Check&& check) {
  const auto shapes = local_shapes<T>(rng);
  std::vector<PreparedShape<T>> prepared;
  for (const auto& s : shapes) prepared.emplace_back(s);
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    for (std::size_t j = 0; j < shapes.size(); ++j) {
      for (int p = 0; p < random_poses; ++p) {
        const auto pa = random_pose<T>(rng, 1.5), pb = random_pose<T>(rng, 1.5);
        check(shapes[i], prepared[i], pa, shapes[j], prepared[j], pb);
      }
    }
  }
  // resting contact: B (a box) on A's top face, turned about z, at exact
  // heights (touching, overlapping by 1/8, separated by 1/8)
  const auto box = shapes::box<T>(0.5, 0.25, 0.5);
  const PreparedShape<T> pbox(box);
  for (double dz : {1.0, 0.875, 1.125}) {
    for (long z : {0L, 1L, 2L, 5L}) {
      const auto pa = RigidTransform<T>::translation_by(Vec3<T>(T(4), T(-2), T(1)));
      const auto pb = from_integer_quaternion<T>(3, 0, 0, z, Vec3<T>(T(4), T(-2), from_double<T>(1 + dz)));
      check(box, pbox, pa, box, pbox, pb);
    }
  }
}

}  // namespace

TEMPLATE_TEST_CASE("robust posed SATs equal the pre-posed SATs bit for bit", "[posed][robust]", float,
                   double) {
  using T = TestType;
  std::mt19937_64 rng(1802);
  const auto shapes = local_shapes<T>(rng);
  const int n = check_posed_against_reference<policy::Robust>(
      shapes, rng, 4, [](std::mt19937_64& g) { return random_pose<T>(g, 1.5); });
  CHECK(n == 7 * 7 * 4 * 3 * 3);
}

TEMPLATE_TEST_CASE("robust posed decisions are the exact decisions on (A, posed(B, X))", "[posed][robust]",
                   float, double) {
  using T = TestType;
  std::mt19937_64 rng(1803);
  int checked = 0;
  std::int64_t fallbacks = 0;
  on_pose_pairs<T>(
      rng, 3,
      [&](const ConvexPolyhedron<T>& a, const PreparedShape<T>& pa_, const RigidTransform<T>& pa,
          const ConvexPolyhedron<T>& b, const PreparedShape<T>& pb_, const RigidTransform<T>& pb) {
        const auto x = relative_pose(pa, pb);
        const auto bp = posed(b, x);
        const auto ea = ConvexPolyhedron<mpq_class>::convert_from(a);
        const auto eb = ConvexPolyhedron<mpq_class>::convert_from(bp);
        const auto exact = sat::gauss_map(ea, eb);
        const auto moved = sat::traversal<policy::Robust>(a, transformed(b, x));
        for (SatAlgorithm alg : kSatAlgorithms) {
          const auto r = sat::run<policy::Robust>(alg, pa_, pa, pb_, pb);
          INFO(to_string(alg) << ": robust " << to_string(r.feature) << " " << r.separation_as_double()
                              << ", exact " << to_string(exact.feature) << " "
                              << exact.separation_as_double());
          REQUIRE(r.feature == exact.feature);
          REQUIRE(r.overlap == exact.overlap);
          REQUIRE(sign(r.separation) == sign(exact.separation));
          REQUIRE(r.feature == moved.feature);
          REQUIRE(r.overlap == moved.overlap);
          fallbacks += r.stats.exact_fallbacks;
          ++checked;
        }
      });
  CHECK(checked == (7 * 7 * 3 + 12) * 3);
  CHECK(fallbacks > 0);  // the resting boxes tie exactly: the exact stage ran
}

TEMPLATE_TEST_CASE(
    "exact posed SATs: bit for bit the pre-posed SATs, and the exact world answer under rational poses",
    "[posed][exact]", mpq_class, CGAL::Gmpq, CGAL::Epeck::FT) {
  using T = TestType;
  std::mt19937_64 rng(1804);
  const auto shapes = local_shapes<T>(rng);
  // random rational poses: posed == pre-posed (posed(B, X) is transformed(B, X) for exact T)
  check_posed_against_reference<policy::Plain>(
      shapes, rng, 1, [](std::mt19937_64& g) { return random_integer_pose<T>(g, 1.5); });
  std::vector<PreparedShape<T>> prepared;
  for (const auto& s : shapes) prepared.emplace_back(s);
  int checked = 0;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    for (std::size_t j = 0; j < shapes.size(); ++j) {
      const auto pa = random_integer_pose<T>(rng, 1.5), pb = random_integer_pose<T>(rng, 1.5);
      // the world-frame exact answer: both shapes moved rigidly and exactly
      const auto wa = transformed(shapes[i], pa), wb = transformed(shapes[j], pb);
      const auto world = sat::gauss_map(wa, wb);
      const auto r = sat::traversal(prepared[i], pa, prepared[j], pb);
      INFO("shapes " << i << ", " << j);
      REQUIRE(r.feature == world.feature);
      REQUIRE(r.overlap == world.overlap);
      REQUIRE(compare(r.separation, world.separation) == 0);
      for (int c = 0; c < 3; ++c) REQUIRE(r.axis[c] == world.axis[c]);
      ++checked;
    }
  }
  CHECK(checked == 49);
}

namespace {

/// B (a box) above A's top face at exact gap g, turned about z; A translated.
/// Every SAT with early_out and margin g (a tie), just below and just above.
template <class Policy, Number T>
void check_margin_ties() {
  const auto box = shapes::box<T>(0.5, 0.5, 0.5);
  const PreparedShape<T> a(box), b(box);
  const double g = 0.125;
  const double tiny = 0x1p-20;
  for (long z : {0L, 1L, 2L}) {
    const auto pa = RigidTransform<T>::translation_by(Vec3<T>(T(64), T(-32), T(16)));
    const auto pb = from_integer_quaternion<T>(2, 0, 0, z, Vec3<T>(T(64), T(-32), from_double<T>(17 + g)));
    for (SatAlgorithm alg : kSatAlgorithms) {
      INFO(to_string(alg) << " z " << z);
      const auto full = sat::run<Policy>(alg, a, pa, b, pb);
      REQUIRE_FALSE(full.overlap);
      REQUIRE(full.feature.type == FeatureType::FaceA);
      REQUIRE(compare(full.separation, Separation<T>{from_double<T>(g), T(1)}) == 0);
      SatOptions opt;
      opt.early_out = true;
      for (double m : {g, g + tiny, 2 * g}) {  // separation not above the margin: the full result
        opt.margin = m;
        const auto r = sat::run<Policy>(alg, a, pa, b, pb, opt);
        INFO("margin " << m);
        REQUIRE_FALSE(r.early_out);
        REQUIRE(r.feature == full.feature);
        REQUIRE(compare(r.separation, full.separation) == 0);
      }
      for (double m : {0.0, g - tiny, g / 2}) {  // above the margin: stops, says so
        opt.margin = m;
        const auto r = sat::run<Policy>(alg, a, pa, b, pb, opt);
        INFO("margin " << m);
        REQUIRE(r.early_out);
        REQUIRE_FALSE(r.overlap);
        REQUIRE(compare(r.separation, Separation<T>{from_double<T>(m), T(1)}) > 0);
      }
    }
  }
}

}  // namespace

TEMPLATE_TEST_CASE("margins at exact ties (robust, plain float)", "[posed][margin]", float, double) {
  check_margin_ties<policy::Robust, TestType>();
  check_margin_ties<policy::Plain, TestType>();
}

TEMPLATE_TEST_CASE("margins at exact ties (exact types)", "[posed][margin][exact]", mpq_class, CGAL::Gmpq,
                   CGAL::Epeck::FT) {
  check_margin_ties<policy::Plain, TestType>();
}

TEST_CASE("robust margin: an edge-pair separation against a margin within its error bound is decided exactly",
          "[posed][margin]") {
  // Two unit cubes crossed edge to edge: B turned 45 degrees about x and z
  // (an irrational separation in exact arithmetic, rounded in float).  The
  // margin is the double nearest the float separation: the filter cannot
  // decide, the exact stage does, and the early-out verdict agrees with
  // the exact comparison on the mpq image.
  using T = float;
  const auto cube = shapes::cube<T>(0.5);
  const PreparedShape<T> a(cube), b(cube);
  std::mt19937_64 rng(1805);
  int decided = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const auto pb = random_pose<T>(rng, 0.0);
    auto pbt = pb;
    pbt.translation = Vec3<T>(T(0), T(0), T(1.8f));
    const auto full = sat::traversal<policy::Robust>(a, RigidTransform<T>{}, b, pbt);
    if (full.overlap) continue;
    SatOptions opt;
    opt.early_out = true;
    opt.margin = static_cast<double>(full.separation.num);
    const auto r = sat::traversal<policy::Robust>(a, RigidTransform<T>{}, b, pbt, opt);
    // exact: is the maximum separation > margin?  (the full query's feature is the maximum)
    const auto bp = posed(cube, relative_pose(RigidTransform<T>{}, pbt));
    const auto ea = ConvexPolyhedron<mpq_class>::convert_from(cube);
    const auto eb = ConvexPolyhedron<mpq_class>::convert_from(bp);
    const auto ex = sat::gauss_map(ea, eb);
    const int c = compare(ex.separation, Separation<mpq_class>{mpq_class(opt.margin), mpq_class(1)});
    if (r.early_out) {
      // stopped: some axis separates by more than the margin, so the maximum does
      REQUIRE(c > 0);
    } else {
      // not stopped: no axis exceeds the margin, the maximum included
      REQUIRE(c <= 0);
      REQUIRE(r.feature == full.feature);
    }
    ++decided;
  }
  CHECK(decided > 10);
}

TEMPLATE_TEST_CASE("warm robust posed queries equal fresh ones along coherent sequences",
                   "[posed][cache][robust]", float, double) {
  using T = TestType;
  std::mt19937_64 rng(1823);
  const auto shapes = local_shapes<T>(rng);
  CHECK(check_warm_sequences<policy::Robust>(shapes, 40) == 7 * 7 * 3 * 3 * 40);
}

TEMPLATE_TEST_CASE("warm exact posed queries equal fresh ones along coherent sequences",
                   "[posed][cache][exact]", mpq_class, CGAL::Gmpq, CGAL::Epeck::FT) {
  using T = TestType;
  std::mt19937_64 rng(1824);
  std::vector<ConvexPolyhedron<T>> shapes{ConvexPolyhedron<T>::convert_from(large_sphere_hull(rng, 8)),
                                          shapes::box<T>(0.5, 0.25, 1.0), shapes::prism<T>(6, 0.8, 0.5),
                                          shapes::regular_polygon<T>(5, 0.7)};
  CHECK(check_warm_sequences<policy::Plain>(shapes, 10) == 4 * 4 * 3 * 3 * 10);
}

TEMPLATE_TEST_CASE(
    "warm robust early-out answers decided on a partial posed B equal those on the full B, and "
    "separate exactly beyond the margin",
    "[posed][cache][robust]", float, double) {
  using T = TestType;
  std::mt19937_64 rng(1826);
  const auto shapes = local_shapes<T>(rng);
  int exact_checked = 0;
  const WarmCounts n = check_warm_against_reference<policy::Robust>(
      shapes, rng, 3,
      [&](std::size_t i, std::size_t, const ConvexPolyhedron<T>& bp, const SatOptions& opt,
          const SatResult<T>& r) {
        // the early-out answer's feature (a cache hit or the margin
        // pre-check), re-evaluated by the mpq kernel on the exact images of
        // (A, B'), separates by more than the margin
        const auto ea = ConvexPolyhedron<mpq_class>::convert_from(shapes[i]);
        const auto eb = ConvexPolyhedron<mpq_class>::convert_from(bp);
        PlainKernel<mpq_class> k(ea, eb);
        const auto ev = sat::reevaluate(k, r.feature);
        REQUIRE(ev.has_value());
        REQUIRE(ev->first == r.feature);
        REQUIRE(compare(ev->second, Separation<mpq_class>{mpq_class(opt.margin), mpq_class(1)}) > 0);
        ++exact_checked;
      });
  check_every_warm_path_taken(n);
  CHECK(exact_checked == n.hits[0] + n.hits[1] + n.hits[2] + n.hits[3] + n.hits[4] + n.prechecked);
}

TEMPLATE_TEST_CASE("warm exact early-out hits on a partial posed B equal the hits on the full B",
                   "[posed][cache][exact]", mpq_class, CGAL::Epeck::FT) {
  using T = TestType;
  std::mt19937_64 rng(1827);
  std::vector<ConvexPolyhedron<T>> shapes{ConvexPolyhedron<T>::convert_from(large_sphere_hull(rng, 8)),
                                          shapes::box<T>(0.5, 0.25, 1.0), shapes::prism<T>(6, 0.8, 0.5),
                                          shapes::regular_polygon<T>(5, 0.7)};
  const WarmCounts n = check_warm_against_reference<policy::Plain>(shapes, rng, 2, [](auto&&...) {});
  CHECK(n.compared == 4 * 4 * 2 * 3 * 4 * 2);
  CHECK(n.hits[0] + n.hits[1] + n.hits[2] > 10);
}

namespace {

/// Warm early-out checks at exact ties: box B above box A's top face at
/// exact gap g (B turned about z by a rational rotation, A translated), the
/// cache holding A's top face or B's bottom face.  A margin at or above g is
/// no hit (the SAT runs: the full result, the miss counted); below g the
/// cached face answers with separation exactly g.  At gap 0 (touching)
/// margin 0 is no hit; and a cache from the separated pose is no hit once B
/// has moved into A (a stale feature: the SAT's own result).
template <class Policy, Number T>
void check_warm_margin_ties() {
  const auto box = shapes::box<T>(0.5, 0.5, 0.5);
  const PreparedShape<T> a(box), b(box);
  const double g = 0.125;
  const double tiny = 0x1p-20;
  // A's top face (+z) and B's bottom face (-z; B turns about z only)
  int top = -1, bottom = -1;
  for (int f = 0; f < box.face_count(); ++f) {
    if (box.plane(f).normal[2] > T(0) && box.plane(f).normal[0] == T(0) && box.plane(f).normal[1] == T(0))
      top = f;
    if (box.plane(f).normal[2] < T(0) && box.plane(f).normal[0] == T(0) && box.plane(f).normal[1] == T(0))
      bottom = f;
  }
  REQUIRE(top >= 0);
  REQUIRE(bottom >= 0);
  const auto pa = RigidTransform<T>::translation_by(Vec3<T>(T(64), T(-32), T(16)));
  for (long z : {0L, 1L, 2L}) {
    auto pose_b = [&](double gap) {
      return from_integer_quaternion<T>(2, 0, 0, z, Vec3<T>(T(64), T(-32), from_double<T>(17 + gap)));
    };
    for (const Feature cached : {Feature::face_a(top, 0), Feature::face_b(0, bottom)}) {
      for (SatAlgorithm alg : kSatAlgorithms) {
        INFO(to_string(alg) << " z " << z << " cached " << to_string(cached));
        const auto pb = pose_b(g);
        const auto full = sat::run<Policy>(alg, a, pa, b, pb);
        REQUIRE_FALSE(full.overlap);
        SatOptions opt;
        opt.early_out = true;
        for (double m : {g, g + tiny, 2 * g}) {  // not above the margin: no hit, the full result
          INFO("margin " << m);
          opt.margin = m;
          SatCache<T> cache;
          cache.valid = true;
          cache.feature = cached;
          const auto r = sat::run<Policy>(alg, a, pa, b, pb, opt, &cache);
          REQUIRE(cache.hits == 0);
          REQUIRE(cache.misses == 1);
          REQUIRE_FALSE(r.early_out);
          REQUIRE(r.feature == full.feature);
          REQUIRE(compare(r.separation, full.separation) == 0);
        }
        for (double m : {0.0, g - tiny, g / 2}) {  // above the margin: the cached face answers
          INFO("margin " << m);
          opt.margin = m;
          SatCache<T> cache;
          cache.valid = true;
          cache.feature = cached;
          const auto r = sat::run<Policy>(alg, a, pa, b, pb, opt, &cache);
          REQUIRE(cache.hits == 1);
          REQUIRE(cache.misses == 0);
          REQUIRE(r.early_out);
          REQUIRE_FALSE(r.overlap);
          REQUIRE(r.feature.type == cached.type);
          REQUIRE((cached.type == FeatureType::FaceA ? r.feature.a == top : r.feature.b == bottom));
          REQUIRE(compare(r.separation, Separation<T>{from_double<T>(g), T(1)}) == 0);
        }
        // touching: separation exactly 0 is not beyond margin 0
        {
          const auto pt = pose_b(0.0);
          opt.margin = 0.0;
          const auto fresh = sat::run<Policy>(alg, a, pa, b, pt, opt);
          SatCache<T> cache;
          cache.valid = true;
          cache.feature = cached;
          const auto r = sat::run<Policy>(alg, a, pa, b, pt, opt, &cache);
          REQUIRE(cache.hits == 0);
          REQUIRE_FALSE(r.early_out);
          REQUIRE(r.overlap == fresh.overlap);
          REQUIRE(r.feature == fresh.feature);
          REQUIRE(compare(r.separation, fresh.separation) == 0);
        }
        // stale: the cache of the separated pose, B then sunk g into A
        {
          opt.margin = 0.02;
          SatCache<T> cache;
          (void)sat::run<Policy>(alg, a, pa, b, pb, opt, &cache);
          REQUIRE(cache.valid);
          const auto ps = pose_b(-g);
          const auto fresh = sat::run<Policy>(alg, a, pa, b, ps, opt);
          const std::int64_t hits = cache.hits;
          const auto r = sat::run<Policy>(alg, a, pa, b, ps, opt, &cache);
          REQUIRE(cache.hits == hits);
          REQUIRE(r.overlap);
          REQUIRE(r.overlap == fresh.overlap);
          REQUIRE(r.feature == fresh.feature);
          REQUIRE(compare(r.separation, fresh.separation) == 0);
        }
      }
    }
  }
}

}  // namespace

TEMPLATE_TEST_CASE("warm early-out checks at exact margin ties, touching and stale (robust, plain float)",
                   "[posed][cache][margin]", float, double) {
  check_warm_margin_ties<policy::Robust, TestType>();
  check_warm_margin_ties<policy::Plain, TestType>();
}

TEMPLATE_TEST_CASE("warm early-out checks at exact margin ties, touching and stale (exact types)",
                   "[posed][cache][margin][exact]", mpq_class, CGAL::Epeck::FT) {
  check_warm_margin_ties<policy::Plain, TestType>();
}
