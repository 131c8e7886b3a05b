// shapes::box / tetrahedron / prism / regular_polygon / triangle in float and
// double: counts, validity, outward normals, flat polygons with exactly
// opposite normals.
#include <catch2/catch.hpp>

#include <sepax/convex_hull.hpp>
#include <sepax/shapes.hpp>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

using namespace sepax;

namespace {

template <class T>
void check_revalidates(const ConvexPolyhedron<T>& p) {
  std::vector<std::vector<int>> faces;
  for (int f = 0; f < p.face_count(); ++f) faces.push_back(p.face_vertices(f));
  CHECK_NOTHROW(ConvexPolyhedron<T>::from_faces(p.vertices(), faces));
}

// Every face normal points away from the centroid of a solid.
template <class T>
void check_outward(const ConvexPolyhedron<T>& p) {
  for (int f = 0; f < p.face_count(); ++f)
    CHECK(dot(p.plane(f).normal, p.centroid()) - p.plane(f).offset < T(0));
}

template <class T>
void check_counts(const ConvexPolyhedron<T>& p, int v, int e, int f) {
  CHECK(p.vertex_count() == v);
  CHECK(p.edge_count() == e);
  CHECK(p.face_count() == f);
}

}  // namespace

TEMPLATE_TEST_CASE("box, cube and tetrahedron", "[shapes]", float, double) {
  using T = TestType;
  const auto b = shapes::box<T>(1.0, 2.0, 3.0);
  check_counts(b, 8, 12, 6);
  check_revalidates(b);
  check_outward(b);
  CHECK(b.bounds_max() == Vec3<T>(T(1), T(2), T(3)));
  CHECK(b.bounds_min() == Vec3<T>(T(-1), T(-2), T(-3)));
  CHECK(b.extent() == Approx(2 * std::sqrt(14.0)));
  for (int f = 0; f < 6; ++f) CHECK(b.face(f).count == 4);
  check_counts(shapes::cube<T>(0.5), 8, 12, 6);
  const auto t = shapes::tetrahedron<T>(2.0);
  check_counts(t, 4, 6, 4);
  check_revalidates(t);
  check_outward(t);
  // the hull of a shape's vertices is the shape again
  check_counts(convex_hull(b.vertices()), 8, 12, 6);
  check_counts(convex_hull(t.vertices()), 4, 6, 4);
}

TEMPLATE_TEST_CASE("prism(n)", "[shapes]", float, double) {
  using T = TestType;
  for (int n : {3, 4, 5, 8, 16, 64}) {
    INFO("n = " << n);
    const auto p = shapes::prism<T>(n, 2.0, 0.5);
    check_counts(p, 2 * n, 3 * n, n + 2);
    check_revalidates(p);
    check_outward(p);
    int caps = 0;
    for (int f = 0; f < p.face_count(); ++f) caps += p.face(f).count == n;
    CHECK(caps == (n == 4 ? 6 : 2));
    const auto h = convex_hull(p.vertices());
    check_counts(h, 2 * n, 3 * n, n + 2);
  }
  CHECK_THROWS_AS(shapes::prism<T>(2), InvalidInput);
}

TEST_CASE("prism(n) with many sides: each cap is one face of n vertices", "[shapes]") {
  // (validation checks each face loop for a repeated vertex in time linear in the loop)
  const int n = 100000;
  const auto p = shapes::prism<double>(n);
  check_counts(p, 2 * n, 3 * n, n + 2);
  CHECK(p.face(n).count == n);
  CHECK(p.face(n + 1).count == n);
}

TEMPLATE_TEST_CASE("regular_polygon and triangle are double-sided with exactly opposite normals", "[shapes]",
                   float, double) {
  using T = TestType;
  for (int n : {3, 4, 6, 17, 100}) {
    INFO("n = " << n);
    const auto g = shapes::regular_polygon<T>(n, 1.5);
    REQUIRE(g.is_flat());
    check_counts(g, n, n, 2);
    check_revalidates(g);
    CHECK(g.plane(0).normal == Vec3<T>(-g.plane(1).normal));
    CHECK(g.plane(0).offset == -g.plane(1).offset);
    CHECK(g.plane(0).normal[2] > T(0));  // front normal +z
    CHECK(g.face(0).count == n);
    CHECK(g.face(1).count == n);
  }
  CHECK_THROWS_AS(shapes::regular_polygon<T>(2), InvalidInput);
  const Vec3<T> a(T(0.1f), T(0.2f), T(0.3f)), b(T(1.7f), T(-0.4f), T(0.9f)), c(T(-0.3f), T(1.1f), T(2.5f));
  const auto tri = shapes::triangle<T>(a, b, c);
  REQUIRE(tri.is_flat());
  check_counts(tri, 3, 3, 2);
  CHECK(tri.plane(0).normal == Vec3<T>(-tri.plane(1).normal));
  // front normal along (b - a) x (c - a)
  CHECK(dot(tri.plane(0).normal, cross(Vec3<T>(b - a), Vec3<T>(c - a))) > T(0));
  // an exactly collinear triangle is refused (DegenerateFace)
  const Vec3<T> d(T(1), T(2), T(-3));
  try {
    shapes::triangle<T>(d, Vec3<T>(T(2) * d), Vec3<T>(T(3) * d));
    FAIL("collinear triangle accepted");
  } catch (const InvalidInput& e) {
    CHECK(e.code() == ErrorCode::DegenerateFace);
  }
}

// A size finite as a double that float cannot hold is BadScale naming the coordinate, for every shape;
// in double the same size is a valid shape, and a NaN size stays NonFinite.
TEST_CASE("shapes beyond float's range are BadScale naming the coordinate", "[shapes]") {
  auto code_and_message = [](auto&& make) {
    try {
      make();
    } catch (const InvalidInput& e) {
      return std::make_pair(e.code(), std::string(e.what()));
    }
    return std::make_pair(ErrorCode::NonFinite, std::string("no error"));
  };
  const auto box = code_and_message([] { return shapes::box<float>(1e300, 1.0, 1.0); });
  CHECK(box.first == ErrorCode::BadScale);
  CHECK(box.second.find("coordinate x of vertex 0 (-1e+300) is beyond the range of float") !=
        std::string::npos);
  const auto cube = code_and_message([] { return shapes::cube<float>(1e39); });
  CHECK(cube.first == ErrorCode::BadScale);
  CHECK(cube.second.find("is beyond the range of float") != std::string::npos);
  const auto tet = code_and_message([] { return shapes::tetrahedron<float>(-1e300); });
  CHECK(tet.first == ErrorCode::BadScale);
  CHECK(tet.second.find("coordinate x of vertex 0 (-1e+300)") != std::string::npos);
  const auto prism = code_and_message([] { return shapes::prism<float>(8, 1.0, 1e40); });
  CHECK(prism.first == ErrorCode::BadScale);
  CHECK(prism.second.find("coordinate z of vertex 0 (-1e+40)") != std::string::npos);
  const auto polygon = code_and_message([] { return shapes::regular_polygon<float>(5, 1e300); });
  CHECK(polygon.first == ErrorCode::BadScale);
  CHECK(polygon.second.find("coordinate x of vertex 0 (1e+300)") != std::string::npos);
  CHECK_NOTHROW(shapes::cube<double>(1e39));
  const auto nan = code_and_message([] { return shapes::cube<float>(std::nan("")); });
  CHECK(nan.first == ErrorCode::NonFinite);
  CHECK(nan.second != "no error");
}
