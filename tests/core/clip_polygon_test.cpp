#include <catch2/catch.hpp>

#include <sepax/clip_polygon.hpp>

using namespace sepax;

namespace {
// Square [-1,1]^2 at z = 0 as an incident polygon of face 7, vertices 0..3,
// edges 10..13.
template <class T>
std::vector<ClipVertex<T>> square() {
  const double xy[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  std::vector<ClipVertex<T>> p;
  for (int i = 0; i < 4; ++i) {
    ClipVertex<T> v;
    v.point = Vec3<T>(T(xy[i][0]), T(xy[i][1]), T(0));
    v.id = {ShapeFeature::face(3), ShapeFeature::vertex(i)};
    v.next_edge = 10 + i;
    p.push_back(v);
  }
  return p;
}

template <class T>
ClipPlane<T> plane(double nx, double ny, double off, int edge, int tail, int head) {
  return ClipPlane<T>{Vec3<T>(T(nx), T(ny), T(0)), T(off), edge, tail, head};
}
}  // namespace

TEMPLATE_TEST_CASE("clip a square by one plane", "[clip]", float, double) {
  using T = TestType;
  std::vector<ClipVertex<T>> out;
  clip_polygon(square<T>(), plane<T>(1, 0, 0.5, 5, 20, 21), 7, out);  // keep x <= 0.5
  REQUIRE(out.size() == 4);
  // order: v0, exit on edge 10 (bottom), entry on edge 12 (top), v3
  CHECK(out[0].id.b == ShapeFeature::vertex(0));
  CHECK(out[1].point == Vec3<T>(T(0.5), T(-1), T(0)));
  CHECK(out[1].id == (ContactFeatureId{ShapeFeature::edge(5), ShapeFeature::edge(10)}));
  CHECK(out[1].next_on_side);
  CHECK(out[1].next_edge == 5);
  CHECK(out[2].point == Vec3<T>(T(0.5), T(1), T(0)));
  CHECK(out[2].id == (ContactFeatureId{ShapeFeature::edge(5), ShapeFeature::edge(12)}));
  CHECK_FALSE(out[2].next_on_side);
  CHECK(out[2].next_edge == 12);
  CHECK(out[3].id.b == ShapeFeature::vertex(3));
}

TEMPLATE_TEST_CASE("clip: inside, outside, and vertices exactly on the plane", "[clip]", float, double) {
  using T = TestType;
  std::vector<ClipVertex<T>> out;
  clip_polygon(square<T>(), plane<T>(1, 0, 2, 5, 20, 21), 7, out);
  CHECK(out.size() == 4);
  clip_polygon(square<T>(), plane<T>(1, 0, -2, 5, 20, 21), 7, out);
  CHECK(out.empty());
  // the plane x <= 1 passes through v1 and v2: nothing is cut, nothing duplicated
  clip_polygon(square<T>(), plane<T>(1, 0, 1, 5, 20, 21), 7, out);
  REQUIRE(out.size() == 4);
  for (int i = 0; i < 4; ++i) CHECK(out[static_cast<std::size_t>(i)].id.b == ShapeFeature::vertex(i));
  // the diagonal x + y <= 0 passes through v1 and v3: a triangle v0 v1 v3,
  // and the segment from v1 now runs along the plane
  clip_polygon(square<T>(), plane<T>(1, 1, 0, 5, 20, 21), 7, out);
  REQUIRE(out.size() == 3);
  CHECK(out[0].id.b == ShapeFeature::vertex(0));
  CHECK(out[1].id.b == ShapeFeature::vertex(1));
  CHECK(out[1].next_on_side);
  CHECK(out[2].id.b == ShapeFeature::vertex(3));
}

TEMPLATE_TEST_CASE("clip by two adjacent side planes: the reference corner", "[clip]", float, double) {
  using T = TestType;
  // reference corner 21 between side edges 5 (20->21) and 6 (21->22):
  // keep x <= 0.5 and y <= 0.5
  std::vector<ClipVertex<T>> once, twice;
  clip_polygon(square<T>(), plane<T>(1, 0, 0.5, 5, 20, 21), 7, once);
  clip_polygon(once, plane<T>(0, 1, 0.5, 6, 21, 22), 7, twice);
  REQUIRE(twice.size() == 4);
  int corners = 0;
  for (const auto& v : twice) {
    if (v.point == Vec3<T>(T(0.5), T(0.5), T(0))) {
      ++corners;
      CHECK(v.id == (ContactFeatureId{ShapeFeature::vertex(21), ShapeFeature::face(7)}));
    }
  }
  CHECK(corners == 1);
  CHECK(shared_corner(20, 21, 21, 22) == 21);
  CHECK(shared_corner(20, 21, 22, 23) == -1);
}

TEMPLATE_TEST_CASE("weld_polygon removes near-duplicates only", "[clip]", float, double) {
  using T = TestType;
  auto p = square<T>();
  ClipVertex<T> dup = p[1];
  dup.point[0] = dup.point[0] + T(1e-6);
  dup.next_edge = 99;
  p.insert(p.begin() + 2, dup);
  auto q = p;
  weld_polygon(q, T(1e-10));  // tolerance 1e-5: merges the duplicate
  REQUIRE(q.size() == 4);
  CHECK(q[1].id.b == ShapeFeature::vertex(1));
  CHECK(q[1].next_edge == 99);  // the label of the segment leaving the run
  weld_polygon(p, T(1e-14));    // tolerance 1e-7: keeps it
  CHECK(p.size() == 5);
}
