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

namespace sepax::fuzz {

struct FamilyStats {
  std::int64_t cases = 0;      // checked
  std::int64_t rejected = 0;   // generated shapes the float validation rejected
  std::int64_t unexplained = 0;
  std::map<std::string, std::int64_t> skipped;  // "comparison/config/sat" -> comparisons not made (size budgets)
};

struct Report {
  std::int64_t cases = 0;      // checked cases (not counting rejected ones)
  std::int64_t rejected = 0;
  double seconds = 0;
  std::uint64_t seed = 0;
  std::map<std::string, FamilyStats> families;
  std::map<std::string, Counts> comparisons;
  std::map<std::string, Counts> by_config;
  std::map<std::string, std::int64_t> skipped;  // "comparison/config/sat" -> comparisons not made (size budgets)
  std::map<std::string, Counts> details;   // sub-comparisons (CaseReport::details)
  std::map<std::string, double> maxima;    // largest error/bound ratios (CaseReport::maxima)
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

}  // namespace sepax::fuzz
