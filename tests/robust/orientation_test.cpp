// (P1) orient_sign against GMP rationals, on inputs built to be hard: exact
// zeros, c = a + b, nearly parallel vectors, points on a line / plane moved by
// one ulp, huge and tiny magnitudes, float and double, random.  The filter is
// also checked on its own: whenever it returns a sign, that sign is exact.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include <sepax/robust/number_types.hpp>
#include <sepax/robust/orientation.hpp>

using namespace sepax;
using namespace sepax::robust;

namespace {

template <class F>
mpq_class q(F x) {
  return mpq_class(static_cast<double>(x));
}

template <class F>
int oracle(const Vec3<F>& a0, const Vec3<F>& a1, const Vec3<F>& b0, const Vec3<F>& b1, const Vec3<F>& c0,
           const Vec3<F>& c1) {
  mpq_class a[3], b[3], c[3];
  for (int i = 0; i < 3; ++i) {
    a[i] = q(a1[i]) - q(a0[i]);
    b[i] = q(b1[i]) - q(b0[i]);
    c[i] = q(c1[i]) - q(c0[i]);
  }
  const mpq_class d = a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                      a[2] * (b[0] * c[1] - b[1] * c[0]);
  return sgn(d);
}

struct Counts {
  int total = 0, zeros = 0, filtered = 0;
};

template <class F>
void check(const Vec3<F>& a0, const Vec3<F>& a1, const Vec3<F>& b0, const Vec3<F>& b1, const Vec3<F>& c0,
           const Vec3<F>& c1, Counts& n) {
  const int want = oracle(a0, a1, b0, b1, c0, c1);
  std::int64_t fb = 0;
  const int got = orient_sign(a0, a1, b0, b1, c0, c1, &fb);
  const int filt = orient_filter(a0[0], a0[1], a0[2], a1[0], a1[1], a1[2], b0[0], b0[1], b0[2], b1[0], b1[1],
                                 b1[2], c0[0], c0[1], c0[2], c1[0], c1[1], c1[2]);
  INFO("a0 " << a0.transpose() << " a1 " << a1.transpose() << " b0 " << b0.transpose() << " b1 "
             << b1.transpose() << " c0 " << c0.transpose() << " c1 " << c1.transpose());
  REQUIRE(got == want);
  if (filt != kUncertain) {
    REQUIRE(filt == want);
    REQUIRE(fb == 0);
    ++n.filtered;
  } else {
    REQUIRE(fb == 1);
  }
  REQUIRE(orient_sign_exact(a0, a1, b0, b1, c0, c1) == want);
  // Antisymmetry: swapping two difference vectors flips the sign.
  REQUIRE(orient_sign(b0, b1, a0, a1, c0, c1) == -want);
  ++n.total;
  if (want == 0) ++n.zeros;
}

template <class F>
F ulp_step(F x, int k) {
  for (int i = 0; i < std::abs(k); ++i)
    x = std::nextafter(x, k > 0 ? std::numeric_limits<F>::infinity() : -std::numeric_limits<F>::infinity());
  return x;
}

template <class F>
Vec3<F> rnd(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-1, 1);
  return Vec3<F>(static_cast<F>(u(rng) * scale), static_cast<F>(u(rng) * scale),
                 static_cast<F>(u(rng) * scale));
}

}  // namespace

TEMPLATE_TEST_CASE("orient_sign: random inputs at many scales", "[orientation]", float, double) {
  using F = TestType;
  std::mt19937_64 rng(1);
  Counts n, in_range;
  for (double scale : {1.0, 1e-150, 1e150, 1e-30, 1e30, 1e-300, 1e300}) {
    if (std::is_same_v<F, float> && (scale > 1e37 || scale < 1e-37)) continue;
    // Triple products of 1e±150 differences leave double's range: the filter
    // must give up there (the exact stage decides); elsewhere it decides.
    Counts& c = (scale >= 1e-30 && scale <= 1e30) ? in_range : n;
    for (int i = 0; i < 2000; ++i) {
      check(rnd<F>(rng, scale), rnd<F>(rng, scale), rnd<F>(rng, scale), rnd<F>(rng, scale),
            rnd<F>(rng, scale), rnd<F>(rng, scale), c);
    }
  }
  CHECK(in_range.filtered > in_range.total * 99 / 100);
}

TEMPLATE_TEST_CASE("orient_sign: exact zeros (c = a + b, collinear, coplanar)", "[orientation]", float,
                   double) {
  using F = TestType;
  std::mt19937_64 rng(2);
  std::uniform_int_distribution<int> small(-1000, 1000);
  Counts n;
  for (double scale : {1.0, 0x1p-60, 0x1p60, 0x1p-500, 0x1p500}) {
    if (std::is_same_v<F, float> && (scale > 0x1p100 || scale < 0x1p-100)) continue;
    for (int i = 0; i < 1000; ++i) {
      auto iv = [&] {
        return Vec3<F>(static_cast<F>(small(rng) * scale), static_cast<F>(small(rng) * scale),
                       static_cast<F>(small(rng) * scale));
      };
      const Vec3<F> o = iv(), a = iv(), b = iv();
      const Vec3<F> z(F(0), F(0), F(0));
      // c = a + b (exact: small integers times a power of two)
      check(z, a, z, b, z, Vec3<F>(a + b), n);
      // differences sharing an origin, third = first + second
      check(o, Vec3<F>(o + a), o, Vec3<F>(o + b), o, Vec3<F>(o + a + b), n);
      // repeated vector
      check(o, a, o, b, o, a, n);
      // three collinear directions
      check(z, a, z, Vec3<F>(a * F(2)), z, b, n);
    }
  }
  CHECK(n.zeros >= n.total * 3 / 4);
}

TEMPLATE_TEST_CASE("orient_sign: points on a plane moved by one ulp", "[orientation]", float, double) {
  using F = TestType;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  Counts n;
  for (double scale : {1.0, 1e-150, 1e150, 1e-20, 1e20}) {
    if (std::is_same_v<F, float> && (scale > 1e30 || scale < 1e-30)) continue;
    for (int i = 0; i < 1000; ++i) {
      // plane z = x + y (exactly representable sums for dyadic x, y); then one
      // coordinate of one point moved by -2..2 ulps.
      auto on_plane = [&] {
        const F x = static_cast<F>(std::ldexp(std::round(u(rng) * 4096), -12) * scale);
        const F y = static_cast<F>(std::ldexp(std::round(u(rng) * 4096), -12) * scale);
        return Vec3<F>(x, y, F(x + y));
      };
      const Vec3<F> p = on_plane(), q1 = on_plane(), r = on_plane();
      Vec3<F> s = on_plane();
      const int k = static_cast<int>(i % 5) - 2;
      s[i % 3] = ulp_step(s[i % 3], k);
      check(p, q1, p, r, p, s, n);  // orient3d-like
    }
  }
  CHECK(n.zeros > 0);
  CHECK(n.zeros < n.total);
}

TEMPLATE_TEST_CASE("orient_sign: nearly parallel vectors", "[orientation]", float, double) {
  using F = TestType;
  std::mt19937_64 rng(4);
  Counts n;
  for (double scale : {1.0, 1e-150, 1e150}) {
    if (std::is_same_v<F, float> && scale != 1.0) continue;
    for (int i = 0; i < 1000; ++i) {
      const Vec3<F> z(F(0), F(0), F(0));
      const Vec3<F> a = rnd<F>(rng, scale);
      Vec3<F> b = a, c = a;
      b[i % 3] = ulp_step(b[i % 3], 1 + static_cast<int>(i % 3));
      c[(i + 1) % 3] = ulp_step(c[(i + 1) % 3], -1);
      check(z, a, z, b, z, c, n);
      // and with a large common offset (cancellation in the differences)
      const Vec3<F> o = rnd<F>(rng, scale * 1e3);
      check(o, Vec3<F>(o + a), o, Vec3<F>(o + b), o, Vec3<F>(o + c), n);
    }
  }
  CHECK(n.total > 0);
}

TEST_CASE("orient_sign: subnormal and mixed-magnitude inputs", "[orientation]") {
  Counts n;
  const double tiny = std::numeric_limits<double>::denorm_min();
  const Vec3<double> z(0, 0, 0);
  check(z, Vec3<double>(tiny, 0, 0), z, Vec3<double>(0, tiny, 0), z, Vec3<double>(0, 0, tiny), n);
  check(z, Vec3<double>(1e300, 0, 0), z, Vec3<double>(0, 1e-300, 0), z, Vec3<double>(0, 0, tiny), n);
  check(z, Vec3<double>(1e-200, 1e-200, 0), z, Vec3<double>(1e-200, 1e-200, tiny), z,
        Vec3<double>(0, 0, 1e-160), n);
  check(z, Vec3<double>(1e200, 1e200, 1e200), z, Vec3<double>(1e200, 1e200, 1e-200), z,
        Vec3<double>(-1e200, 1e200, 3), n);
  const float ft = std::numeric_limits<float>::denorm_min();
  const Vec3<float> zf(0, 0, 0);
  check(zf, Vec3<float>(ft, 0, 0), zf, Vec3<float>(0, ft, 0), zf, Vec3<float>(ft, ft, ft), n);
  CHECK(n.total == 5);
}

TEST_CASE("orient3d is det[q-p, r-p, s-p]", "[orientation]") {
  const Vec3<double> p(0, 0, 0), qx(1, 0, 0), ry(0, 1, 0);
  CHECK(orient3d(p, qx, ry, Vec3<double>(0, 0, 1)) == 1);
  CHECK(orient3d(p, qx, ry, Vec3<double>(0, 0, -1)) == -1);
  CHECK(orient3d(p, qx, ry, Vec3<double>(5, 7, 0)) == 0);
}

TEST_CASE("orient_sign_integer: the rational sign within its exponent spread, declines beyond",
          "[orientation]") {
  // Coordinates m 2^k with random 24-bit mantissas and exponents k drawn from
  // a window of `spread` binades: within kIntegerExponentSpread the integer
  // stage decides and equals the rational sign; beyond it, it declines (and
  // orient_sign_exact's ExactFloat stage decides, checked by check()).
  // Degenerate sets (c = a + b, a repeated vector, aligned boxes' faces) make
  // the exact zeros that reach this stage in practice.
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::int32_t> mant(-(1 << 24) + 1, (1 << 24) - 1);
  Counts n;
  int decided = 0, declined = 0, zeros = 0;
  for (int spread : {0, 1, 8, 15, 16, 17, 20, 40}) {
    std::uniform_int_distribution<int> ex(-30, -30 + spread);
    auto coord = [&] {
      const std::int32_t m = mant(rng);
      return m % 7 == 0 ? 0.0f : std::ldexp(static_cast<float>(m), ex(rng));
    };
    auto v = [&] { return Vec3<float>(coord(), coord(), coord()); };
    for (int i = 0; i < 3000; ++i) {
      const Vec3<float> a0 = v(), a1 = v(), b0 = v(), b1 = v(), c0 = v(), c1 = v();
      // every third set: c1 - c0 = (a1 - a0) exactly when representable (a
      // repeated difference vector, determinant 0)
      const bool repeat = i % 3 == 0;
      const Vec3<float> cc0 = repeat ? a0 : c0, cc1 = repeat ? a1 : c1;
      const int want = oracle(a0, a1, b0, b1, cc0, cc1);
      const int got = orient_sign_integer(a0, a1, b0, b1, cc0, cc1);
      int emin = std::numeric_limits<int>::max(), emax = std::numeric_limits<int>::min();
      for (const Vec3<float>* p : {&a0, &a1, &b0, &b1, &cc0, &cc1})
        for (int c = 0; c < 3; ++c)
          if ((*p)[c] != 0.0f) {
            int e = 0;
            std::frexp((*p)[c], &e);
            emin = std::min(emin, e);
            emax = std::max(emax, e);
          }
      INFO("spread " << spread << " set " << i);
      if (emax - emin <= kIntegerExponentSpread) {
        REQUIRE(got == want);
        ++decided;
        zeros += want == 0;
      } else {
        REQUIRE(got == kUncertain);
        ++declined;
      }
      check(a0, a1, b0, b1, cc0, cc1, n);
    }
  }
  CHECK(decided > 10000);
  CHECK(declined > 5000);
  CHECK(zeros > 3000);
  // the extremes of the range: exponents exactly kIntegerExponentSpread apart
  // with the largest mantissas (the bound's worst case), and a subnormal
  const float big = std::nextafter(0x1p17f, 0.0f), small = 1.0f;  // exponent fields 16 apart
  const Vec3<float> z(0, 0, 0);
  const Vec3<float> ax(big, -big, big), by(-big, big, big), cz(big, big, -big), s(small, -small, small);
  CHECK(orient_sign_integer(Vec3<float>(-ax), ax, Vec3<float>(-by), by, Vec3<float>(-cz), cz) ==
        oracle(Vec3<float>(-ax), ax, Vec3<float>(-by), by, Vec3<float>(-cz), cz));
  CHECK(orient_sign_integer(s, ax, z, by, z, cz) == oracle(s, ax, z, by, z, cz));
  CHECK(orient_sign_integer(z, Vec3<float>(std::numeric_limits<float>::denorm_min(), 0, 0), z, by, z, cz) ==
        kUncertain);
  CHECK(orient_sign_integer(z, z, z, z, z, z) == 0);
}
