// Plane<T>, plane_through and triangle_aspect (plane.hpp) on their own: the
// header builds alone, planes are outward-oriented unit planes at any scale
// float/double can hold, and the aspect measure is scale-free.
#include <catch2/catch.hpp>

#include <sepax/plane.hpp>

#include <cmath>
#include <limits>

using namespace sepax;

TEMPLATE_TEST_CASE("plane_through: right-hand normal, unit length, offset along it", "[plane]", float,
                   double) {
  using T = TestType;
  const Vec3<T> a(T(1), T(2), T(3)), b(T(3), T(2), T(3)), c(T(1), T(5), T(3));
  const Plane<T> p = plane_through(a, b, c);
  CHECK(p.normal[0] == T(0));
  CHECK(p.normal[1] == T(0));
  CHECK(p.normal[2] == T(1));
  CHECK(p.offset == T(3));
  const Plane<T> q = plane_through(a, c, b);  // the other turn: the other side
  CHECK(q.normal[2] == T(-1));
  CHECK(q.offset == T(-3));
}

TEMPLATE_TEST_CASE("plane_through: scale-safe where |N|^2 would overflow or underflow", "[plane]", float,
                   double) {
  using T = TestType;
  // sides of 2^e: |N|^2 = 2^(4e) leaves T's range for these e, the unit
  // normal does not
  const int e = std::numeric_limits<T>::max_exponent / 2 + 2;
  for (const int k : {e, -e}) {
    const T s = std::ldexp(T(1), k);
    const Vec3<T> a(T(0), T(0), T(0)), b(s, T(0), T(0)), c(T(0), s, T(0));
    const Plane<T> p = plane_through(a, b, c);
    INFO("side 2^" << k);
    CHECK(p.normal[0] == T(0));
    CHECK(p.normal[1] == T(0));
    CHECK(p.normal[2] == T(1));
    CHECK(p.offset == T(0));
  }
}

TEMPLATE_TEST_CASE("plane_through_cross is plane_through given the differences and cross product", "[plane]",
                   float, double) {
  using T = TestType;
  const Vec3<T> a(T(0.25), T(-1.5), T(2)), b(T(1.75), T(0.5), T(-1)), c(T(-0.5), T(2.25), T(0.75));
  const Vec3<T> e1(b - a), e2(c - a);
  const Plane<T> p = plane_through(a, b, c);
  const Plane<T> q = plane_through_cross(a, e1, e2, Vec3<T>(cross(e1, e2)));
  for (int i = 0; i < 3; ++i) CHECK(p.normal[i] == q.normal[i]);
  CHECK(p.offset == q.offset);
  CHECK(std::abs(static_cast<double>(squared_norm(p.normal)) - 1.0) < 8 * std::numeric_limits<T>::epsilon());
  // every vertex on the plane, within rounding of the offset
  for (const Vec3<T>* v : {&a, &b, &c})
    CHECK(std::abs(static_cast<double>(dot(p.normal, *v)) - static_cast<double>(p.offset)) <
          32 * std::numeric_limits<T>::epsilon());  // (coordinates and offset below 4)
}

TEMPLATE_TEST_CASE("triangle_aspect: height over longest side, at any scale", "[plane]", float, double) {
  using T = TestType;
  const double eq = std::sqrt(3.0) / 2;  // equilateral: |N| = (sqrt 3 / 2) L^2
  for (const int k : {-60, 0, 60}) {
    const T s = std::ldexp(T(1), k);
    const Vec3<T> a(T(0), T(0), T(0)), b(s, T(0), T(0)), c(T(s / 2), T(s * T(std::sqrt(3.0) / 2)), T(0));
    INFO("scale 2^" << k);
    CHECK(std::abs(detail::triangle_aspect(a, b, c) - eq) < 1e-6);
    // a right isosceles triangle: |N| = 1, L^2 = 2 (the hypotenuse)
    CHECK(std::abs(detail::triangle_aspect(a, b, Vec3<T>(T(0), s, T(0))) - 0.5) < 1e-6);
  }
  // collinear and coincident points have no height
  const Vec3<T> o(T(0), T(0), T(0)), u(T(1), T(1), T(1)), w(T(2), T(2), T(2));
  CHECK(detail::triangle_aspect(o, u, w) == 0);
  CHECK(detail::triangle_aspect(o, o, o) == 0);
  // a non-finite side has none either
  const Vec3<T> inf(std::numeric_limits<T>::infinity(), T(0), T(0));
  CHECK(detail::triangle_aspect(o, inf, u) == 0);
}
