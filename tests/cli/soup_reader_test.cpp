// Tests for src/io/soup_reader.cpp: PLY and STL through CGAL's polygon-soup
// readers.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include <sepax/error.hpp>

#include "cli/cli_test_support.hpp"
#include "io/soup_reader.hpp"

using namespace sepax;
using namespace sepax::cli;

namespace {

const std::string kData = std::string(SEPAX_SOURCE_DIR) + "/tests/data/";

/// The cube [-1,1]^3 as 12 triangles over 8 distinct points.
void check_triangulated_cube(const io::ShapeData& d) {
  CHECK(d.kind == io::ShapeData::Kind::Faces);
  CHECK(d.from_file);
  REQUIRE(d.vertices.size() == 8);
  CHECK(d.faces.size() == 12);
  for (const auto& v : d.vertices) {
    for (int c = 0; c < 3; ++c) CHECK(std::abs(v[c]) == 1);
  }
  for (const auto& f : d.faces) {
    CHECK(f.size() == 3);
    for (const int i : f) CHECK((i >= 0 && i < 8));
  }
}

}  // namespace

TEST_CASE("soup readers: the ASCII STL, binary STL and PLY cubes of tests/data", "[soup]") {
  check_triangulated_cube(io::read_stl_file(kData + "cube.stl"));
  check_triangulated_cube(io::read_stl_file(kData + "cube_binary.stl"));
  check_triangulated_cube(io::read_ply_file(kData + "cube.ply"));
  // the same from a stream (standard input)
  std::istringstream stl(test::file_text(kData + "cube_binary.stl"));
  check_triangulated_cube(io::read_stl(stl, "standard input"));
  std::istringstream ply(test::file_text(kData + "cube.ply"));
  check_triangulated_cube(io::read_ply(ply, "standard input"));
}

TEST_CASE("soup readers: a binary PLY and polygons of more than three vertices", "[soup]") {
  // binary little-endian PLY: two quads sharing nothing (a face list's check
  // comes later); the reader only has to return them as written
  std::string bin =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const float xyz[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  bin.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  bin.push_back(4);
  for (std::int32_t i = 0; i < 4; ++i) bin.append(reinterpret_cast<const char*>(&i), 4);
  std::istringstream in(bin);
  const io::ShapeData d = io::read_ply(in, "quad.ply");
  REQUIRE(d.vertices.size() == 4);
  CHECK(d.vertices[2] == Vec3<double>(1, 1, 0));
  REQUIRE(d.faces.size() == 1);
  CHECK(d.faces[0] == std::vector<int>{0, 1, 2, 3});
}

TEST_CASE("soup readers: a PLY of vertices only (a scanner's point cloud) is a point set", "[soup]") {
  std::istringstream in(
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
  const io::ShapeData d = io::read_ply(in, "cloud.ply");
  CHECK(d.kind == io::ShapeData::Kind::Points);
  REQUIRE(d.vertices.size() == 4);
  CHECK(d.vertices[3] == Vec3<double>(0, 0, 1));
  CHECK(d.faces.empty());
}

TEST_CASE("soup readers: malformed files are errors naming the file, never a crash", "[soup]") {
  const test::TempDir dir("sepax_soup_reader_test");
  const struct {
    const char* name;
    std::string text;
    const char* problem;
  } cases[] = {
      {"garbage.ply", "this is not a ply file\n", "not a readable PLY file"},
      {"empty.ply", "", "not a readable PLY file"},
      {"header_only.ply", "ply\nformat ascii 1.0\nend_header\n", "no vertices"},
      {"truncated.ply",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n",
       "not a readable PLY file"},
      {"bad_index.ply",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
       "vertex index 7 is out of range"},
      {"garbage.stl", "solid x\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 zero\n",
       "no vertices"},
      {"empty.stl", "", "no vertices"},
      {"short.stl", std::string(80, ' ') + std::string("\x05\x00\x00\x00", 4) + std::string(20, '\0'),
       "not a readable STL file"},
  };
  for (const auto& c : cases) {
    INFO(c.name);
    const std::string path = dir.write(c.name, c.text);
    const bool stl = std::string(c.name).ends_with(".stl");
    try {
      (void)(stl ? io::read_stl_file(path) : io::read_ply_file(path));
      FAIL("accepted a malformed file");
    } catch (const InvalidInput& e) {
      CHECK(e.code() == ErrorCode::Parse);
      CHECK_THAT(e.what(), Catch::StartsWith(path + ": ") && Catch::Contains(c.problem));
    }
  }
  CHECK_THROWS_WITH(io::read_ply_file("/nonexistent/x.ply"),
                    Catch::StartsWith("/nonexistent/x.ply: cannot open"));
  CHECK_THROWS_WITH(io::read_stl_file("/nonexistent/x.stl"),
                    Catch::StartsWith("/nonexistent/x.stl: cannot open"));
}
