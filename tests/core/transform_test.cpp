// RigidTransform<float/double>: apply, compose, inverse, quaternions, and
// transformed() polyhedra.
#include <catch2/catch.hpp>

#include <sepax/convex_hull.hpp>
#include <sepax/shapes.hpp>
#include <sepax/transform.hpp>

#include <cmath>
#include <random>

using namespace sepax;

namespace {

template <class T>
double orthogonality_error(const Eigen::Matrix<T, 3, 3>& r) {
  double worst = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += static_cast<double>(r(k, i)) * static_cast<double>(r(k, j));
      worst = std::max(worst, std::abs(s - (i == j ? 1.0 : 0.0)));
    }
  return worst;
}

template <class T>
double dist(const Vec3<T>& a, const Vec3<T>& b) {
  return (vec_to_double(a) - vec_to_double(b)).norm();
}

}  // namespace

TEMPLATE_TEST_CASE("identity, translation, and a quarter turn", "[transform]", float, double) {
  using T = TestType;
  const Vec3<T> p(T(1), T(2), T(3));
  CHECK(RigidTransform<T>::identity().apply(p) == p);
  CHECK(RigidTransform<T>::translation_by(Vec3<T>(T(1), T(0), T(-1))).apply(p) == Vec3<T>(T(2), T(2), T(2)));
  const double h = std::sqrt(0.5);
  const auto rz = RigidTransform<T>::from_quaternion(h, 0, 0, h);  // 90 degrees about z
  CHECK(dist(rz.apply(Vec3<T>(T(1), T(0), T(0))), Vec3<T>(T(0), T(1), T(0))) < 1e-6);
  CHECK(dist(rz.apply(Vec3<T>(T(0), T(1), T(0))), Vec3<T>(T(-1), T(0), T(0))) < 1e-6);
  // unnormalised quaternions are normalised
  const auto rz2 = RigidTransform<T>::from_quaternion(3, 0, 0, 3);
  CHECK(dist(rz2.apply(p), rz.apply(p)) < 1e-6);
  // the integer form: q = (1, 0, 0, 1) is the same quarter turn
  const auto ri = from_integer_quaternion<T>(1, 0, 0, 1);
  CHECK(ri.apply(Vec3<T>(T(1), T(0), T(0))) == Vec3<T>(T(0), T(1), T(0)));
}

TEMPLATE_TEST_CASE("random rotations: orthogonal, compose, inverse", "[transform]", float, double) {
  using T = TestType;
  const double u = number_traits<T>::unit_roundoff;
  std::mt19937 rng(1);
  std::normal_distribution<double> nd;
  std::uniform_int_distribution<int> qi(-50, 50);
  for (int rep = 0; rep < 100; ++rep) {
    const Vec3<T> ta(static_cast<T>(nd(rng)), static_cast<T>(nd(rng)), static_cast<T>(nd(rng)));
    const auto a = RigidTransform<T>::from_quaternion(nd(rng), nd(rng), nd(rng), nd(rng), ta);
    const auto b = from_integer_quaternion<T>(qi(rng), qi(rng), qi(rng), qi(rng) + 51);
    INFO("orthogonality error / u = " << orthogonality_error(a.rotation) / u);
    CHECK(orthogonality_error(a.rotation) < 16 * u);
    CHECK(orthogonality_error(b.rotation) < 8 * u);
    CHECK(static_cast<double>(triple(a.column(0), a.column(1), a.column(2))) == Approx(1.0).epsilon(16 * u));
    const Vec3<T> p(static_cast<T>(nd(rng)), static_cast<T>(nd(rng)), static_cast<T>(nd(rng)));
    const double scale = 1 + vec_to_double(p).norm() + vec_to_double(ta).norm();
    CHECK(dist((a * b).apply(p), a.apply(b.apply(p))) < 32 * u * scale);
    CHECK(dist(a.inverse().apply(a.apply(p)), p) < 32 * u * scale);
    CHECK(dist(b.inverse().apply(b.apply(p)), p) < 32 * u * scale);
    // inverse of a composition is the reversed composition of inverses
    CHECK(dist((a * b).inverse().apply(p), b.inverse().apply(a.inverse().apply(p))) < 64 * u * scale);
    // lengths are preserved
    CHECK(vec_to_double(Vec3<T>(a.rotate(p))).norm() == Approx(vec_to_double(p).norm()).epsilon(16 * u));
  }
}

TEMPLATE_TEST_CASE("transformed polyhedra: planes follow, hull commutes with motion", "[transform]", float,
                   double) {
  using T = TestType;
  const double u = number_traits<T>::unit_roundoff;
  const auto box = shapes::box<T>(1.0, 2.0, 0.5);
  const auto xf = RigidTransform<T>::from_quaternion(0.9, 0.1, -0.3, 0.2, Vec3<T>(T(3), T(-1), T(2)));
  const auto moved = transformed(box, xf);
  REQUIRE(moved.vertex_count() == box.vertex_count());
  REQUIRE(moved.face_count() == box.face_count());
  for (int v = 0; v < box.vertex_count(); ++v) CHECK(moved.vertex(v) == xf.apply(box.vertex(v)));
  for (int f = 0; f < box.face_count(); ++f) {
    // planes recomputed from the moved vertices: normal = R n
    CHECK(dist(moved.plane(f).normal, xf.rotate(box.plane(f).normal)) < 64 * u);
    for (int v : moved.face_vertices(f))
      CHECK(std::abs(to_double(T(dot(moved.plane(f).normal, moved.vertex(v)) - moved.plane(f).offset))) <
            64 * u * 8);
  }
  std::vector<std::vector<int>> faces;
  for (int f = 0; f < moved.face_count(); ++f) faces.push_back(moved.face_vertices(f));
  CHECK_NOTHROW(ConvexPolyhedron<T>::from_faces(moved.vertices(), faces));
  // distances between vertices are preserved (the bounding box is not)
  for (int i = 0; i < box.vertex_count(); ++i)
    for (int j = 0; j < i; ++j)
      CHECK(dist(moved.vertex(i), moved.vertex(j)) ==
            Approx(dist(box.vertex(i), box.vertex(j))).epsilon(64 * u));

  // hull(moved points) has the same combinatorics as moved hull(points)
  std::mt19937 rng(4);
  std::normal_distribution<double> nd;
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 40; ++i) {
    Vec3<double> d(nd(rng), nd(rng), nd(rng));
    pts.push_back(vec_cast<T>(Vec3<double>(d / d.norm())));
  }
  const auto h = convex_hull(pts);
  std::vector<Vec3<T>> mpts;
  for (const auto& p : pts) mpts.push_back(xf.apply(p));
  const auto hm = convex_hull(mpts);
  CHECK(hm.vertex_count() == h.vertex_count());
  CHECK(hm.face_count() == h.face_count());
}

TEMPLATE_TEST_CASE("quaternions of any finite non-zero size give the same rotation", "[transform]", float,
                   double) {
  using T = TestType;
  const auto unit = RigidTransform<T>::from_quaternion(0.9, 0.1, -0.3, 0.2);
  for (double s : {1e300, 1e150, 1e-150, 1e-300}) {
    INFO("scale " << s);
    const auto r = RigidTransform<T>::from_quaternion(0.9 * s, 0.1 * s, -0.3 * s, 0.2 * s);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        CHECK(to_double(r.rotation(i, j)) == Approx(to_double(unit.rotation(i, j))).margin(1e-6));
  }
}

TEMPLATE_TEST_CASE("bad quaternions are InvalidInput", "[transform][errors]", float, double) {
  using T = TestType;
  auto code = [](auto&& make) {
    try {
      make();
    } catch (const InvalidInput& e) {
      return e.code();
    }
    return ErrorCode::Parse;
  };
  CHECK(code([] { RigidTransform<T>::from_quaternion(0, 0, 0, 0); }) == ErrorCode::BadScale);
  CHECK(code([] { RigidTransform<T>::from_quaternion(std::nan(""), 0, 0, 1); }) == ErrorCode::NonFinite);
  CHECK(code([] { RigidTransform<T>::from_quaternion(1, INFINITY, 0, 1); }) == ErrorCode::NonFinite);
  CHECK(code([] { rotation_from_integer_quaternion<T>(0, 0, 0, 0); }) == ErrorCode::BadScale);
  CHECK(code([] { rotation_from_integer_quaternion<T>(1L << 26, 0, 0, 1); }) == ErrorCode::BadScale);
}
