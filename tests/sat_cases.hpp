// tests/sat_cases.hpp
//
// Configurations with hand-checked SAT answers, shared by the float/double
// tests (tests/core) and the exact-type tests (tests/exact), plus the pose
// helpers both use.  Every case is built from the same integer/dyadic/rational
// data for every T, so the exact tests check the answers exactly and the float
// tests check them to rounding (exactly, for the cases whose coordinates are
// dyadic, where float arithmetic makes no rounding error at all).
//
// How each expected answer was derived is written next to the case.
#pragma once

#include <catch2/catch.hpp>

#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/shapes.hpp>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace sepax::test {

template <class T>
using Mat3 = std::array<T, 9>;  // row major

template <class T>
Vec3<T> apply(const Mat3<T>& r, const Vec3<T>& v) {
  return Vec3<T>(T(T(r[0] * v[0] + r[1] * v[1]) + r[2] * v[2]), T(T(r[3] * v[0] + r[4] * v[1]) + r[5] * v[2]),
                 T(T(r[6] * v[0] + r[7] * v[1]) + r[8] * v[2]));
}

/// R v + t for every vertex (same topology; the caller guarantees R is a rotation).
template <class T>
ConvexPolyhedron<T> posed(const ConvexPolyhedron<T>& p, const Mat3<T>& r, const Vec3<T>& t) {
  std::vector<Vec3<T>> vs;
  for (const auto& v : p.vertices()) vs.push_back(Vec3<T>(apply(r, v) + t));
  return p.with_vertices(std::move(vs));
}

template <class T>
ConvexPolyhedron<T> translated(const ConvexPolyhedron<T>& p, const Vec3<T>& t) {
  std::vector<Vec3<T>> vs;
  for (const auto& v : p.vertices()) vs.push_back(Vec3<T>(v + t));
  return p.with_vertices(std::move(vs));
}

/// s * v + t for every vertex.
template <class T>
ConvexPolyhedron<T> scaled(const ConvexPolyhedron<T>& p, const T& s, const Vec3<T>& t) {
  std::vector<Vec3<T>> vs;
  for (const auto& v : p.vertices()) vs.push_back(Vec3<T>(Vec3<T>(v[0] * s, v[1] * s, v[2] * s) + t));
  return p.with_vertices(std::move(vs));
}

template <class T>
Mat3<T> identity() {
  return {T(1), T(0), T(0), T(0), T(1), T(0), T(0), T(0), T(1)};
}

/// Rotation about x / y by the angle with cosine c and sine s.
template <class T>
Mat3<T> rot_x(const T& c, const T& s) {
  return {T(1), T(0), T(0), T(0), c, T(-s), T(0), s, c};
}
template <class T>
Mat3<T> rot_y(const T& c, const T& s) {
  return {c, T(0), s, T(0), T(1), T(0), T(-s), T(0), c};
}

/// The rotation of the integer quaternion (w, x, y, z), not all zero: its
/// entries are rationals, so it is an exact rotation for exact T.
template <class T>
Mat3<T> quaternion_rotation(int w, int x, int y, int z) {
  const T W = from_double<T>(w), X = from_double<T>(x), Y = from_double<T>(y), Z = from_double<T>(z);
  const T n = W * W + X * X + Y * Y + Z * Z;
  const T two(2);
  return {T((W * W + X * X - Y * Y - Z * Z) / n), T(two * (X * Y - W * Z) / n),
          T(two * (X * Z + W * Y) / n),           T(two * (X * Y + W * Z) / n),
          T((W * W - X * X + Y * Y - Z * Z) / n), T(two * (Y * Z - W * X) / n),
          T(two * (X * Z - W * Y) / n),           T(two * (Y * Z + W * X) / n),
          T((W * W - X * X - Y * Y + Z * Z) / n)};
}

template <class T>
Vec3<T> v3(double x, double y, double z) {
  return vec_from_double<T>(Vec3<double>(x, y, z));
}

/// The undirected edge of p joining vertices u and v (-1 if none).
template <class T>
int edge_between(const ConvexPolyhedron<T>& p, int u, int v) {
  for (int e = 0; e < p.edge_count(); ++e) {
    if ((p.edge_tail(e) == u && p.edge_head(e) == v) || (p.edge_tail(e) == v && p.edge_head(e) == u))
      return e;
  }
  return -1;
}

/// Vertices of p whose projection on dir is maximal (exactly for exact T;
/// within 1e-4 of the extent for float T).
template <class T>
std::vector<int> extreme_vertices(const ConvexPolyhedron<T>& p, const Vec3<T>& dir) {
  T best = dot(dir, p.vertex(0));
  for (int i = 1; i < p.vertex_count(); ++i)
    if (dot(dir, p.vertex(i)) > best) best = dot(dir, p.vertex(i));
  T tol(0);
  if constexpr (!number_traits<T>::is_exact) tol = static_cast<T>(1e-4 * p.extent());
  std::vector<int> out;
  for (int i = 0; i < p.vertex_count(); ++i)
    if (dot(dir, p.vertex(i)) >= best - tol) out.push_back(i);
  return out;
}

/// One configuration and its hand-checked answer.
template <class T>
struct SatCase {
  std::string name;
  ConvexPolyhedron<T> a, b;
  Feature feature;           // expected feature (type, index, support feature)
  Separation<T> separation;  // expected separation num / sqrt(norm2), exact
  bool overlap = false;
  Vec3<double> axis;    // expected axis direction (from A to B, any length)
  bool dyadic = false;  // every float operation on this case is exact
  /// Expected separation as a double.
  double value() const { return to_double(separation.num) / std::sqrt(to_double(separation.norm2)); }
};

template <class T>
Separation<T> sep_value(const T& v) {
  return Separation<T>{v, T(1)};
}

/// All the hand-checked cases (A, B in one frame).
template <class T>
std::vector<SatCase<T>> known_cases() {
  std::vector<SatCase<T>> cs;
  const T q = T(1) / T(4);  // a depth of 1/4 (dyadic)
  const auto cube = shapes::cube<T>(1.0);
  const auto up = [](const T& z) { return Vec3<T>(T(0), T(0), z); };

  // --- Box resting on box.  cube(1) vertices: 0(-,-,-) 1(+,-,-) 2(+,+,-) 3(-,+,-),
  // 4..7 the same at z=+1; faces 0:-z 1:+z 2:-y 3:+y 4:-x 5:+x.  B = A + (0,0,2-d).
  // A's top (face 1) and B's bottom (face 0) both separate by -d: the tie goes to
  // FaceA.  Every vertex of B's bottom (0..3) is deepest: the lowest index, 0.
  // The crossing top/bottom edge pairs also give -d along z: FaceA still wins.
  for (double d : {0.25, 0.0, -0.5}) {
    SatCase<T> c;
    c.name = "box on box, depth " + std::to_string(d);
    c.a = cube;
    c.b = translated(cube, up(T(2) - from_double<T>(d)));
    c.feature = Feature::face_a(1, 0);
    c.separation = sep_value(T(-from_double<T>(d)));
    c.overlap = d >= 0;
    c.axis = {0, 0, 1};
    c.dyadic = true;
    cs.push_back(c);
  }

  // --- Crossed edges of two regular tetrahedra.  tetrahedron(1) has a top edge
  // v0(1,1,1)-v3(-1,-1,1) along (1,1,0) and a bottom edge v1(1,-1,-1)-v2(-1,1,-1)
  // along (1,-1,0).  B = A + (0,0,2-d): B's bottom edge crosses A's top edge at
  // depth d along z.  Best face axis: (-2-d)/sqrt(3) < -d for d > -1.
  for (double d : {0.25, 0.0, -0.5}) {
    SatCase<T> c;
    c.name = "crossed tetrahedra, depth " + std::to_string(d);
    c.a = shapes::tetrahedron<T>(1.0);
    c.b = translated(c.a, up(T(2) - from_double<T>(d)));
    c.feature = Feature::edges(edge_between(c.a, 0, 3), edge_between(c.b, 1, 2));
    c.separation = sep_value(T(-from_double<T>(d)));
    c.overlap = d >= 0;
    c.axis = {0, 0, 1};
    c.dyadic = true;
    cs.push_back(c);
  }

  // --- Crossed edges of two boxes.  A = cube rotated about y by (3/5, 4/5): its
  // top is the edge along y at z = 7/5.  B = cube rotated about x by (3/5, 4/5),
  // bottom edge along x at z = -7/5, lifted by 14/5 - 1/4: depth 1/4 along z.
  // Best face axis (A's (-3/5,0,4/5)): -1.72 + 0.8*2.55 - 1 = -0.68 < -1/4.
  {
    SatCase<T> c;
    c.name = "crossed boxes (Pythagorean rotations)";
    const T c35 = T(3) / T(5), s45 = T(4) / T(5);
    c.a = posed(cube, rot_y(c35, s45), up(T(0)));
    c.b = posed(cube, rot_x(c35, s45), up(T(T(14) / T(5)) - q));
    const auto top = extreme_vertices(c.a, up(T(1)));
    const auto bottom = extreme_vertices(c.b, up(T(-1)));
    if (top.size() == 2 && bottom.size() == 2)
      c.feature = Feature::edges(edge_between(c.a, top[0], top[1]), edge_between(c.b, bottom[0], bottom[1]));
    c.separation = sep_value(T(-q));
    c.overlap = true;
    c.axis = {0, 0, 1};
    cs.push_back(c);
  }

  // --- A vertex of a rotated cube into the top face of a flat box.  A =
  // box(4,4,1) (top face 1 at z=1); B = cube rotated by the quaternion
  // (1,2,3,4), lowered so its lowest vertex (unique: generic rotation) is 1/4
  // below z=1.  B's faces and all edge pairs are far more negative: A is 8 wide.
  {
    SatCase<T> c;
    c.name = "vertex of a rotated box into a face";
    c.a = shapes::box<T>(4, 4, 1);
    const auto r = posed(cube, quaternion_rotation<T>(1, 2, 3, 4), up(T(0)));
    const auto low = extreme_vertices(r, up(T(-1)));
    const T zmin = r.vertex(low[0])[2];
    c.b = translated(r, up(T(T(1) - q) - zmin));
    c.feature = Feature::face_a(1, low.size() == 1 ? low[0] : -1);
    c.separation = sep_value(T(-q));
    c.overlap = true;
    c.axis = {0, 0, 1};
    cs.push_back(c);
    // The same with A and B swapped: B's top face against A's lowest vertex.
    SatCase<T> s;
    s.name = "vertex of a rotated box into a face (swapped: FaceB)";
    s.a = c.b;
    s.b = c.a;
    s.feature = Feature::face_b(c.feature.b, 1);
    s.separation = c.separation;
    s.overlap = true;
    s.axis = {0, 0, -1};
    cs.push_back(s);
  }

  // --- Box inside a bigger box, concentric: every face axis of A and of B and
  // every crossing edge pair separates by -1.5: the tie goes to A's lowest face
  // (face 0, normal -z), whose support on B (deepest along +z) is B's vertices
  // 4..7: the lowest index, 4.
  {
    SatCase<T> c;
    c.name = "concentric boxes: all-way tie";
    c.a = cube;
    c.b = shapes::cube<T>(0.5);
    c.feature = Feature::face_a(0, 4);
    c.separation = sep_value(T(T(-3) / T(2)));
    c.overlap = true;
    c.axis = {0, 0, -1};
    c.dyadic = true;
    cs.push_back(c);
  }

  // --- Double-sided triangles against cube(1).  Triangle edges: e0 = v0-v1,
  // e1 = v1-v2, e2 = v2-v0; face 0 has normal (v1-v0) x (v2-v0).
  for (double z : {1.0, -1.0}) {
    // Lying on the top (bottom) face: coplanar with it.  A's face and the
    // triangle's face towards A both give 0: FaceA wins; every triangle vertex
    // is deepest: vertex 0.
    SatCase<T> c;
    c.name = "triangle lying on a box face z=" + std::to_string(z);
    c.a = cube;
    c.b = shapes::triangle<T>(v3<T>(-0.5, -0.5, z), v3<T>(0.5, -0.5, z), v3<T>(0, 0.5, z));
    c.feature = Feature::face_a(z > 0 ? 1 : 0, 0);
    c.separation = sep_value(T(0));
    c.overlap = true;
    c.axis = {0, 0, z};
    c.dyadic = true;
    cs.push_back(c);
  }
  {
    // In the plane of the top face but beside the box: the +x face (5)
    // separates by 1/2; the triangle's vertices 0 and 2 are both at x = 3/2.
    SatCase<T> c;
    c.name = "triangle coplanar with a face, beside the box";
    c.a = cube;
    c.b = shapes::triangle<T>(v3<T>(1.5, -0.5, 1), v3<T>(3, 0, 1), v3<T>(1.5, 0.5, 1));
    c.feature = Feature::face_a(5, 0);
    c.separation = sep_value(T(T(1) / T(2)));
    c.overlap = false;
    c.axis = {1, 0, 0};
    c.dyadic = true;
    cs.push_back(c);
  }
  {
    // Crossing the box edge 6-7 (y=1, z=1, along x): the triangle in the plane
    // x = 1/4 has its edge v0-v1 on y + z = 7/4.  Axis (1,0,0) x (0,1,-1) ~
    // (0,1,1): the box reaches y+z = 2 there, so the separation is
    // (7/4 - 2)/sqrt(2) = -1/sqrt(32).  Best face axes: -3/4.
    SatCase<T> c;
    c.name = "triangle crossing a box edge";
    c.a = cube;
    c.b = shapes::triangle<T>(v3<T>(0.25, 0.25, 1.5), v3<T>(0.25, 1.5, 0.25), v3<T>(0.25, 1.5, 1.5));
    c.feature = Feature::edges(edge_between(c.a, 6, 7), 0);
    c.separation = Separation<T>{T(-1), T(32)};
    c.overlap = true;
    c.axis = {0, 1, 1};
    cs.push_back(c);
  }
  {
    // Piercing the top face: the triangle's base (z = 3/4) is 1/4 inside, its
    // apex far above.  Face 1 of A gives -1/4 with support vertex 0; the pair
    // (A's top edges along y) x (base edge) ties along z at -1/4: FaceA first.
    SatCase<T> c;
    c.name = "triangle piercing a box face";
    c.a = cube;
    c.b = shapes::triangle<T>(v3<T>(-0.5, 0, 0.75), v3<T>(0.5, 0, 0.75), v3<T>(0, 0, 2));
    c.feature = Feature::face_a(1, 0);
    c.separation = sep_value(T(-q));
    c.overlap = true;
    c.axis = {0, 0, 1};
    c.dyadic = true;
    cs.push_back(c);
    // Swapped: the box's top face (FaceB) ties with the edge pairs: FaceB first.
    SatCase<T> s;
    s.name = "triangle piercing a box face (swapped: FaceB before edges)";
    s.a = c.b;
    s.b = c.a;
    s.feature = Feature::face_b(0, 1);
    s.separation = c.separation;
    s.overlap = true;
    s.axis = {0, 0, -1};
    s.dyadic = true;
    cs.push_back(s);
  }

  // --- Triangle against triangle.  T1 = (-2,-2,0) (2,-2,0) (0,2,0), face 0 = +z.
  const auto t1 = shapes::triangle<T>(v3<T>(-2, -2, 0), v3<T>(2, -2, 0), v3<T>(0, 2, 0));
  {
    // Crossing: T2 in the plane x = 0 dips 1/4 below T1 with its vertex 0.  The
    // best edge pair is -2 (T1's edge v1-v2 x T2's top edge), T2's faces -2.
    SatCase<T> c;
    c.name = "triangles crossing";
    c.a = t1;
    c.b = shapes::triangle<T>(v3<T>(0, 0, -0.25), v3<T>(0, 1, 2), v3<T>(0, -1, 2));
    c.feature = Feature::face_a(0, 0);
    c.separation = sep_value(T(-q));
    c.overlap = true;
    c.axis = {0, 0, 1};
    c.dyadic = true;
    cs.push_back(c);
  }
  {
    // Coplanar and overlapping: every axis through the common plane gives 0.
    SatCase<T> c;
    c.name = "triangles coplanar, overlapping";
    c.a = t1;
    c.b = translated(t1, v3<T>(0.5, 0.5, 0));
    c.feature = Feature::face_a(0, 0);
    c.separation = sep_value(T(0));
    c.overlap = true;
    c.axis = {0, 0, 1};
    c.dyadic = true;
    cs.push_back(c);
  }
  {
    // Parallel planes, 1/2 apart: T1's face 0 (+z) and T2's face 1 (-z) tie.
    SatCase<T> c;
    c.name = "triangles in parallel planes";
    c.a = t1;
    c.b = translated(t1, v3<T>(0.5, 0.5, 0.5));
    c.feature = Feature::face_a(0, 0);
    c.separation = sep_value(T(T(1) / T(2)));
    c.overlap = false;
    c.axis = {0, 0, 1};
    c.dyadic = true;
    cs.push_back(c);
  }
  // Coplanar polygons (best_axis.hpp, scan_side_axes): every face and edge-pair
  // axis is +-z with separation 0, so only the in-plane side axes can separate.
  const auto right = shapes::triangle<T>(v3<T>(0, 0, 0), v3<T>(2, 0, 0), v3<T>(0, 2, 0));
  {
    // B = the right triangle moved by 3 along x: a gap of 1 in the plane.
    // Side axes: B's left edge x = 3 (outward normal -x) has A's vertex 1
    // (2,0,0) lowest along +x: separation 3 - 2 = 1.  A's hypotenuse
    // (normal (1,1)/sqrt 2) gives 1/sqrt 2 (B's vertex (3,0)); every other side
    // axis is negative.  So SideB(1, left edge of B), axis +x from A to B.
    SatCase<T> c;
    c.name = "triangles coplanar, gap in the plane";
    c.a = right;
    c.b = translated(right, v3<T>(3, 0, 0));
    c.feature = Feature::side_b(1, edge_between(c.b, 0, 2));
    c.separation = sep_value(T(1));
    c.overlap = false;
    c.axis = {1, 0, 0};
    c.dyadic = true;
    cs.push_back(c);
  }
  {
    // Squares [0,2]^2 and [3,5] x [0,2]: A's right edge x = 2 (normal +x) and
    // B's left edge x = 3 (normal -x) both give exactly 1 (a tie, exact in
    // float too): SideA wins, with B's lowest vertex along +x the lower index
    // of its two vertices at x = 3: vertex 0.
    SatCase<T> c;
    c.name = "squares coplanar, facing edges";
    c.a = ConvexPolyhedron<T>::polygon({v3<T>(0, 0, 0), v3<T>(2, 0, 0), v3<T>(2, 2, 0), v3<T>(0, 2, 0)});
    c.b = ConvexPolyhedron<T>::polygon({v3<T>(3, 0, 0), v3<T>(5, 0, 0), v3<T>(5, 2, 0), v3<T>(3, 2, 0)});
    c.feature = Feature::side_a(edge_between(c.a, 1, 2), 0);
    c.separation = sep_value(T(1));
    c.overlap = false;
    c.axis = {1, 0, 0};
    c.dyadic = true;
    cs.push_back(c);
  }
  {
    // Touching in the plane at the point (2, 0): B's vertex 0 on A's vertex 1.
    // The best side axes give exactly 0 and the face axes 0 too: FaceA(0)
    // wins the tie, with B's lowest vertex along -n (all at 0): vertex 0.
    SatCase<T> c;
    c.name = "triangles coplanar, touching at a vertex";
    c.a = right;
    c.b = translated(right, v3<T>(2, 0, 0));
    c.feature = Feature::face_a(0, 0);
    c.separation = sep_value(T(0));
    c.overlap = true;
    c.axis = {0, 0, 1};
    c.dyadic = true;
    cs.push_back(c);
  }
  return cs;
}

/// Coplanar triangles with a gap between them in their common plane.  The
/// shapes are disjoint, but A - B is flat: its 3D face normals are the plane
/// normal (separation 0), and only the side axes (best_axis.hpp) separate them.
template <class T>
SatCase<T> coplanar_separated_triangles() {
  SatCase<T> c;
  c.name = "triangles coplanar, separated in the plane";
  c.a = shapes::triangle<T>(v3<T>(-2, -2, 0), v3<T>(2, -2, 0), v3<T>(0, 2, 0));
  c.b = translated(c.a, v3<T>(10, 0, 0));
  c.overlap = false;
  return c;
}

/// Random poses for the oracle tests: a rotation from a small random integer
/// quaternion (exact rational matrix) and a translation in multiples of 1/8.
struct RandomPose {
  int w, x, y, z;
  int tx, ty, tz;
};

inline RandomPose random_pose(std::mt19937& rng, int trange) {
  std::uniform_int_distribution<int> qd(-6, 6), td(-trange, trange);
  RandomPose p{};
  do {
    p.w = qd(rng);
    p.x = qd(rng);
    p.y = qd(rng);
    p.z = qd(rng);
  } while (p.w == 0 && p.x == 0 && p.y == 0 && p.z == 0);
  p.tx = td(rng);
  p.ty = td(rng);
  p.tz = td(rng);
  return p;
}

template <class T>
ConvexPolyhedron<T> apply_pose(const ConvexPolyhedron<T>& p, const RandomPose& r) {
  const T e(8);
  return posed(
      p, quaternion_rotation<T>(r.w, r.x, r.y, r.z),
      Vec3<T>(T(from_double<T>(r.tx) / e), T(from_double<T>(r.ty) / e), T(from_double<T>(r.tz) / e)));
}

/// The shape zoo of the random tests.
template <class T>
std::vector<ConvexPolyhedron<T>> zoo() {
  return {shapes::box<T>(1, 0.5, 0.75),
          shapes::tetrahedron<T>(0.75),
          shapes::prism<T>(6, 1.0, 0.5),
          shapes::prism<T>(3, 0.75, 1.0),
          shapes::regular_polygon<T>(5, 1.0),
          shapes::triangle<T>(v3<T>(0, 0, 0), v3<T>(1.5, 0, 0), v3<T>(0, 1, 0.25)),
          shapes::cube<T>(0.5)};
}

/// Check a SAT result against a hand-checked case: feature (type, index and
/// support feature), verdict, separation (exactly for exact T and for dyadic
/// cases in float; to rounding otherwise) and axis direction.
template <class T>
void check_known(const SatCase<T>& c, const SatResult<T>& r) {
  INFO(c.name << " [" << number_traits<T>::name << "]: got " << to_string(r.feature) << " sep "
              << r.separation_as_double() << ", expected " << to_string(c.feature) << " sep " << c.value());
  CHECK(r.overlap == c.overlap);
  CHECK(r.feature == c.feature);
  CHECK(sign(r.separation) == sign_of(c.separation.num));
  if constexpr (number_traits<T>::is_exact && number_traits<T>::normalizes) {
    // exact sqrt (CORE::Expr): the separation itself, norm2 == 1
    CHECK(r.separation.norm2 == T(1));
    CHECK(r.separation.num == T(c.separation.num / number_traits<T>::sqrt(c.separation.norm2)));
  } else if constexpr (number_traits<T>::is_exact) {
    CHECK(compare(r.separation, c.separation) == 0);
  } else if (c.dyadic) {
    CHECK(r.separation_as_double() == c.value());
  } else {
    const double eps = 64 * number_traits<T>::unit_roundoff * (c.a.extent() + c.b.extent());
    CHECK(r.separation_as_double() == Approx(c.value()).margin(eps));
  }
  const Vec3<double> ax = vec_to_double(r.axis);
  REQUIRE(ax.norm() > 0);
  CHECK(ax.normalized().dot(c.axis.normalized()) == Approx(1.0).margin(1e-5));
  if constexpr (number_traits<T>::normalizes) CHECK(ax.norm() == Approx(1.0).margin(1e-5));
}

}  // namespace sepax::test
