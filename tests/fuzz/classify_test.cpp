// Checking core: classification of synthetic disagreements, the forward error
// bounds against exact arithmetic, and the integer arc signs against the
// rational kernel.
#include <catch2/catch.hpp>

#include <optional>
#include <random>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <sepax/fuzz/check.hpp>
#include <sepax/fuzz/classify.hpp>
#include <sepax/fuzz/error_bounds.hpp>
#include <sepax/convex_hull.hpp>
#include <sepax/fuzz/generators.hpp>
#include <sepax/plain_kernel.hpp>
#include <sepax/robust/core_expr.hpp>
#include <sepax/robust/number_types.hpp>

using namespace sepax;
using namespace sepax::fuzz;
using Q = mpq_class;

TEST_CASE("classify_sign: agree, exact zero, explained, unexplained", "[fuzz][classify]") {
  const ExactSep tiny{Q(-1, 1000000), Q(1)};  // -1e-6 on a unit axis
  const ExactSep zero{Q(0), Q(4)};
  const ExactSep big{Q(-1), Q(1)};
  CHECK(classify_sign(-1, tiny, 1e-3, false) == Classification::agree);
  CHECK(classify_sign(+1, tiny, 1e-3, false) == Classification::explained);
  CHECK(classify_sign(+1, tiny, 1e-7, false) == Classification::unexplained);
  CHECK(classify_sign(+1, zero, 0.0, false) == Classification::exact_zero);
  CHECK(classify_sign(0, zero, 0.0, false) == Classification::agree);
  CHECK(classify_sign(+1, big, 0.5, false) == Classification::unexplained);
  // the robust policy claims exact signs: no excuse
  CHECK(classify_sign(+1, tiny, 1e-3, true) == Classification::unexplained);
  CHECK(classify_sign(+1, zero, 1e-3, true) == Classification::unexplained);
  // unnormalised exact value: num / sqrt(norm2) = -3 / sqrt(9e12) = -1e-6
  const ExactSep scaled{Q(-3), Q("9000000000000")};
  CHECK(classify_sign(+1, scaled, 1.0000001e-6, false) == Classification::explained);
  CHECK(classify_sign(+1, scaled, 0.9999999e-6, false) == Classification::unexplained);
}

TEST_CASE("within and cmp_rational_sep are exact at the boundary", "[fuzz][classify]") {
  const ExactSep s{Q(1), Q(4)};  // 0.5
  CHECK(cmp_rational_sep(Q(1, 2), s) == 0);
  CHECK(cmp_rational_sep(Q(-1, 2), s) < 0);
  CHECK(within(0.75, s, 0.25));
  CHECK_FALSE(within(0.75, s, 0.2499999999));
  CHECK(within(0.25, s, 0.25));
  const ExactSep neg{Q(-1), Q(4)};  // -0.5
  CHECK(cmp_rational_sep(Q(-1, 2), neg) == 0);
  CHECK(cmp_rational_sep(Q(-1, 4), neg) > 0);
  CHECK(within(-0.5, neg, 0.0));
  // infinite bound (degenerate exact axis) always holds
  CHECK(within(1e30, s, std::numeric_limits<double>::infinity()));
}

TEST_CASE("classify_overlap and classify_separation", "[fuzz][classify]") {
  const ExactSep touching{Q(0), Q(1)};
  const ExactSep near{Q(1, 1000000000), Q(1)};  // 1e-9: separated
  const ExactSep far{Q(1, 10), Q(1)};
  CHECK(classify_overlap(true, true, far, 0, false) == Classification::agree);
  CHECK(classify_overlap(false, true, touching, 0, false) == Classification::exact_zero);
  CHECK(classify_overlap(true, false, near, 1e-8, false) == Classification::explained);
  CHECK(classify_overlap(true, false, far, 1e-8, false) == Classification::unexplained);
  CHECK(classify_overlap(true, false, near, 1e-8, true) == Classification::unexplained);

  CHECK(classify_separation(0.5, ExactSep{Q(1), Q(4)}, true, 0, 0, false) == Classification::agree);
  CHECK(classify_separation(0.1 + 1e-12, far, true, 1e-11, 0, false) == Classification::explained);
  CHECK(classify_separation(0.1 + 1e-12, far, true, 1e-13, 0, false) == Classification::unexplained);
  CHECK(classify_separation(1e-12, touching, true, 1e-11, 0, false) == Classification::exact_zero);
  // a different feature: tie within the two bounds
  CHECK(classify_separation(0.1 + 1e-12, far, false, 6e-13, 6e-13, false) == Classification::tie);
  CHECK(classify_separation(0.1 + 1e-12, far, false, 4e-13, 4e-13, false) == Classification::unexplained);
  CHECK(classify_separation(0.1 + 1e-12, far, false, 1, 1, true) == Classification::unexplained);
}

TEST_CASE("close: ties between exact separations on different axes", "[fuzz][classify]") {
  const ExactSep a{Q(1), Q(4)};       // 0.5
  const ExactSep b{Q(2), Q(16)};      // 0.5, different representation
  const ExactSep c{Q(3), Q(36)};      // 0.5
  const ExactSep d{Q(51), Q(10000)};  // 0.51
  CHECK(close(a, b, 0));
  CHECK(close(a, c, 0));
  CHECK_FALSE(close(a, d, 0.009));
  CHECK(close(a, d, 0.011));
}

TEST_CASE("close and sign_sep_diff are exact (no doubles), against CORE::Expr", "[fuzz][classify][tie]") {
  // Exactly at the boundary: 3/sqrt(4) - 1/sqrt(16) = 1.25.
  const ExactSep x{Q(3), Q(4)}, y{Q(1), Q(16)};
  CHECK(sign_sep_diff(x, y, Q(5, 4)) == 0);
  CHECK(sign_sep_diff(x, y, Q(5, 4) + Q(1, 1000000000)) < 0);
  CHECK(sign_sep_diff(x, y, Q(5, 4) - Q(1, 1000000000)) > 0);
  CHECK(close(x, y, 1.25));
  CHECK_FALSE(close(x, y, 1.2499999999999998));  // the double just below 1.25
  // Irrational values a double cannot separate: sqrt(2)/2 vs 1/sqrt(2) are equal;
  // 1/sqrt(2) vs 1/sqrt(2 + 2^-120) differ by ~2^-123, far below double resolution.
  const ExactSep r{Q(1), Q(2)}, r2{Q(1), Q(2) + Q(mpz_class(1), mpz_class(1) << 120)};
  CHECK(sign_sep_diff(r, ExactSep{Q(1), Q(2)}, Q(0)) == 0);
  CHECK(sign_sep_diff(r, r2, Q(0)) > 0);
  CHECK(close(r, r2, 0x1p-122));
  CHECK_FALSE(close(r, r2, 0x1p-125));  // the old double-based test called these equal
  // Random small rationals (mixed signs, tiny differences) against CORE::Expr's exact sqrt.
  std::mt19937_64 rng(77);
  std::uniform_int_distribution<int> small(-9, 9), pos(1, 50);
  int decided = 0;
  for (int t = 0; t < 3000; ++t) {
    const Q p(small(rng), pos(rng)), q(small(rng), pos(rng)), m(pos(rng), pos(rng)), n(pos(rng), pos(rng));
    Q b(small(rng), pos(rng));
    if (t % 4 == 0) b = 0;
    using CORE::Expr;
    auto ex = [](const Q& v) { return to_core_expr(v); };
    const Expr diff = ex(p) / sqrt(ex(m)) - ex(q) / sqrt(ex(n)) - ex(b);
    const int want = diff.sign();
    REQUIRE(sign_sep_diff(ExactSep{p, m}, ExactSep{q, n}, b) == want);
    decided += want != 0;
  }
  CHECK(decided > 2000);
}

// The bounds of error_bounds.hpp, tested against exact arithmetic on the very
// operation sequences of the plain kernel: they must never be exceeded.
template <class F>
void check_bounds_on_random_triangles(int trials) {
  std::mt19937_64 rng(1234);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> ex(-12, 12);
  int checked = 0;
  for (int t = 0; t < trials; ++t) {
    const double scale = std::ldexp(1.0, ex(rng));
    const Vec3<double> off(u(rng) * 100, u(rng) * 100, u(rng) * 100);
    auto pt = [&] {
      return Vec3<F>(F((u(rng) + off[0]) * scale), F((u(rng) + off[1]) * scale),
                     F((u(rng) + off[2]) * scale));
    };
    Vec3<F> p0 = pt(), p1 = pt(), p2 = pt();
    if (t % 3 == 0) {  // sliver triangle: p2 nearly on the line p0 p1
      const double w = u(rng);
      for (int c = 0; c < 3; ++c)
        p2[c] = F(double(p0[c]) + w * (double(p1[c]) - double(p0[c])) + 1e-5 * u(rng) * scale);
    }
    const Plane<F> pl = plane_through(p0, p1, p2);
    const Vec3<Q> q0 = vec_cast<Q>(p0), q1 = vec_cast<Q>(p1), q2 = vec_cast<Q>(p2);
    const Vec3<Q> Ne = cross(Vec3<Q>(q1 - q0), Vec3<Q>(q2 - q0));
    if (is_zero(Ne)) continue;
    const double dn = bounds::delta_normal<F>(Vec3<F>(p1 - p0), Vec3<F>(p2 - p0),
                                              bounds::sqrt_lower(squared_norm(Ne).get_d()));
    // (2) arc triple product with a random edge d = head - tail
    const Vec3<F> h = pt(), tl = pt();
    const Vec3<F> d(h - tl);
    const F tf = dot(pl.normal, d);
    const Q te = dot(Ne, Vec3<Q>(vec_cast<Q>(h) - vec_cast<Q>(tl)));
    REQUIRE(within(double(tf), ExactSep{te, squared_norm(Ne)}, bounds::arc_bound<F>(pl.normal, d, dn)));
    // (3) face separation of a vertex v
    const Vec3<F> v = pt();
    const F sf = F(dot(pl.normal, v) - pl.offset);
    const Q se = dot(Ne, Vec3<Q>(vec_cast<Q>(v) - q0));
    REQUIRE(within(double(sf), ExactSep{se, squared_norm(Ne)}, bounds::face_bound<F>(pl.normal, p0, v, dn)));
    // (7) side axis of the edge p0 -> p1 (in-plane outward normal d x n), as
    // the plain kernel computes it (u in F) and as the robust one does (u in
    // double, rounded to F; value u . fl(v - p0))
    {
      const Vec3<F> de(p1 - p0);
      Vec3<F> us = cross(de, pl.normal);
      const F len = std::sqrt(squared_norm(us));
      us = Vec3<F>(us[0] / len, us[1] / len, us[2] / len);
      const double du = bounds::delta_side<F>(de, pl.normal, dn);
      const Vec3<Q> ue = cross(Vec3<Q>(q1 - q0), Ne);
      const ExactSep xe{dot(ue, Vec3<Q>(vec_cast<Q>(v) - q0)), squared_norm(ue)};
      const F s_plain = F(dot(us, v) - dot(us, p0));
      REQUIRE(within(double(s_plain), xe, bounds::side_bound<F>(us, p0, v, du)));
      Vec3<double> ud = cross(Vec3<double>(double(de[0]), double(de[1]), double(de[2])),
                              Vec3<double>(double(pl.normal[0]), double(pl.normal[1]), double(pl.normal[2])));
      ud /= ud.norm();
      const Vec3<F> ur{static_cast<F>(ud[0]), static_cast<F>(ud[1]), static_cast<F>(ud[2])};
      const F s_robust = dot(ur, Vec3<F>(v - p0));
      REQUIRE(within(double(s_robust), xe, bounds::side_bound<F>(ur, p0, v, du)));
    }
    ++checked;
  }
  CHECK(checked > trials / 2);
}

// (8): the orientation sum of PlainKernel::edge_axis, on the kernel's own
// operations (its centroids, fl(p - c), the rounded unit axis), against the
// exact sum on exact centroids; pairs of small polygons far from the origin
// (where the centroid rounding matters) and of solid hulls at every scale.
template <class F>
void check_orientation_bound(int trials) {
  std::mt19937_64 rng(4321);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> ex(-12, 12), npts(3, 9);
  int checked = 0;
  for (int t = 0; t < trials; ++t) {
    const double scale = std::ldexp(1.0, ex(rng));
    auto shape = [&] {
      const Vec3<double> off(u(rng) * 100, u(rng) * 100, u(rng) * 100);
      std::vector<Vec3<F>> pts;
      const int n = npts(rng);
      const bool flat = t % 2 == 0;
      for (int i = 0; i < n; ++i) {
        const double a = 2 * 3.141592653589793 * i / n + 0.3 * u(rng);
        const Vec3<double> p =
            flat ? Vec3<double>(std::cos(a), std::sin(a), 0) : Vec3<double>(u(rng), u(rng), u(rng));
        pts.emplace_back(F((p[0] + off[0]) * scale), F((p[1] + off[1]) * scale), F((p[2] + off[2]) * scale));
      }
      return convex_hull(pts);
    };
    std::optional<ConvexPolyhedron<F>> pa_, pb_;
    try {
      pa_.emplace(shape());
      pb_.emplace(shape());
    } catch (const InvalidInput&) {
      continue;
    }
    const ConvexPolyhedron<F>&A = *pa_, &B = *pb_;
    const auto EA = ConvexPolyhedron<Q>::convert_from(A), EB = ConvexPolyhedron<Q>::convert_from(B);
    for (int ea = 0; ea < A.edge_count(); ea += 2)
      for (int eb = 0; eb < B.edge_count(); eb += 3) {
        const Vec3<F> da = A.edge_direction(ea), db = B.edge_direction(eb);
        const Vec3<Q> N = cross(EA.edge_direction(ea), EB.edge_direction(eb));
        if (is_zero(N)) continue;
        Vec3<F> n = cross(da, db);
        const F len = std::sqrt(squared_norm(n));
        n = Vec3<F>(n[0] / len, n[1] / len, n[2] / len);
        const Vec3<F>& pa = A.vertex(A.edge_tail(ea));
        const Vec3<F>& pb = B.vertex(B.edge_tail(eb));
        const Vec3<F> wa(pa - A.centroid()), wb(B.centroid() - pb);
        const F s = F(dot(n, wa) + dot(n, wb));
        const double dn = bounds::delta_normal<F>(da, db, bounds::sqrt_lower(squared_norm(N).get_d()));
        const double b = bounds::orientation_bound<F>(n, wa, wb, dn, bounds::centroid_error<F>(A),
                                                      bounds::centroid_error<F>(B));
        const Vec3<Q> X = Vec3<Q>(EA.vertex(EA.edge_tail(ea)) - EA.centroid()) +
                          Vec3<Q>(EB.centroid() - EB.vertex(EB.edge_tail(eb)));
        const ExactSep se{dot(N, X), squared_norm(N)};
        REQUIRE(within(double(s), se, b));
        ++checked;
      }
  }
  CHECK(checked > trials);
}

TEST_CASE("forward error bounds hold against exact arithmetic", "[fuzz][bounds]") {
  check_bounds_on_random_triangles<float>(3000);
  check_bounds_on_random_triangles<double>(3000);
  check_orientation_bound<float>(400);
  check_orientation_bound<double>(400);
}

TEST_CASE("integer arc signs and face supports equal the rational kernel's", "[fuzz][arcs]") {
  for (const std::string fam : {"boxes", "flat", "tetra", "scales", "touching", "perturbed"}) {
    for (std::uint64_t seed = 0; seed < 6; ++seed) {
      const FuzzCase c = generate(fam, seed);
      auto build = [](const ShapeSpec& s) {
        std::vector<Vec3<float>> v;
        for (const auto& p : s.vertices) v.push_back(vec_from_double<float>(p));
        return ConvexPolyhedron<float>::from_faces(std::move(v), s.faces);
      };
      ConvexPolyhedron<float> a, b;
      try {
        a = build(c.a);
        b = build(c.b);
      } catch (const InvalidInput&) {
        continue;
      }
      const auto ae = ConvexPolyhedron<Q>::convert_from(a), be = ConvexPolyhedron<Q>::convert_from(b);
      PlainKernel<Q> k(ae, be);
      const auto arcs = exact_arc_signs(a, b);
      for (int ea = 0; ea < a.edge_count(); ++ea)
        for (int eb = 0; eb < b.edge_count(); ++eb) {
          const ArcSigns x = k.arc_signs(ea, eb),
                         y = arcs[static_cast<std::size_t>(ea * b.edge_count() + eb)];
          REQUIRE(x.cba == y.cba);
          REQUIRE(x.dba == y.dba);
          REQUIRE(x.adc == y.adc);
          REQUIRE(x.bdc == y.bdc);
        }
      // the integer support vertices are the rational face queries' (ties
      // included: the lowest index of least height), faces of A and of B
      const auto sa = exact_face_supports(a, b), sb = exact_face_supports(b, a);
      for (int f = 0; f < a.face_count(); ++f)
        REQUIRE(sa[static_cast<std::size_t>(f)] == k.face_query_a(f).support_vertex);
      for (int f = 0; f < b.face_count(); ++f)
        REQUIRE(sb[static_cast<std::size_t>(f)] == k.face_query_b(f).support_vertex);
    }
  }
}

// error_bounds.hpp (6): whenever the plain kernel calls an edge pair parallel,
// parallel_band must say "inside" (soundness), and pairs clearly above the
// tolerance must be "outside" (the band is tight).
template <class F>
void check_parallel_band(double tol) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-1, 1), f(0.5, 1.5);
  std::uniform_int_distribution<int> ex(-10, 10);
  int skipped = 0, measured = 0;
  for (int t = 0; t < 4000; ++t) {
    const double scale = std::ldexp(1.0, ex(rng));
    Vec3<double> d(u(rng), u(rng), u(rng));
    d.normalize();
    Vec3<double> p(u(rng), u(rng), u(rng));
    p = (p - d * d.dot(p)).normalized();
    const double ang = tol * f(rng);  // around the tolerance
    const Vec3<double> e = (d * std::cos(ang) + p * std::sin(ang)) * (scale * f(rng));
    auto tri = [&](const Vec3<double>& dir, const Vec3<double>& off) {
      std::vector<Vec3<F>> v{vec_from_double<F>(off), vec_from_double<F>(Vec3<double>(off + dir * scale)),
                             vec_from_double<F>(Vec3<double>(off + cross(p, d) * scale))};
      return ConvexPolyhedron<F>::from_faces(v, {{0, 1, 2}, {2, 1, 0}});
    };
    const auto A = tri(d, Vec3<double>(0, 0, 0));
    const auto B = tri(e / scale, Vec3<double>(3 * scale, 0, 0));
    const PlainKernel<F> k(A, B);
    for (int ea = 0; ea < A.edge_count(); ++ea)
      for (int eb = 0; eb < B.edge_count(); ++eb) {
        const ParallelBand band = parallel_band<F>(A.edge_direction(ea), B.edge_direction(eb));
        REQUIRE(band != ParallelBand::unknown);
        if (k.edges_parallel(ea, eb)) {
          ++skipped;
          REQUIRE(band == ParallelBand::inside);
        } else {
          ++measured;
        }
        // exact sine clearly above the tolerance: certainly measured
        const Vec3<Q> a = vec_cast<Q>(A.edge_direction(ea)), b = vec_cast<Q>(B.edge_direction(eb));
        const Q k2 = Q(1.01 * tol) * Q(1.01 * tol);
        if (squared_norm(cross(a, b)) > k2 * squared_norm(a) * squared_norm(b))
          REQUIRE(band == ParallelBand::outside);
      }
  }
  CHECK(skipped > 1000);
  CHECK(measured > 1000);
}

TEST_CASE("parallel_band: sound for every pair the plain kernel skips, tight above it",
          "[fuzz][classify][parallel]") {
  check_parallel_band<float>(1e-4);
  check_parallel_band<double>(1e-8);
  // the guard: tiny or huge edges cannot be shown either way
  CHECK(parallel_band<float>(Vec3<float>(1e-20f, 0, 0), Vec3<float>(1, 1e-5f, 0)) == ParallelBand::unknown);
  CHECK(parallel_band<float>(Vec3<float>(1e30f, 0, 0), Vec3<float>(1, 1e-5f, 0)) == ParallelBand::unknown);
  CHECK(parallel_band<float>(Vec3<float>(1, 0, 0), Vec3<float>(1, 1e-5f, 0)) == ParallelBand::inside);
  CHECK(parallel_band<float>(Vec3<float>(1, 0, 0), Vec3<float>(1, 1e-3f, 0)) == ParallelBand::outside);
  CHECK(parallel_band<double>(Vec3<double>(1, 0, 0), Vec3<double>(1, 1e-5, 0)) == ParallelBand::outside);
}

// Two wedges touching ridge to ridge, the ridges turned by 3e-5 rad: exactly,
// the ridge pair (axis z) is a Minkowski face and wins; plain float skips it
// as parallel (sin < 1e-4) and picks a face.  That must be classified
// "explained" (float_plain), while double measures the pair and agrees.
TEST_CASE("check: a winner inside the float parallel skip is explained, not a tie",
          "[fuzz][classify][parallel]") {
  const double th = 3e-5, g = 0.25;
  FuzzCase c;
  c.family = "manual";
  std::vector<Vec3<double>> a{{-1, 0, 1}, {1, 0, 1}, {-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}, {1, 1, 0}};
  std::vector<Vec3<double>> b;
  for (const auto& p : a) {
    const Vec3<double> m(p[0], p[1], 2 + g - p[2]);  // upside down, ridge at z = 1 + g
    b.emplace_back(m[0] * std::cos(th) - m[1] * std::sin(th), m[0] * std::sin(th) + m[1] * std::cos(th),
                   m[2]);
  }
  c.a = hull_of(a);
  c.b = hull_of(b);
  const CaseReport r = check_case(c);
  REQUIRE(r.valid);
  for (const auto& x : r.unexplained)
    UNSCOPED_INFO("[" << x.comparison << " " << x.config << " " << x.sat << "] " << x.detail);
  CHECK(r.unexplained_count == 0);
  CHECK(r.by_config.at("feature/float_plain")[Classification::explained] >= 1);
  CHECK(r.by_config.at("feature/float_plain")[Classification::tie] == 0);
  CHECK(r.by_config.at("feature/double_plain")[Classification::agree] ==
        r.by_config.at("feature/double_plain").total());
}

// exactly_convex (filtered) against the plain rational plane test on the
// exact image: every face's vertices on its plane, every vertex on or below.
TEST_CASE("exactly_convex equals the rational plane test of the exact image", "[fuzz][convex]") {
  auto rational = [](const ConvexPolyhedron<Q>& p) {
    for (int f = 0; f < p.face_count(); ++f) {
      const Plane<Q>& pl = p.plane(f);
      for (int v : p.face_vertices(f))
        if (sgn(Q(dot(pl.normal, p.vertex(v)) - pl.offset)) != 0) return false;
      for (int v = 0; v < p.vertex_count(); ++v)
        if (sgn(Q(dot(pl.normal, p.vertex(v)) - pl.offset)) > 0) return false;
    }
    return true;
  };
  auto build = [](const ShapeSpec& s) {
    std::vector<Vec3<float>> v;
    for (const auto& p : s.vertices) v.push_back(vec_from_double<float>(p));
    return ConvexPolyhedron<float>::from_faces(std::move(v), s.faces);
  };
  int convex = 0, not_convex = 0;
  for (const std::string fam :
       {"boxes", "flat", "tetra", "scales", "touching", "perturbed", "sphere", "decomposition"}) {
    for (std::uint64_t seed = 0; seed < 12; ++seed) {
      const FuzzCase c = generate(fam, seed);
      for (const ShapeSpec* s : {&c.a, &c.b}) {
        ConvexPolyhedron<float> p;
        try {
          p = build(*s);
        } catch (const InvalidInput&) {
          continue;
        }
        const bool want = rational(ConvexPolyhedron<Q>::convert_from(p));
        INFO(fam << " seed " << seed);
        REQUIRE(exactly_convex(p) == want);
        ++(want ? convex : not_convex);
      }
    }
  }
  // both answers occur (the perturbed family moves vertices off their planes)
  CHECK(convex > 20);
  CHECK(not_convex > 0);
}
