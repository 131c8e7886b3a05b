// ConvexPolyhedron validation (every rule: the ErrorCode and a message that
// names the offending element) and the half-edge invariants of valid shapes.
#include <catch2/catch.hpp>

#include <sepax/convex_hull.hpp>
#include <sepax/convex_polyhedron.hpp>
#include <sepax/shapes.hpp>

#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace sepax;

namespace {

using Faces = std::vector<std::vector<int>>;

template <class T>
std::vector<Vec3<T>> cube_vertices() {
  // 0(-,-,-) 1(+,-,-) 2(+,+,-) 3(-,+,-) 4(-,-,+) 5(+,-,+) 6(+,+,+) 7(-,+,+)
  const int s[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                       {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  std::vector<Vec3<T>> v;
  for (const auto& p : s) v.emplace_back(T(p[0]), T(p[1]), T(p[2]));
  return v;
}

const Faces cube_faces{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};

struct Failure {
  ErrorCode code;
  std::string message;
};

template <class T>
Failure failure(std::vector<Vec3<T>> v, const Faces& f) {
  try {
    ConvexPolyhedron<T>::from_faces(std::move(v), f);
  } catch (const InvalidInput& e) {
    return {e.code(), e.what()};
  }
  return {ErrorCode::Parse, "no error"};
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

template <class T>
void check_half_edge_invariants(const ConvexPolyhedron<T>& p) {
  const int nh = p.half_edge_count();
  REQUIRE(nh == 2 * p.edge_count());
  int loop_total = 0;
  for (int h = 0; h < nh; ++h) {
    const auto& he = p.half_edge(h);
    const int t = ConvexPolyhedron<T>::twin(h);
    CHECK(t == (h ^ 1));
    CHECK(ConvexPolyhedron<T>::twin(t) == h);
    // a half-edge ends where its twin starts, and where its next starts
    CHECK(p.half_edge(t).origin == p.half_edge(he.next).origin);
    CHECK(p.half_edge(he.prev).next == h);
    CHECK(p.half_edge(he.next).prev == h);
    CHECK(p.half_edge(he.next).face == he.face);
    CHECK(he.face != p.half_edge(t).face);
  }
  for (int f = 0; f < p.face_count(); ++f) {
    int h = p.face(f).edge, n = 0;
    do {
      CHECK(p.half_edge(h).face == f);
      h = p.half_edge(h).next;
      ++n;
    } while (h != p.face(f).edge && n <= nh);
    CHECK(n == p.face(f).count);
    loop_total += n;
  }
  CHECK(loop_total == nh);
  // fans: every outgoing half-edge of v starts at v; together they are all half-edges
  int fan_total = 0;
  for (int v = 0; v < p.vertex_count(); ++v) {
    for (int h : p.vertex_half_edges(v)) CHECK(p.half_edge(h).origin == v);
    fan_total += static_cast<int>(p.vertex_half_edges(v).size());
    CHECK(p.vertex_half_edges(v).size() >= 2);
  }
  CHECK(fan_total == nh);
  // edge k: tail = origin(2k), head = origin(2k+1), faces of 2k and 2k+1
  for (int e = 0; e < p.edge_count(); ++e) {
    CHECK(p.edge_tail(e) == p.half_edge(2 * e).origin);
    CHECK(p.edge_head(e) == p.half_edge(2 * e + 1).origin);
    CHECK(p.edge_face(e, 0) == p.half_edge(2 * e).face);
    CHECK(p.edge_face(e, 1) == p.half_edge(2 * e + 1).face);
    if (!p.is_flat()) {
      // direction is a positive multiple of n0 x n1
      const Vec3<double> d = vec_to_double(p.edge_direction(e));
      const Vec3<double> c = cross(vec_to_double(p.plane(p.edge_face(e, 0)).normal),
                                   vec_to_double(p.plane(p.edge_face(e, 1)).normal));
      CHECK(dot(d, c) > 0);
      CHECK(std::sqrt(squared_norm(cross(d, c))) <= 1e-4 * d.norm() * c.norm());
    }
  }
  if (!p.is_flat()) CHECK(p.vertex_count() - p.edge_count() + p.face_count() == 2);
}

}  // namespace

TEMPLATE_TEST_CASE("validation: non-finite coordinates and too few points", "[polyhedron][errors]",
                   float, double) {
  using T = TestType;
  auto v = cube_vertices<T>();
  v[3][1] = std::numeric_limits<T>::quiet_NaN();
  auto f = failure<T>(v, cube_faces);
  CHECK(f.code == ErrorCode::NonFinite);
  CHECK(contains(f.message, "vertex 3"));
  v = cube_vertices<T>();
  v[6][2] = -std::numeric_limits<T>::infinity();
  f = failure<T>(v, cube_faces);
  CHECK(f.code == ErrorCode::NonFinite);
  CHECK(contains(f.message, "vertex 6"));
  f = failure<T>({Vec3<T>(T(0), T(0), T(0)), Vec3<T>(T(1), T(0), T(0))}, {{0, 1}, {1, 0}});
  CHECK(f.code == ErrorCode::TooFewPoints);
  CHECK(contains(f.message, "2"));
}

TEMPLATE_TEST_CASE("validation: topology errors name the face, edge or vertex",
                   "[polyhedron][errors]", float, double) {
  using T = TestType;
  const auto v = cube_vertices<T>();
  // repeated vertex in a face
  Faces f = cube_faces;
  f[2] = {0, 1, 5, 1};
  auto r = failure<T>(v, f);
  CHECK(r.code == ErrorCode::DegenerateFace);
  CHECK(contains(r.message, "face 2"));
  CHECK(contains(r.message, "vertex 1"));
  // face with < 3 vertices
  f = cube_faces;
  f[4] = {0, 4};
  r = failure<T>(v, f);
  CHECK(r.code == ErrorCode::DegenerateFace);
  CHECK(contains(r.message, "face 4"));
  // bad index
  f = cube_faces;
  f[1] = {4, 5, 9, 7};
  r = failure<T>(v, f);
  CHECK(r.code == ErrorCode::BadIndex);
  CHECK(contains(r.message, "face 1"));
  CHECK(contains(r.message, "vertex 9"));
  f[1] = {4, 5, -1, 7};
  CHECK(failure<T>(v, f).code == ErrorCode::BadIndex);
  // open surface: the top face missing
  f = cube_faces;
  f.erase(f.begin() + 1);
  r = failure<T>(v, f);
  CHECK(r.code == ErrorCode::NotManifold);
  CHECK(contains(r.message, "only one face"));
  CHECK((contains(r.message, "4-5") || contains(r.message, "5-4") || contains(r.message, "5-6") ||
         contains(r.message, "6-5") || contains(r.message, "6-7") || contains(r.message, "7-6") ||
         contains(r.message, "4-7") || contains(r.message, "7-4")));
  // an edge shared by three faces: a fin triangle on edge 0-1
  auto v9 = v;
  v9.emplace_back(T(0), T(-3), T(-3));
  f = cube_faces;
  f.push_back({0, 1, 8});
  r = failure<T>(v9, f);
  CHECK(r.code == ErrorCode::NotManifold);
  CHECK((contains(r.message, "0-1") || contains(r.message, "0->1") || contains(r.message, "1->0")));
  // inconsistent orientation: one face reversed
  f = cube_faces;
  std::reverse(f[3].begin(), f[3].end());
  r = failure<T>(v, f);
  CHECK(r.code == ErrorCode::NotManifold);
  CHECK(contains(r.message, "same direction"));
  // all faces inward
  f = cube_faces;
  for (auto& face : f) std::reverse(face.begin(), face.end());
  r = failure<T>(v, f);
  CHECK(r.code == ErrorCode::InwardFaces);
  // unused vertex
  auto v_extra = v;
  v_extra.emplace_back(T(0), T(0), T(0));
  r = failure<T>(v_extra, cube_faces);
  CHECK(r.code == ErrorCode::UnusedVertex);
  CHECK(contains(r.message, "vertex 8"));
  // Euler violation: two disjoint tetrahedra (each edge has two faces)
  std::vector<Vec3<T>> two;
  for (int k = 0; k < 2; ++k) {
    const T o = static_cast<T>(3 * k);
    two.emplace_back(o + T(1), T(1), T(1));
    two.emplace_back(o + T(1), T(-1), T(-1));
    two.emplace_back(o - T(1), T(1), T(-1));
    two.emplace_back(o - T(1), T(-1), T(1));
  }
  r = failure<T>(two, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}, {4, 5, 6}, {4, 7, 5}, {4, 6, 7}, {5, 7, 6}});
  CHECK(r.code == ErrorCode::BadEuler);
  CHECK(contains(r.message, "8 - 12 + 8"));
}

TEMPLATE_TEST_CASE("validation: geometric errors", "[polyhedron][errors]", float, double) {
  using T = TestType;
  // non-planar face: lift vertex 6 of the top face slightly
  auto v = cube_vertices<T>();
  v[6][2] = T(1.01);
  auto r = failure<T>(v, cube_faces);
  CHECK(r.code == ErrorCode::NonPlanarFace);
  CHECK(contains(r.message, "is not planar"));
  CHECK(contains(r.message, "face "));
  // reflex face: a chevron prism (cap polygon with a reflex corner at vertex 3)
  std::vector<Vec3<T>> cv;
  const double pts2[4][2] = {{0, 0}, {2, 2}, {0, 1}, {-2, 2}};  // (0,1) is reflex
  for (int k = 0; k < 2; ++k)
    for (const auto& p : pts2) cv.emplace_back(T(p[0]), T(p[1]), T(k));
  Faces cf{{3, 2, 1, 0}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  r = failure<T>(cv, cf);
  CHECK(r.code == ErrorCode::NonConvexFace);
  CHECK(contains(r.message, "vertex 2"));
  // non-convex polyhedron with convex faces: the top of a cube replaced by
  // an inward-pointing pyramid (apex 8 below the top)
  v = cube_vertices<T>();
  v.emplace_back(T(0), T(0), T(0.5));
  Faces dent{{0, 3, 2, 1}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5},
             {4, 5, 8},    {5, 6, 8},    {6, 7, 8},    {7, 4, 8}};
  r = failure<T>(v, dent);
  CHECK(r.code == ErrorCode::NotConvex);
  CHECK(contains(r.message, "above the plane of face"));
  // adjacent coplanar faces: the top split into two triangles
  v = cube_vertices<T>();
  Faces split = cube_faces;
  split[1] = {4, 5, 6};
  split.push_back({4, 6, 7});
  r = failure<T>(v, split);
  CHECK(r.code == ErrorCode::NotConvex);
  CHECK(contains(r.message, "coplanar"));
  CHECK(contains(r.message, "faces 1 and 6"));
  // zero-area face: a flat "polygon" with collinear vertices
  r = failure<T>({Vec3<T>(T(0), T(0), T(0)), Vec3<T>(T(1), T(1), T(1)), Vec3<T>(T(2), T(2), T(2))},
                 {{0, 1, 2}, {2, 1, 0}});
  CHECK(r.code == ErrorCode::DegenerateFace);
  CHECK(contains(r.message, "zero area"));
  CHECK(contains(r.message, "face 0"));
}

TEMPLATE_TEST_CASE("half-edge invariants on valid shapes", "[polyhedron]", float, double) {
  using T = TestType;
  check_half_edge_invariants(shapes::box<T>(1, 2, 3));
  check_half_edge_invariants(shapes::tetrahedron<T>(1));
  for (int n : {3, 4, 7, 32}) {
    check_half_edge_invariants(shapes::prism<T>(n, 1.5, 0.5));
    check_half_edge_invariants(shapes::regular_polygon<T>(n, 2.0));
  }
  check_half_edge_invariants(
      shapes::triangle<T>(Vec3<T>(T(0), T(0), T(0)), Vec3<T>(T(1), T(0), T(0)), Vec3<T>(T(0), T(1), T(1))));
  std::mt19937 rng(12);
  std::normal_distribution<double> nd;
  for (int rep = 0; rep < 10; ++rep) {
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < 30; ++i) pts.push_back(vec_cast<T>(Vec3<double>(nd(rng), nd(rng), nd(rng))));
    check_half_edge_invariants(convex_hull(pts));
  }
}
