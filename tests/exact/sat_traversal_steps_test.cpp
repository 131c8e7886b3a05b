// The pruned traversal under policy::Robust takes exactly the steps that the
// same traversal takes in exact arithmetic (PlainKernel<mpq_class>) on the
// exact images: every decision that steers the walk (hill-climb moves, the
// cutoff against the best so far, the deepest probe vertex, arc pruning, late
// climbs, arc tests) is an exact decision, and the start faces are chosen
// identically for a float shape and its exact image.  This must hold on every input, including inputs
// whose exact image is convex only up to rounding (boxes and prisms rotated in
// floating point), where the walk's path can change the answer: there the
// robust traversal must still report the exact traversal's feature.
#include <catch2/catch.hpp>
#include <sepax/robust/number_types.hpp>
#include <sepax/robust/robust_kernel.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_traversal.hpp>
#include <sepax/shapes.hpp>

#include "traversal_shapes.hpp"

using namespace sepax;

namespace {

using Q = mpq_class;

struct Tally {
  int cases = 0;
  std::int64_t pruned_faces = 0, probe_pruned = 0, pruned_arcs = 0, late_pruned_arcs = 0, late = 0,
               nonconvex_differs = 0;
};

// The walk counters that only decisions change (height_evals counts O(1)
// evaluations, which the float fast path does differently).
void check_same_steps(const sat::TraversalStats& r, const sat::TraversalStats& e) {
  CHECK(r.support_scans == e.support_scans);
  CHECK(r.climb_steps == e.climb_steps);
  CHECK(r.arc_tests == e.arc_tests);
  CHECK(r.corner_passes == e.corner_passes);
  CHECK(r.lex_starts == e.lex_starts);
  CHECK(r.fallback_arcs == e.fallback_arcs);
  CHECK(r.pruned_faces == e.pruned_faces);
  CHECK(r.probe_checks == e.probe_checks);
  CHECK(r.probe_pruned == e.probe_pruned);
  CHECK(r.pruned_arcs == e.pruned_arcs);
  CHECK(r.late_pruned_arcs == e.late_pruned_arcs);
  CHECK(r.late_certified == e.late_certified);
  CHECK(r.wedge_tests == e.wedge_tests);
}

template <class F>
void check_pair(const ConvexPolyhedron<F>& a, const ConvexPolyhedron<F>& b, const char* what, Tally& t,
                bool early_out = false, bool with_brute_force = false) {
  const auto qa = ConvexPolyhedron<Q>::convert_from(a);
  const auto qb = ConvexPolyhedron<Q>::convert_from(b);
  const GaussMapWalk wa(a), wb(b);
  const SatOptions opt{.early_out = early_out};
  RobustKernel<F> rk(a, b);
  sat::TraversalStats rs;
  const auto r = sat::traversal_with(rk, wa, wb, opt, &rs);
  PlainKernel<Q> ek(qa, qb);
  sat::TraversalStats es;
  const auto e = sat::traversal_with(ek, wa, wb, opt, &es);
  INFO(what << " (" << (sizeof(F) == 4 ? "float" : "double") << (early_out ? ", early out" : "")
            << "): robust " << to_string(r.feature) << " " << r.separation_as_double() << ", exact "
            << to_string(e.feature) << " " << e.separation_as_double());
  CHECK(r.feature == e.feature);
  CHECK(r.overlap == e.overlap);
  CHECK(r.early_out == e.early_out);
  CHECK(sign_of(r.separation.num) == sign(e.separation));
  check_same_steps(rs, es);
  ++t.cases;
  t.pruned_faces += rs.pruned_faces;
  t.probe_pruned += rs.probe_pruned;
  t.pruned_arcs += rs.pruned_arcs;
  t.late_pruned_arcs += rs.late_pruned_arcs;
  t.late += rs.late_certified;
  if (with_brute_force) {
    // Not a requirement on inputs convex only up to rounding (the SATs' own
    // definitions differ there), counted for the report.
    const auto bf = sat::brute_force(qa, qb);
    if (!(bf.feature == e.feature)) ++t.nonconvex_differs;
  }
}

}  // namespace

TEST_CASE("robust traversal takes the exact traversal's steps (random hulls)", "[traversal][robust][steps]") {
  std::mt19937_64 rng(4242);
  std::uniform_int_distribution<int> nd(4, 28);
  std::uniform_real_distribution<double> off(-1.5, 1.5);
  Tally t;
  for (int it = 0; it < 100; ++it) {
    const auto a = test::sphere_hull(rng, nd(rng));
    const auto b = test::moved(test::sphere_hull(rng, nd(rng), 0.9), test::random_rotation(rng),
                               test::V3(off(rng), off(rng), off(rng)));
    check_pair(a, b, "random pair", t, false, it % 4 == 0);
    check_pair(a, b, "random pair", t, true);
    const auto af = ConvexPolyhedron<float>::convert_from(a);
    const auto bf = ConvexPolyhedron<float>::convert_from(b);
    check_pair(af, bf, "random pair", t);
  }
  // The cutoff, the probes and the arc pruning must actually happen on these
  // inputs.
  CHECK(t.pruned_faces > 0);
  CHECK(t.probe_pruned > 0);
  CHECK(t.pruned_arcs > 0);
  CHECK(t.late_pruned_arcs > 0);
  // Random hulls are triangulated: exactly convex images, so the exact
  // traversal is the exact brute force.
  CHECK(t.nonconvex_differs == 0);
  WARN("random hulls: " << t.cases << " cases, pruned faces " << t.pruned_faces << " (by a probe "
                        << t.probe_pruned << "), pruned arcs " << t.pruned_arcs << " (after a late climb "
                        << t.late_pruned_arcs << "), late climbs " << t.late);
}

TEST_CASE("robust traversal takes the exact traversal's steps (large hulls: chunked seed tests)",
          "[traversal][robust][steps]") {
  // Hulls of 150-200 points: ~300-400 faces, whose face chunks are long
  // enough for the traversal's chunked seed pass (sat_traversal.hpp,
  // kTraversalMinMeanChunk), which must take the one-face loop's decisions.
  std::mt19937_64 rng(9191);
  std::uniform_int_distribution<int> nd(150, 200);
  std::uniform_real_distribution<double> off(-1.0, 1.0);
  Tally t;
  int float_pairs = 0;
  for (int it = 0; it < 6; ++it) {
    const auto a = test::large_sphere_hull(rng, nd(rng));
    const auto b = test::moved(test::large_sphere_hull(rng, nd(rng), 0.9), test::random_rotation(rng),
                               test::V3(off(rng), off(rng), off(rng)));
    for (const auto* p : {&a, &b}) {
      const GaussMapWalk w(*p);
      REQUIRE(p->face_count() >=
              sat::kTraversalMinMeanChunk * (static_cast<int>(w.face_chunks().size()) - 1));
    }
    check_pair(a, b, "large pair", t);  // (no exact brute force: minutes at this size)
    check_pair(a, b, "large pair", t, true);
    // the float images, when rounding b's rotated vertices keeps it valid
    try {
      const auto af = ConvexPolyhedron<float>::convert_from(a);
      const auto bf = ConvexPolyhedron<float>::convert_from(b);
      check_pair(af, bf, "large pair", t);
      ++float_pairs;
    } catch (const InvalidInput&) {
    }
  }
  CHECK(float_pairs > 0);
  CHECK(t.pruned_faces > 0);
  CHECK(t.probe_pruned > 0);
  CHECK(t.pruned_arcs > 0);
}

TEST_CASE("robust traversal takes the exact traversal's steps (float-rotated boxes and prisms)",
          "[traversal][robust][steps]") {
  // Rotated in double: the quads of the exact images are planar only up to
  // rounding, so hill climbs and pruning see (slightly) non-convex shapes.
  std::mt19937_64 rng(777);
  std::uniform_real_distribution<double> off(-1.6, 1.6);
  const auto box = shapes::box<double>(0.5, 0.3, 0.8);
  const auto cube = shapes::cube<double>(1.0);
  const auto prism = shapes::prism<double>(12, 0.7, 0.6);
  const auto quad = shapes::regular_polygon<double>(4, 0.9);
  const std::vector<const ConvexPolyhedron<double>*> shapes_list = {&box, &cube, &prism, &quad};
  Tally t;
  for (int it = 0; it < 120; ++it) {
    const auto& sa = *shapes_list[static_cast<std::size_t>(it) % shapes_list.size()];
    const auto& sb = *shapes_list[static_cast<std::size_t>(it / 4) % shapes_list.size()];
    const auto a = test::moved(sa, test::random_rotation(rng), test::V3(0, 0, 0));
    // offsets on a coarse grid too, so that faces meet at near-ties
    const double g = (it % 3 == 0) ? 0.25 : 0.0;
    auto o = [&] { return g > 0 ? g * std::round(off(rng) / g) : off(rng); };
    const auto b = test::moved(sb, test::random_rotation(rng), test::V3(o(), o(), o()));
    check_pair(a, b, "rotated shapes", t, false, it % 2 == 0);
    check_pair(a, b, "rotated shapes", t, true);
    check_pair(ConvexPolyhedron<float>::convert_from(a), ConvexPolyhedron<float>::convert_from(b),
               "rotated shapes", t);
  }
  CHECK(t.pruned_faces > 0);
  CHECK(t.probe_pruned > 0);
  WARN("rotated boxes/prisms: " << t.cases << " cases, pruned faces " << t.pruned_faces << " (by a probe "
                                << t.probe_pruned << "), pruned arcs " << t.pruned_arcs
                                << ", exact traversal != exact brute force in " << t.nonconvex_differs
                                << " (inputs convex only up to rounding)");
}
