// The benchmark's targets: ratios of two rows' ns/query in one run, each with
// a bound (at_least for speed-ups, at_most for overheads).  ratio = ns of the
// slower row / ns of the faster row in the same workload and pose set, so it
// can be recomputed from the rows of `sepax_bench --json`.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "timing.hpp"

namespace bench {

struct Target {
  std::string name;
  std::string workload, poses;
  std::string slower, faster;  // row names as in the rows
  bool at_least = true;        // false: at_most
  double bound = 0;
  bool identical = false;  // also requires the faster row's answers to equal the slower row's
  // measured
  double ratio = 0;  // NaN when a row is missing
  int differences = -1;
  bool met = false;
};

/// Every target, in the order of the table.
std::vector<Target> target_list();

/// The targets measured in `rows` (ratio, met).
std::vector<Target> evaluate(const std::vector<Measured>& rows);

/// The table printed after the rows.
void print_targets(const std::vector<Target>& targets);

/// One line per target: name, workload, poses, slower, faster, bound kind,
/// bound (tab-separated; for bench/callgrind_ratios.sh).
void list_targets();

nlohmann::ordered_json to_json(const Measured& m);
nlohmann::ordered_json to_json(const Target& t);

}  // namespace bench
