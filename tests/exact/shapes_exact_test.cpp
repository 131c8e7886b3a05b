// shapes with mpq_class: counts, exact validity, exactly opposite normals of
// flat polygons, faces exactly planar.
#include <catch2/catch.hpp>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <sepax/robust/number_types.hpp>

#include <sepax/shapes.hpp>

#include <vector>

using namespace sepax;

namespace {

template <class T>
void check_exact(const ConvexPolyhedron<T>& p, int v, int e, int f) {
  CHECK(p.vertex_count() == v);
  CHECK(p.edge_count() == e);
  CHECK(p.face_count() == f);
  std::vector<std::vector<int>> faces;
  for (int g = 0; g < p.face_count(); ++g) {
    faces.push_back(p.face_vertices(g));
    for (int w : p.face_vertices(g))
      CHECK(bool(dot(p.plane(g).normal, p.vertex(w)) - p.plane(g).offset == T(0)));
  }
  CHECK_NOTHROW(ConvexPolyhedron<T>::from_faces(p.vertices(), faces));
}

}  // namespace

TEST_CASE("exact shapes (mpq)", "[shapes][exact]") {
  using T = mpq_class;
  check_exact(shapes::box<T>(1.0, 2.0, 0.25), 8, 12, 6);
  check_exact(shapes::tetrahedron<T>(1.0), 4, 6, 4);
  for (int n : {3, 5, 8, 24}) {
    INFO("n = " << n);
    // trigonometric vertices are rounded doubles, converted exactly: the caps
    // are still exactly planar (all cap vertices share one z)
    check_exact(shapes::prism<T>(n, 1.0, 0.5), 2 * n, 3 * n, n + 2);
    const auto g = shapes::regular_polygon<T>(n, 2.0);
    check_exact(g, n, n, 2);
    CHECK(g.is_flat());
    CHECK(bool(g.plane(0).normal == Vec3<T>(-g.plane(1).normal)));
    CHECK(bool(g.plane(0).offset == -g.plane(1).offset));
  }
  const Vec3<T> a(T(1) / 3, T(0), T(2)), b(T(5), T(1) / 7, T(-1)), c(T(-2), T(3), T(1) / 11);
  const auto tri = shapes::triangle<T>(a, b, c);
  check_exact(tri, 3, 3, 2);
  CHECK(bool(tri.plane(0).normal == Vec3<T>(-tri.plane(1).normal)));
  CHECK(bool(tri.plane(0).normal == cross(Vec3<T>(b - a), Vec3<T>(c - a))));
}
