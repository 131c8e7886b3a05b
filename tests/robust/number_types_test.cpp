// CGAL's interval filter (behind CGAL::Epeck::FT and CGAL's filtered
// predicates) rounds outward under the compiler in use.  With GCC the
// CGAL::CGAL target adds -frounding-math; with clang it adds nothing (clang 14
// has no reliable -frounding-math for this), and CGAL instead hides the
// operands from constant folding and from moves across rounding-mode changes
// with asm barriers (CGAL/FPU.h, IA_opacify).  CGAL checks this only in debug
// builds (an assertion); this test checks it in the build type we ship, for
// runtime and compile-time-constant operands.
#include <catch2/catch.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>
#include <gmpxx.h>

#include <sepax/plane.hpp>
#include <sepax/robust/number_types.hpp>
#include <sepax/separation.hpp>
#include <sepax/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace {

// inf <= exact <= sup, and the interval is not a point (exact is not a double)
void check_encloses(const CGAL::Interval_nt<>& x, const mpq_class& exact) {
  CHECK(x.inf() < x.sup());
  CHECK(mpq_class(x.inf()) <= exact);
  CHECK(exact <= mpq_class(x.sup()));
}

}  // namespace

TEST_CASE("CGAL intervals round outward (with or without -frounding-math)", "[robust][number_types]") {
  using I = CGAL::Interval_nt<>;
  // runtime operands
  volatile double one = 1.0, ten = 10.0, a = 1.1, b = 10.1;
  check_encloses(I(one) / I(ten), mpq_class(1, 10));
  check_encloses(I(a) * I(b), mpq_class(1.1) * mpq_class(10.1));
  check_encloses(-(I(-a) * I(b)), mpq_class(1.1) * mpq_class(10.1));
  const I r2 = CGAL::sqrt(I(static_cast<double>(ten) / 5));
  CHECK(r2.inf() < r2.sup());
  CHECK(mpq_class(r2.inf()) * mpq_class(r2.inf()) <= 2);
  CHECK(mpq_class(r2.sup()) * mpq_class(r2.sup()) >= 2);
  // compile-time constants: the case constant folding (in round-to-nearest)
  // would break
  check_encloses(I(1.0) / I(10.0), mpq_class(1, 10));
  check_encloses(I(1.1) * I(10.1), mpq_class(1.1) * mpq_class(10.1));
  check_encloses(-(I(-1.1) * I(10.1)), mpq_class(1.1) * mpq_class(10.1));
  check_encloses(I(0.1) + I(0.2), mpq_class(0.1) + mpq_class(0.2));
}

TEST_CASE("Epeck::FT decides signs exactly near zero", "[robust][number_types]") {
  using FT = CGAL::Epeck::FT;
  // 3 * 0.1 - 0.3 (of the doubles 0.1 and 0.3) is exactly 2^-55 (double
  // arithmetic gives 2^-54); 3 * 0.1 - 0.1 - 0.1 - 0.1 is exactly 0 (double
  // arithmetic gives 2^-55)
  CHECK(CGAL::sign(FT(0.1) * FT(3) - FT(0.3)) == CGAL::POSITIVE);
  CHECK(CGAL::sign(FT(0.1) * FT(3) - FT(0.1) - FT(0.1) - FT(0.1)) == CGAL::ZERO);
  CHECK(CGAL::sign(FT(1) / FT(3) * FT(3) - FT(1)) == CGAL::ZERO);
  CHECK(FT(1) / FT(10) * FT(10) == FT(1));
}

TEST_CASE("GMP rationals convert to the nearest double", "[robust][number_types]") {
  // IEEE division is correctly rounded: p / q in double is the double nearest
  // to the rational p/q.  mpq_get_d truncates, so about half of these differ.
  std::uint64_t x = 88172645463325252ull;
  int truncated_differs = 0;
  for (int i = 0; i < 2000; ++i) {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    const double p = static_cast<double>(static_cast<std::int64_t>(x % 2000001) - 1000000);
    const double q = static_cast<double>(x / 2000001 % 999983 + 1);
    const mpq_class r = mpq_class(p) / mpq_class(q);
    CHECK(sepax::number_traits<mpq_class>::to_double(r) == p / q);
    CHECK(sepax::number_traits<CGAL::Gmpq>::to_double(CGAL::Gmpq(p) / CGAL::Gmpq(q)) == p / q);
    truncated_differs += r.get_d() != p / q;
  }
  CHECK(truncated_differs > 100);  // the test can tell the two apart
  CHECK(sepax::number_traits<mpq_class>::to_double(mpq_class(1e308) * 4) ==
        std::numeric_limits<double>::infinity());
}

TEST_CASE("exact separations convert to double without spurious overflow", "[robust][number_types]") {
  using sepax::Separation;
  using Q = mpq_class;
  // value = num / sqrt(norm2)
  CHECK(to_double(Separation<Q>{Q(3), Q(4)}) == 1.5);
  CHECK(to_double(Separation<Q>{Q(-3), Q(4)}) == -1.5);
  CHECK(to_double(Separation<Q>{Q(0), Q(4)}) == 0.0);
  // num and norm2 beyond double's range, the value not: 1e308 and 1e200
  CHECK(to_double(Separation<Q>{Q(1e308) * 4, Q(16)}) == 1e308);
  // (the value is exactly the double 1e200: the nearest double is that double)
  const Q big = Q(1e200) * Q(1e200) * Q(1e200) * Q(1e200);  // norm2 ~ 1e800, num ~ 1e600
  CHECK(to_double(Separation<Q>{Q(1e200) * Q(1e200) * Q(1e200), big}) == 1e200);
  CHECK(to_double(Separation<Q>{-Q(1e200) * Q(1e200) * Q(1e200), big}) == -1e200);
  // and tiny: norm2 ~ 1e-1200, num ~ 1e-900, value 1e-300
  const Q tiny = Q(1e-300) * Q(1e-300);
  CHECK(to_double(Separation<Q>{Q(1e-300) * Q(1e-300) * Q(1e-300), tiny * tiny}) == 1e-300);
  // the nearest double where value^2 is a normal double: against MPFR at
  // 300 bits, rounded once more to 53 (the odds that this second rounding
  // matters are about 2^-247 per value)
  auto nearest = [](const Q& num, const Q& n2) {
    mpfr_t a, b;
    mpfr_init2(a, 300);
    mpfr_init2(b, 300);
    mpfr_set_q(b, n2.get_mpq_t(), MPFR_RNDN);
    mpfr_rec_sqrt(b, b, MPFR_RNDN);
    mpfr_set_q(a, num.get_mpq_t(), MPFR_RNDN);
    mpfr_mul(a, a, b, MPFR_RNDN);
    const double d = mpfr_get_d(a, MPFR_RNDN);
    mpfr_clear(a);
    mpfr_clear(b);
    return d;
  };
  int plain_differs = 0;
  for (int n2 = 2; n2 < 400; ++n2) {
    for (const Q& num : {Q(7), Q(-2, 5), Q(12345, 677)}) {
      const double v = to_double(Separation<Q>{num, Q(n2)});
      CHECK(v == nearest(num, Q(n2)));
      plain_differs += v != num.get_d() / std::sqrt(static_cast<double>(n2));
    }
  }
  CHECK(plain_differs > 10);  // the naive quotient is not always the nearest
  // the nearest double where value^2 is outside double's range too: values near 2^+-600 and 2^+-1000
  // (value 2^-k scaled exactly, rounded, scaled back), and 5e299 = 2.5e300 - 2e300 exactly
  for (const int e : {600, -600, 1000, -1000}) {
    INFO("value ~ 2^" << e);
    Q scale = 1;
    for (int i = 0; i < std::abs(e); ++i) scale *= 2;
    if (e < 0) scale = 1 / scale;
    for (int n2 = 2; n2 < 60; ++n2) {
      for (const Q& num0 : {Q(7), Q(-2, 5), Q(12345, 677)}) {
        const Q num = num0 * scale;
        CHECK(to_double(Separation<Q>{num, Q(n2)}) == nearest(num, Q(n2)));
      }
    }
  }
  const Q q5(Q(2.5e300) - Q(2e300));
  CHECK(to_double(Separation<Q>{q5 * 3, Q(9)}) == 5e299);
  CHECK(to_double(Separation<Q>{q5 * Q(1e300) * 4, Q(1e300) * Q(1e300) * 16}) == 5e299);
  // the tetrahedron's face against the point (0.2, 0.2, 0.2) in doubles
  const Q p(0.2);
  CHECK(to_double(Separation<Q>{3 * p - 1, Q(3)}) == nearest(3 * p - 1, Q(3)));
}

// Doubles spread over many binades: zeros, signs, subnormals, 2^-1074 ... 2^1000 (xorshift, fixed seed).
struct SpreadDoubles {
  std::uint64_t x = 0x9e3779b97f4a7c15ull;
  std::uint64_t next() {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    return x;
  }
  double operator()() {
    const std::uint64_t r = next();
    if (r % 11 == 0) return 0.0;
    if (r % 13 == 0) return std::ldexp(static_cast<double>(r % 7) - 3.0, -1074);  // subnormal or zero
    const double m = static_cast<double>(static_cast<std::int64_t>(r >> 11) % 2000001 - 1000000) / 1e6;
    const int e =
        static_cast<int>(next() % 61) - 30 + (r % 5 == 0 ? static_cast<int>(next() % 2000) - 1000 : 0);
    return std::ldexp(m, std::min(e, 1000));  // finite: |m| <= 1
  }
};

TEST_CASE("mpq planes of dyadic points are computed in integers, with mpq's values",
          "[robust][number_types]") {
  // number_traits<mpq_class>::exact_plane against the plane computed with mpq operations, on points whose
  // coordinates are doubles spread over many binades (zeros, signs, 2^-1074 ... 2^1000 in one triple), and
  // false, the plane untouched (plane_through then computes in mpq), for a coordinate that is not dyadic.
  using V = sepax::Vec3<mpq_class>;
  auto reference = [](const V& a, const V& b, const V& c) {
    const V e1(b - a), e2(c - a);
    const V n(sepax::cross(e1, e2));
    return sepax::Plane<mpq_class>{n, sepax::dot(n, a)};
  };
  SpreadDoubles coordinate;
  int faces = 0;
  sepax::Plane<mpq_class> fast;
  for (int i = 0; i < 3000; ++i) {
    V p[3];
    for (auto& v : p) v = V(mpq_class(coordinate()), mpq_class(coordinate()), mpq_class(coordinate()));
    // into a plane holding earlier values (as the builder's and a polyhedron's planes do)
    REQUIRE(sepax::number_traits<mpq_class>::exact_plane(fast, p[0], p[1], p[2]));
    const sepax::Plane<mpq_class> slow = reference(p[0], p[1], p[2]);
    for (int j = 0; j < 3; ++j) {
      CHECK(fast.normal[j] == slow.normal[j]);
      // the same representation: lowest terms, positive denominator
      CHECK(mpz_cmp(mpq_denref(fast.normal[j].get_mpq_t()), mpq_denref(slow.normal[j].get_mpq_t())) == 0);
    }
    CHECK(fast.offset == slow.offset);
    CHECK(mpz_cmp(mpq_denref(fast.offset.get_mpq_t()), mpq_denref(slow.offset.get_mpq_t())) == 0);
    faces += !sepax::is_zero(slow.normal);
  }
  CHECK(faces > 2500);  // (most triples span a plane)
  const V a(mpq_class(1, 3), mpq_class(0), mpq_class(0)), b(mpq_class(1), mpq_class(0), mpq_class(0)),
      c(mpq_class(0), mpq_class(1), mpq_class(0));
  sepax::Plane<mpq_class> untouched{V(mpq_class(2), mpq_class(0), mpq_class(0)), mpq_class(5)};
  CHECK_FALSE(sepax::number_traits<mpq_class>::exact_plane(untouched, a, b, c));
  CHECK((untouched.normal == V(mpq_class(2), mpq_class(0), mpq_class(0)) && untouched.offset == 5));
  const sepax::Plane<mpq_class> q = sepax::plane_through(a, b, c), r = reference(a, b, c);
  CHECK((q.normal == r.normal && q.offset == r.offset));
  sepax::assign_plane_through(untouched, a, b, c);  // mpq's operations, into an existing plane
  CHECK((untouched.normal == r.normal && untouched.offset == r.offset));
}

TEST_CASE("mpq differences of dyadic values are computed in integers, with mpq's values",
          "[robust][number_types]") {
  // number_traits<mpq_class>::exact_difference (ConvexPolyhedron's edge directions) against mpq's
  // subtraction: the same value in the same lowest terms, also when the result is one of the operands;
  // false with the result untouched for a value that is not dyadic.
  using Q = mpq_class;
  SpreadDoubles coordinate;
  for (int i = 0; i < 5000; ++i) {
    const Q a(coordinate()), b(coordinate());
    const Q slow = a - b;
    Q fast(7);
    REQUIRE(sepax::number_traits<Q>::exact_difference(fast, a, b));
    CHECK(fast == slow);
    CHECK(mpz_cmp(mpq_denref(fast.get_mpq_t()), mpq_denref(slow.get_mpq_t())) == 0);
    Q in_place = a;
    REQUIRE(sepax::number_traits<Q>::exact_difference(in_place, in_place, b));
    CHECK(in_place == slow);
  }
  Q out(5);
  CHECK_FALSE(sepax::number_traits<Q>::exact_difference(out, Q(1, 3), Q(1)));
  CHECK(out == 5);
  const sepax::Vec3<Q> u(Q(1, 3), Q(0.75), Q(-2)), w(Q(1), Q(0.125), Q(1, 6));
  sepax::Vec3<Q> d;
  sepax::assign_difference(d, u, w);  // one coordinate dyadic on both sides, two not
  CHECK(d == sepax::Vec3<Q>(u - w));
}

TEST_CASE("mpq and Gmpq dot products of dyadic values are computed in integers, with mpq's values",
          "[robust][number_types]") {
  // number_traits<T>::exact_dot (behind sepax::dot for the GMP rationals) against mpq's operations
  // written out: the same value in the same lowest terms; false with the result untouched when a
  // coordinate is not dyadic, and sepax::dot then takes mpq's operations.
  using Q = mpq_class;
  using G = CGAL::Gmpq;
  SpreadDoubles coordinate;
  auto reference = [](const sepax::Vec3<Q>& a, const sepax::Vec3<Q>& b) {
    Q s = a[0] * b[0];
    s += a[1] * b[1];
    s += a[2] * b[2];
    return s;
  };
  auto gmpq = [](const sepax::Vec3<Q>& v) {
    return sepax::Vec3<G>(G(v[0].get_mpq_t()), G(v[1].get_mpq_t()), G(v[2].get_mpq_t()));
  };
  int zeros = 0;
  for (int i = 0; i < 5000; ++i) {
    const sepax::Vec3<Q> a{Q{coordinate()}, Q{coordinate()}, Q{coordinate()}};
    const sepax::Vec3<Q> b{Q{coordinate()}, Q{coordinate()}, Q{coordinate()}};
    for (const sepax::Vec3<Q>& c : {b, sepax::Vec3<Q>(a[1], -a[0], Q(0))}) {  // and a tie (a . c = 0)
      const Q slow = reference(a, c);
      zeros += slow == 0;
      Q fast(7);
      REQUIRE(sepax::number_traits<Q>::exact_dot(fast, a, c));
      CHECK(fast == slow);
      CHECK(mpz_cmp(mpq_denref(fast.get_mpq_t()), mpq_denref(slow.get_mpq_t())) == 0);
      CHECK(sepax::dot(a, c) == slow);
      G g(5);
      const G shared = g;  // a copy sharing g's number is left as it was
      REQUIRE(sepax::number_traits<G>::exact_dot(g, gmpq(a), gmpq(c)));
      CHECK(mpq_equal(g.mpq(), slow.get_mpq_t()));
      CHECK(shared == G(5));
      CHECK(mpq_equal(sepax::dot(gmpq(a), gmpq(c)).mpq(), slow.get_mpq_t()));
    }
  }
  CHECK(zeros >= 5000);
  const sepax::Vec3<Q> u(Q(1, 3), Q(0.75), Q(-2)), w(Q(1), Q(0.125), Q(1, 6));
  Q out(5);
  CHECK_FALSE(sepax::number_traits<Q>::exact_dot(out, u, w));
  CHECK(out == 5);
  CHECK(sepax::dot(u, w) == reference(u, w));
  G gout(5);
  CHECK_FALSE(sepax::number_traits<G>::exact_dot(gout, gmpq(u), gmpq(w)));
  CHECK(gout == G(5));
}

TEST_CASE("exact dot signs (integers, interval filter) are the signs of the exact dot products",
          "[robust][number_types]") {
  // number_traits<T>::dot_sign for mpq_class, CGAL::Gmpq and Epeck::FT against the sign of mpq's dot, on
  // dyadic coordinates over many binades, non-dyadic rationals, and constructed ties: exact zeros with
  // terms of both signs and sums one unit of the last term's place away from zero.  Epeck values made by
  // arithmetic (x / 3 * 3) have intervals that are not points, so the ties reach the exact fallback.
  using Q = mpq_class;
  using X = CGAL::Epeck::FT;
  SpreadDoubles coordinate;
  int zeros = 0, mixed = 0;
  auto check = [&](const sepax::Vec3<Q>& a, const sepax::Vec3<Q>& b) {
    const int expected = sgn(sepax::dot(a, b));
    zeros += expected == 0;
    mixed += (sgn(a[0] * b[0]) * sgn(a[1] * b[1]) < 0) || (sgn(a[1] * b[1]) * sgn(a[2] * b[2]) < 0);
    CHECK(sepax::number_traits<Q>::dot_sign(a, b) == expected);
    using G = CGAL::Gmpq;
    const sepax::Vec3<G> ga(G(a[0].get_mpq_t()), G(a[1].get_mpq_t()), G(a[2].get_mpq_t()));
    const sepax::Vec3<G> gb(G(b[0].get_mpq_t()), G(b[1].get_mpq_t()), G(b[2].get_mpq_t()));
    CHECK(sepax::number_traits<G>::dot_sign(ga, gb) == expected);
    const sepax::Vec3<X> xa{X{a[0]}, X{a[1]}, X{a[2]}}, xb{X{b[0]}, X{b[1]}, X{b[2]}};
    CHECK(sepax::number_traits<X>::dot_sign(xa, xb) == expected);
    const sepax::Vec3<X> ya(xa[0] / 3 * 3, xa[1] / 3 * 3, xa[2] / 3 * 3);  // the same values, wider intervals
    CHECK(sepax::number_traits<X>::dot_sign(ya, xb) == expected);
    CHECK(sepax::sign_of_dot(a, b) == expected);
    // the same sign as a.(p - q), p = b + c and q = c for a random c (difference_dot_sign)
    const sepax::Vec3<Q> c{Q{coordinate()}, Q{coordinate()}, Q{coordinate()}};
    const sepax::Vec3<Q> p(b[0] + c[0], b[1] + c[1], b[2] + c[2]);
    const sepax::Vec3<X> xp{X{p[0]}, X{p[1]}, X{p[2]}}, xc{X{c[0]}, X{c[1]}, X{c[2]}};
    CHECK(sepax::number_traits<X>::difference_dot_sign(xa, xp, xc) == expected);
    CHECK(sepax::number_traits<X>::difference_dot_sign(ya, xp, xc) == expected);
    CHECK(sepax::sign_of_difference_dot(a, p, c) == expected);
  };
  for (int i = 0; i < 3000; ++i) {
    const sepax::Vec3<Q> a{Q{coordinate()}, Q{coordinate()}, Q{coordinate()}};
    const sepax::Vec3<Q> b{Q{coordinate()}, Q{coordinate()}, Q{coordinate()}};
    check(a, b);
    // a tie: a . (a_1 s, -a_0 s, 0) = 0, two terms of opposite signs
    const Q s(coordinate());
    const sepax::Vec3<Q> t(a[1] * s, -a[0] * s, Q(0));
    check(a, t);
    // next to a tie: a . (a_1, -a_0, 2^-1074) = a_2 2^-1074, far below the other terms
    const sepax::Vec3<Q> u(a[1], -a[0], Q(std::ldexp(1.0, -1074)));
    check(a, u);
    // non-dyadic rationals
    const sepax::Vec3<Q> r(a[0] / 3, a[1] / 7, Q(1, 5)), w(b[0] * 3, -a[1] / 3, Q(i % 9 - 4, 11));
    check(r, w);
    check(r, sepax::Vec3<Q>(r[1], -r[0], Q(0)));
  }
  CHECK(zeros > 3000);
  CHECK(mixed > 6000);
}

TEST_CASE("mpq values that are doubles convert without rounding; the others round once, to nearest",
          "[robust][number_types]") {
  // to_double reads a dyadic numerator of at most 53 bits over 2^z (z <= 1022) directly; every other
  // value goes through MPFR.  Both sides of that boundary give the nearest double.
  using Q = mpq_class;
  SpreadDoubles coordinate;
  for (int i = 0; i < 5000; ++i) {
    const double d = coordinate();
    CHECK(sepax::number_traits<Q>::to_double(Q(d)) == d);
    CHECK(sepax::number_traits<CGAL::Gmpq>::to_double(CGAL::Gmpq(d)) == d);
  }
  const Q two53(9007199254740992.0);                                           // 2^53
  CHECK(sepax::number_traits<Q>::to_double(two53 - 1) == 9007199254740991.0);  // 53 bits: exact
  CHECK(sepax::number_traits<Q>::to_double(two53 + 1) == 9007199254740992.0);  // 54 bits: tie to even
  CHECK(sepax::number_traits<Q>::to_double(two53 + 3) == 9007199254740996.0);  // tie to even, upward
  const Q one_plus = Q(1) + Q(std::ldexp(1.0, -60));
  CHECK(sepax::number_traits<Q>::to_double(one_plus) == 1.0);          // 61 bits over 2^60: rounds to 1
  const Q tiny = Q(std::ldexp(1.0, -1000)) * Q(std::ldexp(3.0, -74));  // 3 / 2^1074: z > 1022
  CHECK(sepax::number_traits<Q>::to_double(tiny) == std::ldexp(3.0, -1074));
  CHECK(sepax::number_traits<Q>::to_double(Q(std::ldexp(1.0, -1022))) == std::ldexp(1.0, -1022));
  CHECK(sepax::number_traits<Q>::to_double(-Q(std::ldexp(5.0, -1020))) == -std::ldexp(5.0, -1020));
}
