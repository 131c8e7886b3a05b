// Tests for src/commands/audit_command.cpp: `sepax audit` takes the shapes
// `sepax query` takes (built-ins, OFF/OBJ face lists, points files), rounds
// them to float, and names the file in every error.
#include <catch2/catch.hpp>

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <sepax/error.hpp>

#include "cli/cli_test_support.hpp"
#include "commands/audit_command.hpp"
#include "io/shape_source.hpp"

using namespace sepax;
using namespace sepax::cli;

namespace {

using Run = test::CommandRun;
using test::temp_file;

// audit_main prints to std::cout / std::cerr: capture both.
Run audit(std::vector<std::string> args) {
  args.insert(args.begin(), "audit");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  std::ostringstream out, err;
  auto* old_out = std::cout.rdbuf(out.rdbuf());
  auto* old_err = std::cerr.rdbuf(err.rdbuf());
  const int s = audit_main(static_cast<int>(argv.size()), argv.data());
  std::cout.rdbuf(old_out);
  std::cerr.rdbuf(old_err);
  return {s, out.str(), err.str()};
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
  const auto spec = audit_shape(tri, note);
  REQUIRE(spec.vertices.size() == 3);
  for (const auto& v : spec.vertices)
    for (int c = 0; c < 3; ++c) CHECK(static_cast<double>(static_cast<float>(v[c])) == v[c]);
}

TEST_CASE("audit: bad shape arguments name the file and exit 3", "[audit][errors]") {
  const Run missing = audit({"/nonexistent/sepax_no_such.off", "cube"});
  CHECK(missing.status == 3);
  CHECK_THAT(missing.err, Catch::Contains("sepax_no_such.off"));
  const std::string big = temp_file("big.pts", "0 0 0\n1e39 0 0\n0 1 0\n");
  const Run overflow = audit({big, "cube"});
  CHECK(overflow.status == 3);
  CHECK_THAT(overflow.err, Catch::Contains("big.pts: coordinate x of point 1 (1e+39) overflows float"));
  const std::string line = temp_file("line.pts", "0 0 0\n1 0 0\n2 0 0\n");
  const Run collinear = audit({"cube", line});
  CHECK(collinear.status == 3);
  CHECK_THAT(collinear.err, Catch::Contains("line.pts: "));
  const Run unknown = audit({"cube", "dodecahedron"});
  CHECK(unknown.status == 3);
  CHECK_THAT(unknown.err, Catch::Contains("dodecahedron"));
  const Run usage = audit({"cube"});
  CHECK(usage.status == 2);
  CHECK_THAT(usage.err, Catch::Contains("OFF or OBJ face list"));
}
