// src/commands/command_line.hpp
//
// What every verb of the sepax program shares: one CLI11 parser set up the
// same way (help on stdout, --opt=value and --opt value, unknown options
// rejected), the exit statuses, and the options several verbs take
// (--number, --algorithm, --pose).
//
// Exit status, the same in every verb:
//   0  success
//   1  a finding (an unexplained disagreement: fuzz, audit) or, in
//      `query --batch`, at least one line answered with an error
//   2  usage error (unknown option, bad or missing value, wrong arguments)
//   3  an input that cannot be read, parsed or built (a file, a shape
//      argument, a case file), or an output file that cannot be written
//   4  internal error (an exception escaping a verb, caught in dispatch.cpp)
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "commands/pose.hpp"
#include "commands/sat_runner.hpp"

namespace sepax::cli {

enum ExitStatus : int { kExitOk = 0, kExitFinding = 1, kExitUsage = 2, kExitInput = 3, kExitInternal = 4 };

/// A usage problem found after parsing (e.g. a combination of options).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// One verb's parser.  `verb` names it in messages ("sepax query: ...").
class CommandLine {
 public:
  CommandLine(std::string verb, const std::string& description, std::string footer = {});

  CLI::App app;

  /// Parses args (without the verb).  Returns std::nullopt when the verb
  /// should run, otherwise the exit status: 0 after printing the help to out,
  /// 2 after printing a usage error to err.
  std::optional<int> parse(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

  /// Prints "sepax VERB: what" and the pointer to --help; returns 2.
  int usage_error(std::ostream& err, const std::string& what) const;

  /// The help text (what --help prints).
  std::string help() const;

  /// What the value of an option is, for "--x needs ..." messages.
  void describe_value(const std::string& option, const std::string& what) { needs_[option] = what; }

  /// --number float|double|exact into cfg.number.
  void add_number(RunConfig& cfg, const std::string& default_text = "double");
  /// --algorithm brute|gauss|traversal into cfg.algorithm.
  void add_algorithm(RunConfig& cfg);
  /// --robust into cfg.robust.
  void add_robust(RunConfig& cfg);
  /// --pose tx ty tz [qw qx qy qz] (also --pose=tx,ty,tz[,qw,qx,qy,qz]);
  /// the pose is made by pose() after parse().
  void add_pose(const std::string& what);
  /// The parsed --pose, if given.  Throws UsageError for bad numbers.
  std::optional<Pose> pose() const;

  /// A non-negative decimal integer: digits only ("1.5", "-1" and "0x10" are
  /// usage errors), within the range of the target.
  CLI::Option* add_unsigned(const std::string& name, std::uint64_t& target, const std::string& desc);
  /// An integer in [0, max] (max defaults to INT_MAX).
  CLI::Option* add_unsigned(const std::string& name, int& target, const std::string& desc,
                            int max = std::numeric_limits<int>::max());
  /// A finite number >= 0.
  CLI::Option* add_nonnegative(const std::string& name, double& target, const std::string& desc);

  const std::string& verb() const { return verb_; }

 private:
  std::string verb_;
  std::map<std::string, std::string> needs_;
  std::string pose_text_;  // "tx,ty,tz[,qw,qx,qy,qz]"
  bool has_pose_ = false;
};

/// The most worker threads --jobs asks for (query --batch, fuzz): far more
/// than any machine's cores, few enough that starting them cannot fail.
inline constexpr int kMaxJobs = 1024;

/// An input that cannot be read, parsed or built: prints "sepax VERB: error:
/// what" to err and, when json, {"error": what} to out; returns 3.
int input_error(std::ostream& out, std::ostream& err, bool json, const std::string& verb,
                const std::string& what);

/// argv[1..argc) as strings (argv[0] is the verb).
std::vector<std::string> arguments(int argc, char** argv);

/// A number as the command line accepts it (decimal, optional sign), or nullopt.
std::optional<double> parse_double(const std::string& s);

}  // namespace sepax::cli
