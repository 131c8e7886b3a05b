// Tests for src/commands/pose.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include <sepax/error.hpp>

#include "commands/pose.hpp"

using namespace sepax;
using namespace sepax::cli;

TEST_CASE("pose: identity rotation moves points by the translation only, bit for bit", "[pose]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  for (const double s : {1.0, 2.0, 1e-3}) {  // (s,0,0,0) normalises to the identity
    const Pose p = Pose::make(Vec3<double>(0, 0, 0), {s, 0, 0, 0});
    for (int i = 0; i < 100; ++i) {
      const Vec3<double> x(u(rng), u(rng), u(rng));
      CHECK(p.apply(x) == x);
    }
  }
  const Pose t = Pose::make(Vec3<double>(0.5, -2, 3));
  CHECK(t.apply(Vec3<double>(1, 1, 1)) == Vec3<double>(1.5, -1, 4));
}

TEST_CASE("pose: rotations preserve distances and match known quarter turns", "[pose]") {
  const double h = std::sqrt(0.5);
  const Pose z90 = Pose::make(Vec3<double>(0, 0, 0), {h, 0, 0, h});  // 90 degrees about +z
  const Vec3<double> r = z90.apply(Vec3<double>(1, 0, 0));
  CHECK(r[0] == Approx(0).margin(1e-15));
  CHECK(r[1] == Approx(1).epsilon(1e-15));
  CHECK(r[2] == Approx(0).margin(1e-15));
  // an unnormalised quaternion is normalised first: (1,0,0,1) is the same turn
  const Vec3<double> r2 = Pose::make(Vec3<double>(0, 0, 0), {1, 0, 0, 1}).apply(Vec3<double>(1, 0, 0));
  CHECK((r2 - r).norm() < 1e-15);

  std::mt19937 rng(11);
  std::normal_distribution<double> g;
  for (int i = 0; i < 200; ++i) {
    const Pose p = Pose::make(Vec3<double>(g(rng), g(rng), g(rng)), {g(rng), g(rng), g(rng), g(rng)});
    const Vec3<double> a(g(rng), g(rng), g(rng)), b(g(rng), g(rng), g(rng));
    CHECK((p.apply(a) - p.apply(b)).norm() == Approx((a - b).norm()).epsilon(1e-12));
    // proper rotation: orientation preserved
    const Vec3<double> o = p.apply(Vec3<double>(0, 0, 0));
    const Vec3<double> ex = p.apply(Vec3<double>(1, 0, 0)) - o, ey = p.apply(Vec3<double>(0, 1, 0)) - o,
                       ez = p.apply(Vec3<double>(0, 0, 1)) - o;
    CHECK(sepax::triple(ez, ex, ey) == Approx(1).epsilon(1e-12));
  }
}

TEST_CASE("pose: bad values are InvalidInput", "[pose]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(Pose::make(Vec3<double>(0, 0, 0), {0, 0, 0, 0}), InvalidInput);
  CHECK_THROWS_WITH(Pose::make(Vec3<double>(0, 0, 0), {0, 0, 0, 0}), Catch::Contains("quaternion is zero"));
  CHECK_THROWS_WITH(Pose::make(Vec3<double>(nan, 0, 0)), Catch::Contains("translation is not finite"));
  CHECK_THROWS_WITH(Pose::make(Vec3<double>(0, 0, 0), {1, inf, 0, 0}),
                    Catch::Contains("quaternion is not finite"));
}

TEST_CASE("pose: quaternions of any finite size are normalised (squares out of double's range)", "[pose]") {
  const Pose unit = Pose::make(Vec3<double>(1, 2, 3), {1, 1, 0, 0});
  for (double s : {1e300, 1e-170, 1e-300, 5e-324}) {
    INFO("scale " << s);
    const Pose p = Pose::make(Vec3<double>(1, 2, 3), {s, s, 0, 0});
    for (int i = 0; i < 4; ++i) CHECK(p.rotation[i] == Approx(unit.rotation[i]).margin(1e-15));
    CHECK((p.apply(Vec3<double>(0.5, -1, 2)) - unit.apply(Vec3<double>(0.5, -1, 2))).norm() < 1e-12);
  }
}
