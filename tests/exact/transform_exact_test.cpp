// RigidTransform with exact types: integer-quaternion rotations are exactly
// orthogonal, compositions and inverses are exact, and transformed shapes
// validate exactly.
#include <catch2/catch.hpp>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <sepax/robust/number_types.hpp>

#include <sepax/shapes.hpp>
#include <sepax/transform.hpp>

#include <random>

using namespace sepax;

namespace {

template <class T>
bool exactly_orthogonal(const Eigen::Matrix<T, 3, 3>& r) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      T s = r(0, i) * r(0, j);
      s = s + r(1, i) * r(1, j);
      s = s + r(2, i) * r(2, j);
      if (s != T(i == j ? 1 : 0)) return false;
    }
  return true;
}

// Vec3 equality as a plain bool (Catch would try to print Eigen objects of
// exact types, which Eigen's IO cannot do for Lazy_exact_nt)
template <class T>
bool same(const Vec3<T>& a, const Vec3<T>& b) {
  return a == b;
}

template <class T>
T det(const Eigen::Matrix<T, 3, 3>& r) {
  const Vec3<T> c0(r(0, 0), r(1, 0), r(2, 0)), c1(r(0, 1), r(1, 1), r(2, 1)), c2(r(0, 2), r(1, 2), r(2, 2));
  return triple(c0, c1, c2);
}

}  // namespace

TEMPLATE_TEST_CASE("integer-quaternion rotations are exactly orthogonal", "[transform][exact]", mpq_class,
                   CGAL::Epeck::FT) {
  using T = TestType;
  std::mt19937 rng(8);
  std::uniform_int_distribution<int> qi(-1000, 1000);
  for (int rep = 0; rep < 20; ++rep) {
    const auto a = from_integer_quaternion<T>(qi(rng), qi(rng), qi(rng), qi(rng) | 1,
                                              Vec3<T>(T(qi(rng)), T(1) / T(3), T(-7)));
    const auto b = from_integer_quaternion<T>(qi(rng), qi(rng) | 1, qi(rng), qi(rng));
    CHECK(exactly_orthogonal(a.rotation));
    CHECK(bool(det(a.rotation) == T(1)));
    const auto ab = a * b;
    CHECK(exactly_orthogonal(ab.rotation));
    const Vec3<T> p(T(qi(rng)) / T(7), T(qi(rng)), T(1) / T(qi(rng) | 1));
    CHECK(same(ab.apply(p), a.apply(b.apply(p))));
    CHECK(same(a.inverse().apply(a.apply(p)), p));
    CHECK(same(ab.inverse().apply(ab.apply(p)), p));
    CHECK(bool(squared_norm(Vec3<T>(a.rotate(p))) == squared_norm(p)));
  }
}

TEMPLATE_TEST_CASE("from_quaternion for exact T is the exact value of rounded doubles", "[transform][exact]",
                   mpq_class, CGAL::Epeck::FT) {
  using T = TestType;
  // documented: not exactly orthogonal for a generic quaternion
  const auto x = RigidTransform<T>::from_quaternion(0.9, 0.1, -0.3, 0.2);
  CHECK_FALSE(exactly_orthogonal(x.rotation));
  const auto xd = RigidTransform<double>::from_quaternion(0.9, 0.1, -0.3, 0.2);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) CHECK(bool(x.rotation(i, j) == from_double<T>(xd.rotation(i, j))));
}

TEMPLATE_TEST_CASE("exactly rotated shapes validate exactly", "[transform][exact]", mpq_class,
                   CGAL::Epeck::FT) {
  using T = TestType;
  const auto xf = from_integer_quaternion<T>(3, -1, 2, 5, Vec3<T>(T(1) / T(3), T(2), T(-5)));
  for (const auto& shape :
       {shapes::box<T>(1.0, 2.0, 0.5), shapes::prism<T>(7, 1.0, 2.0), shapes::tetrahedron<T>(1.0)}) {
    const auto moved = transformed(shape, xf);
    std::vector<std::vector<int>> faces;
    for (int f = 0; f < moved.face_count(); ++f) faces.push_back(moved.face_vertices(f));
    // exact validation: planar, convex, maximal faces after the exact motion
    CHECK_NOTHROW(ConvexPolyhedron<T>::from_faces(moved.vertices(), faces));
    for (int f = 0; f < moved.face_count(); ++f) {
      // the recomputed normal is exactly R times the original (unnormalised) normal
      CHECK(same(moved.plane(f).normal, xf.rotate(shape.plane(f).normal)));
    }
    // and back again exactly
    const auto back = transformed(moved, xf.inverse());
    CHECK(bool(back.vertices() == shape.vertices()));
  }
}
