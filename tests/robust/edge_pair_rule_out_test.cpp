// The robust kernel's edge-pair rule-out (edge_pair_rule_out.hpp,
// ExactRuleOut): a pair it rules out is one the kernel's exact test rejects,
// on generic and near-degenerate shapes at every scale; and a wing height it
// trusts has the sign of the exact triple product, checked against GMP at
// the threshold (nearly coplanar wings, nearly parallel edges).  The plain
// kernel over exact types rules out by exact height signs (integers for the
// GMP rationals, an interval filter for Epeck): the same checks; and its
// edge_separation_full, decided by the same signs, gives the decision and
// the value of the projections' extremes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <random>
#include <type_traits>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <gmpxx.h>

#include <sepax/robust/number_types.hpp>
#include <sepax/plain_kernel.hpp>
#include <sepax/robust/robust_kernel.hpp>

#include "edge_pair_rule_out_shapes.hpp"

using namespace sepax;

TEMPLATE_TEST_CASE("robust rule-out: every pair ruled out is rejected by the kernel's exact test",
                   "[robust][brute_force][rule_out]", float, double) {
  using T = TestType;
  const testing::RuleOutCount n = testing::check_rule_out<T>(
      [](const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b) { return RobustKernel<T>(a, b); });
  testing::check_counts(n);
}

TEMPLATE_TEST_CASE("exact rule-out: every pair ruled out is rejected by the exact kernel's test",
                   "[robust][brute_force][rule_out]", mpq_class, CGAL::Gmpq, CGAL::Epeck::FT) {
  // PlainKernel over an exact type: the wings' exact height signs (sign_of_height).  The shapes are the
  // double ones, converted exactly.
  using E = TestType;
  const testing::RuleOutCount n = testing::check_rule_out<double, E>(
      [](const ConvexPolyhedron<E>& a, const ConvexPolyhedron<E>& b) { return PlainKernel<E>(a, b); });
  testing::check_counts(n);
}

namespace {
mpq_class as_mpq(const mpq_class& x) { return x; }
mpq_class as_mpq(const CGAL::Gmpq& x) { return mpq_class(x.mpq()); }
mpq_class as_mpq(const CGAL::Epeck::FT& x) { return as_mpq(CGAL::exact(x)); }
}  // namespace

TEMPLATE_TEST_CASE(
    "exact edge_separation_full: by signs, the decision and value of the projections' extremes",
    "[robust][brute_force]", mpq_class, CGAL::Gmpq, CGAL::Epeck::FT) {
  // The reference projects every vertex on n = dA x dB in mpq: +n is a face of A - B when both endpoints
  // of A's edge are at A's maximum and both of B's at B's minimum (value min_B - max_A), -n the opposite;
  // both (flat shapes): the larger.  Every 7th non-parallel pair of the rule-out tests' shapes.
  using E = TestType;
  using Q = mpq_class;
  std::mt19937_64 rng(5);
  long pairs = 0, faces = 0, both = 0;
  auto run = [&](const ConvexPolyhedron<double>& da, const ConvexPolyhedron<double>& db) {
    const auto qa = ConvexPolyhedron<Q>::convert_from(da), qb = ConvexPolyhedron<Q>::convert_from(db);
    const auto xa = ConvexPolyhedron<E>::convert_from(da), xb = ConvexPolyhedron<E>::convert_from(db);
    const PlainKernel<E> k(xa, xb);
    for (int ea = 0; ea < qa.edge_count(); ++ea) {
      for (int eb = 0; eb < qb.edge_count(); ++eb) {
        if ((ea * 31 + eb) % 7 != 0 || k.edges_parallel(ea, eb)) continue;
        ++pairs;
        const Vec3<Q> n = cross(qa.edge_direction(ea), qb.edge_direction(eb));
        auto extremes = [&](const ConvexPolyhedron<Q>& p) {
          Q lo = dot(n, p.vertex(0)), hi = lo;
          for (const auto& v : p.vertices()) {
            const Q h = dot(n, v);
            lo = std::min(lo, h);
            hi = std::max(hi, h);
          }
          return std::pair<Q, Q>(lo, hi);
        };
        const auto [lo_a, hi_a] = extremes(qa);
        const auto [lo_b, hi_b] = extremes(qb);
        const Q a0 = dot(n, qa.vertex(qa.edge_tail(ea))), a1 = dot(n, qa.vertex(qa.edge_head(ea)));
        const Q b0 = dot(n, qb.vertex(qb.edge_tail(eb))), b1 = dot(n, qb.vertex(qb.edge_head(eb)));
        const bool plus = a0 == hi_a && a1 == hi_a && b0 == lo_b && b1 == lo_b;
        const bool minus = a0 == lo_a && a1 == lo_a && b0 == hi_b && b1 == hi_b;
        const std::optional<Separation<E>> r = k.edge_separation_full(ea, eb);
        REQUIRE(r.has_value() == (plus || minus));
        if (!r) continue;
        ++faces;
        both += plus && minus;
        const Q expected = plus && minus ? std::max(lo_b - hi_a, lo_a - hi_b)
                           : plus        ? lo_b - hi_a
                                         : lo_a - hi_b;
        CHECK(as_mpq(r->num) == expected);
        CHECK(as_mpq(r->norm2) == dot(n, n));
      }
    }
  };
  for (int i = 0; i < 40; ++i) {
    const auto [a, b] = testing::random_pair<double>(rng, i);
    run(a, b);
  }
  for (const auto& [a, b] : testing::degenerate_pairs<double>(rng)) {
    run(a, b);
    run(b, a);
  }
  INFO(pairs << " pairs, " << faces << " faces of A - B, " << both << " in both orientations");
  CHECK(pairs > 50000);
  CHECK(faces > 1000);
  CHECK(both > 0);
}

TEMPLATE_TEST_CASE("exact height signs (integers, interval filter) are the signs of the exact products",
                   "[robust][rule_out]", mpq_class, CGAL::Gmpq, CGAL::Epeck::FT) {
  // number_traits<E>::height_sign(a, b, p, q) = sign((a x b).(p - q)) against mpq's products: on doubles
  // over many binades, exact ties (p - q in the plane of a and b), non-dyadic rationals, and Epeck values
  // made by arithmetic (x / 3 * 3: the same value, an interval that is not a point).
  using E = TestType;
  using Q = mpq_class;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g;
  std::uniform_int_distribution<int> binade(-60, 60);
  auto coordinate = [&] { return std::ldexp(g(rng), binade(rng)); };
  auto to_e = [](const Q& x) {
    if constexpr (std::is_same_v<E, CGAL::Gmpq>) {
      return CGAL::Gmpq(x.get_mpq_t());
    } else {
      return E(x);
    }
  };
  auto vec_e = [&](const Vec3<Q>& v) { return Vec3<E>(to_e(v[0]), to_e(v[1]), to_e(v[2])); };
  int zeros = 0;
  auto check = [&](const Vec3<Q>& a, const Vec3<Q>& b, const Vec3<Q>& p, const Vec3<Q>& q) {
    const int expected = sgn(dot(cross(a, b), Vec3<Q>(p - q)));
    zeros += expected == 0;
    CHECK(number_traits<E>::height_sign(vec_e(a), vec_e(b), vec_e(p), vec_e(q)) == expected);
    CHECK(sign_of_height(vec_e(a), vec_e(b), vec_e(p), vec_e(q)) == expected);
    if constexpr (std::is_same_v<E, CGAL::Epeck::FT>) {
      const Vec3<E> w = vec_e(a);
      const Vec3<E> wide(w[0] / 3 * 3, w[1] / 3 * 3, w[2] / 3 * 3);
      CHECK(number_traits<E>::height_sign(wide, vec_e(b), vec_e(p), vec_e(q)) == expected);
    }
  };
  for (int i = 0; i < 2000; ++i) {
    Vec3<Q> v[4];
    for (auto& x : v) x = Vec3<Q>(Q(coordinate()), Q(coordinate()), Q(coordinate()));
    check(v[0], v[1], v[2], v[3]);
    // p - q = s a + t b: a tie
    const Q s(coordinate()), t(coordinate());
    check(v[0], v[1], Vec3<Q>(v[3] + s * v[0] + t * v[1]), v[3]);
    // non-dyadic
    check(Vec3<Q>(v[0] / 3), v[1], Vec3<Q>(v[2] / 7), v[3]);
    check(Vec3<Q>(v[0] / 3), v[1], Vec3<Q>(v[3] + v[0] / 5), v[3]);
  }
  CHECK(zeros >= 4000);  // (the two ties of each draw, and any others)
}

namespace {

template <class T>
mpq_class q(T x) {
  return mpq_class(static_cast<double>(x));
}

// The exact (E_A x E_B).(w - tail), E = head - tail.
template <class T>
int exact_sign(const Vec3<T>& ta, const Vec3<T>& ha, const Vec3<T>& tb, const Vec3<T>& hb, const Vec3<T>& w) {
  mpq_class ea[3], eb[3], d[3];
  for (int i = 0; i < 3; ++i) {
    ea[i] = q(ha[i]) - q(ta[i]);
    eb[i] = q(hb[i]) - q(tb[i]);
    d[i] = q(w[i]) - q(ta[i]);
  }
  const mpq_class s = (ea[1] * eb[2] - ea[2] * eb[1]) * d[0] + (ea[2] * eb[0] - ea[0] * eb[2]) * d[1] +
                      (ea[0] * eb[1] - ea[1] * eb[0]) * d[2];
  return sgn(s);
}

}  // namespace

TEMPLATE_TEST_CASE("robust rule-out: a trusted wing height has the exact sign",
                   "[robust][brute_force][rule_out]", float, double) {
  using T = TestType;
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> r01(0, 1);
  long decided = 0, across_decided = 0, trials = 0;
  for (int i = 0; i < 100000; ++i) {
    const double scale = std::ldexp(1.0, static_cast<int>(r01(rng) * 60) - 30);
    auto vec = [&](double s) { return testing::random_vec<T>(g, rng, s); };
    const Vec3<T> ta = vec(scale * 100), tb = vec(scale * 100);
    Vec3<T> ha = vec(scale), hb = vec(scale);
    const double f = 1 + 1e-6 * g(rng);
    for (int j = 0; j < 3; ++j) {
      ha[j] = testing::rounded<T>(double(ha[j]) + double(ta[j]));
      hb[j] =
          i % 3 == 0
              ? testing::rounded<T>(double(tb[j]) + (double(ha[j]) - double(ta[j])) * f)  // nearly parallel
              : testing::rounded<T>(double(hb[j]) + double(tb[j]));
    }
    // w nearly in the plane through tail spanned by E_A and E_B
    const Vec3<double> ea = detail::difference_d(ha, ta), eb = detail::difference_d(hb, tb);
    const double k = std::ldexp(g(rng), -static_cast<int>(r01(rng) * 60));
    const Vec3<double> wd = ta.template cast<double>() + g(rng) * ea + g(rng) * eb +
                            k * scale * cross(ea, eb) / (ea.norm() * eb.norm() + 1e-300);
    const Vec3<T> w = testing::rounded_vec<T>(wd);
    const Vec3<double> c = cross(ea, eb);
    const double l1 = (std::abs(ea[0]) + std::abs(ea[1]) + std::abs(ea[2])) *
                      (std::abs(eb[0]) + std::abs(eb[1]) + std::abs(eb[2]));
    double max_abs = 0;
    for (const Vec3<T>* p : std::initializer_list<const Vec3<T>*>{&ta, &ha, &w})
      for (int j = 0; j < 3; ++j) max_abs = std::max(max_abs, std::abs(static_cast<double>((*p)[j])));
    double k_p = 0, z_p = 0;
    detail::ExactRuleOut<T>::constants(max_abs, k_p, z_p);
    const double bound = l1 * k_p + z_p;
    const double s = detail::wing_height(c, detail::difference_d(w, ta));
    // the same height as EdgePairRuleOut's first test evaluates it, E_B.((w - tail) x E_A)
    const double across = detail::wing_height(eb, cross(detail::difference_d(w, ta), ea));
    ++trials;
    if (s > bound || s < -bound) {
      ++decided;
      CHECK(exact_sign(ta, ha, tb, hb, w) == (s > 0 ? 1 : -1));
    }
    if (across > bound || across < -bound) {
      ++across_decided;
      CHECK(exact_sign(ta, ha, tb, hb, w) == (across > 0 ? 1 : -1));
    }
  }
  INFO("decided " << decided << " and " << across_decided << " (across) of " << trials);
  CHECK(decided > trials / 4);
  CHECK(across_decided > trials / 4);
}
