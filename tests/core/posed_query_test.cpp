// Posed queries on prepared shapes (prepared_shape.hpp), plain float and
// double: every posed SAT returns bit for bit what the same SAT returns on
// the pre-posed pair (A, posed(B, relative_pose(pose_a, pose_b))), axis
// mapped to world; margins and bad poses.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <span>

#include <catch2/catch.hpp>

#include <sepax/prepared_shape.hpp>

#include "core/posed_cases.hpp"

using namespace sepax;
using namespace sepax::test;

TEMPLATE_TEST_CASE("posed SATs equal the pre-posed SATs bit for bit (plain)", "[posed]", float, double) {
  using T = TestType;
  std::mt19937_64 rng(1801);
  const auto shapes = local_shapes<T>(rng);
  const int n = check_posed_against_reference<policy::Plain>(
      shapes, rng, 6, [](std::mt19937_64& g) { return random_pose<T>(g, 1.5); });
  CHECK(n == 7 * 7 * 6 * 3 * 3);
}

TEST_CASE("posed queries refuse non-rigid poses and bad margins", "[posed]") {
  const PreparedShape<double> a(shapes::cube<double>(1.0)), b(shapes::cube<double>(0.5));
  RigidTransform<double> scaled;
  scaled.rotation(0, 0) = 2.0;
  REQUIRE_THROWS_AS(sat::traversal(a, RigidTransform<double>{}, b, scaled), InvalidInput);
  RigidTransform<double> mirrored;
  mirrored.rotation(2, 2) = -1.0;
  REQUIRE_THROWS_AS(sat::traversal(a, RigidTransform<double>{}, b, mirrored), InvalidInput);
  SatOptions opt;
  opt.early_out = true;
  opt.margin = -1e-3;
  REQUIRE_THROWS_AS(sat::traversal(a, RigidTransform<double>{}, b, RigidTransform<double>{}, opt),
                    InvalidInput);
  opt.margin = std::numeric_limits<double>::infinity();
  REQUIRE_THROWS_AS(sat::gauss_map(a, RigidTransform<double>{}, b, RigidTransform<double>{}, opt),
                    InvalidInput);
}

TEST_CASE("a posed result is in world coordinates", "[posed]") {
  // B one unit above A along world z; A itself rotated a quarter turn about x
  // (its local y axis points along world z).
  const PreparedShape<double> a(shapes::cube<double>(0.5)), b(shapes::cube<double>(0.5));
  const auto pose_a = from_integer_quaternion<double>(1, 1, 0, 0, Vec3<double>(10, 0, 0));
  const auto pose_b = RigidTransform<double>::translation_by(Vec3<double>(10, 0, 1.25));
  const auto r = sat::traversal(a, pose_a, b, pose_b);
  REQUIRE_FALSE(r.overlap);
  CHECK(r.separation.num == Approx(0.25));
  CHECK(r.axis[0] == Approx(0).margin(1e-12));
  CHECK(r.axis[1] == Approx(0).margin(1e-12));
  CHECK(r.axis[2] == Approx(1));
}

// Posing builds B' in fused passes (ConvexPolyhedron::assign_rigid_vertices,
// finish_rigid_image) and computes normal_conditioning() with the planes;
// every derived array must still be bit for bit what with_vertices computes
// from the same vertices (transformed(B, X)), lane padding and the lazily
// computed conditioning included, also when the per-thread scratch last held
// another shape (require_same_derived, posed_cases.hpp).  The posed
// traversal, brute force and manifold pose B without its edge lane arrays
// (only sat::gauss_map reads them): in passes 1 and 2 everything else,
// lanes_bounded() included, must be bit for bit the same without them, and a
// later request with them must complete the full image (pass 1: after a
// check's partial image at the same pose).
TEMPLATE_TEST_CASE("a shape too small for where it is placed in T is refused, posed or not", "[posed]", float,
                   double) {
  using T = TestType;
  // A unit cube 2^27 (float) or 2^57 (double) from the origin: there T's spacing is 16 or 32, every x
  // coordinate rounds to one value and every y coordinate to another, so the side faces' plane
  // triples are collinear.  Nearer (2^10), the same pose gives a separated pair.
  const double far = std::is_same_v<T, float> ? 0x1p27 : 0x1p57;
  const PreparedShape<T> a(shapes::cube<T>(1.0)), b(shapes::cube<T>(1.0));
  auto refused = [](auto&& call) {
    try {
      call();
    } catch (const InvalidInput& e) {
      CHECK(e.code() == ErrorCode::BadScale);
      CHECK_THAT(e.what(), Catch::Contains("has no plane at these coordinates"));
      return true;
    }
    return false;
  };
  for (const double d : {far, -far}) {
    INFO("d = " << d);
    const auto pose = RigidTransform<T>::translation_by(Vec3<T>(T(d), T(-d), T(0)));
    CHECK(refused([&] { (void)sat::traversal(a, RigidTransform<T>{}, b, pose); }));
    CHECK(refused([&] { (void)sat::brute_force(a, RigidTransform<T>{}, b, pose); }));
    std::vector<Vec3<T>> moved;
    for (const auto& v : b.polyhedron().vertices()) moved.push_back(Vec3<T>(v + Vec3<T>(T(d), T(-d), T(0))));
    CHECK(refused([&] { (void)b.polyhedron().with_vertices(moved); }));
  }
  const auto near = RigidTransform<T>::translation_by(Vec3<T>(T(1024), T(-1024), T(0)));
  CHECK_FALSE(sat::traversal(a, RigidTransform<T>{}, b, near).overlap);
}

TEMPLATE_TEST_CASE("posing derives bit for bit what with_vertices derives", "[posed]", float, double) {
  using T = TestType;
  std::mt19937_64 rng(1802);
  const auto locals = local_shapes<T>(rng);
  std::vector<PreparedShape<T>> prepared;
  for (const auto& s : locals) prepared.emplace_back(s);
  int checked = 0;
  for (int pass = 0; pass < 3; ++pass) {
    // alternate shapes, so the scratch changes topology, grows and shrinks
    for (std::size_t i = 0; i < prepared.size(); ++i) {
      const auto x = random_pose<T>(rng, 2.0);
      const ConvexPolyhedron<T> reference = transformed(locals[i], x);
      if (pass == 1) {
        const int f = 0;
        const ConvexPolyhedron<T>& part =
            prepared[i].posed_part_scratch(x, std::span<const int>(&f, 1), std::span<const int>());
        // a partial image: its edge lanes are stale, its vertex lanes and face 0's plane are not
        CHECK_FALSE(part.lanes_bounded());
        CHECK(part.support_lanes_bounded() == reference.lanes_bounded());
      }
      if (pass > 0) require_same_derived(prepared[i].posed_scratch(x, false), reference, false);
      require_same_derived(prepared[i].posed_scratch(x), reference);
      // B' refers to B's topology (shared, not copied into the scratch)
      CHECK(prepared[i].posed_scratch(x).half_edges().data() == prepared[i].polyhedron().half_edges().data());
      if (pass > 0) require_same_derived(prepared[i].posed_scratch(x, false), reference);  // kept
      require_same_derived(posed(locals[i], x), reference);
      ++checked;
    }
  }
  CHECK(checked == 3 * int(locals.size()));
}

// relative_pose spells out pose_a.inverse() * pose_b (float: in SIMD
// lanes): the same value, bit for bit, for poses near and far from the
// origin and for zeros of either sign.
template <class T>
void same_bits(const RigidTransform<T>& x, const RigidTransform<T>& y) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) REQUIRE(std::memcmp(&x.rotation(r, c), &y.rotation(r, c), sizeof(T)) == 0);
    REQUIRE(std::memcmp(&x.translation[r], &y.translation[r], sizeof(T)) == 0);
  }
}

TEMPLATE_TEST_CASE("relative_pose is pose_a.inverse() * pose_b bit for bit", "[posed]", float, double) {
  using T = TestType;
  std::mt19937_64 rng(4111);
  for (int i = 0; i < 500; ++i) {
    const double reach = i % 2 ? 1.0 : 1e4;
    const RigidTransform<T> pa = random_pose<T>(rng, reach), pb = random_pose<T>(rng, reach);
    same_bits(relative_pose(pa, pb), pa.inverse() * pb);
  }
  // zeros of both signs in the translations and rotations (the sign of a
  // zero sum depends on the order and on how the negation is taken)
  int zeros = 0;
  for (int k = 0; k < 64; ++k) {
    RigidTransform<T> pa = RigidTransform<T>::identity(), pb = RigidTransform<T>::identity();
    for (int i = 0; i < 3; ++i) {
      pa.translation[i] = (k >> i) & 1 ? T(-0.0) : T(0.0);
      pb.translation[i] = (k >> (i + 3)) & 1 ? T(-0.0) : T(0.0);
    }
    if (k & 8) pb.rotation(0, 1) = T(-0.0);
    const RigidTransform<T> x = relative_pose(pa, pb);
    same_bits(x, pa.inverse() * pb);
    for (int i = 0; i < 3; ++i) zeros += std::signbit(x.translation[i]) ? 1 : 0;
  }
  CHECK(zeros > 0);  // some translation is -0: the case is exercised
}

// Posing maps B's vertices a few at a time (SIMD lanes) and folds the lanes
// bounds; a bound that is zero must keep the sign of the first zero in vertex
// order, as the sequential scan of with_vertices keeps it.  Boxes with x in
// {0, 1}, zeros of both signs (a vertex (-0, -1, -1) stays -0 under the
// identity with translation -0; the others become +0) and vertex orders
// shuffled, posed by the identity with translation (-0, -0, -0): bounds and
// everything else bit for bit transformed(B, X).
TEMPLATE_TEST_CASE("posing keeps the sign of a zero bound in vertex order", "[posed]", float, double) {
  using T = TestType;
  const ConvexPolyhedron<T> unit = shapes::box<T>(0.5, 1.0, 1.0);
  RigidTransform<T> x = RigidTransform<T>::identity();
  x.translation = Vec3<T>(T(-0.0), T(-0.0), T(-0.0));
  std::mt19937_64 rng(2059);
  int negative_zero_bounds = 0, positive_zero_bounds = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<int> order(static_cast<std::size_t>(unit.vertex_count()));
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<int> new_index(order.size());
    std::vector<Vec3<T>> v;
    for (std::size_t i = 0; i < order.size(); ++i) {
      new_index[static_cast<std::size_t>(order[i])] = static_cast<int>(i);
      Vec3<T> p = unit.vertex(order[i]);
      p[0] = p[0] > T(0) ? T(1) : (rng() % 2 ? T(-0.0) : T(0.0));
      v.push_back(p);
    }
    std::vector<std::vector<int>> faces;
    for (int f = 0; f < unit.face_count(); ++f) {
      std::vector<int> loop;
      for (const int i : unit.face_vertices(f)) loop.push_back(new_index[static_cast<std::size_t>(i)]);
      faces.push_back(loop);
    }
    const ConvexPolyhedron<T> b = ConvexPolyhedron<T>::from_faces(v, faces);
    const PreparedShape<T> pb(b);
    const ConvexPolyhedron<T> reference = transformed(b, x);
    require_same_derived(pb.posed_scratch(x), reference);
    require_same_derived(posed(b, x), reference);
    (std::signbit(reference.bounds_min()[0]) ? negative_zero_bounds : positive_zero_bounds)++;
  }
  CHECK(negative_zero_bounds > 0);  // both signs were met
  CHECK(positive_zero_bounds > 0);
}

// Posing checks B's image as with_vertices checks new vertices: a pose that
// puts a coordinate out of T's range or makes it NaN is refused with the
// same error code (BadScale, NonFinite) by the fused pass over the vertices,
// and the scratch is usable afterwards.
TEMPLATE_TEST_CASE("posing refuses an image out of range like with_vertices", "[posed]", float, double) {
  using T = TestType;
  const ConvexPolyhedron<T> box = shapes::box<T>(0.5, 0.25, 1.0);
  const PreparedShape<T> b(box);
  auto code_of = [](auto&& f) {
    try {
      f();
    } catch (const InvalidInput& e) {
      return e.code();
    }
    FAIL("no InvalidInput");
    return ErrorCode::BadScale;
  };
  const T big = std::numeric_limits<T>::max() / 4;
  const T inf = std::numeric_limits<T>::infinity();
  const T nan = std::numeric_limits<T>::quiet_NaN();
  for (const T t : {big, T(-big), inf, nan}) {
    RigidTransform<T> x;
    x.translation = Vec3<T>(T(0), t, T(0));
    const ErrorCode expected = code_of([&] { (void)transformed(box, x); });
    CHECK(expected == (t == big || t == -big ? ErrorCode::BadScale : ErrorCode::NonFinite));
    CHECK(code_of([&] { (void)b.posed_scratch(x); }) == expected);
    CHECK(code_of([&] { (void)b.posed_scratch(x, false); }) == expected);
    CHECK(code_of([&] { (void)posed(box, x); }) == expected);
    const RigidTransform<T> ok;
    require_same_derived(b.posed_scratch(ok), transformed(box, ok));
  }
}
