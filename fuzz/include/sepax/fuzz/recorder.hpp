// sepax/fuzz/recorder.hpp
//
// Recorder: the checking core's bookkeeping (check.cpp, check_posed.cpp):
// adds a classified comparison to a CaseReport (per comparison and per
// "comparison/configuration"), keeps the first few unexplained findings in
// words, and counts comparisons skipped above a size budget.
#pragma once

#include <functional>
#include <string>

#include <sepax/fuzz/check.hpp>

namespace sepax::fuzz {

struct Recorder {
  CaseReport& rep;
  const CheckOptions& opt;
  std::map<std::string, int> kept;
  void add(const std::string& cmp, const std::string& cfg, const std::string& sat, Classification k,
           const std::function<std::string()>& detail, std::int64_t times = 1) {
    rep.by_comparison[cmp].add(k, times);
    rep.by_config[cmp + "/" + cfg].add(k, times);
    if (k == Classification::unexplained) {
      rep.unexplained_count += times;
      if (kept[cmp]++ < opt.max_findings) rep.unexplained.push_back({cmp, cfg, sat, detail()});
    }
  }
  /// A comparison not made (size budget): counted in CaseReport::skipped.
  void skip(const std::string& cmp, const std::string& cfg, const std::string& sat) {
    ++rep.skipped[cmp + "/" + cfg + "/" + sat];
  }
};

}  // namespace sepax::fuzz
