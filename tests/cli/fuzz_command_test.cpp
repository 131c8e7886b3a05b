// Tests for src/commands/fuzz_command.cpp: the command line of `sepax fuzz`
// (and of `sepax audit`, whose parser shares command_line.hpp).
#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_test_support.hpp"
#include "commands/audit_command.hpp"
#include "commands/fuzz_command.hpp"

using namespace sepax::cli;

namespace {

int fuzz_main_args(std::vector<std::string> args) {
  return test::verb_main(&fuzz_main, std::move(args)).status;
}

int audit_main_args(std::vector<std::string> args) {
  return test::verb_main(&audit_main, std::move(args)).status;
}

test::CommandRun fuzz(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int s = run_fuzz(args, out, err);
  return {s, out.str(), err.str()};
}

}  // namespace

TEST_CASE("sepax fuzz command line", "[fuzz][cli]") {
  CHECK(fuzz_main_args({"fuzz", "--cases", "4", "--quiet", "--json", "--out", "fuzz-test-out"}) == 0);
  CHECK(fuzz_main_args({"fuzz", "--families", "nope"}) == 2);
  CHECK(audit_main_args({"audit", "cube", "triangle", "--pose", "0", "0", "1"}) == 0);
  CHECK(audit_main_args({"audit", "cube"}) == 2);
}

TEST_CASE("sepax fuzz shrink options", "[fuzz][cli][shrink]") {
  CHECK(fuzz_main_args({"fuzz", "--cases", "2", "--quiet", "--shrink-steps", "0", "--shrink-seconds", "5",
                        "--shrink-max", "1", "--out", "fuzz-test-out"}) == 0);
  CHECK(fuzz_main_args({"fuzz", "--shrink-steps", "x"}) == 2);
  CHECK(fuzz_main_args({"fuzz", "--shrink-seconds"}) == 2);
  // replaying passing cases with --shrink writes nothing and succeeds
  CHECK(fuzz_main_args({"fuzz", "--quiet", "--replay",
                        SEPAX_SOURCE_DIR "/fuzz/corpus/00-triangle-on-box-face.case", "--shrink", "--out",
                        "fuzz-test-shrink-out"}) == 0);
}

TEST_CASE("fuzz: numbers are validated, --opt=value works, help goes to stdout", "[fuzz][cli]") {
  for (const auto& args : std::vector<std::vector<std::string>>{{"--seed", "1.5"},
                                                                {"--seed=-1"},
                                                                {"--seed", "0x10"},
                                                                {"--cases", "2.0"},
                                                                {"--seconds", "-1"},
                                                                {"--seconds", "inf"},
                                                                {"--jobs", "two"},
                                                                {"--shrink-max=1e3"},
                                                                {"--families", "boxes,nope"},
                                                                {"--number", "exact"},
                                                                {"stray"},
                                                                {"--replay"},
                                                                {"--bytes"},
                                                                {"--replay", "x.case", "--seed", "3"}}) {
    INFO(args[0]);
    const auto r = fuzz(args);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Catch::StartsWith("sepax fuzz: ") && Catch::Contains("sepax fuzz --help"));
  }
  CHECK_THAT(fuzz({"--seed", "1.5"}).err, Catch::Contains("'1.5' is not a non-negative integer"));
  CHECK_THAT(fuzz({"--families", "boxes,nope"}).err, Catch::Contains("unknown family 'nope'"));
  CHECK_THAT(fuzz({"--frobnicate"}).err, Catch::Contains("unknown option '--frobnicate'"));
  const auto ok = fuzz({"--cases=2", "--seed=18446744073709551615", "--families=boxes", "--quiet", "--json",
                        "--out=fuzz-test-out"});
  CHECK(ok.status == 0);
  CHECK_THAT(ok.out, Catch::Contains("\"seed\":18446744073709551615"));
  const auto h = fuzz({"--help"});
  CHECK(h.status == 0);
  CHECK(h.err.empty());
  for (const char* s : {"--seconds", "--cases", "--seed", "--families", "--jobs", "--replay", "Exit status"})
    CHECK_THAT(h.out, Catch::Contains(s));
}

TEST_CASE("fuzz: exit status 1 for a finding, 3 for an unreadable replay file", "[fuzz][cli]") {
  const auto missing = fuzz({"--replay", "/nonexistent/x.case", "--quiet"});
  CHECK(missing.status == 3);
  CHECK(missing.out.empty());  // nothing was checked: no report of zero cases
  CHECK(fuzz({"--replay", "/nonexistent/x.case", "--quiet", "--json"}).out.empty());
  const std::string bad = test::temp_file("bad.case", "not a case file\n");
  CHECK(fuzz({"--replay", bad, "--quiet"}).status == 3);
  // one case read and one not: the report of the one, and status 3
  const std::string good = std::string(SEPAX_SOURCE_DIR) + "/fuzz/corpus/00-triangle-on-box-face.case";
  const auto mixed = fuzz({"--replay", good, "/nonexistent/x.case", "--quiet", "--json"});
  CHECK(mixed.status == 3);
  CHECK_THAT(mixed.out, Catch::Contains("\"unexplained\""));
}

TEST_CASE("fuzz: a replay directory replays its cases, and one without any is an error", "[fuzz][cli]") {
  // (the campaign's messages go to the process's stderr: the program's runs check them, exit_status_test)
  const auto empty = test::temp_dir().path / "no_cases";
  std::filesystem::create_directories(empty);
  test::temp_dir().write("no_cases/notes.txt", "not a case\n");
  CHECK(fuzz({"--replay", empty.string(), "--quiet"}).status == 3);

  // libFuzzer corpus files have no extension: with --bytes every file counts
  const auto corpus = test::temp_dir().path / "libfuzzer_corpus";
  std::filesystem::create_directories(corpus);
  test::temp_dir().write("libfuzzer_corpus/3f2a9c", std::string(64, '\x5a'));
  CHECK(fuzz({"--replay", corpus.string(), "--bytes", "--quiet"}).status == 0);
  CHECK(fuzz({"--replay", empty.string(), "--bytes", "--quiet"}).status != 3);  // notes.txt is an input
}
