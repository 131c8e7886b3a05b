#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <type_traits>
#include <vector>

#include <Eigen/Geometry>

#include <sepax/contact_manifold.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/shapes.hpp>

using namespace sepax;

namespace {

// Rotation about a unit axis (double), then translation; converted to T.
template <Number T>
ConvexPolyhedron<T> moved(const ConvexPolyhedron<T>& p, const Eigen::Matrix3d& R, const Vec3<double>& t) {
  std::vector<Vec3<T>> vs;
  for (const auto& v : p.vertices()) {
    const Vec3<double> w = R * vec_to_double(v) + t;
    vs.push_back(vec_from_double<T>(w));
  }
  return p.with_vertices(vs);
}

Eigen::Matrix3d rot(const Vec3<double>& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

template <Number T>
ConvexPolyhedron<T> scaled_box(double s, double hx, double hy, double hz) {
  return shapes::box<T>(s * hx, s * hy, s * hz);
}

/// The properties every manifold must have, whatever the configuration.
template <Number T>
void check_invariants(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b,
                      const ContactManifold<T>& m) {
  const double ext = std::max(a.extent(), b.extent());
  const double tol = (std::is_same_v<T, float> ? 2e-5 : 1e-11) * ext;
  for (const auto& c : m.points) {
    // point_a on A, point_b on B (inside the closures)
    for (int f = 0; f < a.face_count(); ++f)
      CHECK(to_double(T(dot(a.plane(f).normal, c.point_a) - a.plane(f).offset)) <= tol);
    for (int f = 0; f < b.face_count(); ++f)
      CHECK(to_double(T(dot(b.plane(f).normal, c.point_b) - b.plane(f).offset)) <= tol);
    // the separation is measured along the normal between the two points
    CHECK(to_double(T(dot(m.normal, Vec3<T>(c.point_b - c.point_a)))) ==
          Approx(to_double(c.separation.num)).margin(tol));
    // ... and is never deeper than the SAT's minimum penetration
    CHECK(to_double(c.separation) >= to_double(m.separation) - tol);
  }
}

template <Number T>
std::vector<ContactFeatureId> ids_of(const ContactManifold<T>& m) {
  std::vector<ContactFeatureId> out;
  for (const auto& c : m.points) out.push_back(c.id);
  return out;
}

}  // namespace

TEMPLATE_TEST_CASE("box resting on a box: 4 points at the right depth", "[contact]", float, double) {
  using T = TestType;
  const auto a = shapes::cube<T>(1.0);
  const auto b = moved(shapes::cube<T>(0.5), Eigen::Matrix3d::Identity(), Vec3<double>(0.1, -0.2, 1.375));
  const auto m = contact_manifold(a, b);
  REQUIRE(m.kind == ContactKind::Face);
  CHECK(m.reference_shape == 0);
  CHECK(m.reference_face == 1);  // +z face of A
  CHECK(m.incident_face == 0);   // -z face of B
  CHECK(vec_to_double(m.normal).isApprox(Vec3<double>(0, 0, 1)));
  REQUIRE(m.size() == 4);
  for (const auto& c : m.points) {
    CHECK(c.depth() == Approx(0.125));
    CHECK(to_double(c.point_b[2]) == Approx(0.875));
    CHECK(to_double(c.point_a[2]) == Approx(1.0));
    CHECK(std::abs(to_double(c.point_b[0]) - 0.1) == Approx(0.5));
    CHECK(std::abs(to_double(c.point_b[1]) + 0.2) == Approx(0.5));
    CHECK(c.id.a == ShapeFeature::face(1));
    CHECK(c.id.b.kind == ShapeFeatureKind::Vertex);
  }
  // distinct incident vertices: all four corners of B's bottom face
  std::vector<int> vs;
  for (const auto& c : m.points) vs.push_back(c.id.b.index);
  std::sort(vs.begin(), vs.end());
  CHECK(vs == std::vector<int>{0, 1, 2, 3});
  check_invariants(a, b, m);
  // Moving B by the depth along the normal brings the shapes to touching.
  const auto t = vec_to_double(m.resolving_translation());
  const auto b2 = moved(b, Eigen::Matrix3d::Identity(), t);
  CHECK(sat::gauss_map(a, b2).separation_as_double() == Approx(0.0).margin(1e-6));
}

TEMPLATE_TEST_CASE("box on a larger box rotated by 45 degrees: octagon reduced to 4", "[contact]", float,
                   double) {
  using T = TestType;
  const auto a = shapes::cube<T>(1.0);
  const auto b = moved(shapes::box<T>(0.9, 0.9, 0.5), rot({0, 0, 1}, std::numbers::pi / 4), {0, 0, 1.4});
  ManifoldOptions all;
  all.reduce = false;
  all.record_steps = true;
  const auto full = contact_manifold(a, b, sat::gauss_map(a, b), all);
  REQUIRE(full.kind == ContactKind::Face);
  REQUIRE(full.size() == 8);
  CHECK(full.clip_steps.size() == 4);
  for (const auto& c : full.points) {
    CHECK(c.depth() == Approx(0.1));
    // every octagon corner is a side edge of A's top face cutting an edge of B
    CHECK(c.id.a.kind == ShapeFeatureKind::Edge);
    CHECK(c.id.b.kind == ShapeFeatureKind::Edge);
  }
  check_invariants(a, b, full);
  const auto red = contact_manifold(a, b);
  REQUIRE(red.size() == 4);
  CHECK(red.candidate_points == 8);
  // the kept points are octagon points, and the deepest (first, all equal) is kept
  for (const auto& c : red.points) {
    bool found = false;
    for (const auto& d : full.points) found = found || (c.id == d.id);
    CHECK(found);
  }
  CHECK(red.points[0].id == full.points[0].id);
  // area of the kept quad vs the best quad of 4 octagon points
  auto quad_area = [](std::array<Vec3<double>, 4> q) {
    // sort by angle around the centroid, then shoelace in xy
    Vec3<double> c = (q[0] + q[1] + q[2] + q[3]) / 4;
    std::sort(q.begin(), q.end(), [&](auto& x, auto& y) {
      return std::atan2(x[1] - c[1], x[0] - c[0]) < std::atan2(y[1] - c[1], y[0] - c[0]);
    });
    double s = 0;
    for (int i = 0; i < 4; ++i) s += q[i][0] * q[(i + 1) % 4][1] - q[(i + 1) % 4][0] * q[i][1];
    return std::abs(s) / 2;
  };
  std::array<Vec3<double>, 4> kept;
  for (int i = 0; i < 4; ++i) kept[i] = vec_to_double(red.points[i].position);
  // The kept quad has the largest area among all 4-subsets of the octagon
  // that contain the kept deepest point (brute force over the subsets).
  int d = -1;
  for (int i = 0; i < full.size(); ++i)
    if (full.points[i].id == red.points[0].id) d = i;
  REQUIRE(d >= 0);
  double best = 0;
  int subsets = 0;
  for (int i = 0; i < 8; ++i)
    for (int j = i + 1; j < 8; ++j)
      for (int k = j + 1; k < 8; ++k)
        for (int l = k + 1; l < 8; ++l) {
          if (i != d && j != d && k != d && l != d) continue;
          ++subsets;
          best = std::max(
              best,
              quad_area({vec_to_double(full.points[i].position), vec_to_double(full.points[j].position),
                         vec_to_double(full.points[k].position), vec_to_double(full.points[l].position)}));
        }
  CHECK(subsets == 35);
  // Float: candidates within the reduction's tie tolerance (kContactArea *
  // extent^2 of doubled area, plus the float rounding of the areas, below it)
  // of the best are ties.
  const double ext = std::min(a.extent(), b.extent());
  CHECK(quad_area(kept) >= best - Tolerances<T>::kContactArea * ext * ext);
  CHECK(quad_area(kept) <= best + 1e-12);
  // deterministic: the same input gives the same manifold
  const auto again = contact_manifold(a, b);
  CHECK(ids_of(again) == ids_of(red));
}

TEMPLATE_TEST_CASE("crossed edges: one point at the right place", "[contact]", float, double) {
  using T = TestType;
  const double r2 = std::sqrt(2.0);
  const auto a = moved(shapes::cube<T>(1.0), rot({1, 0, 0}, std::numbers::pi / 4), {0, 0, 0});
  const auto b = moved(shapes::cube<T>(1.0), rot({0, 1, 0}, std::numbers::pi / 4), {0.1, -0.2, 2 * r2 - 0.1});
  const auto m = contact_manifold(a, b);
  REQUIRE(m.kind == ContactKind::Edge);
  REQUIRE(m.size() == 1);
  const auto& c = m.points[0];
  CHECK(c.depth() == Approx(0.1).epsilon(1e-4));
  CHECK(vec_to_double(m.normal).isApprox(Vec3<double>(0, 0, 1), 1e-5));
  CHECK(vec_to_double(c.position).isApprox(Vec3<double>(0.1, 0, r2 - 0.05), 1e-5));
  CHECK(vec_to_double(c.point_a).isApprox(Vec3<double>(0.1, 0, r2), 1e-5));
  CHECK(vec_to_double(c.point_b).isApprox(Vec3<double>(0.1, 0, r2 - 0.1), 1e-5));
  CHECK(c.id == ContactFeatureId{ShapeFeature::edge(m.feature.a), ShapeFeature::edge(m.feature.b)});
  check_invariants(a, b, m);
}

TEMPLATE_TEST_CASE("double-sided triangle on a box face", "[contact]", float, double) {
  using T = TestType;
  const auto box = shapes::cube<T>(1.0);
  SECTION("small triangle as incident face: its three vertices") {
    const auto tri =
        shapes::triangle<T>(vec_from_double<T>({-0.5, -0.5, 0.95}), vec_from_double<T>({0.6, -0.4, 0.95}),
                            vec_from_double<T>({0.0, 0.7, 0.95}));
    const auto m = contact_manifold(box, tri);
    REQUIRE(m.kind == ContactKind::Face);
    CHECK(m.reference_shape == 0);
    CHECK(m.reference_face == 1);
    REQUIRE(m.size() == 3);
    for (const auto& c : m.points) {
      CHECK(c.depth() == Approx(0.05));
      CHECK(c.id.a == ShapeFeature::face(1));
      CHECK(c.id.b.kind == ShapeFeatureKind::Vertex);
    }
    // the incident face of the triangle faces down
    CHECK(to_double(tri.plane(m.incident_face).normal[2]) < 0);
    check_invariants(box, tri, m);
  }
  SECTION("large triangle as incident face: clipped to the box face's corners") {
    const auto tri = shapes::triangle<T>(vec_from_double<T>({-3, -2, 0.95}),
                                         vec_from_double<T>({3, -2, 0.95}), vec_from_double<T>({0, 4, 0.95}));
    const auto m = contact_manifold(box, tri);
    REQUIRE(m.kind == ContactKind::Face);
    REQUIRE(m.size() == 4);
    for (const auto& c : m.points) {
      CHECK(c.depth() == Approx(0.05));
      CHECK(c.id.a.kind == ShapeFeatureKind::Vertex);  // a corner of the box's top face
      CHECK(c.id.b == ShapeFeature::face(m.incident_face));
      CHECK(std::abs(to_double(c.point_a[0])) == Approx(1.0));
      CHECK(std::abs(to_double(c.point_a[1])) == Approx(1.0));
    }
    check_invariants(box, tri, m);
  }
  SECTION("triangle as reference face (shape A), box corners as incident vertices") {
    const auto tri = shapes::triangle<T>(vec_from_double<T>({-3, -2, 0}), vec_from_double<T>({3, -2, 0}),
                                         vec_from_double<T>({0, 4, 0}));
    const auto b = moved(box, Eigen::Matrix3d::Identity(), {0, 0, 0.95});
    const auto m = contact_manifold(tri, b);
    REQUIRE(m.kind == ContactKind::Face);
    CHECK(m.reference_shape == 0);
    CHECK(to_double(tri.plane(m.reference_face).normal[2]) > 0);
    REQUIRE(m.size() == 4);
    for (const auto& c : m.points) {
      CHECK(c.depth() == Approx(0.05));
      CHECK(c.id.a == ShapeFeature::face(m.reference_face));
      CHECK(c.id.b.kind == ShapeFeatureKind::Vertex);
    }
    check_invariants(tri, b, m);
  }
}

TEMPLATE_TEST_CASE("triangle against triangle", "[contact]", float, double) {
  using T = TestType;
  SECTION("coplanar star: the hexagon of the two triangles") {
    const auto a = shapes::regular_polygon<T>(3, 1.0);
    const auto b = moved(a, rot({0, 0, 1}, std::numbers::pi), {0, 0, 0});
    ManifoldOptions all;
    all.reduce = false;
    const auto m = contact_manifold(a, b, sat::gauss_map(a, b), all);
    REQUIRE(m.kind == ContactKind::Face);
    REQUIRE(m.size() == 6);
    for (const auto& c : m.points) {
      CHECK(c.depth() == Approx(0.0).margin(1e-6));
      CHECK(c.id.a.kind == ShapeFeatureKind::Edge);
      CHECK(c.id.b.kind == ShapeFeatureKind::Edge);
    }
    check_invariants(a, b, m);
    CHECK(contact_manifold(a, b).size() == 4);
  }
  SECTION("a tilted triangle piercing another") {
    const auto a = shapes::triangle<T>(vec_from_double<T>({-2, -2, 0}), vec_from_double<T>({2, -2, 0}),
                                       vec_from_double<T>({0, 2, 0}));
    const auto b =
        shapes::triangle<T>(vec_from_double<T>({-0.3, 0.1, -0.1}), vec_from_double<T>({0.4, -0.2, 0.8}),
                            vec_from_double<T>({0.1, 0.5, 0.9}));
    const auto m = contact_manifold(a, b);
    REQUIRE(m.kind != ContactKind::None);
    REQUIRE(m.size() >= 1);
    check_invariants(a, b, m);
    const auto b2 = moved(b, Eigen::Matrix3d::Identity(), vec_to_double(m.resolving_translation()));
    CHECK(sat::gauss_map(a, b2).separation_as_double() >= -1e-5);
  }
}

namespace {
// Configurations for the scale tests: (A, B) at scale s.
template <Number T>
std::pair<ConvexPolyhedron<T>, ConvexPolyhedron<T>> config(int which, double s) {
  const double r2 = std::sqrt(2.0);
  switch (which) {
    case 0:
      return {shapes::cube<T>(s), moved(shapes::cube<T>(0.5 * s), Eigen::Matrix3d::Identity(),
                                        s * Vec3<double>(0.1, -0.2, 1.375))};
    case 1:
      return {shapes::cube<T>(s), moved(shapes::box<T>(0.9 * s, 0.9 * s, 0.5 * s),
                                        rot({0, 0, 1}, std::numbers::pi / 4), s * Vec3<double>(0, 0, 1.4))};
    case 2:
      return {moved(shapes::cube<T>(s), rot({1, 0, 0}, std::numbers::pi / 4), {0, 0, 0}),
              moved(shapes::cube<T>(s), rot({0, 1, 0}, std::numbers::pi / 4),
                    s * Vec3<double>(0.1, -0.2, 2 * r2 - 0.1))};
    case 3:
      return {shapes::prism<T>(7, s, s), moved(shapes::prism<T>(5, 0.8 * s, 0.5 * s), rot({1, 1, 0}, 0.3),
                                               s * Vec3<double>(0.2, 0.1, 1.3))};
    default:
      return {moved(shapes::tetrahedron<T>(s), rot({0, 1, 1}, 0.7), {0, 0, 0}),
              moved(shapes::cube<T>(0.6 * s), rot({1, 0, 1}, 1.1), s * Vec3<double>(0.9, 0.4, 0.5))};
  }
}
}  // namespace

// The five configurations at each scale in `scales` give the manifold of
// scale 1, scaled: same kind, feature, ids; depths and positions within a
// relative tolerance.
template <class T>
void check_scaled_manifolds(std::initializer_list<double> scales) {
  for (int which = 0; which < 5; ++which) {
    const auto [a1, b1] = config<T>(which, 1.0);
    const auto m1 = contact_manifold(a1, b1);
    REQUIRE(m1.kind != ContactKind::None);
    for (double s : scales) {
      INFO("config " << which << " scale " << s);
      const auto [as, bs] = config<T>(which, s);
      const auto ms = contact_manifold(as, bs);
      CHECK(ms.kind == m1.kind);
      CHECK(ms.feature == m1.feature);
      REQUIRE(ms.size() == m1.size());
      CHECK(ids_of(ms) == ids_of(m1));
      const double tol = std::is_same_v<T, float> ? 1e-4 : 1e-9;
      for (int i = 0; i < ms.size(); ++i) {
        CHECK(ms.points[i].depth() / s == Approx(m1.points[i].depth()).margin(tol));
        CHECK((vec_to_double(ms.points[i].position) / s - vec_to_double(m1.points[i].position)).norm() <=
              tol);
      }
      check_invariants(as, bs, ms);
    }
  }
}

TEMPLATE_TEST_CASE("scale invariance: 1e-3 and 1e3 give the same manifold up to scale", "[contact][scale]",
                   float, double) {
  check_scaled_manifolds<TestType>({1e-3, 1e3});
}

// Extreme scales: squared lengths and cross products leave the range of T
// here (float: 2^+-55 squared twice is 2^+-220; double: 2^+-400), so this is
// the scale-safe paths (ConvexPolyhedron planes, scaled_cross, the clip).
TEMPLATE_TEST_CASE("extreme scales give the same manifold up to scale", "[contact][scale][extreme]", float,
                   double) {
  if constexpr (std::is_same_v<TestType, float>)
    check_scaled_manifolds<float>({0x1p-55, 0x1p55, 1e-15, 1e15});
  else
    check_scaled_manifolds<double>({0x1p-400, 0x1p400, 1e-120, 1e120});
}

TEMPLATE_TEST_CASE("speculative margin", "[contact][margin]", float, double) {
  using T = TestType;
  const auto a = shapes::cube<T>(1.0);
  const auto b = moved(shapes::cube<T>(0.5), Eigen::Matrix3d::Identity(), {0, 0, 1.5625});  // gap 0.0625
  CHECK(contact_manifold(a, b).empty());
  ManifoldOptions opt;
  opt.margin = 0.125;
  const auto m = contact_manifold(a, b, sat::gauss_map(a, b), opt);
  REQUIRE(m.size() == 4);
  for (const auto& c : m.points) CHECK(to_double(c.separation) == Approx(0.0625));
  opt.margin = 0.03125;
  CHECK(contact_manifold(a, b, sat::gauss_map(a, b), opt).empty());
  // a tilted box: only the corners within the margin are kept
  const auto t = moved(shapes::cube<T>(0.5), rot({1, 0, 0}, 0.1), {0, 0, 1.6});
  opt.margin = 0.2;
  const auto mt = contact_manifold(a, t, sat::gauss_map(a, t), opt);
  REQUIRE(mt.kind == ContactKind::Face);
  opt.margin = 0.1;
  const auto mt2 = contact_manifold(a, t, sat::gauss_map(a, t), opt);
  CHECK(mt2.size() < mt.size());
  for (const auto& c : mt2.points) CHECK(to_double(c.separation) <= 0.1 + 1e-6);
}

TEMPLATE_TEST_CASE("coplanar polygons with a gap: side contact within the margin", "[contact][margin][side]",
                   float, double) {
  using T = TestType;
  auto v = [](double x, double y) { return vec_from_double<T>(Vec3<double>(x, y, 0)); };
  // squares [0,2]^2 and [3,5] x [0,1]: A's right edge x = 2 against B's left
  // edge x = 3, a gap of 1 (SideA, feature.hpp)
  const auto a = ConvexPolyhedron<T>::polygon({v(0, 0), v(2, 0), v(2, 2), v(0, 2)});
  const auto b = ConvexPolyhedron<T>::polygon({v(3, 0), v(5, 0), v(5, 1), v(3, 1)});
  const auto r = sat::gauss_map(a, b);
  REQUIRE(r.feature.type == FeatureType::SideA);
  CHECK(contact_manifold(a, b, r).empty());
  ManifoldOptions opt;
  opt.margin = 1.5;
  const auto m = contact_manifold(a, b, r, opt);
  CHECK(m.kind == ContactKind::Side);
  REQUIRE(m.size() == 2);  // B's left edge, inside A's edge's slab
  for (const auto& c : m.points) {
    CHECK(to_double(c.separation) == 1.0);
    CHECK(vec_to_double(c.point_a)[0] == 2.0);
    CHECK(vec_to_double(c.point_b)[0] == 3.0);
    CHECK(c.id.a == ShapeFeature::edge(r.feature.a));
    CHECK(c.id.b.kind == ShapeFeature::vertex(0).kind);
  }
  // B lower by 1/2: its left edge [(3,-0.5), (3,0.5)] is cut by the slab of
  // A's edge at y = 0: A's corner (2,0) against B's edge, and B's vertex 3
  const auto low = ConvexPolyhedron<T>::polygon({v(3, -0.5), v(5, -0.5), v(5, 0.5), v(3, 0.5)});
  const auto rl = sat::gauss_map(a, low);
  REQUIRE(rl.feature.type == FeatureType::SideA);
  const auto ml = contact_manifold(a, low, rl, opt);
  CHECK(ml.kind == ContactKind::Side);
  REQUIRE(ml.size() == 2);
  int clipped = 0;
  for (const auto& c : ml.points) {
    CHECK(to_double(c.separation) == 1.0);
    if (vec_to_double(c.point_b)[1] == 0.0) {
      ++clipped;
      CHECK(c.id.a.kind == ShapeFeature::vertex(0).kind);
      CHECK(c.id.b.kind == ShapeFeature::edge(0).kind);
    } else {
      CHECK(c.id.b == ShapeFeature::vertex(3));
    }
  }
  CHECK(clipped == 1);
  // B lower by 3/2: its edge misses the slab (corner against corner): the
  // support vertex alone, flagged
  const auto lower = ConvexPolyhedron<T>::polygon({v(3, -1.5), v(5, -1.5), v(5, -0.5), v(3, -0.5)});
  const auto rw = sat::gauss_map(a, lower);
  const auto mw = contact_manifold(a, lower, rw, opt);
  CHECK(mw.support_fallback);
  REQUIRE(mw.size() == 1);
  CHECK(vec_to_double(mw.points[0].point_b) == Vec3<double>(3, -1.5, 0));
  // moving B by the separation along the normal makes the polygons touch
  const Vec3<double> shift = vec_to_double(m.resolving_translation());
  CHECK(shift[0] == -1.0);
  const auto rt = sat::gauss_map(a, moved(b, Eigen::Matrix3d::Identity(), shift));
  CHECK(rt.overlap);
  CHECK(to_double(rt.separation) == 0.0);
  // The reference edge on B (SideB): the right triangle against B; B's left
  // edge x = 3 gives 1, A's hypotenuse only 1/sqrt 2.  The incident edge is
  // A's hypotenuse (more perpendicular to the normal than the bottom edge),
  // clipped to B's edge's slab 0 <= y <= 1: (2,0) at 1 and (1,1) at 2.
  const auto tri = ConvexPolyhedron<T>::polygon({v(0, 0), v(2, 0), v(0, 2)});
  const auto rs = sat::gauss_map(tri, b);
  REQUIRE(rs.feature.type == FeatureType::SideB);
  CHECK(vec_to_double(rs.axis)[0] == Approx(1.0));
  const auto ms = contact_manifold(tri, b, rs, opt);
  CHECK(ms.kind == ContactKind::Side);
  CHECK(ms.reference_shape == 1);
  REQUIRE(ms.size() == 1);
  CHECK(vec_to_double(ms.points[0].point_a) == Vec3<double>(2, 0, 0));
  opt.margin = 2.5;
  const auto ms2 = contact_manifold(tri, b, rs, opt);
  REQUIRE(ms2.size() == 2);
  CHECK(to_double(ms2.points[1].separation) == Approx(2.0));
  CHECK(vec_to_double(ms2.points[1].point_a).isApprox(Vec3<double>(1, 1, 0)));
}

TEST_CASE("bad input to contact_manifold", "[contact][errors]") {
  const auto a = shapes::cube<double>(1.0);
  const auto b = moved(shapes::cube<double>(1.0), Eigen::Matrix3d::Identity(), {0, 0, 1.5});
  auto sat = sat::gauss_map(a, b);
  ManifoldOptions opt;
  opt.margin = -1;
  CHECK_THROWS_AS(contact_manifold(a, b, sat, opt), InvalidInput);
  // The message shows the value as written, not std::to_string's "-0.000000".
  opt.margin = -1e-20;
  CHECK_THROWS_WITH(contact_manifold(a, b, sat, opt), Catch::Matchers::Contains("margin -1e-20 is negative"));
  opt.margin = std::nan("");
  CHECK_THROWS_AS(contact_manifold(a, b, sat, opt), InvalidInput);
  sat.feature = Feature::face_a(17, 0);
  try {
    (void)contact_manifold(a, b, sat);
    FAIL("expected InvalidInput");
  } catch (const InvalidInput& e) {
    CHECK(e.code() == ErrorCode::BadIndex);
    CHECK(std::string(e.what()).find("face of A 17") != std::string::npos);
  }
  sat.feature = Feature::edges(0, 99);
  CHECK_THROWS_AS(contact_manifold(a, b, sat), InvalidInput);
  // a face feature without support vertex: found by a scan
  sat = sat::gauss_map(a, b);
  sat.feature.b = -1;
  CHECK(contact_manifold(a, b, sat).size() == 4);
}

TEST_CASE("random overlapping pairs: brute force and Gauss map agree, moving B by the depth separates",
          "[contact][random]") {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1, 1);
  int overlapping = 0;
  for (int iter = 0; iter < 300; ++iter) {
    auto shape = [&](int k) {
      switch (k % 4) {
        case 0:
          return shapes::box<double>(0.5 + 0.5 * std::abs(u(rng)), 0.5 + 0.5 * std::abs(u(rng)),
                                     0.3 + 0.5 * std::abs(u(rng)));
        case 1:
          return shapes::prism<double>(3 + iter % 6, 0.8, 0.6);
        case 2:
          return shapes::tetrahedron<double>(0.9);
        default:
          return shapes::regular_polygon<double>(3 + iter % 5, 1.0);
      }
    };
    const auto a = moved(shape(iter), rot({u(rng), u(rng), u(rng)}, 3 * u(rng)), {0, 0, 0});
    const auto b =
        moved(shape(iter / 4 + 1), rot({u(rng), u(rng), u(rng)}, 3 * u(rng)), {u(rng), u(rng), u(rng)});
    const auto sg = sat::gauss_map(a, b);
    if (!sg.overlap) continue;
    ++overlapping;
    INFO("iteration " << iter);
    const auto m = contact_manifold(a, b, sg);
    const auto mb = contact_manifold(a, b, sat::brute_force(a, b));
    REQUIRE(m.kind != ContactKind::None);
    CHECK(m.size() >= 1);
    CHECK(m.size() <= 4);
    check_invariants(a, b, m);
    CHECK(ids_of(m) == ids_of(mb));
    if (m.kind == ContactKind::Face) {
      // the incident face is the most anti-parallel of the faces around the
      // support vertex, and the deepest point is as deep as the SAT says
      const auto& R = m.reference_shape == 0 ? a : b;
      const auto& I = m.reference_shape == 0 ? b : a;
      const int sv = m.reference_shape == 0 ? sg.feature.b : sg.feature.a;
      const Vec3<double> n = R.plane(m.reference_face).normal;
      int best = -1;
      for (int h : I.vertex_half_edges(sv)) {
        const int f = I.half_edge(h).face;
        if (best < 0 || -n.dot(I.plane(f).normal) > -n.dot(I.plane(best).normal) ||
            (-n.dot(I.plane(f).normal) == -n.dot(I.plane(best).normal) && f < best))
          best = f;
      }
      CHECK(m.incident_face == best);
      CHECK_FALSE(m.support_fallback);
      double deepest = 1e300;
      for (const auto& c : m.points) deepest = std::min(deepest, to_double(c.separation));
      CHECK(deepest == Approx(to_double(m.separation)).margin(1e-12));
    }
    const auto b2 = moved(b, Eigen::Matrix3d::Identity(), vec_to_double(m.resolving_translation()));
    CHECK(sat::gauss_map(a, b2).separation_as_double() >= -1e-9 * std::max(a.extent(), b.extent()));
  }
  CHECK(overlapping > 50);
}

TEMPLATE_TEST_CASE("feature ids are stable across frames while the same features touch", "[contact][frames]",
                   float, double) {
  using T = TestType;
  const auto a = shapes::box<T>(2.0, 2.0, 1.0);
  std::vector<ContactFeatureId> first;
  for (int frame = 0; frame < 20; ++frame) {
    const double x = -0.5 + 0.05 * frame;
    const auto b = moved(shapes::cube<T>(0.5), rot({0, 0, 1}, 0.2 + 0.01 * frame), {x, 0.3, 1.45});
    const auto m = contact_manifold(a, b);
    REQUIRE(m.size() == 4);
    INFO("frame " << frame);
    if (frame == 0)
      first = ids_of(m);
    else
      CHECK(ids_of(m) == first);
  }
}

#if __has_include(<sepax/sat_cache.hpp>) && __has_include(<sepax/sat_traversal.hpp>)
#include <sepax/sat_cache.hpp>
#include <sepax/sat_traversal.hpp>

TEMPLATE_TEST_CASE("a cached query gives the same manifold as a fresh one", "[contact][cache]", float,
                   double) {
  using T = TestType;
  const auto a = shapes::prism<T>(9, 1.0, 0.8);
  SatCache<T> cache;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int overlapping = 0;
  for (int frame = 0; frame < 60; ++frame) {
    const double t = 0.1 * frame;
    const auto b = moved(shapes::box<T>(0.5, 0.4, 0.3), rot({std::sin(t), 1, 0.3}, t),
                         {0.8 * std::cos(t), 0.5 * std::sin(t), 0.9 + 0.4 * std::sin(2 * t)});
    for (bool early : {false, true}) {
      SatOptions o;
      o.early_out = early;
      const auto rc = sat::cached(
          cache, a, b, [](auto& k, const SatOptions& oo) { return sat::gauss_map_with(k, oo); }, o);
      const auto rf = sat::traversal(a, b);
      if (!rf.overlap) {
        CHECK_FALSE(rc.overlap);
        continue;
      }
      ++overlapping;
      const auto mc = contact_manifold(a, b, rc);
      const auto mf = contact_manifold(a, b, rf);
      INFO("frame " << frame);
      CHECK(mc.feature == mf.feature);
      REQUIRE(mc.size() == mf.size());
      CHECK(ids_of(mc) == ids_of(mf));
      for (int i = 0; i < mc.size(); ++i) {
        CHECK(mc.points[i].position == mf.points[i].position);
        CHECK(mc.points[i].separation.num == mf.points[i].separation.num);
      }
    }
  }
  CHECK(overlapping > 20);
}
#endif

TEMPLATE_TEST_CASE("scale invariance on random overlapping pairs", "[contact][scale][random]", float,
                   double) {
  using T = TestType;
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0;
  for (int iter = 0; iter < 200 && checked < 60; ++iter) {
    const Eigen::Matrix3d ra = rot({u(rng), u(rng), u(rng)}, 3 * u(rng));
    const Eigen::Matrix3d rb = rot({u(rng), u(rng), u(rng)}, 3 * u(rng));
    const Vec3<double> t(u(rng), u(rng), u(rng));
    const int ka = iter % 3, kb = (iter / 3) % 3;
    auto make = [&](int k, double s) {
      switch (k) {
        case 0:
          return shapes::box<T>(0.7 * s, 0.5 * s, 0.4 * s);
        case 1:
          return shapes::prism<T>(6, 0.8 * s, 0.5 * s);
        default:
          return shapes::regular_polygon<T>(5, 0.9 * s);
      }
    };
    const auto a1 = moved(make(ka, 1), ra, {0, 0, 0});
    const auto b1 = moved(make(kb, 1), rb, t);
    const auto m1 = contact_manifold(a1, b1);
    if (m1.empty()) continue;
    ++checked;
    for (double s : {1e-3, 1e3}) {
      INFO("iteration " << iter << " scale " << s);
      const auto as = moved(make(ka, s), ra, {0, 0, 0});
      const auto bs = moved(make(kb, s), rb, s * t);
      const auto ms = contact_manifold(as, bs);
      CHECK(ms.feature == m1.feature);
      REQUIRE(ms.size() == m1.size());
      CHECK(ids_of(ms) == ids_of(m1));
      for (int i = 0; i < ms.size(); ++i)
        CHECK(ms.points[i].depth() / s ==
              Approx(m1.points[i].depth()).margin(std::is_same_v<T, float> ? 1e-4 : 1e-9));
    }
  }
  CHECK(checked >= 40);
}

TEMPLATE_TEST_CASE("closest_segment_points: scale-free, and a zero-length segment is its tail",
                   "[contact][segments]", float, double) {
  using T = TestType;
  using detail::closest_segment_points;
  // two crossing segments: x axis from (-1,0,0), and a segment along y at x = 0.25, z = 1
  T s, t;
  const double big = std::is_same_v<T, float> ? 0x1p60 : 0x1p500;
  for (double k : {1.0, big, 1 / big}) {
    INFO("scale " << k);
    closest_segment_points(vec_from_double<T>(Vec3<double>(-1, 0, 0) * k),
                           vec_from_double<T>(Vec3<double>(2, 0, 0) * k),
                           vec_from_double<T>(Vec3<double>(0.25, -1, 1) * k),
                           vec_from_double<T>(Vec3<double>(0, 4, 0) * k), s, t);
    CHECK(s == T(0.625));
    CHECK(t == T(0.25));
  }
  // zero-length first segment: the point (0.5, 3, 0) against the x segment from the origin
  closest_segment_points(vec_from_double<T>({0.5, 3, 0}), Vec3<T>(T(0), T(0), T(0)),
                         vec_from_double<T>({0, 0, 0}), vec_from_double<T>({2, 0, 0}), s, t);
  CHECK(s == T(0));
  CHECK(t == T(0.25));
  // zero-length second segment
  closest_segment_points(vec_from_double<T>({0, 0, 0}), vec_from_double<T>({2, 0, 0}),
                         vec_from_double<T>({3, 1, 0}), Vec3<T>(T(0), T(0), T(0)), s, t);
  CHECK(s == T(1));
  CHECK(t == T(0));
}

TEMPLATE_TEST_CASE("box on a box at every scale: clipped to the 4 corners, octagons reduced to 4",
                   "[contact][scale]", float, double) {
  // Unscaled, a side plane's offset |edge| |tail| overflows double beyond coordinates of about 1e154
  // (float beyond 1e19), and the weld and reduction tolerances (squared lengths, areas) over- or
  // underflow beyond about 1e+-150 (float 1e+-19): nothing would be clipped, or every point welded into
  // one.  The manifold must be the one of scale 1, scaled.
  using T = TestType;
  const std::vector<double> scales =
      std::is_same_v<T, float> ? std::vector<double>{1.0, 1e12, 1e19, 1e25, 1e30, 1e-20, 1e-25, 1e-30}
                               : std::vector<double>{1.0, 1e130, 1e160, 1e200, 1e300, 1e-160, 1e-200};
  for (double s : scales) {
    INFO("scale " << s);
    const auto a = shapes::box<T>(static_cast<T>(s), static_cast<T>(s), static_cast<T>(s));
    const auto b = moved(a, Eigen::Matrix3d::Identity(), Vec3<double>(0.5 * s, 0.5 * s, 1.5 * s));
    const auto m = contact_manifold(a, b);
    REQUIRE(m.kind == ContactKind::Face);
    CHECK(m.candidate_points == 4);
    REQUIRE(m.size() == 4);
    for (const auto& c : m.points) {
      // the overlap of the two faces: x and y in {-0.5 s, s}
      for (int k = 0; k < 2; ++k) {
        const double x = to_double(c.position[k]) / s;
        CHECK((std::abs(x + 0.5) < 1e-5 || std::abs(x - 1.0) < 1e-5));
      }
      CHECK(to_double(c.separation.num) / s == Approx(-0.5).epsilon(1e-5));
    }
    // a box turned by 45 degrees on A: an octagon, reduced to 4 of its corners as at scale 1
    const auto c =
        moved(shapes::box<T>(static_cast<T>(0.9 * s), static_cast<T>(0.9 * s), static_cast<T>(0.5 * s)),
              rot({0, 0, 1}, std::numbers::pi / 4), {0, 0, 1.4 * s});
    ManifoldOptions all;
    all.reduce = false;
    const auto full = contact_manifold(a, c, sat::gauss_map(a, c), all);
    CHECK(full.size() == 8);
    const auto red = contact_manifold(a, c);
    CHECK(red.candidate_points == 8);
    REQUIRE(red.size() == 4);
    std::vector<int> kept;
    for (const auto& p : red.points) {
      for (int k = 0; k < static_cast<int>(full.size()); ++k)
        if (full.points[static_cast<std::size_t>(k)].id == p.id) kept.push_back(k);
    }
    CHECK(kept.size() == 4);
    const auto one_a = shapes::box<T>(T(1), T(1), T(1));
    const auto one_c =
        moved(shapes::box<T>(T(0.9), T(0.9), T(0.5)), rot({0, 0, 1}, std::numbers::pi / 4), {0, 0, 1.4});
    const auto red1 = contact_manifold(one_a, one_c);
    REQUIRE(red1.size() == 4);
    for (std::size_t k = 0; k < 4; ++k) CHECK(red.points[k].id == red1.points[k].id);
  }
}
