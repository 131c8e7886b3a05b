// Tests for src/commands/audit_command.cpp: `sepax audit` takes the shapes
// `sepax query` takes (built-ins, OFF/OBJ face lists, points files), rounds
// them to float, and names the file in every error.
#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <sepax/error.hpp>

#include "cli/cli_test_support.hpp"
#include "commands/audit_command.hpp"
#include "commands/shape_pair.hpp"
#include "io/shape_source.hpp"

using namespace sepax;
using namespace sepax::cli;

namespace {

using Run = test::CommandRun;
using test::temp_file;

// audit_main prints to std::cout / std::cerr: captured.
Run audit(std::vector<std::string> args, const std::string& stdin_text = "") {
  args.insert(args.begin(), "audit");
  return test::verb_main(&audit_main, std::move(args), stdin_text);
}

}  // namespace

TEST_CASE("audit: a points file and an OFF file, as for sepax query", "[audit]") {
  // The seed talk's case: a double-sided triangle lying on a box face.
  const std::string tri = temp_file("tri.pts", "0 0 0\n1 0 0\n0 1 0\n");
  // The built-in cube written out as an OFF file, in its own vertex and face order.
  const io::ShapeData c = io::builtin_shape("cube");
  std::ostringstream off;
  off << "OFF\n" << c.vertices.size() << " " << c.faces.size() << " 0\n";
  for (const auto& v : c.vertices) off << v[0] << " " << v[1] << " " << v[2] << "\n";
  for (const auto& f : c.faces) {
    off << f.size();
    for (int i : f) off << " " << i;
    off << "\n";
  }
  const std::string cube = temp_file("cube.off", off.str());
  const Run r = audit({tri, cube, "--pose", "0", "0", "1"});
  CHECK(r.status == 0);
  CHECK(r.err.empty());  // float-valued input: no rounding note
  CHECK_THAT(r.out, Catch::Contains("A: 3 vertices, 3 edges, 2 faces (double-sided polygon"));
  CHECK_THAT(r.out, Catch::Contains("B: 8 vertices, 12 edges, 6 faces"));
  CHECK_THAT(r.out, Catch::Contains("no unexplained disagreement"));
  // The file gives the same audit, line for line, as the built-in it was written from.
  const Run builtin = audit({tri, "cube", "--pose", "0", "0", "1"});
  CHECK(builtin.status == 0);
  CHECK(builtin.out == r.out);
}

TEST_CASE("audit: a file with one face is that polygon, double-sided", "[audit]") {
  const std::string obj = temp_file("tri1.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const Run r = audit({obj, "cube", "--pose", "0.25", "0.25", "1"});
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("A: 3 vertices, 3 edges, 2 faces (double-sided polygon"));
  const Run builtin = audit({"triangle", "cube", "--pose", "0.25", "0.25", "1"});
  CHECK(builtin.status == 0);
  CHECK(builtin.out == r.out);
}

TEST_CASE("audit: coordinates are rounded to float, with a note", "[audit]") {
  const std::string tri = temp_file("tri01.xyz", "0.1 0 0\n1 0 0\n0 1 0.3\n");
  const Run r = audit({tri, "cube"});
  CHECK(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("tri01.xyz: 2 coordinate(s) rounded to float"));
  std::ostringstream note;
  const fuzz::FuzzCase c = audit_case(load_pair({tri, "cube"}, false), nullptr, note);
  CHECK_THAT(note.str(), Catch::Contains("2 coordinate(s) rounded to float"));
  REQUIRE(c.a.vertices.size() == 3);
  for (const auto& v : c.a.vertices)
    for (int k = 0; k < 3; ++k) CHECK(static_cast<double>(static_cast<float>(v[k])) == v[k]);
}

TEST_CASE("audit: shapes are loaded and built as sepax query --number float builds them", "[audit][mesh]") {
  const std::string data = std::string(SEPAX_SOURCE_DIR) + "/tests/data/";
  // a triangulated cube OBJ is the cube (a closed convex mesh), as in query
  const Run tri = audit({data + "cube_tri.obj", "cube", "--pose", "2.5", "0", "0"});
  CHECK(tri.status == 0);
  CHECK_THAT(tri.out, Catch::Contains("A: 8 vertices, 12 edges, 6 faces"));
  const Run builtin = audit({"cube", "cube", "--pose", "2.5", "0", "0"});
  CHECK(builtin.status == 0);
  // V-HACD pieces 150 units from the origin: moved exactly near the origin,
  // with a note; float validates them there
  const Run pieces = audit({data + "vhacd_pieces.obj#convex_0", data + "vhacd_pieces.obj#1"});
  CHECK(pieces.status == 0);
  CHECK_THAT(pieces.err, Catch::Contains("the shapes are audited moved by -(150"));
  CHECK_THAT(pieces.out, Catch::Contains("no unexplained disagreement"));
  std::ostringstream note;
  const fuzz::FuzzCase c = audit_case(
      load_pair({data + "vhacd_pieces.obj#convex_0", data + "vhacd_pieces.obj#1"}, false), nullptr, note);
  for (const auto& v : c.a.vertices) CHECK(std::abs(v[0]) < 1);
  // standard input, with the format guessed from the content
  const Run in = audit({"-", "cube", "--pose", "2.5", "0", "0"}, test::file_text(data + "cube.off"));
  CHECK(in.status == 0);
  CHECK(in.out == builtin.out);
  // a .case as the pair or through --case: the case as it is
  const std::string corpus = std::string(SEPAX_SOURCE_DIR) + "/fuzz/corpus/00-triangle-on-box-face.case";
  const Run as_pair = audit({corpus});
  const Run as_option = audit({"--case", corpus});
  CHECK(as_pair.status == 0);
  CHECK(as_pair.out == as_option.out);
  CHECK(as_pair.err.empty());
  CHECK(audit({corpus, "--pose", "1", "0", "0"}).status == 2);
  // an invalid case names the file
  const Run inward = audit({std::string(SEPAX_SOURCE_DIR) + "/fuzz/corpus/invalid-inward-box.case"});
  CHECK(inward.status == 3);
  CHECK_THAT(inward.err,
             Catch::StartsWith("sepax audit: error: ") && Catch::Contains("invalid-inward-box.case A: "));
}

TEST_CASE("audit: bad shape arguments name the file and exit 3", "[audit][errors]") {
  const Run missing = audit({"/nonexistent/sepax_no_such.off", "cube"});
  CHECK(missing.status == 3);
  CHECK_THAT(missing.err, Catch::Contains("sepax_no_such.off"));
  const std::string big = temp_file("big.pts", "0 0 0\n1e39 0 0\n0 1 0\n");
  const Run overflow = audit({big, "cube"});
  CHECK(overflow.status == 3);
  CHECK_THAT(overflow.err,
             Catch::Contains("big.pts: coordinate x of point 1 (1e+39) is beyond the range of float"));
  const Run overflow_json = audit({big, "cube", "--json"});
  CHECK(overflow_json.status == 3);
  CHECK_THAT(overflow_json.out,
             Catch::StartsWith("{\"error\":\"") && Catch::Contains("is beyond the range of float"));
  const std::string line = temp_file("line.pts", "0 0 0\n1 0 0\n2 0 0\n");
  const Run collinear = audit({"cube", line});
  CHECK(collinear.status == 3);
  CHECK_THAT(collinear.err, Catch::Contains("line.pts: "));
  const Run unknown = audit({"cube", "dodecahedron"});
  CHECK(unknown.status == 3);
  CHECK_THAT(unknown.err, Catch::Contains("dodecahedron"));
  const Run usage = audit({"cube"});
  CHECK(usage.status == 2);
  CHECK_THAT(usage.err, Catch::Contains("OFF, OBJ, PLY or STL meshes"));
}
