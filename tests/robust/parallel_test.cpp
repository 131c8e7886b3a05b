// (P2) parallel() against GMP: exactly parallel directions (scaled copies,
// axis-aligned, zero length), one-ulp perturbations, random, huge and tiny.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <sepax/robust/number_types.hpp>
#include <sepax/robust/parallel.hpp>

using namespace sepax;
using namespace sepax::robust;

namespace {

template <class F>
bool oracle(const Vec3<F>& a0, const Vec3<F>& a1, const Vec3<F>& b0, const Vec3<F>& b1) {
  mpq_class a[3], b[3];
  for (int i = 0; i < 3; ++i) {
    a[i] = mpq_class(static_cast<double>(a1[i])) - mpq_class(static_cast<double>(a0[i]));
    b[i] = mpq_class(static_cast<double>(b1[i])) - mpq_class(static_cast<double>(b0[i]));
  }
  return a[1] * b[2] - a[2] * b[1] == 0 && a[2] * b[0] - a[0] * b[2] == 0 && a[0] * b[1] - a[1] * b[0] == 0;
}

struct Counts {
  int total = 0, parallel = 0;
};

template <class F>
void check(const Vec3<F>& a0, const Vec3<F>& a1, const Vec3<F>& b0, const Vec3<F>& b1, Counts& n) {
  const bool want = oracle(a0, a1, b0, b1);
  INFO("a0 " << a0.transpose() << " a1 " << a1.transpose() << " b0 " << b0.transpose() << " b1 "
             << b1.transpose());
  REQUIRE(parallel(a0, a1, b0, b1) == want);
  REQUIRE(parallel_exact(a0, a1, b0, b1) == want);
  REQUIRE(parallel(b0, b1, a0, a1) == want);
  ++n.total;
  n.parallel += want;
}

template <class F>
Vec3<F> rnd(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-1, 1);
  return Vec3<F>(static_cast<F>(u(rng) * scale), static_cast<F>(u(rng) * scale),
                 static_cast<F>(u(rng) * scale));
}

}  // namespace

TEMPLATE_TEST_CASE("parallel: exact and near-parallel directions", "[parallel]", float, double) {
  using F = TestType;
  std::mt19937_64 rng(9);
  std::uniform_int_distribution<int> small(-64, 64);
  Counts n;
  for (double scale : {1.0, 1e-150, 1e150, 1e-20, 1e20}) {
    if (std::is_same_v<F, float> && (scale > 1e30 || scale < 1e-30)) continue;
    for (int i = 0; i < 1000; ++i) {
      const Vec3<F> o = rnd<F>(rng, scale), p = rnd<F>(rng, scale), d = rnd<F>(rng, scale);
      const Vec3<F> z(F(0), F(0), F(0));
      // scaled copy by a small integer: parallel iff the products stay exact
      const F k = static_cast<F>(small(rng));
      check(z, d, z, Vec3<F>(d * k), n);
      // same direction from different origins (differences round: the oracle decides)
      check(o, Vec3<F>(o + d), p, Vec3<F>(p + d), n);
      // one ulp off
      Vec3<F> e = d;
      e[i % 3] = std::nextafter(e[i % 3], F(0));
      check(z, d, z, e, n);
      // zero-length edge
      check(o, o, p, d, n);
      // random
      check(o, p, d, rnd<F>(rng, scale), n);
      // axis-aligned integer edges, as in boxes and prisms
      const F s = static_cast<F>(scale);
      check(Vec3<F>(F(small(rng)) * s, F(1) * s, F(2) * s), Vec3<F>(F(small(rng)) * s, F(1) * s, F(2) * s),
            Vec3<F>(F(3) * s, F(small(rng)) * s, F(-1) * s),
            Vec3<F>(F(small(rng)) * s, F(small(rng)) * s, F(-1) * s), n);
    }
  }
  CHECK(n.parallel > n.total / 10);  // scaled copies and zero-length edges (2 of 6 checks) are parallel
  CHECK(n.parallel < n.total);
}

TEST_CASE("parallel: subnormal directions", "[parallel]") {
  Counts n;
  const double t = std::numeric_limits<double>::denorm_min();
  const Vec3<double> z(0, 0, 0);
  check(z, Vec3<double>(t, 0, 0), z, Vec3<double>(3 * t, 0, 0), n);
  check(z, Vec3<double>(t, t, 0), z, Vec3<double>(3 * t, 2 * t, 0), n);
  check(z, Vec3<double>(1e-160, 1e-160, 0), z, Vec3<double>(1e-160, 1e-160, t), n);
  CHECK(n.total == 3);
}
