// sepax/fuzz/campaign.hpp
//
// A fuzz campaign: run cases through check_case and aggregate the report
// (cases per family, per-class counts per comparison and per configuration,
// cases per second, reproducers written).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include <sepax/fuzz/check.hpp>
#include <sepax/fuzz/shrink.hpp>

namespace sepax::fuzz {

struct FamilyStats {
  std::int64_t cases = 0;     // checked
  std::int64_t rejected = 0;  // generated shapes the float validation rejected
  std::int64_t unexplained = 0;
  std::map<std::string, std::int64_t>
      skipped;  // "comparison/config/sat" -> comparisons not made (size budgets)
};

struct Report {
  std::int64_t cases = 0;  // checked cases (not counting rejected ones)
  std::int64_t rejected = 0;
  double seconds = 0;
  std::uint64_t seed = 0;
  std::map<std::string, FamilyStats> families;
  std::map<std::string, Counts> comparisons;
  std::map<std::string, Counts> by_config;
  std::map<std::string, std::int64_t>
      skipped;                            // "comparison/config/sat" -> comparisons not made (size budgets)
  std::map<std::string, Counts> details;  // sub-comparisons (CaseReport::details)
  std::map<std::string, double> maxima;   // largest error/bound ratios (CaseReport::maxima)
  std::vector<std::string> reproducers;
  std::vector<Finding> findings;  // first few unexplained findings
  std::int64_t unexplained() const;
  std::int64_t skipped_total() const;
  void add(const std::string& family, const CaseReport& r);
};

/// Write a reproducer: the case, with the findings as '#' comments at the top.
std::string write_reproducer(const std::string& dir, const FuzzCase& c, const CaseReport& r);

void print_text(std::ostream& out, const Report& r);
void print_json(std::ostream& out, const Report& r);

/// What `sepax fuzz` runs (parsed by the sepax program, src/commands/fuzz_command.cpp).
struct CampaignOptions {
  double seconds = 30;                       ///< campaign length when cases == 0
  std::uint64_t cases = 0;                   ///< generated cases (checked + rejected); 0: run for `seconds`
  std::uint64_t seed = 1;                    ///< campaign seed
  std::vector<std::string> families;         ///< generator families in turn; empty: all (family_names())
  std::string out_dir = "fuzz-reproducers";  ///< reproducers (and decoded --bytes inputs)
  bool out_given = false;  ///< out_dir was given (replay --bytes writes decoded cases only then)
  ShrinkOptions shrink;    ///< budget per shrunk finding (max_steps 0: no shrinking)
  int shrink_max = 5;      ///< findings shrunk per run
  bool json = false;       ///< report as one JSON object instead of text
  bool quiet = false;      ///< no progress or per-file lines on stderr
  bool replay = false;     ///< replay `replay_files` instead of generating cases
  std::vector<std::string> replay_files;  ///< .case files or directories of them
  bool bytes = false;                     ///< replay files are libFuzzer inputs
  bool shrink_replays = false;            ///< shrink unexplained replayed cases too
  bool inject_fault = false;              ///< replay with CheckOptions::inject_fault (checks the checker)
  int jobs = 0;                           ///< parallel workers; 0: all cores
};

/// Runs a campaign (or a replay) and prints its report to `out`; progress,
/// per-file lines and shrinking notes go to std::cerr.  Exit status: 0 no unexplained disagreement,
/// 1 at least one (reproducers written), 3 a replay file that cannot be read
/// or parsed.
int run_campaign(const CampaignOptions& opt, std::ostream& out);

}  // namespace sepax::fuzz
