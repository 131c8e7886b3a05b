// Fuzz cases: text round trip, parse errors that name the line, reproducer
// round trip through the checking core.
#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>

#include <Eigen/Eigenvalues>

#include <sepax/error.hpp>
#include <sepax/fuzz/campaign.hpp>
#include <sepax/fuzz/generators.hpp>

using namespace sepax;
using namespace sepax::fuzz;

TEST_CASE("every family round-trips through the text format exactly", "[fuzz][io]") {
  for (const auto& fam : family_names()) {
    for (std::uint64_t seed = 0; seed < 3; ++seed) {
      const FuzzCase c = generate(fam, seed);
      INFO(fam << " seed " << seed);
      std::stringstream s;
      write_case(s, c, "a comment\nover two lines");
      const FuzzCase d = read_case(s);
      CHECK(d.family == c.family);
      CHECK(d.seed == c.seed);
      REQUIRE(d.a.vertices.size() == c.a.vertices.size());
      REQUIRE(d.b.vertices.size() == c.b.vertices.size());
      for (std::size_t i = 0; i < c.a.vertices.size(); ++i) REQUIRE(d.a.vertices[i] == c.a.vertices[i]);
      for (std::size_t i = 0; i < c.b.vertices.size(); ++i) REQUIRE(d.b.vertices[i] == c.b.vertices[i]);
      CHECK(d.a.faces == c.a.faces);
      CHECK(d.b.faces == c.b.faces);
    }
  }
}

TEST_CASE("generated coordinates are float values", "[fuzz][io]") {
  for (const auto& fam : family_names()) {
    const FuzzCase c = generate(fam, 11);
    INFO(fam);
    for (const auto* s : {&c.a, &c.b})
      for (const auto& v : s->vertices)
        for (int k = 0; k < 3; ++k) REQUIRE(static_cast<double>(static_cast<float>(v[k])) == v[k]);
  }
}

TEST_CASE("parse errors name the line", "[fuzz][io]") {
  auto fails_with = [](const std::string& text, const std::string& needle) {
    std::stringstream s(text);
    try {
      read_case(s, "t.case");
    } catch (const InvalidInput& e) {
      CHECK(e.code() == ErrorCode::Parse);
      CHECK(std::string(e.what()).find(needle) != std::string::npos);
      return;
    }
    FAIL("no error for: " << text);
  };
  fails_with("", "empty");
  fails_with("hello\n", "t.case:1");
  fails_with("sepax-fuzz-case 1\nshape A\nv 0 0\nend\n", "t.case:3");
  fails_with("sepax-fuzz-case 1\nshape A\nv 0 0 0\nf 0 1 2\nend\n", "vertex 1");
  fails_with("sepax-fuzz-case 1\nshape A\nend\n", "shape B");
  fails_with("sepax-fuzz-case 1\nshape C\n", "A or B");
  fails_with("sepax-fuzz-case 1\nshape A\nv 0 0 0\n", "missing 'end'");
  // face entries: whole integers in range, however large the text
  const std::string three = "sepax-fuzz-case 1\nshape A\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
  fails_with(three + "f 0 1 2 99999999999999999999\nend\n",
             "t.case:6: face refers to vertex 99999999999999999999");
  fails_with(three + "f 0 1 2 -99999999999999999999\nend\n", "vertex -99999999999999999999");
  fails_with(three + "f 0 1 2 18446744073709551616\nend\n", "vertex 18446744073709551616");
  fails_with(three + "f 0 1 2 -1\nend\n", "vertex -1");
  fails_with(three + "f 0 1 1.5\nend\n", "'1.5' is not one");
  fails_with(three + "f 0 1 2x\nend\n", "'2x' is not one");
}

TEST_CASE("a reproducer replays to the same report", "[fuzz][io]") {
  const auto dir = std::filesystem::temp_directory_path() / "sepax-fuzz-test-repro";
  std::filesystem::remove_all(dir);
  const FuzzCase c = generate("flat", 5);
  const CaseReport r1 = check_case(c);
  REQUIRE(r1.valid);
  const std::string path = write_reproducer(dir.string(), c, r1);
  const FuzzCase d = read_case_file(path);
  const CaseReport r2 = check_case(d);
  REQUIRE(r2.valid);
  CHECK(r2.unexplained_count == r1.unexplained_count);
  REQUIRE(r2.by_comparison.size() == r1.by_comparison.size());
  for (const auto& [k, v] : r1.by_comparison) CHECK(r2.by_comparison.at(k).n == v.n);
  std::filesystem::remove_all(dir);
}

TEST_CASE("invalid shapes are rejected, never crash", "[fuzz][io]") {
  FuzzCase c;
  c.a.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};  // collinear "polygon"
  c.a.faces = {{0, 1, 2}, {2, 1, 0}};
  c.b = builtin_shape("cube");
  const CaseReport r = check_case(c);
  CHECK_FALSE(r.valid);
  CHECK(r.reject_reason.find("shape A") != std::string::npos);
  // a coordinate a double holds and float does not: named with its value, not as an infinity
  FuzzCase big;
  big.a = builtin_shape("cube");
  big.b = builtin_shape("cube");
  big.b.vertices[2][1] = 1e39;
  const CaseReport rb = check_case(big);
  CHECK_FALSE(rb.valid);
  CHECK(rb.reject_reason.find("shape B: coordinate y of vertex 2 (1e+39) is beyond the range of float") !=
        std::string::npos);
  CHECK_THROWS_AS(builtin_shape("dodecahedron"), InvalidInput);
  CHECK_THROWS_AS(builtin_shape("prism:2"), InvalidInput);
  CHECK_THROWS_AS(builtin_shape("box:1,x,2"), InvalidInput);
}

TEST_CASE("decomposition and scanned families: the shapes they imitate", "[fuzz][generators]") {
  int touching_or_near = 0, thin = 0, far = 0;
  for (std::uint64_t seed = 0; seed < 12; ++seed) {
    const FuzzCase d = generate("decomposition", seed);
    CHECK(d.family == "decomposition");
    for (const ShapeSpec* s : {&d.a, &d.b}) {
      CHECK(s->vertices.size() >= 4);
      CHECK(s->vertices.size() <= 64);  // hulls of 16..64 points
    }
    // neighbouring pieces: they share the vertices of the cut section, B
    // moved by a gap or overlap of at most 1e-3 (of radii >= 0.3, times the
    // world scale), so their closest vertices are within 4e-3 of A's extent
    sepax::Vec3<double> mn = d.a.vertices[0], mx = mn;
    double closest = 1e300, lo = 1e300;
    for (const auto& p : d.a.vertices) {
      mn = mn.cwiseMin(p);
      mx = mx.cwiseMax(p);
      lo = std::min(lo, p.norm());
      for (const auto& q : d.b.vertices) closest = std::min(closest, (p - q).norm());
    }
    const double extent = (mx - mn).maxCoeff();
    touching_or_near += closest <= 4e-3 * extent;
    far += lo > 50;  // moved 1e2..1e4 from the origin
    // thin: the vertices' covariance is flat (rotation invariant)
    sepax::Vec3<double> c = sepax::Vec3<double>::Zero();
    for (const auto& p : d.a.vertices) c += p;
    c /= static_cast<double>(d.a.vertices.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& p : d.a.vertices) cov += (p - c) * (p - c).transpose();
    const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvalues();
    thin += ev[0] < 0.04 * ev[2];
  }
  CHECK(touching_or_near >= 10);
  CHECK(far >= 2);
  CHECK(thin >= 1);
  for (std::uint64_t seed = 0; seed < 3; ++seed) {
    const FuzzCase c = generate("scanned", seed);
    CHECK(c.family == "scanned");
    CHECK(c.a.vertices.size() >= 60);  // a dense hull: most of the 200..2000 noisy points
    CHECK(c.a.vertices.size() <= 2000);
    CHECK(c.b.vertices.size() <= 8);  // a small partner (box or tetrahedron)
  }
}
