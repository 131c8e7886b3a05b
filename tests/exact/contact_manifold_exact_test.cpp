#include <catch2/catch.hpp>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <sepax/robust/number_types.hpp>

#include <Eigen/Geometry>
#include <random>

#include <sepax/contact_manifold.hpp>
#include <sepax/manifold_compare.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/shapes.hpp>

using namespace sepax;

namespace {

template <Number T>
T q(long num, long den = 1) {
  return T(static_cast<int>(num)) / T(static_cast<int>(den));
}

template <Number T>
ConvexPolyhedron<T> map_vertices(const ConvexPolyhedron<T>& p, const auto& f) {
  std::vector<Vec3<T>> vs;
  for (const auto& v : p.vertices()) vs.push_back(f(v));
  return p.with_vertices(vs);
}

template <Number T>
ConvexPolyhedron<T> translated(const ConvexPolyhedron<T>& p, const Vec3<T>& t) {
  return map_vertices(p, [&](const Vec3<T>& v) { return Vec3<T>(v + t); });
}

// Exact equality of vectors, as a plain bool (Catch must not print Eigen
// matrices of CGAL number types).
template <Number T>
bool same(const Vec3<T>& x, const Vec3<T>& y) {
  return x[0] == y[0] && x[1] == y[1] && x[2] == y[2];
}

/// Exact checks that hold for every point of every manifold with exact T.
/// `planar`: every face's vertices are exactly on its plane (false for the
/// exact image of a rotated float shape, whose faces are planar only up to the
/// float rounding of its vertices; then only the checks that do not depend on
/// it are made).
template <Number T>
void check_exact_invariants(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b,
                            const ContactManifold<T>& m, bool planar = true) {
  for (const auto& c : m.points) {
    if (planar) {
      for (int f = 0; f < a.face_count(); ++f)
        CHECK(dot(a.plane(f).normal, c.point_a) - a.plane(f).offset <= T(0));
      for (int f = 0; f < b.face_count(); ++f)
        CHECK(dot(b.plane(f).normal, c.point_b) - b.plane(f).offset <= T(0));
    }
    CHECK(dot(m.normal, Vec3<T>(c.point_b - c.point_a)) == c.separation.num);
    CHECK(c.separation.norm2 == m.norm2);
    CHECK(compare(c.separation, m.separation) >= 0);
    const Vec3<T> mid((c.point_a + c.point_b) * (T(1) / T(2)));
    CHECK(same(c.position, mid));
  }
  if (m.kind == ContactKind::Face) {
    const auto& R = m.reference_shape == 0 ? a : b;
    const auto& I = m.reference_shape == 0 ? b : a;
    for (const auto& c : m.points) {
      const Vec3<T>& on_ref = m.reference_shape == 0 ? c.point_a : c.point_b;
      const Vec3<T>& on_inc = m.reference_shape == 0 ? c.point_b : c.point_a;
      CHECK(dot(R.plane(m.reference_face).normal, on_ref) == R.plane(m.reference_face).offset);
      if (planar) CHECK(dot(I.plane(m.incident_face).normal, on_inc) == I.plane(m.incident_face).offset);
    }
  }
}

/// Moving B by the manifold's depth along its normal leaves the shapes exactly
/// touching.
template <Number T>
void check_resolves_exactly(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b,
                            const ContactManifold<T>& m) {
  const auto b2 = translated(b, m.resolving_translation());
  const auto r = sat::gauss_map(a, b2);
  CHECK(r.overlap);
  CHECK(sign(r.separation) == 0);
}

// Triangular prism along x, top edge (+-1, 0, 1).
template <Number T>
ConvexPolyhedron<T> wedge() {
  std::vector<Vec3<T>> v{{q<T>(-1), q<T>(-1), q<T>(0)}, {q<T>(-1), q<T>(1), q<T>(0)},
                         {q<T>(-1), q<T>(0), q<T>(1)},  {q<T>(1), q<T>(-1), q<T>(0)},
                         {q<T>(1), q<T>(1), q<T>(0)},   {q<T>(1), q<T>(0), q<T>(1)}};
  return ConvexPolyhedron<T>::from_faces(v, {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {0, 3, 5, 2}, {1, 2, 5, 4}});
}

}  // namespace

TEMPLATE_TEST_CASE("exact: box resting on a box", "[contact][exact]", mpq_class, CGAL::Gmpq,
                   CGAL::Epeck::FT) {
  using T = TestType;
  const auto a = shapes::cube<T>(1.0);
  const auto b = translated(shapes::cube<T>(0.5), Vec3<T>(q<T>(1, 10), q<T>(-1, 5), q<T>(7, 5)));
  const auto m = contact_manifold(a, b);
  REQUIRE(m.kind == ContactKind::Face);
  REQUIRE(m.size() == 4);
  for (const auto& c : m.points) {
    // depth 1/10 exactly: num / sqrt(norm2) == -1/10  <=>  num^2 == norm2/100, num < 0
    CHECK(c.separation.num < T(0));
    CHECK(c.separation.num * c.separation.num * T(100) == c.separation.norm2);
    CHECK(c.point_b[2] == q<T>(9, 10));
    CHECK(c.point_a[2] == T(1));
  }
  check_exact_invariants(a, b, m);
  check_resolves_exactly(a, b, m);
}

TEMPLATE_TEST_CASE("exact: rotated box on a larger box (rational rotation), every clip point exact",
                   "[contact][exact]", mpq_class, CGAL::Epeck::FT) {
  using T = TestType;
  const auto a = shapes::cube<T>(1.0);
  // rotation about z by atan(3/4): cos 4/5, sin 3/5 (exact)
  const T c = q<T>(4, 5), s = q<T>(3, 5);
  const auto b = map_vertices(shapes::box<T>(0.9, 0.9, 0.5), [&](const Vec3<T>& v) {
    return Vec3<T>(c * v[0] - s * v[1] + q<T>(1, 20), s * v[0] + c * v[1], v[2] + q<T>(7, 5));
  });
  ManifoldOptions all;
  all.reduce = false;
  const auto m = contact_manifold(a, b, sat::gauss_map(a, b), all);
  REQUIRE(m.kind == ContactKind::Face);
  CHECK(m.size() >= 6);
  for (const auto& p : m.points) CHECK(p.separation.num * p.separation.num * T(100) == p.separation.norm2);
  check_exact_invariants(a, b, m);
  check_resolves_exactly(a, b, m);
  const auto r = contact_manifold(a, b);
  CHECK(r.size() == 4);
  // the same manifold from the brute-force SAT
  const auto rb = contact_manifold(a, b, sat::brute_force(a, b));
  REQUIRE(rb.size() == r.size());
  for (int i = 0; i < r.size(); ++i) {
    CHECK(rb.points[i].id == r.points[i].id);
    CHECK(same(rb.points[i].position, r.points[i].position));
  }
}

TEMPLATE_TEST_CASE(
    "exact: the reduced rotated-box octagon has exactly the largest area with the deepest point",
    "[contact][exact][reduction]", mpq_class, CGAL::Gmpq, CGAL::Epeck::FT) {
  using T = TestType;
  const auto a = shapes::cube<T>(1.0);
  // rotation about z by atan(3/4), tilted so that the depths differ: the
  // incident face is a rational plane, the deepest clip point is unique
  const T c = q<T>(4, 5), s = q<T>(3, 5);
  const auto b = map_vertices(shapes::box<T>(0.9, 0.9, 0.5), [&](const Vec3<T>& v) {
    return Vec3<T>(c * v[0] - s * v[1] + q<T>(1, 20), s * v[0] + c * v[1],
                   v[2] + q<T>(7, 5) + v[0] * q<T>(1, 50));
  });
  ManifoldOptions all;
  all.reduce = false;
  const auto full = contact_manifold(a, b, sat::gauss_map(a, b), all);
  REQUIRE(full.kind == ContactKind::Face);
  REQUIRE(full.size() == 8);
  const auto red = contact_manifold(a, b);
  REQUIRE(red.size() == 4);
  // map kept ids to full indices
  std::vector<int> kept;
  for (const auto& p : red.points)
    for (int i = 0; i < full.size(); ++i)
      if (full.points[i].id == p.id) kept.push_back(i);
  REQUIRE(kept.size() == 4);
  // the first kept point is the exactly deepest one
  for (const auto& p : full.points) CHECK(compare(red.points[0].separation, p.separation) <= 0);
  std::vector<Vec3<T>> pos;
  for (const auto& p : full.points) pos.push_back(p.position);
  const Vec3<T>& n = full.normal;
  const T h = contact_hull_area2(pos, kept, n);
  CHECK(h > T(0));
  // exactly maximal over every 4-subset containing the deepest point, and the
  // only maximum (no tie here)
  const int d = kept[0];
  int equal = 0;
  for (int i = 0; i < 8; ++i)
    for (int j = i + 1; j < 8; ++j)
      for (int k = j + 1; k < 8; ++k) {
        if (i == d || j == d || k == d) continue;
        const T hs = contact_hull_area2(pos, {d, i, j, k}, n);
        CHECK(hs <= h);
        if (hs == h) ++equal;
      }
  CHECK(equal == 1);
  // both scans agree exactly
  std::vector<T> keys;
  for (const auto& p : full.points) keys.push_back(p.separation.num);
  CHECK(reduce_contact_points(pos, keys, n, T(0), T(0)) == kept);
  CHECK(reduce_contact_points(pos, keys, n, T(0), T(0), true) == kept);
  // float and double make the same choice on the same configuration (no tie)
  auto float_ids = [&](auto zero) {
    using F = decltype(zero);
    const auto af = shapes::cube<F>(1.0);
    const auto bf = map_vertices(shapes::box<F>(0.9, 0.9, 0.5), [&](const Vec3<F>& v) {
      return Vec3<F>(F(0.8) * v[0] - F(0.6) * v[1] + F(0.05), F(0.6) * v[0] + F(0.8) * v[1],
                     v[2] + F(1.4) + v[0] * F(0.02));
    });
    std::vector<ContactFeatureId> ids;
    for (const auto& p : contact_manifold(af, bf).points) ids.push_back(p.id);
    return ids;
  };
  std::vector<ContactFeatureId> exact_ids;
  for (const auto& p : red.points) exact_ids.push_back(p.id);
  CHECK((float_ids(0.0) == exact_ids));
  CHECK((float_ids(0.0f) == exact_ids));
}

TEMPLATE_TEST_CASE("exact: crossed edges", "[contact][exact]", mpq_class, CGAL::Epeck::FT) {
  using T = TestType;
  const auto a = wedge<T>();
  // B: the wedge turned upside down about the axis (1,1,0) (x,y,z) -> (y,x,-z),
  // shifted so its bottom edge (x = 1/4, along y) dips 1/8 into A's top edge.
  const auto b = map_vertices(wedge<T>(), [&](const Vec3<T>& v) {
    return Vec3<T>(v[1] + q<T>(1, 4), v[0] + q<T>(1, 8), q<T>(15, 8) - v[2]);
  });
  const auto m = contact_manifold(a, b);
  REQUIRE(m.kind == ContactKind::Edge);
  REQUIRE(m.size() == 1);
  const auto& p = m.points[0];
  CHECK(same(p.point_a, Vec3<T>(q<T>(1, 4), T(0), T(1))));
  CHECK(same(p.point_b, Vec3<T>(q<T>(1, 4), T(0), q<T>(7, 8))));
  CHECK(same(p.position, Vec3<T>(q<T>(1, 4), T(0), q<T>(15, 16))));
  CHECK(p.separation.num * p.separation.num * T(64) == p.separation.norm2);
  CHECK(p.separation.num < T(0));
  CHECK(p.id.a.kind == ShapeFeatureKind::Edge);
  CHECK(p.id.b.kind == ShapeFeatureKind::Edge);
  check_exact_invariants(a, b, m);
  check_resolves_exactly(a, b, m);
}

TEMPLATE_TEST_CASE("exact: double-sided triangle on a box face, triangle against triangle",
                   "[contact][exact]", mpq_class, CGAL::Epeck::FT) {
  using T = TestType;
  const auto box = shapes::cube<T>(1.0);
  const auto big =
      shapes::triangle<T>(Vec3<T>(q<T>(-3), q<T>(-2), q<T>(19, 20)), Vec3<T>(q<T>(3), q<T>(-2), q<T>(19, 20)),
                          Vec3<T>(q<T>(0), q<T>(4), q<T>(19, 20)));
  const auto m = contact_manifold(box, big);
  REQUIRE(m.size() == 4);
  for (const auto& p : m.points) {
    CHECK(p.id.a.kind == ShapeFeatureKind::Vertex);
    CHECK(p.point_b[2] == q<T>(19, 20));
  }
  check_exact_invariants(box, big, m);
  check_resolves_exactly(box, big, m);
  // two coplanar triangles: touching, separation exactly 0, a hexagon
  const auto t1 = shapes::triangle<T>(Vec3<T>(q<T>(-2), q<T>(-1), T(0)), Vec3<T>(q<T>(2), q<T>(-1), T(0)),
                                      Vec3<T>(q<T>(0), q<T>(2), T(0)));
  const auto t2 = shapes::triangle<T>(Vec3<T>(q<T>(2), q<T>(1), T(0)), Vec3<T>(q<T>(-2), q<T>(1), T(0)),
                                      Vec3<T>(q<T>(0), q<T>(-2), T(0)));
  ManifoldOptions all;
  all.reduce = false;
  const auto mt = contact_manifold(t1, t2, sat::gauss_map(t1, t2), all);
  CHECK(mt.size() == 6);
  for (const auto& p : mt.points) CHECK(sign(p.separation) == 0);
  check_exact_invariants(t1, t2, mt);
}

namespace {
Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::Quaterniond qd(u(rng), u(rng), u(rng), u(rng));
  qd.normalize();
  return qd.toRotationMatrix();
}

ConvexPolyhedron<double> random_unrotated_shape(std::mt19937& rng, int k) {
  std::uniform_real_distribution<double> u(0.3, 1.0);
  switch (k % 4) {
    case 0:
      return shapes::box<double>(u(rng), u(rng), u(rng));
    case 1:
      return shapes::prism<double>(3 + k % 5, u(rng), u(rng));
    case 2:
      return shapes::tetrahedron<double>(u(rng));
    default:
      return shapes::regular_polygon<double>(3 + k % 4, u(rng));
  }
}

ConvexPolyhedron<double> random_shape(std::mt19937& rng, int k) {
  const auto p = random_unrotated_shape(rng, k);
  const Eigen::Matrix3d R = random_rotation(rng);
  std::vector<Vec3<double>> vs;
  for (const auto& v : p.vertices()) vs.push_back(R * v);
  return p.with_vertices(vs);
}

// An exact rational rotation: the matrix of the integer quaternion (w,x,y,z)
// divided by its squared norm.  Rotating exactly keeps faces exactly planar.
ConvexPolyhedron<mpq_class> rational_rotated(const ConvexPolyhedron<double>& p, std::mt19937& rng,
                                             const Vec3<double>& shift) {
  std::uniform_int_distribution<int> d(-9, 9);
  int w = 0, x = 0, y = 0, z = 0;
  while (w == 0 && x == 0 && y == 0 && z == 0) w = d(rng), x = d(rng), y = d(rng), z = d(rng);
  const mpq_class n = w * w + x * x + y * y + z * z;
  const mpq_class R[3][3] = {{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
                             {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
                             {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
  const auto qp = ConvexPolyhedron<mpq_class>::convert_from(p);
  const auto qs = vec_from_double<mpq_class>(shift);
  std::vector<Vec3<mpq_class>> vs;
  for (const auto& v : qp.vertices()) {
    Vec3<mpq_class> r;
    for (int i = 0; i < 3; ++i) r[i] = (R[i][0] * v[0] + R[i][1] * v[1] + R[i][2] * v[2]) / n + qs[i];
    vs.push_back(r);
  }
  return qp.with_vertices(vs);
}

// Doubled area of the convex quad/triangle spanned by the points of m, seen
// along the normal (for comparing reductions; reporting precision).
template <Number T>
double spanned_area(const ContactManifold<T>& m) {
  const Vec3<double> n = vec_to_double(m.normal).normalized();
  std::vector<Vec3<double>> p;
  for (const auto& c : m.points) p.push_back(vec_to_double(c.position));
  if (p.size() < 3) return 0;
  auto tri = [&](int i, int j, int k) { return std::abs((p[j] - p[i]).cross(p[k] - p[i]).dot(n)); };
  if (p.size() == 3) return tri(0, 1, 2);
  double best = 0;
  for (const auto& o :
       {std::array<int, 4>{0, 1, 2, 3}, std::array<int, 4>{0, 2, 1, 3}, std::array<int, 4>{0, 1, 3, 2}}) {
    double s = 0;
    for (int i = 0; i < 4; ++i) {
      const auto& u = p[o[i]];
      const auto& v = p[o[(i + 1) % 4]];
      s += u.cross(v).dot(n);
    }
    best = std::max(best, std::abs(s));
  }
  return best;
}
}  // namespace

TEST_CASE("exact: random exactly-rotated overlapping pairs: exact points, depth resolves exactly",
          "[contact][exact][random]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.8, 0.8);
  int checked = 0;
  for (int iter = 0; iter < 200 && checked < 40; ++iter) {
    const auto a = rational_rotated(random_unrotated_shape(rng, iter), rng, {0, 0, 0});
    const auto b = rational_rotated(random_unrotated_shape(rng, iter / 4 + 1), rng, {u(rng), u(rng), u(rng)});
    const auto s = sat::gauss_map(a, b);
    if (!s.overlap) continue;
    ++checked;
    INFO("iteration " << iter);
    ManifoldOptions all;
    all.reduce = false;
    const auto m = contact_manifold(a, b, s, all);
    REQUIRE(m.size() >= 1);
    check_exact_invariants(a, b, m);
    check_resolves_exactly(a, b, m);
    const auto r = contact_manifold(a, b, s);
    CHECK(r.size() <= 4);
    check_exact_invariants(a, b, r);
    // the reduction keeps a deepest point
    const auto* deepest = &r.points[0];
    for (const auto& c : r.points)
      if (compare(c.separation, deepest->separation) < 0) deepest = &c;
    for (const auto& c : m.points) CHECK(compare(deepest->separation, c.separation) <= 0);
    // ... and it is exactly as deep as the SAT says (the deepest vertex is on
    // the incident face and over the reference face)
    CHECK_FALSE(r.support_fallback);
    CHECK(compare(deepest->separation, s.separation) == 0);
  }
  CHECK(checked >= 30);
}

TEST_CASE("exact vs double on the same random overlapping pairs", "[contact][exact][random]") {
  using Q = mpq_class;
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-0.8, 0.8);
  int compared = 0, same_axis = 0, same_manifold = 0;
  for (int iter = 0; iter < 120 && compared < 40; ++iter) {
    const auto a = random_shape(rng, iter);
    auto b = random_shape(rng, iter / 4 + 1);
    std::vector<Vec3<double>> vs;
    const Vec3<double> t(u(rng), u(rng), u(rng));
    for (const auto& v : b.vertices()) vs.push_back(v + t);
    b = b.with_vertices(vs);
    const auto sd = sat::gauss_map(a, b);
    if (!sd.overlap) continue;
    ++compared;
    INFO("iteration " << iter);
    const auto qa = ConvexPolyhedron<Q>::convert_from(a);
    const auto qb = ConvexPolyhedron<Q>::convert_from(b);
    const auto sq = sat::gauss_map(qa, qb);
    REQUIRE(sq.overlap);
    const auto md = contact_manifold(a, b, sd);
    const auto mq = contact_manifold(qa, qb, sq);
    check_exact_invariants(qa, qb, mq, false);
    check_resolves_exactly(qa, qb, mq);
    if (!(sd.feature == sq.feature)) continue;  // a float near-tie picked another axis
    ++same_axis;
    CHECK(md.kind == mq.kind);
    CHECK(md.reference_face == mq.reference_face);
    CHECK(md.incident_face == mq.incident_face);
    CHECK(md.candidate_points == mq.candidate_points);
    REQUIRE(md.size() == mq.size());
    // the deepest point is the same, with the same depth
    const double ext = std::max(a.extent(), b.extent());
    const auto diff = compare_manifolds(md, mq);
    CHECK(diff.same_kind);
    CHECK(diff.same_faces);
    CHECK(diff.same_deepest);
    CHECK(diff.deepest_depth_error <= 1e-12 * ext);
    CHECK(md.points[0].id == mq.points[0].id);
    CHECK(std::abs(to_double(md.points[0].separation) - to_double(mq.points[0].separation)) <= 1e-12 * ext);
    bool same = true;
    for (int i = 0; i < md.size(); ++i) same = same && md.points[i].id == mq.points[i].id;
    if (same) {
      ++same_manifold;
      for (int i = 0; i < md.size(); ++i) {
        CHECK(std::abs(to_double(md.points[i].separation) - to_double(mq.points[i].separation)) <=
              1e-12 * ext);
        CHECK((md.points[i].position - vec_to_double(mq.points[i].position)).norm() <= 1e-12 * ext);
      }
    } else {
      // The reductions may differ only where the float run saw a near-tie
      // (symmetric prisms and polygons): the kept areas agree.
      CHECK(spanned_area(md) == Approx(spanned_area(mq)).epsilon(1e-9));
    }
  }
  CHECK(compared >= 30);
  // Random rotations leave no exact ties between axes.
  CHECK(same_axis == compared);
  CHECK(same_manifold >= compared - 5);
}

TEMPLATE_TEST_CASE("exact: speculative margin, faces and edges", "[contact][exact][margin]", mpq_class,
                   CGAL::Epeck::FT) {
  using T = TestType;
  const auto a = shapes::cube<T>(1.0);
  // gap 1/16 between A's top face and B's bottom face
  const auto b = translated(shapes::cube<T>(0.5), Vec3<T>(T(0), T(0), q<T>(25, 16)));
  CHECK(contact_manifold(a, b).empty());
  ManifoldOptions opt;
  opt.margin = 0.125;
  auto m = contact_manifold(a, b, sat::gauss_map(a, b), opt);
  REQUIRE(m.size() == 4);
  for (const auto& p : m.points) {
    CHECK(p.separation.num > T(0));
    CHECK(p.separation.num * p.separation.num * T(256) == p.separation.norm2);
  }
  check_exact_invariants(a, b, m);
  opt.margin = 0.0625;  // exactly the gap: still in
  CHECK(contact_manifold(a, b, sat::gauss_map(a, b), opt).size() == 4);
  opt.margin = 0.0625 - 1.0 / 1024;
  CHECK(contact_manifold(a, b, sat::gauss_map(a, b), opt).empty());
  // crossed edges 1/8 apart
  const auto w = wedge<T>();
  const auto w2 = map_vertices(
      wedge<T>(), [&](const Vec3<T>& v) { return Vec3<T>(v[1] + q<T>(1, 4), v[0], q<T>(17, 8) - v[2]); });
  opt.margin = 0.25;
  const auto me = contact_manifold(w, w2, sat::gauss_map(w, w2), opt);
  REQUIRE(me.kind == ContactKind::Edge);
  REQUIRE(me.size() == 1);
  CHECK(me.points[0].separation.num * me.points[0].separation.num * T(64) == me.points[0].separation.norm2);
  CHECK(me.points[0].separation.num > T(0));
  CHECK(same(me.points[0].position, Vec3<T>(q<T>(1, 4), T(0), q<T>(17, 16))));
  check_exact_invariants(w, w2, me);
  // the resolving translation brings them exactly into touch
  check_resolves_exactly(w, w2, me);
}
