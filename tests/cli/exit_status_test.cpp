// Tests of the exit statuses of the sepax program (src/dispatch.cpp,
// src/commands/command_line.hpp, docs/cli.md): for every verb, each status
// it can give, with the message naming the problem.  Statuses 0-3 come from
// the program itself, run in a child process on real arguments.  Status 4 (an
// exception escaping a verb) is what no input of a correct program causes:
// here every verb is run through dispatch's run() in this process with
// standard output set to throw when a write fails, and writing to a buffer
// that refuses every byte.
#include <catch2/catch.hpp>

#include <iostream>
#include <streambuf>
#include <string>
#include <vector>

#include "cli/cli_test_support.hpp"
#include "dispatch.hpp"

using namespace sepax::cli;

namespace {

const std::string kData = std::string(SEPAX_SOURCE_DIR) + "/tests/data/";

struct Expectation {
  std::vector<std::string> args;  // the command line after `sepax`
  int status;
  const char* out;  // what standard output contains ("" for nothing asked)
  const char* err;  // what standard error contains ("" for nothing asked)
};

void check_program(const Expectation& e) {
  std::string line;
  for (const auto& a : e.args) line += " " + a;
  INFO("sepax" << line);
  const test::ProgramRun r = test::run_program(e.args, "", 120);
  INFO("stdout: " << r.out.substr(0, 600));
  INFO("stderr: " << r.err.substr(0, 600));
  REQUIRE_FALSE(r.timed_out);
  REQUIRE(r.signal == 0);
  CHECK(r.status == e.status);
  CHECK_THAT(r.out, Catch::Contains(e.out));
  CHECK_THAT(r.err, Catch::Contains(e.err));
}

// A stream buffer that refuses every byte: a write through it fails.
struct RefusingBuffer : std::streambuf {
  int_type overflow(int_type) override { return traits_type::eof(); }
  std::streamsize xsputn(const char*, std::streamsize) override { return 0; }
};

}  // namespace

TEST_CASE("exit status: query gives 0, 1 (a batch line failed), 2 and 3", "[exit]") {
  for (const Expectation& e : std::vector<Expectation>{
           {{"query", "cube", "cube", "--pose", "2.5", "0", "0"}, 0, "separation: 0.5", ""},
           {{"query", "--batch", kData + "batch.jsonl"},
            1,
            "\"error\":\"line 3: a: ",
            "2 of 4 queries failed"},
           {{"query", "cube", "cube", "--frobnicate"}, 2, "", "sepax query: unknown option '--frobnicate'"},
           {{"query", "cube"}, 2, "", "expected two shapes A and B, got 1"},
           {{"query", "--batch", kData + "batch.jsonl", "--jobs", "5000"},
            2,
            "",
            "--jobs: '5000' is too large (at most 1024)"},
           {{"query", "cube", "/nonexistent/shape.off"},
            3,
            "",
            "sepax query: error: /nonexistent/shape.off: cannot open"},
           {{"query", "cube", kData + "malformed.off", "--json"},
            3,
            "{\"error\":\"",
            "malformed.off:5: bad number 'oops'"},
           {{"query", "--batch", "/nonexistent/lines.jsonl"}, 3, "", "/nonexistent/lines.jsonl: cannot open"},
           // a unit cube posed 1e19 away: its coordinates round to a spacing of 2048 in double, so its
           // faces have no plane, in double and in the exact run on the same coordinates; the error ends
           // by saying where the pose placed it (the shape is built about its centre, at small coordinates)
           {{"query", "box:1e20,1e20,1e20", "cube", "--pose", "0", "1e19", "0"},
            3,
            "",
            "cube: face 0 has no plane at these coordinates"},
           {{"query", "box:1e20,1e20,1e20", "cube", "--pose", "0", "1e19", "0", "--number", "exact"},
            3,
            "",
            "cube: face 0 has no plane at these coordinates"},
           {{"query", "triangle", "cube", "--pose", "1e8", "-1e8", "0", "--number", "float", "--robust"},
            3,
            "",
            "cube: face 0 has no plane at these coordinates: its plane vertices 0, 3, 2 are collinear in "
            "float"},
           {{"query", "triangle", "cube", "--pose", "1e8", "-1e8", "0", "--number", "float"},
            3,
            "",
            "wider number type; the pose placed the shape at coordinates up to 100000001, rounded in float "
            "there"},
           {{"query", "box:1e20,1e20,1e20", "cube", "--pose", "0", "1e19", "0", "--number", "exact"},
            3,
            "",
            "wider number type; the pose placed the shape at coordinates up to 1e+19, rounded in double "
            "there"},
       })
    check_program(e);
}

TEST_CASE("exit status: info gives 0, 2 and 3", "[exit]") {
  for (const Expectation& e : std::vector<Expectation>{
           {{"info", "cube"}, 0, "cube: 8 vertices, 12 edges, 6 faces", ""},
           {{"info"}, 2, "", "sepax info: expected one shape, got 0"},
           {{"info", "cube", "--robust"}, 2, "", "sepax info: unknown option '--robust'"},
           {{"info", "box:0,1,1"}, 3, "", "sepax info: error: shape 'box:0,1,1'"},
           {{"info", "cube", "--pose", "1e308", "0", "0"},
            3,
            "",
            "sepax info: error: cube: face 0 has no plane at these coordinates: its plane vertices 0, 3, 2 "
            "are "
            "collinear in double (extent 2.83, coordinates up to 1): the shape is too small for its distance "
            "from the origin in this type; place it nearer the origin of its frame or use a wider number "
            "type; "
            "the pose placed the shape at coordinates up to 1e+308, rounded in double there"},
           {{"info", kData + "malformed.off"}, 3, "", "malformed.off:5: "},
           // a file of several objects lists them, as text or as JSON
           {{"info", kData + "vhacd_pieces.obj"}, 0, "2  convex_2: 14 vertices, 24 faces in the file", ""},
           {{"info", kData + "vhacd_pieces.obj", "--json"},
            0,
            "\"objects\":[{\"name\":\"convex_0\",\"vertices\":8,\"faces\":12}",
            ""},
       })
    check_program(e);
}

TEST_CASE("exit status: render gives 0, 2 and 3", "[exit]") {
  for (const Expectation& e : std::vector<Expectation>{
           {{"render", "cube", "cube", "--pose", "3", "0", "0", "--svg", "-"}, 0, "<svg ", ""},
           {{"render", "cube", "cube"}, 2, "", "sepax render: --svg FILE is required"},
           {{"render", "cube", "cube", "--svg", "-", "--number", "exact"},
            2,
            "",
            "unknown option '--number'"},
           {{"render", "cube", "/nonexistent/shape.obj", "--svg", "-"},
            3,
            "",
            "sepax render: error: /nonexistent/shape.obj: cannot open"},
           {{"render", "cube", "cube", "--svg", "/nonexistent/dir/picture.svg"},
            3,
            "",
            "cannot write /nonexistent/dir/picture.svg"},
       })
    check_program(e);
}

#ifdef SEPAX_HAVE_FUZZ
TEST_CASE("exit status: fuzz gives 0, 1, 2 and 3", "[exit][fuzz]") {
  const std::string out_dir = (test::temp_dir().path / "reproducers").string();
  for (const Expectation& e : std::vector<Expectation>{
           {{"fuzz", "--cases", "2", "--quiet", "--out", out_dir}, 0, "unexplained disagreements: 0", ""},
           {{"fuzz", "--quiet", "--replay",
             std::string(SEPAX_SOURCE_DIR) + "/fuzz/corpus/00-triangle-on-box-face.case"},
            0,
            "unexplained disagreements: 0",
            ""},
           // the checker catches a wrong verdict: exit 1, the finding named
           {{"fuzz", "--replay", std::string(SEPAX_SOURCE_DIR) + "/fuzz/corpus/00-triangle-on-box-face.case",
             "--inject-fault"},
            1,
            "",
            "[overlap float_robust gauss_map]"},
           {{"fuzz", "--cases", "2", "--inject-fault"}, 2, "", "--inject-fault applies to --replay only"},
           {{"fuzz", "--seed", "1.5"}, 2, "", "sepax fuzz: --seed: '1.5' is not a non-negative integer"},
           {{"fuzz", "--frobnicate"}, 2, "", "unknown option '--frobnicate'"},
           {{"fuzz", "--cases", "0"}, 2, "", "--cases 0 would run no case"},
           {{"fuzz", "--cases", "3", "--jobs", "100000"},
            2,
            "",
            "--jobs: '100000' is too large (at most 1024)"},
           {{"fuzz", "--replay", "/nonexistent/x.case", "--quiet"}, 3, "", "/nonexistent/x.case"},
           // a directory without a case file is an error, not "0 cases checked"
           {{"fuzz", "--replay", std::string(SEPAX_SOURCE_DIR) + "/docs", "--quiet"},
            3,
            "",
            "/docs' holds no .case files to replay"},
       })
    check_program(e);
}

TEST_CASE("exit status: audit gives 0, 1, 2 and 3", "[exit][audit]") {
  for (const Expectation& e : std::vector<Expectation>{
           {{"audit", "cube", "triangle", "--pose", "0", "0", "1"}, 0, "no unexplained disagreement", ""},
           {{"audit", "cube", "triangle", "--pose", "0", "0", "1", "--inject-fault"},
            1,
            "[overlap float_robust gauss_map]",
            ""},
           {{"audit", "cube"}, 2, "", "sepax audit: expected two shapes A and B, got 1"},
           {{"audit", "cube", "cube", "--number", "exact"},
            2,
            "",
            "the audit compares float or double against exact"},
           {{"audit", "cube", "/nonexistent/shape.obj"},
            3,
            "",
            "sepax audit: error: /nonexistent/shape.obj: cannot open"},
           {{"audit", std::string(SEPAX_SOURCE_DIR) + "/fuzz/corpus/invalid-inward-box.case"},
            3,
            "",
            "invalid-inward-box.case A: "},
       })
    check_program(e);
}
#endif

TEST_CASE("exit status: help, --version, no verb and an unknown verb", "[exit]") {
  for (const Expectation& e : std::vector<Expectation>{
           {{"help"}, 0, "exit status (every verb)", ""},
           {{"help", "query"}, 0, "--pose", ""},
           {{"query", "--help"}, 0, "--algorithm", ""},
           {{"--version"}, 0, "sepax ", ""},
           {{"help", "nonsense"}, 2, "", "sepax help: unknown verb 'nonsense'"},
           {{"help", "query", "info"}, 2, "", "expected at most one verb"},
           {{}, 2, "", "usage: sepax VERB"},
           {{"frobnicate"}, 2, "", "sepax: unknown verb 'frobnicate'"},
       })
    check_program(e);
}

TEST_CASE("exit status: 3 when standard output cannot be written", "[exit]") {
  // (the batch has failing lines, status 1 when its answers are written: its report is lost too)
  for (const std::vector<std::string>& args : {std::vector<std::string>{"query", "cube", "cube"},
                                               {"info", "cube"},
                                               {"help"},
                                               {"query", "--batch", kData + "batch.jsonl"}}) {
    INFO(args[0]);
    const test::ProgramRun r = test::run_program(args, "", 60, "/dev/full");
    CHECK(r.status == 3);
    CHECK_THAT(r.err, Catch::Contains("sepax " + args[0] + ": error: cannot write standard output"));
  }
  for (const char* flag : {"--version", "--help", "-h"}) {
    INFO(flag);
    const test::ProgramRun v = test::run_program({flag}, "", 60, "/dev/full");
    CHECK(v.status == 3);
    CHECK_THAT(v.err, Catch::Contains("sepax: error: cannot write standard output"));
  }
}

TEST_CASE("exit status: 4 for an exception escaping any verb, with its message", "[exit]") {
  std::vector<std::vector<std::string>> commands = {
      {"query", "cube", "cube"},
      {"query", "--batch", kData + "batch.jsonl", "--jobs",
       "1"},  // the writer thread of --jobs N runs outside the verb
      {"info", "cube"},
      {"render", "cube", "cube", "--svg", "-"},
      {"help"},
  };
#ifdef SEPAX_HAVE_FUZZ
  const std::string out_dir = (test::temp_dir().path / "reproducers").string();
  commands.push_back({"fuzz", "--cases", "1", "--quiet", "--out", out_dir});
  commands.push_back({"audit", "cube", "triangle", "--pose", "0", "0", "1"});
#endif
  for (auto args : commands) {
    INFO(args[0]);
    args.insert(args.begin(), "sepax");
    RefusingBuffer refusing;
    std::streambuf* saved = nullptr;
    const test::CommandRun r = test::with_captured_streams([&] {
      saved = std::cout.rdbuf(&refusing);
      // std::cerr is tied to std::cout (flushes it first): untied, so that
      // the message about the exception is not itself a write to std::cout
      std::ostream* tied = std::cerr.tie(nullptr);
      std::cout.exceptions(std::ios::badbit);
      auto argv = test::argv_of(args);
      int status = -1;
      try {
        status = run(static_cast<int>(args.size()), argv.data());
      } catch (const std::exception& e) {
        std::cerr << "escaped run(): " << e.what() << "\n";
        status = -2;  // a failure of this test
      } catch (...) {
        status = -3;
      }
      std::cout.exceptions(std::ios::goodbit);
      std::cout.clear();
      std::cout.rdbuf(saved);
      std::cerr.tie(tied);
      return status;
    });
    CHECK(r.status == 4);
    CHECK_THAT(r.err, Catch::Contains("sepax " + args[1] + ": internal error: "));
  }
}
