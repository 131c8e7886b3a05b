// The brute force's edge-pair rule-out (edge_pair_rule_out.hpp): a pair the
// kernel rules out is one its own test rejects (edges_parallel or no
// edge_separation_full), on generic and near-degenerate shapes at every
// scale; and it rules out most pairs of generic hulls (else it is useless).
#include <catch2/catch.hpp>

#include <sepax/convex_hull.hpp>
#include <sepax/plain_kernel.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/shapes.hpp>
#include <sepax/transform.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "edge_pair_rule_out_shapes.hpp"

using namespace sepax;
using sepax::testing::RuleOutCount;

TEMPLATE_TEST_CASE("plain rule-out: every pair ruled out is rejected by the kernel's own test",
                   "[sat][brute_force][rule_out]", float, double) {
  using T = TestType;
  const RuleOutCount n = sepax::testing::check_rule_out<T>(
      [](const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b) { return PlainKernel<T>(a, b); });
  sepax::testing::check_counts(n);
}

TEMPLATE_TEST_CASE("plain rule-out: brute force results unchanged by it on posed hull pairs",
                   "[sat][brute_force][rule_out]", float, double) {
  using T = TestType;
  // the brute force without the rule-out: the same loop over every pair
  std::mt19937_64 rng(7);
  for (int i = 0; i < 40; ++i) {
    const auto [a, b] = sepax::testing::random_pair<T>(rng, i);
    PlainKernel<T> k(a, b);
    const SatResult<T> r = sat::brute_force(a, b);
    sat::detail::BestAxis<PlainKernel<T>> best;
    SatStats stats;
    sat::detail::scan_face_axes(k, best, stats, SatOptions{});
    for (int ea = 0; ea < a.edge_count(); ++ea) {
      for (int eb = 0; eb < b.edge_count(); ++eb) {
        ++stats.edge_pairs;
        if (k.edges_parallel(ea, eb)) continue;
        const auto s = k.edge_separation_full(ea, eb);
        if (!s) continue;
        ++stats.minkowski_faces;
        best.consider(k, *s, Feature::edges(ea, eb));
      }
    }
    sat::detail::scan_side_axes(k, best, stats, SatOptions{});
    const SatResult<T> ref = best.result(k, stats, false);
    CHECK(r.overlap == ref.overlap);
    CHECK(r.feature == ref.feature);
    CHECK(r.separation_as_double() == ref.separation_as_double());
    CHECK(r.stats.minkowski_faces == ref.stats.minkowski_faces);
    CHECK(r.stats.edge_pairs == ref.stats.edge_pairs);
  }
}

// PlainRuleOut's bound at the threshold: a wing placed at exact height t + x
// above the tail along the pair's axis, x within +-256 u R, against the plain
// kernel's rounded test as edge_separation_full computes it (n =
// fl(normalise(fl(dA x dB))), e0 = fl(n.tail), h = fl(n.w), e0 < fl(h - t)).
// A claim must always hold; the bound may miss (then the kernel decides).
TEMPLATE_TEST_CASE("plain rule-out: the bound holds at the threshold of the rounded test",
                   "[sat][brute_force][rule_out]", float, double) {
  using T = TestType;
  constexpr double u = number_traits<T>::unit_roundoff;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> r01(0, 1);
  long claims = 0, across_claims = 0, trials = 0;
  for (int i = 0; i < 200000; ++i) {
    const double scale = std::ldexp(1.0, static_cast<int>(r01(rng) * 40) - 20);
    auto vec = [&](double s) { return testing::random_vec<T>(g, rng, s); };
    const Vec3<T> da = vec(scale * std::ldexp(1.0, static_cast<int>(r01(rng) * 8) - 4));
    const Vec3<T> db = vec(scale);
    const Vec3<T> tail = vec(scale * (r01(rng) < 0.5 ? 1.0 : 100.0));
    const Vec3<double> c = cross(vec_to_double(da), vec_to_double(db));
    const double cn = std::sqrt(c.dot(c));
    if (!(cn > 0)) continue;
    const double mt =
        std::max({std::abs(double(tail[0])), std::abs(double(tail[1])), std::abs(double(tail[2]))});
    const double r = std::sqrt(3.0) * mt;
    const double t = r01(rng) < 0.3 ? 0.0 : 1e-5 * scale;
    const double x = (r01(rng) * 512 - 256) * u * r;
    // w = tail + (t + x) c/|c| + an offset orthogonal to c, rounded to T
    Vec3<double> off(g(rng), g(rng), g(rng));
    off -= (off.dot(c) / (cn * cn)) * c;
    const Vec3<double> wd = tail.template cast<double>() + ((t + x) / cn) * c + 0.3 * scale * off;
    const Vec3<T> w = testing::rounded_vec<T>(wd);
    const double max_abs =
        std::max({mt, std::abs(double(w[0])), std::abs(double(w[1])), std::abs(double(w[2]))});
    double x_p = 0, y_p = 0;
    detail::PlainRuleOut<T>::constants(max_abs, t, x_p, y_p);
    const double bound =
        cn * x_p + std::sqrt(vec_to_double(da).squaredNorm() * vec_to_double(db).squaredNorm()) * y_p;
    const double s = detail::wing_height(c, detail::difference_d(w, tail));
    // the kernel's rounded test (PlainKernel::unoriented_axis, rule_out)
    const Vec3<T> n0 = scaled_cross(da, db);
    const T len = number_traits<T>::sqrt(squared_norm(n0));
    const Vec3<T> n(n0[0] / len, n0[1] / len, n0[2] / len);
    const T e0 = dot(n, tail), h = dot(n, w), tt = static_cast<T>(t);
    ++trials;
    // a height beyond its bound claims the kernel's verdict on that side
    auto claim = [&](double height, double b, long& count) {
      if (height > b) {
        ++count;
        CHECK(e0 < T(h - tt));
      }
      if (height < -b) {
        ++count;
        CHECK(e0 > T(h + tt));
      }
    };
    claim(s, bound, claims);
    // the across form (EdgePairRuleOut's first test): the height as
    // dB.((w - tail) x dA), the bound on L = |dA|_1 |dB|_1 instead of |c|
    const Vec3<double> dad = vec_to_double(da), dbd = vec_to_double(db);
    const double l = detail::l1_norm(dad) * detail::l1_norm(dbd);
    if (!(l >= detail::PlainRuleOut<T>::kMinAcross)) continue;
    claim(
        detail::wing_height(dbd, cross(detail::difference_d(w, tail), dad)),
        l * detail::PlainRuleOut<T>::across_constant(max_abs, t) + detail::PlainRuleOut<T>::kAcrossUnderflow,
        across_claims);
  }
  INFO("claims " << claims << " and " << across_claims << " (across) of " << trials);
  CHECK(claims > trials / 10);
  CHECK(across_claims > trials / 50);
}
