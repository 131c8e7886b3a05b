// posing.hpp's rigidity check against exact arithmetic: rotation_defect is an
// upper bound on |R^T R - I|_F (computed exactly in GMP rationals from the
// same float/double entries) and a tight one, and check_rigid accepts and
// refuses on both sides of its 1e-3 limit.
#include <catch2/catch.hpp>
#include <sepax/robust/number_types.hpp>

#include <sepax/posing.hpp>

#include <cmath>
#include <random>

using namespace sepax;

namespace {

// |R^T R - I|_F^2 exactly, R's entries taken exactly.
mpq_class exact_defect_squared(const double (&m)[3][3]) {
  mpq_class o2 = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      mpq_class g = 0;
      for (int k = 0; k < 3; ++k) g += mpq_class(m[k][i]) * mpq_class(m[k][j]);
      if (i == j) g -= 1;
      o2 += g * g;
    }
  }
  return o2;
}

// A rotation (from a random unit quaternion) times a random perturbation of
// relative size about 10^-digits per entry, entries rounded to T.
template <class T>
RigidTransform<T> near_rotation(std::mt19937_64& rng, int digits) {
  std::normal_distribution<double> n(0.0, 1.0);
  double q[4], len = 0;
  for (double& c : q) {
    c = n(rng);
    len += c * c;
  }
  len = std::sqrt(len);
  for (double& c : q) c /= len;
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                          {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                          {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  const double eps = std::pow(10.0, -digits);
  RigidTransform<T> t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t.rotation(i, j) = static_cast<T>(r[i][j] + eps * n(rng));
  return t;
}

template <class T>
void check_defect_bounds() {
  std::mt19937_64 rng(20261130);
  int tight = 0;
  for (int it = 0; it < 3000; ++it) {
    const int digits = 1 + it % 16;
    const RigidTransform<T> x = near_rotation<T>(rng, digits);
    double m[3][3];
    detail::rotation_in_double(x, m);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) REQUIRE(m[i][j] == static_cast<double>(x.rotation(i, j)));
    const double bound = detail::rotation_defect(x);
    const mpq_class exact2 = exact_defect_squared(m);
    // an upper bound
    REQUIRE(mpq_class(bound) * mpq_class(bound) >= exact2);
    // and a tight one: its rounding allowance is 13 u_d (|R|_F^2 + 1) plus a
    // relative 1e-10 (|R|_F^2 <= 3 (1 + 1e-2)^2 here)
    const double slack = 13 * 0x1p-53 * (3 * 1.03 + 1) * 1.01;
    const double lower = (bound - slack) / (1 + 2e-10);
    if (lower > 0) {
      REQUIRE(mpq_class(lower) * mpq_class(lower) <= exact2);
      ++tight;
    }
  }
  CHECK(tight > 1000);  // most cases are far above the rounding allowance
}

// s Q for a rotation Q (entries rounded to T): R^T R - I = (s^2 - 1) Q^T Q
// + (Q^T Q - I), a defect of sqrt(3) |s^2 - 1| up to Q's rounding.
template <class T>
RigidTransform<T> scaled_rotation(double s) {
  const double c = 0.6, d = 0.8;  // a turn about z (0.6 and 0.8 are rounded to T)
  RigidTransform<T> t;
  t.rotation << static_cast<T>(s * c), static_cast<T>(-s * d), T(0), static_cast<T>(s * d),
      static_cast<T>(s * c), T(0), T(0), T(0), static_cast<T>(s);
  return t;
}

}  // namespace

TEST_CASE("posing: rotation_defect bounds |R^T R - I| from above, tightly (float)", "[posing]") {
  check_defect_bounds<float>();
}

TEST_CASE("posing: rotation_defect bounds |R^T R - I| from above, tightly (double)", "[posing]") {
  check_defect_bounds<double>();
}

TEMPLATE_TEST_CASE("posing: check_rigid's limit of 1e-3 and its determinant test", "[posing]", float,
                   double) {
  using T = TestType;
  // defect sqrt(3) |s^2 - 1| = 1e-3 (1 -+ 3e-3): inside and outside, by far
  // more than the rounding of the entries to float (a few 1e-7)
  const double in = std::sqrt(1 + 0.997e-3 / std::sqrt(3.0));
  const double out = std::sqrt(1 + 1.003e-3 / std::sqrt(3.0));
  REQUIRE_NOTHROW(detail::check_rigid(scaled_rotation<T>(1.0)));
  REQUIRE_NOTHROW(detail::check_rigid(scaled_rotation<T>(in)));
  REQUIRE_NOTHROW(detail::check_rigid(scaled_rotation<T>(1 / in)));
  REQUIRE_THROWS_AS(detail::check_rigid(scaled_rotation<T>(out)), InvalidInput);
  REQUIRE_THROWS_AS(detail::check_rigid(scaled_rotation<T>(1 / out)), InvalidInput);
  // a reflection: orthogonal, det -1
  RigidTransform<T> mirror = scaled_rotation<T>(1.0);
  mirror.rotation(2, 2) = T(-1);
  REQUIRE_THROWS_AS(detail::check_rigid(mirror), InvalidInput);
  // a NaN entry
  RigidTransform<T> nan = scaled_rotation<T>(1.0);
  nan.rotation(1, 2) = std::numeric_limits<T>::quiet_NaN();
  REQUIRE_THROWS_AS(detail::check_rigid(nan), InvalidInput);
  // the message names the problem
  try {
    detail::check_rigid(scaled_rotation<T>(out));
    FAIL("no throw");
  } catch (const InvalidInput& e) {
    CHECK(std::string(e.what()).find("not a rotation") != std::string::npos);
  }
}
