// ConvexPolyhedron validation (every rule: the ErrorCode and a message that
// names the offending element) and the half-edge invariants of valid shapes.
#include <catch2/catch.hpp>

#include <sepax/convex_hull.hpp>
#include <sepax/convex_polyhedron.hpp>
#include <sepax/posing.hpp>
#include <sepax/shapes.hpp>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <type_traits>
#include <string>
#include <vector>

using namespace sepax;

// Shapes move (not copy) when a container of them grows: the cached
// normal_conditioning() must not make the moves throwing.
static_assert(std::is_nothrow_move_constructible_v<ConvexPolyhedron<float>>);
static_assert(std::is_nothrow_move_assignable_v<ConvexPolyhedron<double>>);

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

TEMPLATE_TEST_CASE("validation: non-finite coordinates and too few points", "[polyhedron][errors]", float,
                   double) {
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

TEMPLATE_TEST_CASE("validation: topology errors name the face, edge or vertex", "[polyhedron][errors]", float,
                   double) {
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
  r = failure<T>(two,
                 {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}, {4, 5, 6}, {4, 7, 5}, {4, 6, 7}, {5, 7, 6}});
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
  CHECK_FALSE(contains(r.message, "0.010000 off"));  // (the height as "%.9g", not std::to_string's "%f")
  CHECK(contains(r.message, "(tolerance "));
  // two corners of a face at one point: vertex 6 of the cube given twice (6 and 8), joined by an edge of
  // length 0 between the top face and the face y = +1
  v = cube_vertices<T>();
  v.push_back(v[6]);
  r = failure<T>(v,
                 {{0, 3, 2, 1}, {4, 5, 6, 8, 7}, {0, 1, 5, 4}, {2, 3, 7, 8, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}});
  CHECK(r.code == ErrorCode::DegenerateFace);
  CHECK(contains(r.message, "two consecutive corners at one point (vertices 6 and 8)"));
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

// The topology (half-edges, loops, fans) is shared by copies, rigid images
// and conversions, never copied; a new shape builds its own, and a moved-from
// shape is empty and still usable.
TEMPLATE_TEST_CASE("copies, images and conversions share the topology", "[polyhedron]", float, double) {
  using T = TestType;
  const auto a = shapes::prism<T>(7, 1.5, 0.5);
  const auto b = shapes::prism<T>(7, 1.5, 0.5);
  auto same = [](const auto& p, const auto& q) {
    return p.half_edges().data() == q.half_edges().data() && p.faces().data() == q.faces().data() &&
           p.fan().data() == q.fan().data() && p.fan_start().data() == q.fan_start().data();
  };
  CHECK_FALSE(same(a, b));  // built separately: two topologies with equal contents
  CHECK(a.half_edges().size() == b.half_edges().size());
  const ConvexPolyhedron<T> copy = a;
  CHECK(same(copy, a));
  std::vector<Vec3<T>> moved = a.vertices();
  for (auto& v : moved) v = Vec3<T>(v[0] + T(3), v[1], v[2]);
  const auto image = a.with_vertices(moved);
  CHECK(same(image, a));
  const auto exact = ConvexPolyhedron<double>::convert_from(a);
  CHECK(same(exact, a));
  RigidTransform<T> x;
  x.translation = Vec3<T>(T(1), T(2), T(3));
  ConvexPolyhedron<T> scratch = b;  // holds another topology first
  detail::pose_into(scratch, a, x);
  CHECK(same(scratch, a));
  check_half_edge_invariants(scratch);
  ConvexPolyhedron<T> from = a;
  ConvexPolyhedron<T> to = std::move(from);
  CHECK(same(to, a));
  CHECK(from.face_count() == 0);  // NOLINT(bugprone-use-after-move): a moved-from shape is empty
  CHECK(from.half_edge_count() == 0);
  check_half_edge_invariants(to);
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

// ---- scale: planes at any scale in range, clear errors out of range ----------

namespace {

// p's vertices times s, rebuilt (and validated) from p's face lists.
template <class T>
ConvexPolyhedron<T> scaled(const ConvexPolyhedron<T>& p, double s) {
  std::vector<Vec3<T>> v;
  for (const auto& q : p.vertices())
    v.emplace_back(static_cast<T>(q[0] * s), static_cast<T>(q[1] * s), static_cast<T>(q[2] * s));
  Faces f;
  for (int i = 0; i < p.face_count(); ++i) f.push_back(p.face_vertices(i));
  return ConvexPolyhedron<T>::from_faces(std::move(v), f);
}

template <class T>
std::vector<ConvexPolyhedron<T>> unit_shapes() {
  std::vector<ConvexPolyhedron<T>> out{shapes::box<T>(1, 2, 0.5), shapes::tetrahedron<T>(1),
                                       shapes::prism<T>(32, 1.5, 0.5), shapes::regular_polygon<T>(7, 2.0)};
  out.push_back(shapes::triangle<T>(Vec3<T>(T(0.1f), T(0.2f), T(0.3f)), Vec3<T>(T(1.7f), T(-0.4f), T(0.9f)),
                                    Vec3<T>(T(-0.3f), T(1.1f), T(2.5f))));
  std::mt19937 rng(7);
  std::normal_distribution<double> nd;
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 40; ++i) pts.push_back(vec_cast<T>(Vec3<double>(nd(rng), nd(rng), nd(rng))));
  out.push_back(convex_hull(pts));
  return out;
}

template <class T>
std::vector<double> in_range_scales() {
  if constexpr (std::is_same_v<T, double>)
    return {1e-150, 1e150, 1e300, 1e-80, 1e80, 0x1p-960, 0x1p1000};
  else
    return {1e-30, 1e30, 1e36, 1e-12, 1e12, 0x1p-100, 0x1p120};
}

}  // namespace

TEMPLATE_TEST_CASE("scale: valid shapes build at any scale in range, with the same plane triples",
                   "[polyhedron][scale]", float, double) {
  using T = TestType;
  const double tol = std::is_same_v<T, float> ? 1e-4 : 1e-12;  // rounding of scaled vertices
  for (const auto& unit : unit_shapes<T>()) {
    for (const double s : in_range_scales<T>()) {
      INFO("scale " << s << ", " << unit.vertex_count() << " vertices");
      ConvexPolyhedron<T> p;
      REQUIRE_NOTHROW(p = scaled(unit, s));
      // A power of two scales every rounding exactly: the same plane triples
      // and normals, bit for bit.  (Other scales round the vertices: triangles
      // of equal area may then tie-break differently.)
      int exponent = 0;
      const bool pow2 = std::frexp(s, &exponent) == 0.5;
      for (int f = 0; f < p.face_count(); ++f) {
        const Vec3<T>& n = p.plane(f).normal;
        const Vec3<T>& n1 = unit.plane(f).normal;
        if (pow2) {
          CHECK(p.face(f).plane_vertices == unit.face(f).plane_vertices);
          CHECK(n == n1);
          CHECK(p.plane(f).offset == static_cast<T>(unit.plane(f).offset * s));
        } else {
          CHECK((vec_to_double(n) - vec_to_double(n1)).norm() < tol);
          CHECK(std::abs(to_double(p.plane(f).offset) / s - to_double(unit.plane(f).offset)) < 1e-5);
        }
        CHECK(std::abs(to_double(squared_norm(n)) - 1.0) < tol);
      }
      if (p.is_flat()) CHECK(p.plane(1).normal == Vec3<T>(-p.plane(0).normal));
      CHECK(std::abs(p.extent() / s / unit.extent() - 1.0) < 1e-6);
      CHECK(std::abs(to_double(p.centroid()[0]) / s - to_double(unit.centroid()[0])) < 1e-5);
    }
  }
}

TEMPLATE_TEST_CASE("scale: every stored plane is plane_through of its plane triple, bit for bit",
                   "[polyhedron][scale]", float, double) {
  // compute_planes derives a few faces at a time in SIMD lanes, face by face
  // where a lane's cross product leaves the safe range (tiny and huge
  // scales), and the remainder one at a time: each plane must be the scalar
  // plane_through's, and the eagerly scanned normal conditioning (posed) the
  // lazily computed one's.
  using T = TestType;
  auto scales = in_range_scales<T>();
  scales.push_back(1.0);
  for (const auto& unit : unit_shapes<T>()) {
    for (const double s : scales) {
      INFO("scale " << s << ", " << unit.face_count() << " faces");
      const ConvexPolyhedron<T> p = scaled(unit, s);
      const int nf = p.is_flat() ? 1 : p.face_count();
      for (int f = 0; f < nf; ++f) {
        const auto& t = p.face(f).plane_vertices;
        const Plane<T> q = plane_through(p.vertex(t[0]), p.vertex(t[1]), p.vertex(t[2]));
        CHECK(std::memcmp(&q.normal, &p.plane(f).normal, sizeof(q.normal)) == 0);
        CHECK(std::memcmp(&q.offset, &p.plane(f).offset, sizeof(q.offset)) == 0);
      }
      const ConvexPolyhedron<T> moved = posed(p, RigidTransform<T>::identity());
      CHECK(moved.normal_conditioning() == p.normal_conditioning());
    }
  }
}

TEMPLATE_TEST_CASE("scale: tolerances stay relative to the extent at every scale", "[polyhedron][scale]",
                   float, double) {
  using T = TestType;
  auto scales = in_range_scales<T>();
  scales.push_back(1.0);
  for (const double s : scales) {
    INFO("scale " << s);
    // vertex 6 of the cube (half size s) moved up by r*s: within planarity*extent
    // it is accepted, beyond it faces 1, 3 and 5 are not planar.
    for (const double r : {Tolerances<T>::kPlanarity / 8, 1e-3}) {
      auto v = cube_vertices<T>();
      for (auto& q : v)
        q = Vec3<T>(static_cast<T>(q[0] * s), static_cast<T>(q[1] * s), static_cast<T>(q[2] * s));
      v[6][2] = static_cast<T>(s * (1 + r));
      const auto f = failure<T>(v, cube_faces);
      if (r < 1e-3) {
        CHECK(f.message == "no error");
      } else {
        CHECK(f.code == ErrorCode::NonPlanarFace);
      }
    }
  }
}

TEMPLATE_TEST_CASE(
    "scale: the power-of-two helpers are std::ldexp and std::ilogb bit for bit at every exponent",
    "[polyhedron][scale]", float, double) {
  // (the corner tests of validation and the plane triples scale by them)
  using T = TestType;
  using L = std::numeric_limits<T>;
  auto bits = [](T x) { return std::bit_cast<typename detail::FloatBits<T>::Uint>(x); };
  // normal_pow2: every normal power of two
  for (int e = L::min_exponent - 1; e <= L::max_exponent - 1; ++e) {
    INFO("2^" << e);
    CHECK(bits(detail::normal_pow2<T>(e)) == bits(std::ldexp(T(1), e)));
  }
  // pow2_exponent: powers of two and values between them, normal and subnormal
  for (int e = L::min_exponent - L::digits; e <= L::max_exponent - 1; ++e) {
    for (const T x :
         {std::ldexp(T(1), e), std::ldexp(T(1.75), e), std::nextafter(std::ldexp(T(1), e), T(0))}) {
      INFO(x);
      if (x > T(0) && x <= L::max()) CHECK(detail::pow2_exponent(x) == std::ilogb(x));
    }
  }
  CHECK(detail::pow2_exponent(L::max()) == std::ilogb(L::max()));
  CHECK(detail::pow2_exponent(L::denorm_min()) == std::ilogb(L::denorm_min()));
  // scale_value_pow2 and scale_pow2: x 2^-e for every e that moves a value of T across its whole range
  // (results exact, subnormal, zero or infinite), against std::ldexp
  const T values[] = {T(1),
                      T(-1.5),
                      T(0.1),
                      T(0),
                      T(-0.0),
                      std::nextafter(T(1), T(2)),
                      L::min(),
                      L::denorm_min(),
                      T(3) * L::denorm_min(),
                      L::max(),
                      -std::ldexp(T(1.9), L::max_exponent - 2),
                      std::ldexp(T(1.3), L::min_exponent - 3)};
  const int span = L::max_exponent - L::min_exponent + L::digits + 4;
  for (int e = -span; e <= span; ++e) {
    for (const T x : values) {
      INFO(x << " 2^-" << e);
      CHECK(bits(detail::scale_value_pow2(x, e)) == bits(std::ldexp(x, -e)));
    }
    const Vec3<T> v(values[1], values[2], values[8]);
    const Vec3<T> w = detail::scale_pow2(v, e);
    for (int c = 0; c < 3; ++c) {
      INFO("component " << c << " 2^-" << e);
      CHECK(bits(w[c]) == bits(std::ldexp(v[c], -e)));
    }
  }
}

TEST_CASE("scale: mixed magnitudes in one shape (double)", "[polyhedron][scale]") {
  using T = double;
  // a tetrahedron whose coordinates range over 1e140 .. 1e160, and its mirror
  // image at 1e-160 .. 1e-140
  for (const double s : {1.0, 1e-300}) {
    const std::vector<Vec3<T>> v{Vec3<T>(1e150 * s, 1e140 * s, 0), Vec3<T>(3e160 * s, 0, 0),
                                 Vec3<T>(0, 2e155 * s, 0), Vec3<T>(0, 0, 5e158 * s)};
    const Faces f{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    if (s == 1.0) {
      ConvexPolyhedron<T> t;
      REQUIRE_NOTHROW(t = ConvexPolyhedron<T>::from_faces(v, f));
      for (int i = 0; i < 4; ++i) CHECK(std::abs(squared_norm(t.plane(i).normal) - 1.0) < 1e-15);
    } else {
      // 1e-160 .. 1e-140: extent 3e-140 is in range
      ConvexPolyhedron<T> t;
      REQUIRE_NOTHROW(t = ConvexPolyhedron<T>::from_faces(v, f));
      CHECK(t.plane(0).normal == Vec3<T>(0, 0, -1));
    }
  }
}

TEMPLATE_TEST_CASE("scale: out-of-range input gets BadScale naming the problem",
                   "[polyhedron][scale][errors]", float, double) {
  using T = TestType;
  const double big = static_cast<double>(std::numeric_limits<T>::max()) / 4;
  // coordinates near max: edges and plane offsets would overflow
  auto v = cube_vertices<T>();
  for (auto& q : v)
    q = Vec3<T>(static_cast<T>(q[0] * big), static_cast<T>(q[1] * big), static_cast<T>(q[2] * big));
  auto f = failure<T>(v, cube_faces);
  CHECK(f.code == ErrorCode::BadScale);
  CHECK(contains(f.message, "out of range"));
  CHECK(!contains(f.message, "zero area"));
  // so small that the relative tolerances are subnormal
  const double tiny = static_cast<double>(std::numeric_limits<T>::min()) * 16;
  v = cube_vertices<T>();
  for (auto& q : v)
    q = Vec3<T>(static_cast<T>(q[0] * tiny), static_cast<T>(q[1] * tiny), static_cast<T>(q[2] * tiny));
  f = failure<T>(v, cube_faces);
  CHECK(f.code == ErrorCode::BadScale);
  CHECK(contains(f.message, "too small"));
  CHECK(!contains(f.message, "zero area"));
}

TEMPLATE_TEST_CASE("scale: with_vertices and convert_from check the new coordinates",
                   "[polyhedron][scale][errors]", float, double) {
  using T = TestType;
  const auto cube = ConvexPolyhedron<T>::from_faces(cube_vertices<T>(), cube_faces);
  auto code_of = [](auto&& make) {
    try {
      (void)make();
    } catch (const InvalidInput& e) {
      return std::make_pair(e.code(), std::string(e.what()));
    }
    return std::make_pair(ErrorCode::Parse, std::string("no error"));
  };
  // a rigid image moved beyond the range: BadScale, not infinite planes
  const T far = static_cast<T>(static_cast<double>(std::numeric_limits<T>::max()) / 4);
  auto moved = cube.vertices();
  for (auto& q : moved) q[0] += far;
  auto e = code_of([&] { return cube.with_vertices(moved); });
  CHECK(e.first == ErrorCode::BadScale);
  CHECK(contains(e.second, "out of range"));
  moved = cube.vertices();
  moved[3][1] = std::numeric_limits<T>::quiet_NaN();
  e = code_of([&] { return cube.with_vertices(moved); });
  CHECK(e.first == ErrorCode::NonFinite);
  CHECK(contains(e.second, "vertex 3"));
  moved.pop_back();
  e = code_of([&] { return cube.with_vertices(moved); });
  CHECK(e.first == ErrorCode::BadIndex);
  // a valid image converts without a change
  CHECK(ConvexPolyhedron<float>::convert_from(cube).vertex_count() == 8);
  // a double shape beyond float's range names the coordinate
  if constexpr (std::is_same_v<T, double>) {
    auto big = cube.vertices();
    for (auto& q : big) q *= 1e300;
    const auto huge = ConvexPolyhedron<double>::from_faces(big, cube_faces);
    e = code_of([&] { return ConvexPolyhedron<float>::convert_from(huge); });
    CHECK(e.first == ErrorCode::BadScale);
    CHECK(contains(e.second, "beyond the range of float"));
    // one below float's range says the conversion made the vertices one point
    auto small = cube.vertices();
    for (auto& q : small) q *= 1e-200;
    const auto tiny = ConvexPolyhedron<double>::from_faces(small, cube_faces);
    e = code_of([&] { return ConvexPolyhedron<float>::convert_from(tiny); });
    CHECK(e.first == ErrorCode::BadScale);
    CHECK(contains(e.second,
                   "converted to float, every vertex of the shape (extent 3.46e-200 in double) "
                   "rounds to the same point"));
  }
}

// ---- sliver faces: zero area up to rounding -----------------------------------

TEMPLATE_TEST_CASE("validation: a face that is zero-area only up to rounding is refused",
                   "[polyhedron][errors]", float, double) {
  using T = TestType;
  // Three points on the line t*(1/3, 1/7, 1/11), rounded to T: collinear but
  // for rounding, so (b - a) x (c - a) is not zero -- the old check (normal
  // != 0) accepted this triangle with a normal made of rounding noise.
  const Vec3<T> a(T(0), T(0), T(0));
  const Vec3<T> b(T(1) / T(3), T(1) / T(7), T(1) / T(11));
  const Vec3<T> c(T(5) / T(3), T(5) / T(7), T(5) / T(11));
  REQUIRE(!is_zero(cross(Vec3<T>(b - a), Vec3<T>(c - a))));
  auto r = failure<T>({a, b, c}, {{0, 1, 2}, {0, 2, 1}});
  CHECK(r.code == ErrorCode::DegenerateFace);
  CHECK(contains(r.message, "face 0"));
  CHECK(contains(r.message, "zero area up to rounding"));
  // the same at scale 1e20 (relative to the face, not absolute)
  const T k(1e20f);
  r = failure<T>({Vec3<T>(a * k), Vec3<T>(b * k), Vec3<T>(c * k)}, {{0, 1, 2}, {0, 2, 1}});
  CHECK(r.code == ErrorCode::DegenerateFace);

  // a sliver triangle, height sliver/4 over its longest side, vs a thin but
  // valid one (4 * sliver), flat and as the base of a tetrahedron
  const double sl = Tolerances<T>::kSliver;
  for (const double h : {sl / 4, sl * 4}) {
    INFO("height " << h);
    const std::vector<Vec3<T>> tri{Vec3<T>(T(0), T(0), T(0)), Vec3<T>(T(1), T(0), T(0)),
                                   Vec3<T>(T(0.5), static_cast<T>(h), T(0))};
    const auto flat = failure<T>(tri, {{0, 1, 2}, {0, 2, 1}});
    auto tet_v = tri;
    tet_v.emplace_back(T(0.5), T(0.3), T(1));
    const auto solid = failure<T>(tet_v, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}});
    if (h < sl) {
      CHECK(flat.code == ErrorCode::DegenerateFace);
      CHECK(contains(flat.message, "face 0"));
      CHECK(solid.code == ErrorCode::DegenerateFace);
      CHECK(contains(solid.message, "face 0"));
      CHECK(contains(solid.message, "sliver"));
    } else {
      CHECK(flat.message == "no error");
      CHECK(solid.message == "no error");
    }
  }
}
