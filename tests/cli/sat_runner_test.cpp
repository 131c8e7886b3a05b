// Tests for src/commands/sat_runner.cpp (and the shape_builder.hpp it uses):
// the run-time choice of number type, algorithm and policy.  Oracles: every
// algorithm agrees with the brute force; double agrees with exact arithmetic
// away from touching; the robust policy decides exactly what exact arithmetic
// decides on the same (double) inputs.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include <sepax/error.hpp>
#include <sepax/robust/number_types.hpp>

#include "commands/sat_runner.hpp"
#include "commands/shape_builder.hpp"
#include "io/off_reader.hpp"
#include "io/shape_source.hpp"

using namespace sepax;
using namespace sepax::cli;

namespace {

const char* kShapes[] = {"cube", "tetra", "prism:5", "polygon:6", "triangle", "box:0.5,1,2", "prism:12"};

Pose random_pose(std::mt19937& rng, double reach) {
  std::uniform_real_distribution<double> u(-reach, reach);
  std::normal_distribution<double> g;
  return Pose::make(Vec3<double>(u(rng), u(rng), u(rng)), {g(rng), g(rng), g(rng), g(rng)});
}

RunConfig config(NumberKind n, AlgorithmKind a, bool robust = false) {
  RunConfig c;
  c.number = n;
  c.algorithm = a;
  c.robust = robust;
  return c;
}

}  // namespace

TEST_CASE("sat runner: option names", "[runner]") {
  CHECK(parse_number_kind("float") == NumberKind::Float);
  CHECK(parse_number_kind("exact") == NumberKind::Exact);
  CHECK_FALSE(parse_number_kind("mpq"));
  CHECK(parse_algorithm_kind("brute") == AlgorithmKind::Brute);
  CHECK(parse_algorithm_kind("traversal") == AlgorithmKind::Traversal);
  CHECK_FALSE(parse_algorithm_kind("Gauss"));
  for (auto k : {NumberKind::Float, NumberKind::Double, NumberKind::Exact})
    CHECK(parse_number_kind(name(k)) == k);
  for (auto k : {AlgorithmKind::Brute, AlgorithmKind::Gauss, AlgorithmKind::Traversal}) {
    CHECK(parse_algorithm_kind(name(k)) == k);
  }
}

TEST_CASE("sat runner: configurations this build cannot run are refused with a reason", "[runner]") {
  const auto cube = io::builtin_shape("cube");
  CHECK_THAT(unsupported_reason(config(NumberKind::Exact, AlgorithmKind::Gauss, true)),
             Catch::Contains("--robust"));
  CHECK_THROWS_AS(run_sat(cube, cube, nullptr, config(NumberKind::Exact, AlgorithmKind::Gauss, true)),
                  std::invalid_argument);
  CHECK(unsupported_reason(config(NumberKind::Double, AlgorithmKind::Traversal)).empty() ==
        traversal_available());
  CHECK(unsupported_reason(config(NumberKind::Float, AlgorithmKind::Gauss, true)).empty() ==
        robust_available());
  CHECK(unsupported_reason(config(NumberKind::Double, AlgorithmKind::Brute)).empty());
}

TEST_CASE("sat runner: two unit cubes offset by t along x are separated by exactly t - 2", "[runner]") {
  const auto cube = io::builtin_shape("cube");
  for (const double t : {2.5, 3.0, 2.125, 1.5, 0.75, -2.25}) {
    for (auto n : {NumberKind::Float, NumberKind::Double, NumberKind::Exact}) {
      for (auto a : {AlgorithmKind::Brute, AlgorithmKind::Gauss}) {
        INFO("t = " << t << ", " << name(n) << ", " << name(a));
        const Pose p = Pose::make(Vec3<double>(t, 0, 0));
        const RunOutcome r = run_sat(cube, cube, &p, config(n, a));
        CHECK(r.separation == std::abs(t) - 2);
        CHECK(r.overlap == (std::abs(t) - 2 <= 0));
        CHECK(std::abs(r.normal[0]) == 1);
        CHECK(r.normal[0] * t > 0);  // from A towards B
        CHECK(r.a.vertices == 8);
        CHECK(r.b.faces == 6);
      }
    }
  }
}

TEST_CASE("sat runner: every algorithm agrees with the brute force, in every number type", "[runner]") {
  std::mt19937 rng(2024);
  std::vector<AlgorithmKind> algs{AlgorithmKind::Gauss};
  if (traversal_available()) algs.push_back(AlgorithmKind::Traversal);
  int compared = 0;
  for (const char* sa : kShapes) {
    for (const char* sb : kShapes) {
      const auto a = io::builtin_shape(sa), b = io::builtin_shape(sb);
      for (int k = 0; k < 3; ++k) {
        const Pose pose = random_pose(rng, 2.5);
        for (auto n : {NumberKind::Double, NumberKind::Exact}) {
          const RunOutcome ref = run_sat(a, b, &pose, config(n, AlgorithmKind::Brute));
          for (auto alg : algs) {
            INFO(sa << " vs " << sb << " pose " << k << ", " << name(n) << ", " << name(alg));
            const RunOutcome r = run_sat(a, b, &pose, config(n, alg));
            CHECK(r.overlap == ref.overlap);
            CHECK(r.feature == ref.feature);
            if (n == NumberKind::Exact) {
              CHECK(r.separation == ref.separation);
            } else {
              CHECK(r.separation == Approx(ref.separation).margin(1e-12));
            }
            ++compared;
          }
        }
      }
    }
  }
  CHECK(compared >= 2 * 3 * 49);
}

TEST_CASE("sat runner: double and float agree with exact arithmetic away from touching", "[runner]") {
  std::mt19937 rng(99);
  int decided = 0;
  for (const char* sa : kShapes) {
    for (const char* sb : kShapes) {
      const auto a = io::builtin_shape(sa), b = io::builtin_shape(sb);
      for (int k = 0; k < 4; ++k) {
        const Pose pose = random_pose(rng, 3.0);
        const RunOutcome ex = run_sat(a, b, &pose, config(NumberKind::Exact, AlgorithmKind::Gauss));
        const RunOutcome db = run_sat(a, b, &pose, config(NumberKind::Double, AlgorithmKind::Gauss));
        const RunOutcome fl = run_sat(a, b, &pose, config(NumberKind::Float, AlgorithmKind::Gauss));
        INFO(sa << " vs " << sb << " pose " << k << ": exact separation " << ex.separation);
        CHECK(db.separation == Approx(ex.separation).margin(1e-9));
        CHECK(fl.separation == Approx(ex.separation).margin(1e-4));
        if (std::abs(ex.separation) > 1e-3) {
          CHECK(db.overlap == ex.overlap);
          CHECK(fl.overlap == ex.overlap);
          ++decided;
        }
      }
    }
  }
  CHECK(decided > 100);
}

TEST_CASE("sat runner: the robust policy decides what exact arithmetic decides on the same inputs",
          "[runner]") {
  if (!robust_available()) {
    WARN("this build has no robust policy: test not run");
    return;
  }
  std::mt19937 rng(5);
  for (const char* sa : kShapes) {
    for (const char* sb : kShapes) {
      const auto a = io::builtin_shape(sa), b = io::builtin_shape(sb);
      for (int k = 0; k < 3; ++k) {
        const Pose pose = random_pose(rng, 2.5);
        const RunOutcome ex = run_sat(a, b, &pose, config(NumberKind::Exact, AlgorithmKind::Gauss));
        const RunOutcome rb = run_sat(a, b, &pose, config(NumberKind::Double, AlgorithmKind::Gauss, true));
        INFO(sa << " vs " << sb << " pose " << k);
        CHECK(rb.overlap == ex.overlap);
        CHECK(rb.feature == ex.feature);
      }
    }
  }
  // touching exactly: face contact at distance 0 is overlap for exact and robust alike
  const auto cube = io::builtin_shape("cube");
  const Pose touch = Pose::make(Vec3<double>(2, 0, 0));
  CHECK(run_sat(cube, cube, &touch, config(NumberKind::Double, AlgorithmKind::Gauss, true)).overlap);
  CHECK(run_sat(cube, cube, &touch, config(NumberKind::Exact, AlgorithmKind::Gauss)).overlap);
}

TEST_CASE("shape builder: face-list errors name the file and the line of the face or vertex", "[runner]") {
  std::istringstream in(
      "OFF\n4 4 6\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n"
      "3 0 1 2\n3 0 3 1\n3 0 2 2\n3 1 3 2\n");
  const auto d = io::read_off(in, "tet.off");
  for (auto n : {NumberKind::Float, NumberKind::Double, NumberKind::Exact}) {
    INFO(name(n));
    CHECK_THROWS_WITH(shape_counts(d, n), Catch::StartsWith("tet.off:9: face 2 uses vertex 2 twice"));
  }
  // a vertex on no face is named with its line (validation numbers the file's vertices as given)
  std::istringstream in2(
      "OFF\n5 4 6\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n0 0 0\n"
      "3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
  const auto d2 = io::read_off(in2, "tet5.off");
  CHECK_THROWS_WITH(shape_counts(d2, NumberKind::Double),
                    Catch::StartsWith("tet5.off:7: vertex 4 is on no face"));
  CHECK_THROWS_AS(shape_counts(d2, NumberKind::Exact), InvalidInput);
  // inward faces
  std::istringstream in3(
      "OFF\n4 4 6\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n"
      "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const auto d3 = io::read_off(in3, "inward.off");
  CHECK_THROWS_WITH(shape_counts(d3, NumberKind::Exact), Catch::StartsWith("inward.off"));
}

TEST_CASE("shape builder: a coordinate beyond float's range is named, not called non-finite", "[runner]") {
  std::istringstream in(
      "OFF\n4 4 6\n1 1 1\n1 -1 -1\n-1 1e300 -1\n-1 -1 1\n"
      "3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
  const auto d = io::read_off(in, "big.off");
  CHECK_THROWS_WITH(
      shape_counts(d, NumberKind::Float),
      Catch::StartsWith("big.off: coordinate y of vertex 2 (1e+300) is beyond the range of float"));
  io::ShapeData pts;
  pts.kind = io::ShapeData::Kind::Points;
  pts.name = "big.pts";
  pts.vertices = {{0, 0, 0}, {4e38, 0, 0}, {0, 4e38, 0}, {0, 0, -4e38}};
  CHECK_THROWS_WITH(
      shape_counts(pts, NumberKind::Float),
      Catch::StartsWith("big.pts: coordinate x of point 1 (4e+38) is beyond the range of float"));
  // double holds it: a tetrahedron
  CHECK(shape_counts(pts, NumberKind::Double).faces == 4);
}

TEST_CASE("shape builder: a single face is that polygon, double-sided", "[runner]") {
  std::istringstream in("OFF\n4 1 4\n0 0 0\n2 0 0\n2 1 0\n0 1 0\n4 0 1 2 3\n");
  const auto d = io::read_off(in, "quad.off");
  for (auto n : {NumberKind::Float, NumberKind::Double, NumberKind::Exact}) {
    INFO(name(n));
    const ShapeCounts c = shape_counts(d, n);
    CHECK(c.vertices == 4);
    CHECK(c.edges == 4);
    CHECK(c.faces == 2);
  }
  const auto q = build_shape<double>(d);
  CHECK(q.is_flat());
  CHECK(q.plane(0).normal.z() > 0);  // the loop as given is the front face
  CHECK(q.plane(1).normal.z() < 0);
  // two faces that are not a closed surface are still an error
  std::istringstream in2("OFF\n4 2 0\n0 0 0\n2 0 0\n2 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  CHECK_THROWS_AS(shape_counts(io::read_off(in2, "two.off"), NumberKind::Double), InvalidInput);
}

TEST_CASE("shape builder: a posed exact shape has exactly the posed double coordinates", "[runner]") {
  const auto prism = io::builtin_shape("prism:7");
  std::mt19937 rng(3);
  for (int k = 0; k < 5; ++k) {
    const Pose pose = random_pose(rng, 4);
    const auto pd = build_shape<double>(prism, &pose);
    const auto pq = build_shape<mpq_class>(prism, &pose);
    REQUIRE(pd.vertex_count() == pq.vertex_count());
    REQUIRE(pd.face_count() == pq.face_count());
    for (int v = 0; v < pd.vertex_count(); ++v) {
      for (int c = 0; c < 3; ++c) CHECK(pq.vertex(v)[c] == mpq_class(pd.vertex(v)[c]));
    }
    for (int f = 0; f < pd.face_count(); ++f) CHECK(pd.face(f).plane_vertices == pq.face(f).plane_vertices);
  }
}

TEST_CASE("shape builder: points are hulled in the chosen number type", "[runner]") {
  if (!hull_builder_available()) {
    WARN("this build has no hull builder: test not run");
    return;
  }
  io::ShapeData pts;
  pts.kind = io::ShapeData::Kind::Points;
  pts.name = "pts";
  for (int i = 0; i < 8; ++i) pts.vertices.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  pts.vertices.emplace_back(0.25, -0.5, 0.125);  // interior
  pts.vertices.emplace_back(1, 0, 0);            // on a face
  const auto cube = io::builtin_shape("cube");
  for (auto n : {NumberKind::Float, NumberKind::Double, NumberKind::Exact}) {
    INFO(name(n));
    const ShapeCounts c = shape_counts(pts, n);
    CHECK(c.vertices == 8);
    CHECK(c.edges == 12);
    CHECK(c.faces == 6);
    // the hull of the points behaves as the cube
    std::mt19937 rng(17);
    for (int k = 0; k < 10; ++k) {
      const Pose pose = random_pose(rng, 3);
      const RunOutcome hp = run_sat(pts, pts, &pose, config(n, AlgorithmKind::Gauss));
      const RunOutcome cp = run_sat(cube, cube, &pose, config(n, AlgorithmKind::Gauss));
      CHECK(hp.overlap == cp.overlap);
      CHECK(hp.separation == Approx(cp.separation).margin(1e-5));
    }
  }
  io::ShapeData line = pts;
  line.vertices = {Vec3<double>(0, 0, 0), Vec3<double>(1, 1, 1), Vec3<double>(2, 2, 2)};
  CHECK_THROWS_WITH(shape_counts(line, NumberKind::Exact), Catch::StartsWith("pts: "));
}
