// Tests for src/io/obj_reader.cpp.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/error.hpp>

#include "io/obj_reader.hpp"
#include "cli/malformed_input.hpp"

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
      std::string(kVerts) +
          "f -8 -5 -6 -7\nf -4 -3 -2 -1\nf -8 -7 -3 -4\nf -6 -5 -1 -2\nf -8 -4 -1 -5\nf -7 -6 -2 -3\n",
      // w = 1 and vertex colours; CRLF
      "v -1 -1 -1 1\r\nv 1 -1 -1 1.0\r\nv 1 1 -1 0.5 0.5 0.5\r\nv -1 1 -1\r\nv -1 -1 1\r\nv 1 -1 1\r\n"
      "v 1 1 1\r\nv -1 1 1\r\nf 1 4 3 2\r\nf 5 6 7 8\r\nf 1 2 6 5\r\nf 3 4 8 7\r\nf 1 5 8 4\r\nf 2 3 7 6\r\n",
      // a UTF-8 byte order mark before the first vertex (it is not part of the 'v')
      "\xEF\xBB\xBF" + std::string(kVerts) +
          "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 1 5 8 4\nf 2 3 7 6\n",
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

TEST_CASE("obj: malformed files are rejected naming FILE:LINE and the problem", "[obj]") {
  const std::string v = kVerts;
  const std::vector<test::Malformed> cases = {
      {"", 1, "empty file"},
      {"# nothing\n\n", 2, "empty file"},
      {"g only\nvt 0 0\n", 2, "no vertices"},
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
      {v + "f 1/1/1/1 2 3\n", 9, "face 1: bad vertex entry '1/1/1/1' (expected v, v/vt, v//vn or v/vt/vn)"},
      {v + "f 1 2/x 3\n", 9, "face 1: bad vertex entry '2/x'"},
      {v + "f 1 2//1.5 3\n", 9, "face 1: bad vertex entry '2//1.5'"},
  };
  test::check_malformed(
      cases, [](const std::string& text) { (void)read(text, "bad.obj"); }, "bad.obj");
}

TEST_CASE("obj: a file of 'v' lines only is a point set (hulled), whatever its 'o' statements", "[obj]") {
  std::istringstream in("o scan\n" + std::string(kVerts) + "o second\nv 9 9 9\n");
  const auto objects = io::read_obj_objects(in, "cloud.obj");
  REQUIRE(objects.size() == 1);
  const io::ShapeData& d = objects[0].shape;
  CHECK(d.kind == io::ShapeData::Kind::Points);
  CHECK(d.vertices.size() == 9);
  CHECK(d.faces.empty());
  CHECK(d.vertices.back() == Vec3<double>(9, 9, 9));
}

TEST_CASE("obj: a missing file is an error naming it", "[obj]") {
  CHECK_THROWS_WITH(io::read_obj_file("/nonexistent/x.obj"),
                    Catch::StartsWith("/nonexistent/x.obj: cannot open"));
}

TEST_CASE("obj: each 'o' is one object; indices stay global, negative ones relative", "[obj]") {
  // two tetrahedra, the second written with negative indices and after it a
  // third object; a 'g' inside an object does not split it
  const std::string text =
      "o first\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\ng part\nf 1 4 3\nf 2 3 4\n"
      "o second\nv 5 0 0\nv 6 0 0\nv 5 1 0\nv 5 0 1\nf -4 -2 -3\nf -4 -3 -1\nf -4 -1 -2\nf -3 -2 -1\n"
      "o third\nf 5 7 6\nf 5 6 8\nf 5 8 7\nf 6 7 8\n";
  std::istringstream in(text);
  const auto objects = io::read_obj_objects(in, "p.obj");
  REQUIRE(objects.size() == 3);
  CHECK(objects[0].name == "first");
  CHECK(objects[1].name == "second");
  CHECK(objects[0].shape.name == "p.obj#first");
  CHECK(objects[0].shape.faces.size() == 4);
  CHECK(objects[0].shape.vertices.size() == 4);
  // the second object's own vertices, renumbered from 0 in file order
  CHECK(objects[1].shape.vertices.front() == Vec3<double>(5, 0, 0));
  CHECK(objects[1].shape.faces.front() == std::vector<int>{0, 2, 1});
  CHECK(objects[1].shape.face_lines.front() == 16);
  // the third reuses the second's vertices through global indices
  CHECK(objects[2].shape.vertices == objects[1].shape.vertices);
  CHECK(
      ConvexPolyhedron<double>::from_faces(objects[2].shape.vertices, objects[2].shape.faces).face_count() ==
      4);

  CHECK(io::select_object(objects, "p.obj", std::string("second")).name == "p.obj#second");
  CHECK(io::select_object(objects, "p.obj", std::string("2")).name == "p.obj#third");
  CHECK_THROWS_WITH(io::select_object(objects, "p.obj", std::nullopt),
                    Catch::Contains("p.obj: the file holds 3 objects (0 'first', 1 'second', 2 'third')") &&
                        Catch::Contains("p.obj#NAME"));
  CHECK_THROWS_WITH(io::select_object(objects, "p.obj", std::string("fourth")),
                    Catch::Contains("no object 'fourth'") && Catch::Contains("2 'third'"));
  CHECK_THROWS_WITH(io::select_object(objects, "p.obj", std::string("3")), Catch::Contains("no object '3'"));
  std::istringstream again(text);
  CHECK_THROWS_WITH(io::read_obj(again, "p.obj"), Catch::Contains("holds 3 objects"));
}

TEST_CASE("obj: without 'o' statements each 'g' is one object; one object is the file", "[obj]") {
  const std::string tet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  std::istringstream groups(tet + "g a\nf 1 3 2\nf 1 2 4\ng b\nf 1 4 3\ng a\nf 2 3 4\n");
  const auto objects = io::read_obj_objects(groups, "g.obj");
  REQUIRE(objects.size() == 2);
  CHECK(objects[0].name == "a");
  CHECK(objects[0].shape.faces.size() == 3);  // both 'g a' runs
  CHECK(objects[1].shape.faces.size() == 1);
  // faces before any name form the object "" (named by its index)
  std::istringstream unnamed(tet + "f 1 3 2\ng b\nf 1 2 4\n");
  const auto u = io::read_obj_objects(unnamed, "u.obj");
  REQUIRE(u.size() == 2);
  CHECK(u[0].name.empty());
  CHECK(u[0].shape.name == "u.obj#0");
  // one object: the file's name, unused vertices dropped
  std::istringstream one("v 9 9 9\n" + tet + "o only\nf 2 4 3\nf 2 3 5\nf 2 5 4\nf 3 4 5\n");
  const auto d = io::read_obj(one, "one.obj");
  CHECK(d.name == "one.obj");
  CHECK(d.vertices.size() == 4);
  CHECK(d.vertices.front() == Vec3<double>(0, 0, 0));
}

TEST_CASE("obj: the V-HACD-style file of tests/data has three pieces", "[obj]") {
  const auto objects = [] {
    std::ifstream in(std::string(SEPAX_SOURCE_DIR) + "/tests/data/vhacd_pieces.obj");
    return io::read_obj_objects(in, "vhacd_pieces.obj");
  }();
  REQUIRE(objects.size() == 3);
  CHECK(objects[0].name == "convex_0");
  CHECK(objects[2].name == "convex_2");
  CHECK(objects[0].shape.faces.size() == 12);  // triangulated box
  CHECK(objects[2].shape.vertices.size() == 14);
}
