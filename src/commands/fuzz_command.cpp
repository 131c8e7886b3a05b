// src/commands/fuzz_command.cpp -- see fuzz_command.hpp.
#include "commands/fuzz_command.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>

#include <sepax/fuzz/campaign.hpp>
#include <sepax/fuzz/generators.hpp>

#include "commands/command_line.hpp"

namespace sepax::cli {

namespace {

std::string families_help() {
  std::string s = "families:";
  for (const auto& f : fuzz::family_names()) s += " " + f;
  return s +
         "\n\nExit status: 0 no unexplained disagreement, 1 at least one (reproducers written), 2 usage "
         "error,\n"
         "3 a replay file that cannot be read or parsed, 4 internal error.\n";
}

}  // namespace

int run_fuzz(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  fuzz::CampaignOptions o;
  double shrink_seconds = o.shrink.max_seconds;
  int shrink_steps = o.shrink.max_steps;
  CommandLine cl(
      "fuzz",
      "Random differential testing: generated shape pairs run through every SAT in float, double and "
      "exact arithmetic, every disagreement classified; or the replay of saved cases.",
      families_help());
  auto& app = cl.app;
  cl.add_nonnegative("--seconds", o.seconds, "campaign length in seconds (default 30; ignored with --cases)");
  cl.add_unsigned("--cases", o.cases, "stop after N generated cases instead of after --seconds");
  cl.add_unsigned("--seed", o.seed, "campaign seed (default 1): the same seed gives the same cases");
  app.add_option("--families", o.families, "generator families to run in turn (default: all)")
      ->delimiter(',')
      ->type_name("A,B,...")
      ->check(
          [](const std::string& f) {
            const auto& names = fuzz::family_names();
            return std::find(names.begin(), names.end(), f) != names.end() ? std::string()
                                                                           : "unknown family '" + f + "'";
          },
          "");
  cl.describe_value("--families", "a comma-separated list of families");
  cl.add_unsigned("--jobs", o.jobs,
                  "parallel workers (default 0: all cores; at most " + std::to_string(kMaxJobs) + ")",
                  kMaxJobs);
  app.add_option("--out", o.out_dir, "directory for reproducers (default fuzz-reproducers)")
      ->type_name("DIR");
  cl.describe_value("--out", "a directory");
  app.add_flag("--json", o.json, "print the report as one JSON object");
  app.add_flag("--quiet", o.quiet, "no progress or per-file lines on standard error");
  cl.add_unsigned("--shrink-steps", shrink_steps, "checks per shrunk finding (default 300; 0: no shrinking)");
  cl.add_nonnegative("--shrink-seconds", shrink_seconds, "seconds per shrunk finding (default 60)");
  cl.add_unsigned("--shrink-max", o.shrink_max, "findings shrunk per run (default 5)");
  app.add_option("--replay", o.replay_files,
                 "check saved cases (.case files, or directories of them) instead")
      ->type_name("FILE_OR_DIR...")
      ->expected(1, CLI::detail::expected_max_vector_size);
  cl.describe_value("--replay", "at least one case file or directory");
  app.add_flag("--bytes", o.bytes,
               "with --replay: the files are libFuzzer inputs (with --out DIR each is also "
               "written there as a readable DIR/NAME.case)");
  app.add_flag("--shrink", o.shrink_replays, "with --replay: shrink unexplained cases too");
  app.add_flag("--inject-fault", o.inject_fault,
               "with --replay: check the checker: float_robust's Gauss map reports the opposite overlap "
               "verdict, which every valid case must report as unexplained (exit status 1)")
      ->excludes("--shrink");
  if (const auto status = cl.parse(args, out, err)) return *status;
  o.replay = !o.replay_files.empty();
  o.out_given = app.count("--out") > 0;
  o.shrink.max_steps = shrink_steps;
  o.shrink.max_seconds = shrink_seconds;
  if (!o.replay) {
    for (const char* only : {"--bytes", "--shrink", "--inject-fault"})
      if (app.count(only)) return cl.usage_error(err, std::string(only) + " applies to --replay only");
    if (app.count("--cases") && o.cases == 0)
      return cl.usage_error(err, "--cases 0 would run no case (give N >= 1, or --seconds S)");
  } else {
    for (const char* no : {"--seconds", "--cases", "--seed", "--families"})
      if (app.count(no)) return cl.usage_error(err, std::string(no) + " does not apply to --replay");
  }
  return fuzz::run_campaign(o, out);
}

int fuzz_main(int argc, char** argv) { return run_fuzz(arguments(argc, argv), std::cout, std::cerr); }

}  // namespace sepax::cli
