// Tests for src/io/soup_reader.cpp: STL through CGAL's polygon-soup reader.
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

TEST_CASE("soup readers: the ASCII and binary STL cubes of tests/data", "[soup]") {
  check_triangulated_cube(io::read_stl_file(kData + "cube.stl"));
  check_triangulated_cube(io::read_stl_file(kData + "cube_binary.stl"));
  // the same from a stream (standard input)
  std::istringstream stl(test::file_text(kData + "cube_binary.stl"));
  check_triangulated_cube(io::read_stl(stl, "standard input"));
}

TEST_CASE("soup readers: malformed files are errors naming the file, never a crash", "[soup]") {
  const test::TempDir dir("sepax_soup_reader_test");
  const struct {
    const char* name;
    std::string text;
    const char* problem;
  } cases[] = {
      {"garbage.stl", "solid x\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 zero\n",
       "no vertices"},
      {"empty.stl", "", "no vertices"},
      {"short.stl", std::string(80, ' ') + std::string("\x05\x00\x00\x00", 4) + std::string(20, '\0'),
       "not a readable STL file"},
  };
  for (const auto& c : cases) {
    INFO(c.name);
    const std::string path = dir.write(c.name, c.text);
    try {
      (void)io::read_stl_file(path);
      FAIL("accepted a malformed file");
    } catch (const InvalidInput& e) {
      CHECK(e.code() == ErrorCode::Parse);
      CHECK_THAT(e.what(), Catch::StartsWith(path + ": ") && Catch::Contains(c.problem));
    }
  }
  CHECK_THROWS_WITH(io::read_stl_file("/nonexistent/x.stl"),
                    Catch::StartsWith("/nonexistent/x.stl: cannot open"));
}
