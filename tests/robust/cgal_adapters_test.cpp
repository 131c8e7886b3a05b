// CGAL adapters (ConvexPolyhedron <-> Surface_mesh / Polyhedron_3, exact
// number conversion) and the exact CGAL hull with maximal faces.
#include <catch2/catch.hpp>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <sepax/robust/cgal_adapters.hpp>
#include <sepax/robust/cgal_hull.hpp>
#include <sepax/robust/number_types.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/shapes.hpp>

#if __has_include(<sepax/convex_hull.hpp>)
#include <sepax/convex_hull.hpp>
#define SEPAX_HAVE_OWN_HULL 1
#endif

#include <random>
#include <set>

using namespace sepax;
using Epeck = CGAL::Epeck;
using Epick = CGAL::Epick;
using KGmpq = CGAL::Simple_cartesian<CGAL::Gmpq>;

namespace {

template <class T>
bool same_polyhedron(const ConvexPolyhedron<T>& x, const ConvexPolyhedron<T>& y) {
  if (x.vertices() != y.vertices() || x.face_count() != y.face_count()) return false;
  for (int f = 0; f < x.face_count(); ++f)
    if (x.face_vertices(f) != y.face_vertices(f)) return false;
  return true;
}

// Combinatorics independent of vertex/face numbering: the set of faces, each
// as the set of its vertex positions (as exact rationals).
template <class T>
std::set<std::set<std::array<mpq_class, 3>>> face_sets(const ConvexPolyhedron<T>& p) {
  std::set<std::set<std::array<mpq_class, 3>>> out;
  for (int f = 0; f < p.face_count(); ++f) {
    std::set<std::array<mpq_class, 3>> s;
    for (int v : p.face_vertices(f)) {
      const auto& q = p.vertex(v);
      s.insert({cgal::to_mpq(q[0]), cgal::to_mpq(q[1]), cgal::to_mpq(q[2])});
    }
    out.insert(s);
  }
  return out;
}

// Every point inside or on the hull, exactly; every face's vertices exactly on
// its plane (exact T: plane normals are exact cross products).
template <class T>
void check_hull_contains(const ConvexPolyhedron<T>& h, const std::vector<Vec3<T>>& pts) {
  for (int f = 0; f < h.face_count(); ++f) {
    const auto& pl = h.plane(f);
    for (int v : h.face_vertices(f)) CHECK(dot(pl.normal, h.vertex(v)) == pl.offset);
    for (const auto& p : pts) CHECK(dot(pl.normal, p) <= pl.offset);
  }
}

template <class T>
std::vector<Vec3<T>> random_rational_points(std::mt19937& rng, int n, int range, int den) {
  std::uniform_int_distribution<int> d(-range, range);
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back(Vec3<T>(T(T(d(rng)) / T(den)), T(T(d(rng)) / T(den)), T(T(d(rng)) / T(den))));
  return pts;
}

}  // namespace

TEST_CASE("cgal adapters: exact number conversion never rounds", "[cgal]") {
  const mpq_class third(1, 3);
  CHECK(cgal::convert_number<CGAL::Gmpq>(third) == CGAL::Gmpq(1, 3));
  CHECK(cgal::convert_number<Epeck::FT>(third) == Epeck::FT(1) / Epeck::FT(3));
  CHECK(cgal::to_mpq(cgal::convert_number<Epeck::FT>(CGAL::Gmpq(2, 7))) == mpq_class(2, 7));
  CHECK(cgal::convert_number<mpq_class>(0.1) == mpq_class(0.1));  // the double, exactly
  CHECK(cgal::convert_number<mpq_class>(0.1) != mpq_class(1, 10));
  // a value that double cannot hold survives an exact -> exact -> exact trip
  const mpq_class tiny = mpq_class(1, 3) + mpq_class(1) / mpq_class(mpz_class(1) << 200);
  CHECK(cgal::to_mpq(cgal::convert_number<CGAL::Gmpq>(cgal::convert_number<Epeck::FT>(tiny))) == tiny);
}

TEMPLATE_TEST_CASE("cgal adapters: round trips keep vertices, faces and loops", "[cgal]", mpq_class,
                   CGAL::Gmpq, Epeck::FT) {
  using T = TestType;
  const std::vector<ConvexPolyhedron<T>> shapes_{
      shapes::cube<T>(1.0), shapes::prism<T>(7, 1.0, 0.5), shapes::tetrahedron<T>(0.3),
      shapes::regular_polygon<T>(6, 2.0)};  // the last one is flat (double-sided)
  for (const auto& p : shapes_) {
    const auto sm = cgal::to_cgal_mesh<CGAL::Surface_mesh<Epeck::Point_3>>(p);
    CHECK(sm.number_of_faces() == static_cast<std::size_t>(p.face_count()));
    CHECK(sm.number_of_vertices() == static_cast<std::size_t>(p.vertex_count()));
    CHECK(CGAL::is_closed(sm));
    CHECK(same_polyhedron(cgal::from_cgal_mesh<T>(sm), p));

    const auto ph = cgal::to_cgal_mesh<CGAL::Polyhedron_3<KGmpq>>(p);
    CHECK(ph.size_of_facets() == static_cast<std::size_t>(p.face_count()));
    CHECK(same_polyhedron(cgal::from_cgal_mesh<T>(ph), p));

    const auto pe = cgal::to_cgal_mesh<CGAL::Polyhedron_3<Epeck>>(p);
    CHECK(same_polyhedron(cgal::from_cgal_mesh<T>(pe), p));
  }
}

TEST_CASE("cgal adapters: double <-> Epick and double -> Epeck -> mpq are exact", "[cgal]") {
  const auto p = shapes::prism<double>(5, 1.3, 0.7);
  const auto sm = cgal::to_cgal_mesh<CGAL::Surface_mesh<Epick::Point_3>>(p);
  CHECK(same_polyhedron(cgal::from_cgal_mesh<double>(sm), p));
  const auto se = cgal::to_cgal_mesh<CGAL::Surface_mesh<Epeck::Point_3>>(p);
  const auto q = cgal::from_cgal_mesh<mpq_class>(se);
  CHECK(same_polyhedron(q, ConvexPolyhedron<mpq_class>::convert_from(p)));
  // the SAT sees the same shapes
  const auto b = shapes::cube<mpq_class>(0.5);
  const auto r1 = sat::gauss_map(q, b), r2 = sat::gauss_map(ConvexPolyhedron<mpq_class>::convert_from(p), b);
  CHECK(r1.feature == r2.feature);
  CHECK(compare(r1.separation, r2.separation) == 0);
}

TEST_CASE("cgal adapters: a triangulated mesh is rejected by validation, naming the problem", "[cgal]") {
  CGAL::Surface_mesh<Epeck::Point_3> sm;
  const std::vector<Epeck::Point_3> cube{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  CGAL::convex_hull_3(cube.begin(), cube.end(), sm);
  CHECK(sm.number_of_faces() == 12);
  try {
    (void)cgal::from_cgal_mesh<mpq_class>(sm);
    FAIL("triangulated cube accepted");
  } catch (const InvalidInput& e) {
    CHECK(e.code() == ErrorCode::NotConvex);
    CHECK(std::string(e.what()).find("coplanar") != std::string::npos);
  }
}

TEMPLATE_TEST_CASE("cgal hull: cube lattice gives the cube with 6 quads", "[cgal][hull]", mpq_class,
                   Epeck::FT) {
  using T = TestType;
  std::vector<Vec3<T>> pts;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 3; ++z) pts.push_back(Vec3<T>(T(x), T(y), T(z)));
  const auto h = cgal::exact_hull(pts);
  CHECK(h.vertex_count() == 8);
  CHECK(h.face_count() == 6);
  CHECK(h.edge_count() == 12);
  for (int f = 0; f < h.face_count(); ++f) CHECK(h.face(f).count == 4);
  check_hull_contains(h, pts);
}

TEST_CASE("cgal hull: points in the middle of edges and faces are removed", "[cgal][hull]") {
  using T = mpq_class;
  // a tetrahedron with extra points on its edges and faces and duplicates
  std::vector<Vec3<T>> pts{{T(0), T(0), T(0)},       {T(4), T(0), T(0)}, {T(0), T(4), T(0)},
                           {T(0), T(0), T(4)},       {T(2), T(0), T(0)}, {T(2), T(2), T(0)},
                           {T(1), T(1), T(0)},       {T(1), T(1), T(2)}, {T(4), T(0), T(0)},
                           {T(0), T(1, 3), T(11, 3)}};
  const auto h = cgal::exact_hull(pts);
  CHECK(h.vertex_count() == 4);
  CHECK(h.face_count() == 4);
  check_hull_contains(h, pts);
}

TEMPLATE_TEST_CASE("cgal hull: random rational points", "[cgal][hull]", mpq_class, Epeck::FT) {
  using T = TestType;
  std::mt19937 rng(17);
  for (int it = 0; it < 12; ++it) {
    // few distinct coordinates: many coplanar and collinear subsets
    const auto pts = random_rational_points<T>(rng, 20 + 10 * it, it % 2 ? 3 : 30, it % 2 ? 1 : 7);
    const auto h = cgal::exact_hull(pts);
    INFO("set " << it);
    CHECK(h.vertex_count() - h.edge_count() + h.face_count() == 2);
    check_hull_contains(h, pts);
    // every hull vertex is an input point
    for (const auto& v : h.vertices()) CHECK(std::find(pts.begin(), pts.end(), v) != pts.end());
#ifdef SEPAX_HAVE_OWN_HULL
    const auto own = convex_hull(pts);
    CHECK(own.vertex_count() == h.vertex_count());
    CHECK(own.face_count() == h.face_count());
    CHECK(face_sets(own) == face_sets(h));
#endif
  }
}

TEST_CASE("cgal hull: double input, exact decisions, coordinates kept", "[cgal][hull]") {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> d(-1, 1);
  std::vector<Vec3<double>> pts;
  for (int i = 0; i < 200; ++i) pts.push_back(Vec3<double>(d(rng), d(rng), d(rng)));
  const auto h = cgal::exact_hull(pts);
  for (const auto& v : h.vertices()) CHECK(std::find(pts.begin(), pts.end(), v) != pts.end());
  // the exact image has the same combinatorics, and contains every point exactly
  std::vector<Vec3<mpq_class>> q;
  for (const auto& p : pts) q.push_back(vec_cast<mpq_class>(p));
  const auto hq = cgal::exact_hull(q);
  CHECK(face_sets(hq) == face_sets(h));
  check_hull_contains(hq, q);
}

TEMPLATE_TEST_CASE("cgal hull: coplanar input gives a flat polygon", "[cgal][hull]", mpq_class, Epeck::FT) {
  using T = TestType;
  // points on the plane x + 2y + 3z = 6 (a 6x? lattice), interior and boundary ones
  std::vector<Vec3<T>> pts;
  for (int a = 0; a <= 6; a += 2)
    for (int b = 0; b <= 3; ++b) {
      const T x(a), y(b);
      pts.push_back(Vec3<T>(x, y, T(T(T(6) - x - T(2) * y) / T(3))));
    }
  const auto h = cgal::exact_hull(pts);
  CHECK(h.is_flat());
  CHECK(h.face_count() == 2);
  CHECK(h.vertex_count() == 4);  // the corners of the (a, b) rectangle
  for (const auto& p : pts) {
    // inside or on: on the plane, and on the inner side of every edge
    CHECK(dot(h.plane(0).normal, p) == h.plane(0).offset);
  }
  CHECK_THROWS_AS(cgal::exact_hull(std::vector<Vec3<T>>{Vec3<T>(T(0), T(0), T(0)), Vec3<T>(T(1), T(1), T(1)),
                                                        Vec3<T>(T(2), T(2), T(2))}),
                  InvalidInput);
  try {
    (void)cgal::exact_hull(std::vector<Vec3<T>>{Vec3<T>(T(0), T(0), T(0)), Vec3<T>(T(0), T(0), T(0)),
                                                Vec3<T>(T(1), T(0), T(0))});
    FAIL("two distinct points accepted");
  } catch (const InvalidInput& e) {
    CHECK(e.code() == ErrorCode::TooFewPoints);
  }
}
