// Tests for src/io/obj_reader.cpp.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/error.hpp>

#include "io/obj_reader.hpp"

using namespace sepax;
using namespace sepax::cli;

namespace {

io::ShapeData read(const std::string& text, const std::string& name = "t.obj") {
  std::istringstream in(text);
  return io::read_obj(in, name);
}

const char* kVerts =
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n";  // lines 1..8

// The cube's faces (0-based), as the OFF test uses them.
const std::vector<std::vector<int>> kFaces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                              {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};

}  // namespace

TEST_CASE("obj: index forms, negative indices and ignored statements all give the cube", "[obj]") {
  const std::string variants[] = {
      std::string(kVerts) + "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 1 5 8 4\nf 2 3 7 6\n",
      // v/vt/vn, v//vn, v/vt forms; comments; statements that are ignored
      "# cube\nmtllib cube.mtl\no Cube\n" + std::string(kVerts) +
          "vt 0 0\nvt 1 0\nvn 0 0 -1\nvp 0.5\ng side\nusemtl red\ns off\n"
          "f 1/1/1 4/2/1 3/1/1 2/2/1\nf 5//1 6//1 7//1 8//1\nf 1/1 2/2 6/1 5/2\n"
          "f 3 4 8 7 # top\nf 1 5 8 4\nf 2 3 7 6\nl 1 2\np 3\n",
      // negative (relative) indices: -8 is the first of the 8 vertices read so far
      std::string(kVerts) + "f -8 -5 -6 -7\nf -4 -3 -2 -1\nf -8 -7 -3 -4\nf -6 -5 -1 -2\nf -8 -4 -1 -5\nf -7 -6 -2 -3\n",
      // w = 1 and vertex colours; CRLF
      "v -1 -1 -1 1\r\nv 1 -1 -1 1.0\r\nv 1 1 -1 0.5 0.5 0.5\r\nv -1 1 -1\r\nv -1 -1 1\r\nv 1 -1 1\r\n"
      "v 1 1 1\r\nv -1 1 1\r\nf 1 4 3 2\r\nf 5 6 7 8\r\nf 1 2 6 5\r\nf 3 4 8 7\r\nf 1 5 8 4\r\nf 2 3 7 6\r\n",
  };
  for (const auto& text : variants) {
    INFO(text);
    const auto d = read(text);
    REQUIRE(d.kind == io::ShapeData::Kind::Faces);
    CHECK(d.vertices.size() == 8);
    CHECK(d.faces == kFaces);
    const auto p = ConvexPolyhedron<double>::from_faces(d.vertices, d.faces);
    CHECK(p.face_count() == 6);
  }
  const auto d = read(variants[1]);
  CHECK(d.face_lines.front() == 19);
  CHECK(d.face_lines.back() == 24);
}

namespace {
struct Bad {
  std::string text;
  std::size_t line;
  const char* problem;
};
}  // namespace

TEST_CASE("obj: malformed files are rejected naming FILE:LINE and the problem", "[obj]") {
  const std::string v = kVerts;
  const Bad cases[] = {
      {"", 1, "empty file"},
      {"# nothing\n\n", 2, "empty file"},
      {"g only\nvt 0 0\n", 2, "no vertices"},
      {v, 8, "no faces"},
      {"v 1 2\n", 1, "vertex 1 has 2 values"},
      {"v 1 2 3 4 5\n", 1, "vertex 1 has 5 values"},
      {"v 1 2 3 2\n", 1, "only w = 1"},
      {"v 1 2 abc\n", 1, "bad number 'abc' for coordinate z of vertex 1"},
      {"v 1 NaN 3\n", 1, "NaN and infinity are not allowed"},
      {"v 1 2 3 red 0 0\n", 1, "bad number 'red' for a colour value"},
      {v + "f 1 2\n", 9, "face 1 has 2 vertices; a face needs at least 3"},
      {v + "f 1 2 0\n", 9, "vertex index 0 is invalid (OBJ indices start at 1)"},
      {v + "f 1 2 9\n", 9, "face 1: vertex index 9 is out of range (8 vertices read so far)"},
      {v + "f 1 2 -9\n", 9, "vertex index -9 is out of range"},
      {v + "f 1 2 x/1/1\n", 9, "bad integer 'x' for a vertex index of face 1"},
      {v + "f 1 2 /1\n", 9, "bad integer ''"},
      {v + "f 1 2 3.5\n", 9, "bad integer '3.5'"},
      {v + "f 1 2 99999999999999999999\n", 9, "too large"},
  };
  for (const Bad& b : cases) {
    INFO("input:\n" << b.text);
    try {
      (void)read(b.text, "bad.obj");
      FAIL("accepted a malformed file");
    } catch (const InvalidInput& e) {
      CHECK(e.code() == ErrorCode::Parse);
      CHECK_THAT(e.what(), Catch::StartsWith("bad.obj:" + std::to_string(b.line) + ": "));
      CHECK_THAT(e.what(), Catch::Contains(b.problem));
    }
  }
}

TEST_CASE("obj: a missing file is an error naming it", "[obj]") {
  CHECK_THROWS_WITH(io::read_obj_file("/nonexistent/x.obj"), Catch::StartsWith("/nonexistent/x.obj: cannot open"));
}
