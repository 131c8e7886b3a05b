// What a new user feeds the sepax program, run as the program itself (a
// child process, killed after a timeout): empty files, binary garbage, NaN
// and 1e300 coordinates, too few or coplanar points, a non-convex mesh, a
// scanned mesh of a million vertices, a missing file, a directory, an unknown
// option.  Each gets the documented exit status (docs/cli.md) and a message
// naming the problem; none may crash or hang.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/cli_test_support.hpp"

using namespace sepax::cli;

namespace {

const std::string kData = std::string(SEPAX_SOURCE_DIR) + "/tests/data/";

/// The verbs that take a shape, each with `shape` in a command line.
std::vector<std::vector<std::string>> commands_on(const std::string& shape) {
  std::vector<std::vector<std::string>> c = {
      {"query", "cube", shape},
      {"info", shape},
      {"render", shape, "cube", "--svg", "-"},
  };
#ifdef SEPAX_HAVE_FUZZ
  c.push_back({"audit", "cube", shape});
#endif
  return c;
}

void check_run(const std::vector<std::string>& args, int status, const std::string& message,
               const std::string& stdin_path = "") {
  std::string line;
  for (const auto& a : args) line += " " + a;
  INFO("sepax" << line);
  const test::ProgramRun r = test::run_program(args, stdin_path, 60);
  INFO("stderr: " << r.err.substr(0, 600));
  REQUIRE_FALSE(r.timed_out);
  REQUIRE(r.signal == 0);
  CHECK(r.status == status);
  CHECK_THAT(r.err, Catch::Contains(message));
}

/// Every verb on the file gives status 3 and a message with `message`.
void check_unreadable(const std::string& path, const std::string& message) {
  for (const auto& args : commands_on(path)) check_run(args, 3, message);
}

/// Deterministic bytes of every value (a linear congruential sequence).
std::string garbage(std::size_t n, unsigned seed) {
  std::string s(n, '\0');
  unsigned x = seed;
  for (auto& c : s) {
    x = x * 1664525u + 1013904223u;
    c = static_cast<char>(x >> 24);
  }
  return s;
}

}  // namespace

TEST_CASE("bad input: empty files", "[bad_input]") {
  check_unreadable(test::temp_file("empty.obj", ""), "empty.obj:1: empty file");
  check_unreadable(test::temp_file("empty.off", ""), "empty.off:1: empty file: expected the OFF header");
  check_unreadable(test::temp_file("empty.pts", ""), "empty.pts:1: empty file: no points");
  check_unreadable(test::temp_file("empty.stl", ""), "empty.stl: no vertices in the file");
  check_unreadable(test::temp_file("empty.ply", ""),
                   "empty.ply:1: not a readable PLY file: the file is empty");
  check_run({"query", "-", "cube"}, 3, "standard input: nothing to read");
}

TEST_CASE("bad input: binary garbage", "[bad_input]") {
  for (unsigned seed : {1u, 2u, 3u}) {
    const std::string bytes = garbage(4096, seed);
    const std::string tag = std::to_string(seed);
    check_unreadable(test::temp_file("garbage" + tag + ".obj", bytes), "garbage" + tag + ".obj:");
    check_unreadable(test::temp_file("garbage" + tag + ".off", bytes), "garbage" + tag + ".off:1: ");
    check_unreadable(test::temp_file("garbage" + tag + ".pts", bytes), "garbage" + tag + ".pts:");
    check_unreadable(test::temp_file("garbage" + tag + ".stl", bytes), "garbage" + tag + ".stl: ");
    check_unreadable(test::temp_file("garbage" + tag + ".ply", bytes),
                     "garbage" + tag + ".ply:1: not a readable PLY file: ");
  }
  // garbage on standard input
  check_run({"query", "-", "cube"}, 3, "standard input: ", test::temp_file("garbage.bin", garbage(4096, 4)));
}

TEST_CASE("bad input: bytes that are not UTF-8 in names, ids and batch lines", "[bad_input]") {
  // JSON output stays valid JSON and SVG stays well-formed XML: each invalid byte is U+FFFD
  const std::string replacement = "\xEF\xBF\xBD";
  const std::string off = test::temp_file("\xff.off",
                                          "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                          "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  auto no_raw_byte = [](const std::string& s) { return s.find('\xff') == std::string::npos; };
  test::ProgramRun r = test::run_program({"info", off, "--json"}, "", 60);
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("{\"shape\":\"") && Catch::Contains(replacement + ".off\""));
  CHECK(no_raw_byte(r.out));
  r = test::run_program({"render", off, "cube", "--svg", "-"}, "", 60);
  CHECK(r.status == 0);
  CHECK(no_raw_byte(r.out));
  r = test::run_program({"query", "box:1,\xff,1", "cube", "--json"}, "", 60);
  CHECK(r.status == 3);
  CHECK_THAT(r.out, Catch::StartsWith("{\"error\":\"shape 'box:1," + replacement));
  // a batch: a bad id, a line of one bad byte, then a good line that is still answered
  const std::string tri = "\"a\":[[0,0,0],[1,0,0],[0,1,0]],\"b\":[[2,0,0],[3,0,0],[2,1,0]]";
  const std::string batch =
      test::temp_file("utf8.jsonl", "{\"id\":\"\xff\"," + tri + "}\n\xff\n{\"id\":2," + tri + "}\n");
  for (const char* jobs : {"1", "2"}) {
    INFO("--jobs " << jobs);
    r = test::run_program({"query", "--batch", batch, "--jobs", jobs}, "", 60);
    REQUIRE(r.signal == 0);
    CHECK(r.status == 1);
    CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 3);
    CHECK_THAT(r.out,
               Catch::Contains("line 2: invalid JSON") && Catch::Contains("{\"id\":2,\"overlap\":false"));
    CHECK(no_raw_byte(r.out));
  }
}

TEST_CASE("bad input: NaN, infinite and out-of-range coordinates", "[bad_input]") {
  const std::string tet_faces = "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  check_unreadable(test::temp_file("nan.obj", "v 0 0 0\nv 1 0 nan\nv 0 1 0\nv 0 0 1\n" + tet_faces),
                   "nan.obj:2: coordinate z of vertex 2 is 'nan': NaN and infinity are not allowed");
  check_unreadable(test::temp_file("nan.pts", "0 0 0\n1 0 0\n0 NaN 0\n0 0 1\n"),
                   "nan.pts:3: coordinate y of point 2 is 'NaN'");
  check_unreadable(test::temp_file("inf.off", "OFF\n4 4 6\n0 0 0\ninf 0 0\n0 1 0\n0 0 1\n"),
                   "inf.off:4: coordinate x of vertex 1 is 'inf'");
  check_unreadable(test::temp_file("e400.pts", "0 0 0\n1e400 0 0\n0 1 0\n0 0 1\n"),
                   "e400.pts:2: number '1e400' for coordinate x of point 1 is out of the range of a double");
}

TEST_CASE("bad input: a pose that moves a point beyond double's range", "[bad_input]") {
  // The file's coordinates are finite; the pose's translation takes them past max(double): BadScale naming
  // the point, in every number type (the pose is applied in double first), for a point set and a face list.
  const std::string pts = test::temp_file("far.pts", "0 0 0\n1e308 0 0\n0 1 0\n0 0 1\n");
  const std::string obj = test::temp_file(
      "far.obj", "v 0 0 0\nv 1e308 0 0\nv 0 1e308 0\nv 0 0 1e308\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  for (const char* number : {"double", "float", "exact"}) {
    check_run({"info", pts, "--pose", "1e308", "0", "0", "--number", number}, 3,
              "far.pts: the pose moves coordinate x of point 1 beyond the range of double");
    check_run({"query", "cube", obj, "--pose", "1e308", "0", "0", "--number", number}, 3,
              "far.obj: the pose moves coordinate x of vertex 1 beyond the range of double");
  }
}

TEST_CASE("bad input: a vertex on no face is named with its line", "[bad_input]") {
  // OFF and ASCII PLY: the unused vertex is the file's fifth (index 4), on line 7 and 14.  (An OBJ's
  // object takes the vertices its faces use: an unused one is dropped.)
  const std::string off = test::temp_file(
      "unused.off", "OFF\n5 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n5 5 5\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const std::string ply =
      test::temp_file("unused.ply",
                      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\n"
                      "property float y\nproperty float z\nelement face 4\n"
                      "property list uchar int vertex_indices\nend_header\n"
                      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n5 5 5\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  check_run({"info", off}, 3, "unused.off:7: vertex 4 is on no face");
  check_run({"info", ply}, 3, "unused.ply:14: vertex 4 is on no face");
}

TEST_CASE("bad input: 1e300 coordinates", "[bad_input]") {
  // A face list at 1e300 is a valid shape in double and exactly: the same
  // answer both ways.  float cannot hold it: an error naming the coordinate.
  const std::string big = test::temp_file(
      "big.obj", "v 0 0 0\nv 1e300 0 0\nv 0 1e300 0\nv 0 0 1e300\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const test::ProgramRun d = test::run_program({"query", "cube", big, "--json"}, "", 60);
  const test::ProgramRun e = test::run_program({"query", "cube", big, "--json", "--number", "exact"}, "", 60);
  CHECK(d.status == 0);
  CHECK(e.status == 0);
  CHECK_THAT(d.out, Catch::StartsWith("{\"overlap\":true,\"separation\":-1,\"feature\":{\"type\":\"faceA\""));
  CHECK_THAT(e.out, Catch::StartsWith("{\"overlap\":true,\"separation\":-1,\"feature\":{\"type\":\"faceA\""));
  check_run({"query", "cube", big, "--number", "float"}, 3,
            "big.obj: coordinate x of vertex 1 (1e+300) is beyond the range of float");
  // the same points as a point set: its hull is that tetrahedron (numbered its own way), the same answer
  const test::ProgramRun p = test::run_program(
      {"query", "cube", test::temp_file("big.pts", "0 0 0\n1e300 0 0\n0 1e300 0\n0 0 1e300\n"), "--json"}, "",
      60);
  CHECK(p.status == 0);
  CHECK_THAT(p.out, Catch::StartsWith("{\"overlap\":true,\"separation\":-1,\"feature\":{\"type\":\"faceA\""));
  // points beyond max/16 of double: an error naming the range
  check_run({"query", "cube", test::temp_file("huge.pts", "0 0 0\n1.5e308 0 0\n0 1e300 0\n0 0 1e300\n")}, 3,
            "huge.pts: coordinates up to 1.5e+308 are out of range for double");
}

TEST_CASE("bad input: too few, collinear and coplanar points", "[bad_input]") {
  check_unreadable(test::temp_file("two.pts", "0 0 0\n1 0 0\n"),
                   "two.pts: convex_hull: needs at least 3 distinct points, got 2");
  check_unreadable(test::temp_file("line.pts", "0 0 0\n1 0 0\n2 0 0\n"), "line.pts: convex_hull: ");
  // coplanar points are a documented result: the flat double-sided polygon
  const std::string flat = test::temp_file("flat.pts", "0 0 0\n1 0 0\n0 1 0\n1 1 0\n");
  const test::ProgramRun r = test::run_program({"info", flat}, "", 60);
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("4 vertices, 4 edges, 2 faces (flat: a double-sided polygon)"));
}

TEST_CASE("bad input: a non-convex OBJ is refused with the way out", "[bad_input]") {
  // the cube with its top pushed in to a point below the top
  const std::string dent = test::temp_file(
      "dent.obj",
      "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\nv 0 0 0.5\n"
      "f 1 4 3\nf 1 3 2\nf 5 6 9\nf 6 7 9\nf 7 8 9\nf 8 5 9\nf 1 2 6\nf 1 6 5\nf 3 4 8\nf 3 8 7\nf 1 5 8\n"
      "f 1 8 4\nf 2 3 7\nf 2 7 6\n");
  for (const auto& args : commands_on(dent))
    check_run(
        args, 3,
        "the mesh is not convex; to use the convex hull of the vertices, write hull:FILE (or pass --hull)");
  check_run({"query", "cube", dent, "--hull"}, 0, "");
}

TEST_CASE("bad input: missing file, directory, unknown extension, unknown option", "[bad_input]") {
  check_unreadable("/nonexistent/shape.obj",
                   "/nonexistent/shape.obj: cannot open: No such file or directory");
  const std::string dir = (test::temp_dir().path / "folder.obj").string();
  std::filesystem::create_directories(dir);
  check_unreadable(dir, "folder.obj: cannot open: is a directory");
  check_unreadable("shape.dxf", "'shape.dxf' is neither a built-in shape");
  for (const char* verb : {"query", "info", "render", "audit", "fuzz"}) {
#ifndef SEPAX_HAVE_FUZZ
    if (std::string(verb) == "audit" || std::string(verb) == "fuzz") continue;
#endif
    check_run({verb, "--frobnicate"}, 2, std::string("sepax ") + verb + ": unknown option '--frobnicate'");
  }
}

TEST_CASE("bad input: a scanned mesh of a million vertices is refused in bounded time and memory",
          "[bad_input][huge]") {
  // A 1000 x 1000 height field (an open surface, as a scan is): 10^6
  // vertices, about 2 * 10^6 triangles, 86 MB of OBJ text.
  const std::string path = (test::temp_dir().path / "scan.obj").string();
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    REQUIRE(f != nullptr);
    const int n = 1000;
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const double x = i / double(n - 1) * 2 - 1, y = j / double(n - 1) * 2 - 1;
        std::fprintf(f, "v %.9g %.9g %.9g\n", x, y, 0.1 * std::sin(7 * x) * std::cos(5 * y));
      }
    }
    for (int i = 0; i + 1 < n; ++i) {
      for (int j = 0; j + 1 < n; ++j) {
        const int a = i * n + j + 1, b = a + n;
        std::fprintf(f, "f %d %d %d\nf %d %d %d\n", a, b, b + 1, a, b + 1, a + 1);
      }
    }
    REQUIRE(std::fclose(f) == 0);
  }
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"query", path, "cube"}, {"info", path}}) {
    INFO(args[0]);
    const test::ProgramRun r = test::run_program(args, "", 300);
    REQUIRE_FALSE(r.timed_out);
    REQUIRE(r.signal == 0);
    CHECK(r.status == 3);
    CHECK_THAT(
        r.err,
        Catch::Contains("scan.obj:1000001: face 0: its edge 0-1000 is on no other face: the mesh is open") &&
            Catch::Contains("hull:FILE"));
    // peak memory: about 5 times the file's size (the text is read line by
    // line; the vertices, faces and their directed edges are held)
    CHECK(r.max_rss_kb < 1024 * 1024);
    // processor time (wall time depends on the machine's load): reading and
    // checking take a few seconds; 30 leaves room for a slow machine
    CHECK(r.cpu_seconds < 30);
    WARN(args[0] << ": " << r.cpu_seconds << " s processor time (" << r.seconds << " s wall), "
                 << r.max_rss_kb / 1024 << " MB peak");
  }
  std::filesystem::remove(path);
}
