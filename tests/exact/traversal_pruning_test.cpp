// The traversal's arc bound with the wedge test (traversal_pruning.hpp,
// arc_below_best): pruning never changes an answer.  A kernel whose wedge
// test is hidden prunes arcs only with a best <= 0; with the test it also
// prunes arcs below a positive best.  Both must return the same feature,
// verdict and separation, bit for bit, in exact arithmetic and under
// policy::Robust; and on separated pairs the wedge must actually prune.
#include <catch2/catch.hpp>

#include <random>
#include <type_traits>

#include <sepax/robust/number_types.hpp>
#include <sepax/robust/robust_kernel.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/sat_traversal.hpp>
#include <sepax/shapes.hpp>

#include "traversal_shapes.hpp"

using namespace sepax;

namespace {

// K without in_edge_wedge_a: the traversal falls back to the bound for a
// best <= 0 only.
template <class K>
struct NoWedge : K {
  using K::K;
  bool in_edge_wedge_a(int, int) const = delete;
};

static_assert(HasEdgeWedge<PlainKernel<mpq_class>> && HasEdgeWedge<PlainKernel<float>> &&
              HasEdgeWedge<RobustKernel<float>> && HasEdgeWedge<RobustKernel<double>>);
static_assert(!HasEdgeWedge<NoWedge<PlainKernel<mpq_class>>> && !HasEdgeWedge<NoWedge<RobustKernel<float>>>);

struct Totals {
  std::int64_t arc_tests = 0, arc_tests_without = 0, wedge_tests = 0, pruned = 0, pruned_without = 0;
  int separated = 0;
};

template <class T>
void compare_pair(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b, bool robust, Totals& t) {
  const GaussMapWalk wa(a), wb(b);
  const SatOptions opt{};
  sat::TraversalStats with, without;
  SatResult<T> r, r0;
  if constexpr (std::is_same_v<T, mpq_class>) {
    (void)robust;
    PlainKernel<T> k(a, b);
    NoWedge<PlainKernel<T>> k0(a, b);
    r = sat::traversal_with(k, wa, wb, opt, &with);
    r0 = sat::traversal_with(k0, wa, wb, opt, &without);
  } else if (robust) {
    RobustKernel<T> k(a, b);
    NoWedge<RobustKernel<T>> k0(a, b);
    r = sat::traversal_with(k, wa, wb, opt, &with);
    r0 = sat::traversal_with(k0, wa, wb, opt, &without);
  } else {
    PlainKernel<T> k(a, b);
    NoWedge<PlainKernel<T>> k0(a, b);
    r = sat::traversal_with(k, wa, wb, opt, &with);
    r0 = sat::traversal_with(k0, wa, wb, opt, &without);
  }
  INFO("with the wedge " << to_string(r.feature) << " " << r.separation_as_double() << ", without "
                         << to_string(r0.feature) << " " << r0.separation_as_double());
  CHECK(r.feature == r0.feature);
  CHECK(r.overlap == r0.overlap);
  CHECK(r.separation.num == r0.separation.num);
  CHECK(r.separation.norm2 == r0.separation.norm2);
  CHECK(without.wedge_tests == 0);
  t.arc_tests += with.arc_tests;
  t.arc_tests_without += without.arc_tests;
  t.wedge_tests += with.wedge_tests;
  t.pruned += with.pruned_arcs;
  t.pruned_without += without.pruned_arcs;
  t.separated += !r.overlap;
}

}  // namespace

TEST_CASE("the wedge bound prunes arcs below a positive best and changes no answer",
          "[traversal][pruning][wedge]") {
  std::mt19937_64 rng(2718);
  std::uniform_int_distribution<int> nd(6, 40);
  std::uniform_real_distribution<double> off(-1.0, 1.0);
  Totals exact_t, robust_f, robust_d, plain_f;
  for (int it = 0; it < 60; ++it) {
    const auto a = test::sphere_hull(rng, nd(rng));
    // separated by 2.1 .. 3 along a random direction, or close (overlapping
    // or nearly touching)
    test::V3 d(off(rng), off(rng), off(rng));
    if (d.norm() < 1e-3) d = test::V3(1, 0, 0);
    const double dist = it % 3 == 0 ? 1.6 + 0.4 * off(rng) : 2.5 + 0.5 * off(rng);
    const auto b =
        test::moved(test::sphere_hull(rng, nd(rng)), test::random_rotation(rng), d.normalized() * dist);
    compare_pair(ConvexPolyhedron<mpq_class>::convert_from(a), ConvexPolyhedron<mpq_class>::convert_from(b),
                 true, exact_t);
    compare_pair(a, b, true, robust_d);
    try {
      const auto af = ConvexPolyhedron<float>::convert_from(a);
      const auto bf = ConvexPolyhedron<float>::convert_from(b);
      compare_pair(af, bf, true, robust_f);
      compare_pair(af, bf, false, plain_f);
    } catch (const InvalidInput&) {
      // rounding to float made the hull invalid: the double pair is enough
    }
  }
  for (const Totals* t : {&exact_t, &robust_d, &robust_f}) {
    CHECK(t->separated > 20);
    CHECK(t->wedge_tests > 0);
    CHECK(t->pruned > t->pruned_without);
    CHECK(t->arc_tests < t->arc_tests_without);
  }
  WARN("arc tests with / without the wedge: exact "
       << exact_t.arc_tests << " / " << exact_t.arc_tests_without << ", robust double " << robust_d.arc_tests
       << " / " << robust_d.arc_tests_without << ", robust float " << robust_f.arc_tests << " / "
       << robust_f.arc_tests_without << ", plain float " << plain_f.arc_tests << " / "
       << plain_f.arc_tests_without);
}

// The bound on the rest of an arc walk (traversal_pruning.hpp,
// rest_below_best): after a crossing exactly below the best, the entered
// vertex's height over the walk's end face bounds every crossing left.
// Overlapping 32-sided prisms (the caps' fans of arcs cross many arcs of the
// other shape): the bound must end walks, every kernel the same number of
// times and after the same arc tests, and the answer must be the brute
// force's.
TEST_CASE("the bound on the rest of an arc walk ends walks and changes no answer", "[traversal][pruning]") {
  std::mt19937_64 rng(3301);
  std::uniform_real_distribution<double> off(-1.0, 1.0);
  const auto cyl = shapes::prism<double>(32, 1.0, 1.5);
  std::int64_t rest_exact = 0;
  int pairs = 0;
  for (int it = 0; it < 12; ++it) {
    const test::V3 d = test::random_unit(rng) * (0.8 + 0.6 * off(rng));
    const auto b = test::moved(cyl, test::random_rotation(rng), d);
    const auto aq = ConvexPolyhedron<mpq_class>::convert_from(cyl);
    const auto bq = ConvexPolyhedron<mpq_class>::convert_from(b);
    const GaussMapWalk wa(cyl), wb(b);
    sat::TraversalStats te, tr;
    PlainKernel<mpq_class> ke(aq, bq);
    RobustKernel<double> kr(cyl, b);
    const auto re = sat::traversal_with(ke, wa, wb, SatOptions{}, &te);
    const auto rr = sat::traversal_with(kr, wa, wb, SatOptions{}, &tr);
    // exact: the brute force's answer; robust: the Gauss-map SAT's (the
    // same kernel calls per axis, so the same separation bit for bit)
    const auto refe = sat::brute_force(aq, bq);
    const auto ref = sat::gauss_map<policy::Robust>(cyl, b);
    INFO("pair " << it << ": traversal " << to_string(rr.feature) << ", Gauss map "
                 << to_string(ref.feature));
    CHECK(re.feature == refe.feature);
    CHECK(compare(re.separation, refe.separation) == 0);
    CHECK(re.overlap == refe.overlap);
    CHECK(rr.feature == refe.feature);
    CHECK(rr.feature == ref.feature);
    CHECK(rr.overlap == ref.overlap);
    CHECK(rr.separation.num == ref.separation.num);
    CHECK(rr.separation.norm2 == ref.separation.norm2);
    CHECK(tr.pruned_rest == te.pruned_rest);
    CHECK(tr.arc_tests == te.arc_tests);
    rest_exact += te.pruned_rest;
    pairs += re.overlap ? 1 : 0;
  }
  CHECK(pairs > 6);
  CHECK(rest_exact > 0);
}

TEST_CASE("the wedge of a box edge", "[traversal][pruning][wedge]") {
  // The edge of the cube [-1, 1]^3 between its +x and +y faces: seen along
  // the edge, a point is strictly inside its wedge when x > 1 and y > 1; on a
  // boundary plane (x = 1 or y = 1) or outside, not.  The point is vertex 0
  // of a triangle B.
  auto check_box = [](auto tag) {
    using T = decltype(tag);
    const auto a = shapes::box<T>(1, 1, 1);
    int edge = -1;
    for (int e = 0; e < a.edge_count(); ++e) {
      const auto& t = a.vertex(a.edge_tail(e));
      const auto& h = a.vertex(a.edge_head(e));
      if (t[0] == T(1) && t[1] == T(1) && h[0] == T(1) && h[1] == T(1)) edge = e;
    }
    REQUIRE(edge >= 0);
    struct Probe {
      double x, y;
      bool inside;
    };
    for (const Probe& p : {Probe{2, 2, true}, Probe{1.5, 3, true}, Probe{1.0001, 1.0001, true},
                           Probe{2, 0.5, false}, Probe{0.5, 2, false}, Probe{1, 2, false}, Probe{2, 1, false},
                           Probe{1, 1, false}, Probe{-3, -3, false}, Probe{0, 0, false}}) {
      const auto b = shapes::triangle<T>(vec_from_double<T>(test::V3(p.x, p.y, 0.25)),
                                         vec_from_double<T>(test::V3(p.x, p.y, 0.75)),
                                         vec_from_double<T>(test::V3(p.x + 0.25, p.y + 0.5, 0.75)));
      int x = -1;
      for (int v = 0; v < b.vertex_count(); ++v) {
        if (b.vertex(v)[2] == vec_from_double<T>(test::V3(0, 0, 0.25))[2]) x = v;
      }
      REQUIRE(x >= 0);
      const PlainKernel<T> k(a, b);
      INFO("probe (" << p.x << ", " << p.y << ")");
      CHECK(k.in_edge_wedge_a(edge, x) == p.inside);
      if constexpr (!std::is_same_v<T, mpq_class>) {
        const RobustKernel<T> rk(a, b);
        CHECK(rk.in_edge_wedge_a(edge, x) == p.inside);
      }
    }
  };
  check_box(float{});
  check_box(double{});
  check_box(mpq_class{});
}
