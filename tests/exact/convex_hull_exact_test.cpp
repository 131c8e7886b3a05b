// convex_hull with exact number types (mpq_class, CGAL::Epeck::FT): the exact
// hull.  Faces exactly planar and maximal, no vertex in the middle of an
// edge (both enforced by validation, which is exact for these types), every
// input point exactly inside or on the hull, and the extreme points exactly
// the hull's vertices.  Sets are kept small: exact arithmetic is slow.
#include <catch2/catch.hpp>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <sepax/robust/number_types.hpp>

#include <sepax/convex_hull.hpp>

#include "../../tools/hull_compare_signature.hpp"
#include "../../tools/reference/convex_hull_reference.hpp"
#include "../core/hull_point_sets.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using namespace sepax;

namespace {

template <class T>
Vec3<T> pt(long x, long y, long z, long d = 1) {
  return Vec3<T>(T(static_cast<int>(x)) / T(static_cast<int>(d)),
                 T(static_cast<int>(y)) / T(static_cast<int>(d)),
                 T(static_cast<int>(z)) / T(static_cast<int>(d)));
}

// Every input point exactly inside or on every face plane; every face's
// vertices exactly on its plane.
template <class T>
void check_exact_hull(const ConvexPolyhedron<T>& h, const std::vector<Vec3<T>>& pts) {
  for (int f = 0; f < h.face_count(); ++f) {
    const auto& pl = h.plane(f);
    for (const auto& p : pts) CHECK(dot(pl.normal, p) - pl.offset <= T(0));
    for (int v : h.face_vertices(f)) CHECK(dot(pl.normal, h.vertex(v)) - pl.offset == T(0));
  }
  // every hull vertex is an input point
  for (const auto& v : h.vertices()) {
    bool found = false;
    for (const auto& p : pts) found = found || p == v;
    CHECK(found);
  }
  // re-validation from the face lists (exact: planar, strictly convex, maximal)
  std::vector<std::vector<int>> faces;
  for (int f = 0; f < h.face_count(); ++f) faces.push_back(h.face_vertices(f));
  CHECK_NOTHROW(ConvexPolyhedron<T>::from_faces(h.vertices(), faces));
}

}  // namespace

TEMPLATE_TEST_CASE("exact hull: cube corners with interior and boundary points", "[hull][exact]", mpq_class,
                   CGAL::Epeck::FT) {
  using T = TestType;
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 8; ++i) pts.push_back(pt<T>(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
  // interior points, face centres, edge midpoints, points exactly on faces
  pts.push_back(pt<T>(0, 0, 0));
  pts.push_back(pt<T>(1, 0, 0));
  pts.push_back(pt<T>(0, -1, 0));
  pts.push_back(pt<T>(1, 1, 0));
  pts.push_back(pt<T>(-1, 0, -1));
  pts.push_back(pt<T>(1, 1, 3, 7));
  pts.push_back(pt<T>(7, 3, 7, 7));
  const auto h = convex_hull(pts);
  CHECK(h.vertex_count() == 8);
  CHECK(h.face_count() == 6);
  for (int f = 0; f < 6; ++f) CHECK(h.face(f).count == 4);
  check_exact_hull(h, pts);
}

TEMPLATE_TEST_CASE("exact hull: lattice and random integer grid points", "[hull][exact]", mpq_class,
                   CGAL::Epeck::FT) {
  using T = TestType;
  std::vector<Vec3<T>> lattice;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) lattice.push_back(pt<T>(i, j, k));
  const auto h = convex_hull(lattice);
  CHECK(h.vertex_count() == 8);
  CHECK(h.face_count() == 6);
  check_exact_hull(h, lattice);
  // random small-grid points: many exact coplanarities and collinearities
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> g(-2, 2);
  for (int rep = 0; rep < 6; ++rep) {
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < 25; ++i) pts.push_back(pt<T>(g(rng), g(rng), g(rng)));
    try {
      const auto hg = convex_hull(pts);
      check_exact_hull(hg, pts);
    } catch (const InvalidInput& e) {
      // only an exactly flat/collinear draw may be rejected
      CHECK((e.code() == ErrorCode::Collinear || e.code() == ErrorCode::TooFewPoints));
    }
  }
}

TEMPLATE_TEST_CASE("exact hull of random rational points agrees with the double hull", "[hull][exact]",
                   mpq_class, CGAL::Epeck::FT) {
  using T = TestType;
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int rep = 0; rep < 4; ++rep) {
    std::vector<Vec3<double>> d;
    for (int i = 0; i < 24; ++i) d.emplace_back(u(rng), u(rng), u(rng));
    std::vector<Vec3<T>> pts;
    for (const auto& p : d) pts.push_back(vec_cast<T>(p));  // exact conversion
    const auto h = convex_hull(pts);
    check_exact_hull(h, pts);
    // generic points: the double hull makes the same decisions
    const auto hd = convex_hull(d);
    CHECK(h.vertex_count() == hd.vertex_count());
    CHECK(h.face_count() == hd.face_count());
    for (const auto& v : hd.vertices()) {
      bool found = false;
      for (const auto& w : h.vertices()) found = found || vec_cast<T>(v) == w;
      CHECK(found);
    }
  }
}

TEMPLATE_TEST_CASE("exact hull of rational points exactly on a sphere keeps every point", "[hull][exact]",
                   mpq_class, CGAL::Epeck::FT) {
  using T = TestType;
  // inverse stereographic projection of rational (a, b): an exact point on
  // the unit sphere; all such points are extreme
  std::vector<Vec3<T>> pts;
  const int ab[][2] = {{0, 0},  {1, 0}, {0, 1},   {-1, 0}, {0, -1}, {1, 1},  {2, -1},
                       {-1, 3}, {3, 2}, {-2, -2}, {5, 1},  {1, -4}, {-3, 1}, {2, 5}};
  for (const auto& q : ab) {
    const T a(q[0]), b(q[1]), s = a * a + b * b;
    pts.push_back(Vec3<T>(T(2) * a / (s + T(1)), T(2) * b / (s + T(1)), (s - T(1)) / (s + T(1))));
  }
  const auto h = convex_hull(pts);
  CHECK(h.vertex_count() == static_cast<int>(pts.size()));
  check_exact_hull(h, pts);
}

TEMPLATE_TEST_CASE("exact hull: coplanar gives a polygon, collinear and duplicates fail", "[hull][exact]",
                   mpq_class, CGAL::Epeck::FT) {
  using T = TestType;
  // points exactly on x + 2y + 3z = 6 (a 4x4 grid and interior points)
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) pts.push_back(Vec3<T>(T(i), T(j), (T(6) - T(i) - T(2 * j)) / T(3)));
  const auto h = convex_hull(pts);
  REQUIRE(h.is_flat());
  CHECK(h.vertex_count() == 4);
  CHECK(is_zero(Vec3<T>(h.plane(0).normal + h.plane(1).normal)));
  check_exact_hull(h, pts);
  // a point 1/1000 off the plane makes it a solid (exact: no flat tolerance)
  pts.push_back(Vec3<T>(T(1), T(1), T(1) + T(1) / T(1000)));
  const auto s = convex_hull(pts);
  CHECK_FALSE(s.is_flat());
  check_exact_hull(s, pts);

  auto code_of = [](const std::vector<Vec3<T>>& p) {
    try {
      convex_hull(p);
    } catch (const InvalidInput& e) {
      return e.code();
    }
    return ErrorCode::Parse;
  };
  // exactly collinear, with rational steps
  std::vector<Vec3<T>> line;
  for (int i = 0; i < 6; ++i) line.push_back(Vec3<T>(T(i) / T(3), T(1) - T(i) / T(7), T(2 * i)));
  CHECK(code_of(line) == ErrorCode::Collinear);
  // one point 1e-30 off the line: not collinear for exact T
  line.push_back(Vec3<T>(T(1) / T(3), T(1) - T(1) / T(7), T(2)) + Vec3<T>(T(0), from_double<T>(1e-30), T(0)));
  const auto tri = convex_hull(line);
  CHECK(tri.is_flat());
  CHECK(code_of({pt<T>(1, 2, 3), pt<T>(1, 2, 3), pt<T>(4, 5, 6)}) == ErrorCode::TooFewPoints);
}

TEMPLATE_TEST_CASE("exact hull of the benchmark's point kinds is the reference builder's polytope",
                   "[hull][exact]", mpq_class, CGAL::Epeck::FT) {
  using T = TestType;
  // (the filtered paths: every coordinate a double; the reference scans every vertex and face in T)
  for (const char* kind : {"sphere", "ball", "slab", "cylinder"}) {
    INFO(kind);
    std::vector<Vec3<T>> pts;
    for (const auto& p : hull_sets::bench_point_set(kind, 150)) pts.push_back(vec_from_double<T>(p));
    const auto h = convex_hull(pts);
    const auto r = reference::convex_hull(pts);
    CHECK(hull_compare::signature(h) == hull_compare::signature(r));
    check_exact_hull(h, pts);
  }
}

TEMPLATE_TEST_CASE("exact hull validation refuses a doubly wound vertex and a reflex edge", "[hull][exact]",
                   mpq_class, CGAL::Epeck::FT) {
  using T = TestType;
  // A bipyramid over a pentagon whose apexes see the pentagon in pentagram order: every edge convex, the
  // centre below every face plane, but each apex wound twice (not convex).
  std::vector<Vec3<double>> d{{0, 0, 1}, {0, 0, -1}};
  for (int k = 0; k < 5; ++k)
    d.push_back({std::cos(2 * std::numbers::pi * k / 5), std::sin(2 * std::numbers::pi * k / 5), 0});
  std::vector<std::vector<int>> star;
  for (int j = 0; j < 5; ++j) {
    const int w0 = 2 + (2 * j) % 5, w1 = 2 + (2 * j + 2) % 5;
    star.push_back({0, w0, w1});
    star.push_back({1, w1, w0});
  }
  std::vector<std::vector<int>> convex;  // the same points in pentagon order: convex
  for (int k = 0; k < 5; ++k) {
    const int u0 = 2 + k, u1 = 2 + (k + 1) % 5;
    convex.push_back({0, u0, u1});
    convex.push_back({1, u1, u0});
  }
  // an octahedron whose top apex is pushed below the equator: reflex edges
  std::vector<Vec3<double>> o{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -0.5}, {0, 0, -1}};
  std::vector<std::vector<int>> dented;
  for (int k = 0; k < 4; ++k) {
    dented.push_back({4, k, (k + 1) % 4});
    dented.push_back({5, (k + 1) % 4, k});
  }
  auto exact = [](const std::vector<Vec3<double>>& v) {
    std::vector<Vec3<T>> t;
    for (const auto& p : v) t.push_back(vec_from_double<T>(p));
    return t;
  };
  using H = hull::detail::HullPolyhedron<T>;
  CHECK_NOTHROW(H::from_faces(exact(d), convex, &d));
  CHECK_THROWS_AS(H::from_faces(exact(d), star, &d), InvalidInput);
  CHECK_THROWS_AS(ConvexPolyhedron<T>::from_faces(exact(d), star), InvalidInput);
  CHECK_THROWS_AS(H::from_faces(exact(o), dented, &o), InvalidInput);
}
