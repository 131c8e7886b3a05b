// Tests for src/io/off_reader.cpp.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/error.hpp>

#include "io/off_reader.hpp"
#include "cli/malformed_input.hpp"

using namespace sepax;
using namespace sepax::cli;

namespace {

const char* kCube =
    "OFF\n"
    "8 6 12\n"
    "-1 -1 -1\n 1 -1 -1\n 1 1 -1\n -1 1 -1\n"
    "-1 -1 1\n 1 -1 1\n 1 1 1\n -1 1 1\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 0 4 7 3\n4 1 2 6 5\n";

io::ShapeData read(const std::string& text, const std::string& name = "t.off") {
  std::istringstream in(text);
  return io::read_off(in, name);
}

// The cube as a validated polyhedron: the reader's output is what from_faces wants.
void check_cube(const io::ShapeData& d) {
  REQUIRE(d.kind == io::ShapeData::Kind::Faces);
  REQUIRE(d.vertices.size() == 8);
  REQUIRE(d.faces.size() == 6);
  REQUIRE(d.face_lines.size() == 6);
  const auto p = ConvexPolyhedron<double>::from_faces(d.vertices, d.faces);
  CHECK(p.vertex_count() == 8);
  CHECK(p.edge_count() == 12);
  CHECK(p.face_count() == 6);
}

}  // namespace

TEST_CASE("off: a plain cube", "[off]") {
  const auto d = read(kCube);
  check_cube(d);
  CHECK(d.name == "t.off");
  CHECK(d.vertices[6] == Vec3<double>(1, 1, 1));
  CHECK(d.faces[0] == std::vector<int>{0, 3, 2, 1});
  CHECK(d.face_lines[0] == 11);
  CHECK(d.face_lines[5] == 16);
}

TEST_CASE("off: a file declaring 0 faces is a point set (hulled)", "[off]") {
  const auto d = read("OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
  CHECK(d.kind == io::ShapeData::Kind::Points);
  REQUIRE(d.vertices.size() == 4);
  CHECK(d.vertices[1] == Vec3<double>(1, 0, 0));
  CHECK(d.faces.empty());
}

TEST_CASE("off: accepted quirks give the same shape", "[off]") {
  const std::string variants[] = {
      // comments, blank lines, CRLF, trailing comments
      "# a cube\r\nOFF\r\n\r\n# counts\r\n8 6 12 # V F E\r\n-1 -1 -1\r\n1 -1 -1\r\n1 1 -1\r\n-1 1 -1\r\n"
      "-1 -1 1\r\n1 -1 1\r\n1 1 1\r\n-1 1 1\r\n# faces\r\n4 0 3 2 1\r\n4 4 5 6 7\r\n4 0 1 5 4\r\n"
      "4 2 3 7 6\r\n4 0 4 7 3\r\n4 1 2 6 5 # last\r\n# end\r\n",
      // counts on the header line, no edge count, tabs, '+' signs and exponents
      "OFF 8 6\n-1 -1 -1\n+1 -1 -1\n1e0 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1\t1\t1\n-1 1 1.0\n"
      "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 0 4 7 3\n4 1 2 6 5\n",
      // no header at all
      "8 6 0\n-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n"
      "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 0 4 7 3\n4 1 2 6 5\n",
      // COFF: per-vertex colours; face colours after the indices
      "COFF\n8 6 12\n-1 -1 -1 255 0 0 255\n1 -1 -1 0 255 0 255\n1 1 -1 0 0 0 1\n-1 1 -1 1 1 1 1\n"
      "-1 -1 1 1 1 1 1\n1 -1 1 1 1 1 1\n1 1 1 1 1 1 1\n-1 1 1 1 1 1 1\n"
      "4 0 3 2 1 255 0 0\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 0 4 7 3\n4 1 2 6 5 0.5 0.5 0.5\n",
  };
  const auto ref = read(kCube);
  for (const auto& text : variants) {
    INFO(text);
    const auto d = read(text);
    check_cube(d);
    CHECK(d.vertices == ref.vertices);
    CHECK(d.faces == ref.faces);
  }
}

TEST_CASE("off: malformed files are rejected naming FILE:LINE and the problem", "[off]") {
  const std::string v8 =
      "-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n";  // lines 3..10
  const std::string f6 =
      "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 0 4 7 3\n4 1 2 6 5\n";  // lines 11..16
  const std::vector<test::Malformed> cases = {
      {"", 1, "empty file"},
      {"# only a comment\n\n", 2, "empty file"},
      {"FOO\n", 1, "expected the OFF header"},
      {"4OFF\n", 1, "only 3-dimensional"},
      {"nOFF\n", 1, "only 3-dimensional"},
      {"OFF BINARY\n", 1, "binary OFF"},
      {"OFF\n", 1, "missing the counts line"},
      {"OFF\n8\n", 2, "missing counts"},
      {"OFF\n8 6 12 1\n", 2, "too many values"},
      {"OFF\n8 x 12\n", 2, "bad integer 'x' for the face count"},
      {"OFF\n8.5 6 12\n", 2, "bad integer '8.5' for the vertex count"},
      {"OFF\n-8 6 12\n", 2, "vertex count is negative"},
      {"OFF\n99999999999 6 12\n", 2, "too large"},
      {"OFF\n2 6 0\n", 2, "at least 3"},
      {"OFF\n8 6 12\n" + v8.substr(0, 17) + "1 1\n", 5, "vertex 2 has 2 values"},
      {"OFF\n8 6 12\n-1 -1 -1 7\n", 3, "vertex 0 has 4 values"},
      {"OFF\n8 6 12\n-1 -1 1.0.0\n", 3, "bad number '1.0.0' for coordinate z of vertex 0"},
      {"OFF\n8 6 12\n-1 nan -1\n", 3, "coordinate y of vertex 0 is 'nan': NaN and infinity are not allowed"},
      {"OFF\n8 6 12\n-1 -1 -inf\n", 3, "NaN and infinity are not allowed"},
      {"OFF\n8 6 12\n1e999 -1 -1\n", 3, "out of the range of a double"},
      {"OFF\n8 6 12\n0x10 -1 -1\n", 3, "bad number '0x10'"},
      {"OFF\n8 6 12\n" + v8.substr(0, 24), 5, "expected 8 vertices, found 3"},
      {"OFF\n8 6 12\n" + v8 + "2 0 1\n", 11, "face 0 has 2 vertices; a face needs at least 3"},
      {"OFF\n8 6 12\n" + v8 + "4 0 3 2\n", 11, "face 0 declares 4 vertices but lists 3"},
      {"OFF\n8 6 12\n" + v8 + "4 0 3 2 1\n4 4 5 6 8\n", 12,
       "face 1: vertex index 8 is out of range (the file has 8 vertices, indices 0..7)"},
      {"OFF\n8 6 12\n" + v8 + "4 0 -3 2 1\n", 11, "vertex index -3 is out of range"},
      {"OFF\n8 6 12\n" + v8 + "4 0 3 2 x\n", 11, "bad integer 'x' for a vertex index of face 0"},
      {"OFF\n8 6 12\n" + v8 + "4 0 3 2 1\n", 11, "expected 6 faces, found 1"},
      {"OFF\n8 6 12\n" + v8 + f6 + "3 0 1 2\n", 17, "unexpected content after the last face"},
      {std::string("OFF\n8 6 12\n-1 -1\0 -1\n", 21), 3, "NUL byte"},
  };
  test::check_malformed(
      cases, [](const std::string& text) { (void)read(text, "dir/bad.off"); }, "dir/bad.off");
}

TEST_CASE("off: a file that cannot be opened is an error naming it", "[off]") {
  CHECK_THROWS_WITH(io::read_off_file("/nonexistent/x.off"),
                    Catch::StartsWith("/nonexistent/x.off: cannot open"));
  CHECK_THROWS_WITH(io::read_off_file("/"), Catch::Contains("is a directory"));
}
