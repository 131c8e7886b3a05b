// Tests for src/io/points_reader.cpp.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include <sepax/error.hpp>

#include "io/points_reader.hpp"
#include "cli/malformed_input.hpp"

using namespace sepax;
using namespace sepax::cli;

namespace {
io::ShapeData read(const std::string& text) {
  std::istringstream in(text);
  return io::read_points(in, "p.pts");
}
}  // namespace

TEST_CASE("points: whitespace or commas, comments, blank lines", "[points]") {
  const auto d = read("# corners\n0 0 0\n\n1,0,0\n 0 , 1 , 0 # third\n\t0\t0\t1\r\n+2.5e-1 -0 1E2\n");
  CHECK(d.kind == io::ShapeData::Kind::Points);
  CHECK(d.name == "p.pts");
  REQUIRE(d.vertices.size() == 5);
  CHECK(d.vertices[1] == Vec3<double>(1, 0, 0));
  CHECK(d.vertices[2] == Vec3<double>(0, 1, 0));
  CHECK(d.vertices[3] == Vec3<double>(0, 0, 1));
  CHECK(d.vertices[4] == Vec3<double>(0.25, 0, 100));
  CHECK(d.faces.empty());
}

TEST_CASE("points: decimal input converts to the nearest double", "[points]") {
  const auto d = read("0.1 0.2 0.3\n");
  CHECK(d.vertices[0][0] == 0.1);
  CHECK(d.vertices[0][1] == 0.2);
  CHECK(d.vertices[0][2] == 0.3);
}

TEST_CASE("points: malformed files are rejected naming FILE:LINE and the problem", "[points]") {
  const std::vector<test::Malformed> cases = {
      {"", 1, "empty file"},
      {"# nothing\n", 1, "empty file"},
      {"0 0 0\n1 0\n", 2, "point 1 has 2 values; expected 3"},
      {"0 0 0 0\n", 1, "point 0 has 4 values"},
      {"0 0 0\n0 0 zero\n", 2, "bad number 'zero' for coordinate z of point 1"},
      {"0 inf 0\n", 1, "NaN and infinity are not allowed"},
      {"0 0 -1e309\n", 1, "out of the range"},
      {"0 0 0\n1,,2,3\n", 2, "point 1 has 3 commas; commas separate exactly 3 values"},
      {"4,5,6,\n", 1, "point 0 has 3 commas"},
      {"4,5 6\n", 1, "point 0 has 1 comma;"},
  };
  test::check_malformed(
      cases, [](const std::string& text) { (void)read(text); }, "p.pts");
}
