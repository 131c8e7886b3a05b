// Tests for src/io/shape_source.cpp: built-in shape names and file dispatch.
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/error.hpp>
#include <sepax/shapes.hpp>

#include "cli/cli_test_support.hpp"
#include "io/shape_source.hpp"

using namespace sepax;
using namespace sepax::cli;

namespace {

ConvexPolyhedron<double> built(const io::ShapeData& d) {
  return ConvexPolyhedron<double>::from_faces(d.vertices, d.faces);
}

}  // namespace

TEST_CASE("shape source: built-in names give the shapes of sepax/shapes.hpp", "[shapes]") {
  const struct {
    const char* spec;
    ConvexPolyhedron<double> expected;
  } cases[] = {
      {"cube", shapes::cube<double>()},
      {"tetra", shapes::tetrahedron<double>()},
      {"box:0.5,2,3e1", shapes::box<double>(0.5, 2, 30)},
      {"prism:7", shapes::prism<double>(7)},
      {"polygon:5", shapes::regular_polygon<double>(5)},
      {"triangle",
       shapes::triangle<double>(Vec3<double>(0, 0, 0), Vec3<double>(1, 0, 0), Vec3<double>(0, 1, 0))},
  };
  for (const auto& c : cases) {
    INFO(c.spec);
    CHECK(io::is_builtin_shape(c.spec));
    const io::ShapeData d = io::load_shape(c.spec);
    CHECK(d.kind == io::ShapeData::Kind::Faces);
    CHECK(d.name == c.spec);
    const auto p = built(d);
    CHECK(p.vertices() == c.expected.vertices());
    CHECK(p.face_count() == c.expected.face_count());
    CHECK(p.edge_count() == c.expected.edge_count());
    CHECK(p.is_flat() == c.expected.is_flat());
  }
}

TEST_CASE("shape source: bad built-in parameters are clear errors", "[shapes]") {
  const struct {
    const char* spec;
    const char* problem;
  } cases[] = {
      {"box:1,2", "expected box:HX,HY,HZ"},
      {"box:1,2,3,4", "expected box:HX,HY,HZ"},
      {"box:1,-2,3", "HY must be a positive finite number"},
      {"box:1,0,3", "HY must be a positive finite number"},
      {"box:1,x,3", "bad number 'x' for HY"},
      {"box:", "expected box:HX,HY,HZ"},
      {"box:1,2,inf", "HZ must be a positive finite number"},
      {"prism:2", "between 3 and 1000, got 2"},
      {"prism:", "bad side count ''"},
      {"prism:4.5", "bad side count '4.5'"},
      {"polygon:1001", "between 3 and 1000"},
      // parsed, but refused by the shape's own validation: named all the same
      {"box:1,1,1e-30", "has zero area up to rounding"},
      {"box:1e308,1,1", "coordinates up to"},
  };
  for (const auto& c : cases) {
    INFO(c.spec);
    CHECK_THROWS_WITH(io::load_shape(c.spec), Catch::StartsWith(std::string("shape '") + c.spec + "': ") &&
                                                  Catch::Contains(c.problem));
  }
}

TEST_CASE("shape source: files are read by extension", "[shapes]") {
  const test::TempDir dir("sepax_shape_source_test");
  const std::string off = dir.write("c.OFF",
                                    "OFF\n4 4 6\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n"
                                    "3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
  const std::string obj =
      dir.write("c.obj", "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n");
  const std::string pts = dir.write("c.xyz", "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n0 0 0\n");
  const std::string txt = dir.write("c.txt", "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n");
  const auto a = io::load_shape(off);
  const auto b = io::load_shape(obj);
  CHECK(a.kind == io::ShapeData::Kind::Faces);
  CHECK(b.kind == io::ShapeData::Kind::Faces);
  CHECK(a.vertices == b.vertices);
  CHECK(a.faces == b.faces);
  CHECK(built(a).vertices() == shapes::tetrahedron<double>().vertices());
  CHECK(io::load_shape(pts).kind == io::ShapeData::Kind::Points);
  CHECK(io::load_shape(pts).vertices.size() == 5);
  CHECK(io::load_shape(txt).kind == io::ShapeData::Kind::Points);
  CHECK(io::load_shape(dir.write("c.pts", "0 0 0\n")).vertices.size() == 1);
  // a mesh file of vertices without faces (a scanner's point cloud) is a point set, hulled like a points file
  const std::string cloud = "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n0 0 0\n";
  const std::string ply_header =
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
      "end_header\n";
  const std::string obj_cloud = "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nv 0 0 0\n";
  for (const auto& file : {dir.write("cloud.ply", ply_header + cloud), dir.write("cloud.obj", obj_cloud),
                           dir.write("cloud.off", "OFF\n5 0 0\n" + cloud)}) {
    INFO(file);
    const auto d = io::load_shape(file);
    CHECK(d.kind == io::ShapeData::Kind::Points);
    CHECK(d.vertices == io::load_shape(pts).vertices);
    const auto h = io::load_shape("hull:" + file);
    CHECK(h.kind == io::ShapeData::Kind::Points);
    CHECK(h.vertices.size() == 5);
  }

  CHECK_THROWS_WITH(io::load_shape(dir.write("c.3ds", "solid")), Catch::Contains("known extension"));
  // .stl and .ply are read (soup_reader.hpp): an STL without facets is an error naming it
  CHECK_THROWS_WITH(io::load_shape(dir.write("c.stl", "solid")), Catch::Contains("c.stl: no vertices"));
  CHECK_THROWS_WITH(io::load_shape((dir.path / "missing.off").string()),
                    Catch::Contains("missing.off: cannot open"));
  CHECK_THROWS_WITH(io::load_shape(""), Catch::Contains("empty shape argument"));
  // a built-in name wins over a file; ./name reads the file
  CHECK_FALSE(io::is_builtin_shape("./cube"));
  CHECK_THROWS_WITH(io::load_shape("./cube"), Catch::Contains("known extension"));
  CHECK_FALSE(io::is_builtin_shape("cubes"));
  CHECK_FALSE(io::is_builtin_shape("boxes.off"));
}

TEST_CASE("shape source: OBJ objects by #NAME or #K, hull:, and - for standard input", "[shapes]") {
  const test::TempDir dir("sepax_shape_source_objects");
  const std::string tet = "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\n";
  const std::string faces = "f 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";
  const std::string two = dir.write("two.obj", "o a\n" + tet + faces + "o b piece\n" + tet +
                                                   "f -4 -3 -2\nf -4 -1 -3\nf -4 -2 -1\nf -3 -1 -2\n");
  CHECK(io::load_shape(two + "#a").name == two + "#a");
  CHECK(io::load_shape(two + "#b piece").vertices.size() == 4);
  CHECK(io::load_shape(two + "#1").name == two + "#b piece");
  CHECK_THROWS_WITH(io::load_shape(two), Catch::Contains("holds 2 objects (0 'a', 1 'b piece')"));
  CHECK_THROWS_WITH(io::load_shape(two + "#c"), Catch::Contains("no object 'c'"));
  // a '#' in another file's name is part of the name
  CHECK_THROWS_WITH(io::load_shape(dir.path.string() + "/x#1.off"), Catch::Contains("x#1.off: cannot open"));
  const auto listing = io::object_listing(two);
  REQUIRE(listing);
  CHECK_THAT(listing->text(),
             Catch::Contains("2 objects") && Catch::Contains("1  b piece: 4 vertices, 4 faces"));
  REQUIRE(listing->objects.size() == 2);
  CHECK(listing->objects[1].name == "b piece");
  CHECK(listing->objects[1].faces == 4);
  CHECK_FALSE(io::object_listing(two + "#a"));
  CHECK_FALSE(io::object_listing("cube"));

  // hull: the vertices as a point set, named as written
  const auto h = io::load_shape("hull:" + two + "#a");
  CHECK(h.kind == io::ShapeData::Kind::Points);
  CHECK(h.name == "hull:" + two + "#a");
  CHECK(h.vertices.size() == 4);
  CHECK(h.faces.empty());
  CHECK(io::load_shape("hull:cube").vertices.size() == 8);
  CHECK_THROWS_WITH(io::load_shape("hull:"), Catch::Contains("empty shape argument"));

  // standard input
  std::istringstream obj(tet + faces);
  const auto s = io::load_shape("-", obj);
  CHECK(s.name == "standard input");
  CHECK(s.faces.size() == 4);
  std::istringstream objects("o a\n" + tet + faces + "o b\n" + tet + faces);
  CHECK(io::load_shape("-:obj#b", objects).vertices.size() == 4);
  std::istringstream points("1,1,1\n1,-1,-1\n-1,1,-1\n-1,-1,1\n");
  CHECK(io::load_shape("hull:-", points).kind == io::ShapeData::Kind::Points);
  std::istringstream counts("4 4 6\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
  CHECK(io::load_shape("-:OFF", counts).faces.size() == 4);  // a header-less OFF must be named
}
