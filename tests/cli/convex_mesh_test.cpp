// Tests for src/io/convex_mesh.hpp and src/io/closed_mesh.cpp, through the
// program's shape building (commands/shape_builder.hpp): closed convex
// meshes as users have them load as their polyhedra; open, non-manifold and
// non-convex ones are refused naming the problem and suggesting hull:.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include <gmpxx.h>

#include <sepax/error.hpp>
#include <sepax/robust/number_types.hpp>

#include "commands/sat_runner.hpp"
#include "commands/shape_builder.hpp"
#include "io/closed_mesh.hpp"
#include "io/obj_reader.hpp"
#include "io/shape_source.hpp"

using namespace sepax;
using namespace sepax::cli;

namespace {

const std::string kData = std::string(SEPAX_SOURCE_DIR) + "/tests/data/";

io::ShapeData obj(const std::string& text, const std::string& name = "m.obj") {
  std::istringstream in(text);
  return io::read_obj(in, name);
}

const char* kCubeVerts =
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n";

// The cube's 12 triangles (1-based), two per side.
const char* kCubeTris =
    "f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 3 4 8\nf 3 8 7\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 "
    "7 6\n";

template <Number T>
void check_cube(const io::ShapeData& d) {
  const ConvexPolyhedron<T> p = build_shape<T>(d);
  CHECK(p.vertex_count() == 8);
  CHECK(p.edge_count() == 12);
  CHECK(p.face_count() == 6);
  for (const auto& v : p.vertices()) {
    for (int c = 0; c < 3; ++c) CHECK((v[c] == T(1) || v[c] == T(-1)));
  }
}

template <Number T>
void check_refused(const io::ShapeData& d, const std::string& problem) {
  try {
    (void)build_shape<T>(d);
    FAIL("accepted");
  } catch (const InvalidInput& e) {
    CHECK_THAT(e.what(),
               Catch::StartsWith(d.name) && Catch::Contains(problem) && Catch::Contains("hull:FILE"));
  }
}

}  // namespace

TEST_CASE("convex mesh: the triangulated cube is the cube in every number type", "[mesh]") {
  const io::ShapeData files[] = {
      io::load_shape(kData + "cube_tri.obj"),
      io::load_shape(kData + "cube.stl"),
      io::load_shape(kData + "cube_binary.stl"),
      io::load_shape(kData + "cube.ply"),
      obj(std::string(kCubeVerts) + kCubeTris),
      // a texture seam: vertex 1 repeated as vertex 9, used by two triangles
      obj(std::string(kCubeVerts) + "v -1 -1 -1\n" +
          "f 9 4 3\nf 9 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 3 4 8\nf 3 8 7\nf 1 5 8\nf 1 8 4\nf 2 3 "
          "7\nf 2 7 6\n"),
      // a side split into four triangles around a vertex at its centre
      obj(std::string(kCubeVerts) + "v 0 0 -1\n" +
          "f 1 4 9\nf 4 3 9\nf 3 2 9\nf 2 1 9\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 3 4 8\nf 3 8 7\nf 1 5 "
          "8\n"
          "f 1 8 4\nf 2 3 7\nf 2 7 6\n"),
  };
  for (const auto& d : files) {
    INFO(d.name);
    check_cube<float>(d);
    check_cube<double>(d);
    check_cube<mpq_class>(d);
  }
  // info reports the cube
  for (const NumberKind n : {NumberKind::Float, NumberKind::Double, NumberKind::Exact}) {
    const ShapeCounts c = shape_counts(files[0], n);
    CHECK(c.vertices == 8);
    CHECK(c.edges == 12);
    CHECK(c.faces == 6);
  }
}

TEST_CASE("convex mesh: open, non-manifold, inconsistent and non-convex meshes are refused", "[mesh]") {
  const std::string v = kCubeVerts;
  // open: the last triangle missing
  const auto open = obj(
      v +
      "f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 3 4 8\nf 3 8 7\nf 1 5 8\nf 1 8 4\nf 2 3 7\n");
  // inconsistent: one triangle turned over
  const auto flipped = obj(v +
                           "f 1 3 4\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 3 4 8\nf 3 8 7\nf 1 5 "
                           "8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n");
  // non-convex: the top's centre pushed down into the cube (a dent)
  const auto dent = obj(
      v + "v 0 0 0.5\n" +
      "f 1 4 3\nf 1 3 2\nf 5 6 9\nf 6 7 9\nf 7 8 9\nf 8 5 9\nf 1 2 6\nf 1 6 5\nf 3 4 8\nf 3 8 7\nf 1 5 8\n"
      "f 1 8 4\nf 2 3 7\nf 2 7 6\n");
  for (const auto& [d, problem] :
       {std::pair{open, "the mesh is open"}, std::pair{flipped, "inconsistently oriented"},
        std::pair{dent, "not convex"}}) {
    INFO(problem);
    check_refused<float>(d, problem);
    check_refused<double>(d, problem);
    check_refused<mpq_class>(d, problem);
  }
  // the error names the face and its line in the file
  try {
    (void)build_shape<double>(open);
    FAIL("accepted");
  } catch (const InvalidInput& e) {
    CHECK_THAT(e.what(),
               Catch::Matches("m\\.obj:[0-9]+: face [0-9]+: its edge [0-9]+-[0-9]+ is on no other face.*"));
  }
  // a dented mesh names the vertex inside the hull (vertex 8, 0-based)
  CHECK_THROWS_WITH(build_shape<mpq_class>(dent), Catch::Contains("its vertex 8 is inside the convex hull"));
  // as a point set (what hull: makes of it), the dented mesh is the cube
  io::ShapeData h = dent;
  h.kind = io::ShapeData::Kind::Points;
  CHECK(build_shape<double>(h).face_count() == 6);
}

TEST_CASE("convex mesh: a face that is not the hull's boundary (a flat fold) is refused", "[mesh]") {
  // a closed 2-manifold whose top and bottom are the same square, turned
  // over and triangulated along the other diagonal: it encloses nothing
  const auto flat = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4\nf 1 4 3\nf 1 3 2\nf 2 3 4\n");
  check_refused<double>(flat, "enclose no volume");
}

TEST_CASE("convex mesh: built-in shapes and single faces keep their own errors", "[mesh]") {
  // a built-in's validation error has no hull: suggestion
  CHECK_THROWS_WITH(io::load_shape("box:1,1,1e-30"), !Catch::Contains("hull:"));
  // the closed_mesh check on its own
  const auto open = obj(std::string(kCubeVerts) + "f 1 4 3\nf 1 3 2\n");
  CHECK_THROWS_AS(io::closed_mesh(open), InvalidInput);
  const auto m = io::closed_mesh(obj(std::string(kCubeVerts) + kCubeTris));
  CHECK(m.vertex.size() == 8);
  CHECK(m.faces.size() == 12);
}
