// sepax_bench: sepax's SATs against each other and against Bullet, libccd and
// FCL on the same shape pairs, pre-posed and posed as an engine runs them.  A
// plain harness (not Google Benchmark): every row's verdicts and depth errors
// are checked against an exact reference, which is easier when the harness
// owns the loop.  docs/bench.md describes the workloads, rows, fairness rules
// and targets.
//
//   sepax_bench [--quick] [--pairs=P] [--filter=SUBSTR] [--workload=W] [--poses=P] [--json=FILE]
//   sepax_bench --callgrind --row=NAME --workload=W [--poses=P] [--passes=K]
//   sepax_bench --list-targets
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "reference.hpp"
#include "rows.hpp"
#include "targets.hpp"
#include "timing.hpp"
#include "workloads.hpp"

#if SEPAX_BENCH_CALLGRIND
#include <valgrind/callgrind.h>
#endif
#if SEPAX_BENCH_BULLET
#include <LinearMath/btScalar.h>
#endif

#ifndef SEPAX_BENCH_VERSION
#define SEPAX_BENCH_VERSION "unknown"
#endif

namespace {

using namespace bench;

const std::string kBaseline = "traversal float";

struct Options {
  bool quick = false;
  double min_time = 0.2;
  double max_pass = 1.0;
  int pairs = 64;
  std::string filter, json, workload, poses;
  bool callgrind = false, list = false;
  std::string row;
  int passes = 10;
};

std::vector<Row> cell_rows(Cell& c) {
  std::vector<Row> rows = sepax_rows(c);
  for (auto& r : exact_rows(c)) rows.push_back(std::move(r));
  for (auto& r : peer_rows(c)) rows.push_back(std::move(r));
  return rows;
}

Pool make_pool(const WorkloadSpec& spec) {
  Rng rng(0x5e9a7 + static_cast<std::uint64_t>(spec.n) * 7919 + spec.kind.size());
  Pool pool;
  build_pool(pool, spec, rng, 8);
  return pool;
}

void print_header() {
  std::printf("%-11s %-11s %-46s %11s %9s %7s %5s %10s %10s %8s\n", "workload", "poses", "row", "ns/query",
              "x trav", "verdict", "fail", "depth-err", "depth-err", "exact");
  std::printf("%-11s %-11s %-46s %11s %9s %7s %5s %10s %10s %8s\n", "", "", "", "", "", "diff", "", "median",
              "max", "/query");
}

void print_row(const Measured& m) {
  std::printf("%-11s %-11s %-46s %11.1f %9.2f %4d/%-3d %4d %10.2e %10.2e %8.2f", m.workload.c_str(),
              m.poses.c_str(), m.row.c_str(), m.ns, m.ratio, m.disagree, m.queries, m.failed, m.depth_med,
              m.depth_max, m.exact_fallbacks);
  if (!m.same_as.empty()) std::printf("  answers differing from '%s': %d", m.same_as.c_str(), m.differences);
  std::printf("\n");
  std::fflush(stdout);
}

// A cached row must answer exactly as the same row without the cache.
std::string uncached_name(const std::string& row) {
  const std::string suffix = " cached";
  if (row.size() > suffix.size() && row.compare(row.size() - suffix.size(), suffix.size(), suffix) == 0)
    return row.substr(0, row.size() - suffix.size());
  return {};
}

int run_callgrind(const Options& o) {
#if SEPAX_BENCH_CALLGRIND
  for (const auto& spec : workloads(false)) {
    if (spec.name != o.workload) continue;
    const auto sets = pose_sets(spec);
    const std::string poses = o.poses.empty() ? sets.front() : o.poses;
    if (std::find(sets.begin(), sets.end(), poses) == sets.end()) break;
    Pool pool = make_pool(spec);
    Cell c;
    setup_cell(c, spec, poses, pool, o.pairs);
    for (auto& row : cell_rows(c)) {
      if (row.name != o.row) continue;
      const std::size_t np = std::min(c.pairs.size(), row.max_pairs);
      double s = 0;
      for (std::size_t i = 0; i < np; ++i) s += row.run(i).sep;  // warm-up
      CALLGRIND_START_INSTRUMENTATION;
      for (int k = 0; k < o.passes; ++k)
        for (std::size_t i = 0; i < np; ++i) s += row.run(i).sep;
      CALLGRIND_STOP_INSTRUMENTATION;
      g_sink = g_sink + s;
      std::printf("queries %zu\n", np * static_cast<std::size_t>(o.passes));
      return 0;
    }
  }
  std::fprintf(stderr, "sepax_bench: no row '%s' in workload '%s', poses '%s'\n", o.row.c_str(),
               o.workload.c_str(), o.poses.c_str());
  return 2;
#else
  (void)o;
  std::fprintf(stderr, "sepax_bench: built without valgrind/callgrind.h\n");
  return 2;
#endif
}

int run(const Options& o) {
  std::printf(
      "sepax_bench %s: %d pairs per pose set; pre-posed rows get B posed at setup, posed rows a world\n"
      "pose per shape and query (docs/bench.md)\n",
      SEPAX_BENCH_VERSION, o.pairs);
#if SEPAX_BENCH_BULLET
  std::printf("Bullet btScalar: %s, margin 0\n", sizeof(btScalar) == 4 ? "float" : "double");
#endif
#if !SEPAX_BENCH_PREPARED
  std::printf("(sepax/prepared_shape.hpp not available: no posed sepax rows)\n");
#endif
  std::printf(
      "reference: sepax traversal SAT in mpq_class on the pre-posed B (pre-posed rows) and on the\n"
      "posed B' = posed(B, relative_pose(pose_a, pose_b)) (posed rows)\n\n");
  print_header();
  std::vector<Measured> all;
  std::vector<std::string> counters;
  for (const auto& spec : workloads(o.quick && o.workload.empty())) {
    if (!o.workload.empty() && spec.name != o.workload) continue;
    Pool pool = make_pool(spec);
    for (const auto& poses : pose_sets(spec)) {
      if (!o.poses.empty() && poses != o.poses) continue;
      Cell c;
      setup_cell(c, spec, poses, pool, o.pairs);
      const double tr = now_s();
      compute_reference(c);
      std::fprintf(stderr, "[%s %s: exact reference %.1f s]\n", c.workload.c_str(), c.poses.c_str(),
                   now_s() - tr);
      counters.push_back(traversal_counters(c));
      const std::vector<Row> rows = cell_rows(c);
      std::vector<const Row*> chosen;
      for (const auto& row : rows)
        if (o.filter.empty() || row.name.find(o.filter) != std::string::npos || row.name == kBaseline)
          chosen.push_back(&row);
      std::vector<std::vector<Out>> outs;
      std::vector<Measured> cell = measure_cell(c, chosen, o.min_time, o.max_pass, outs);
      std::map<std::string, std::vector<Out>> answers;
      for (std::size_t r = 0; r < chosen.size(); ++r) answers[chosen[r]->name] = std::move(outs[r]);
      double base = 0;
      for (const auto& m : cell)
        if (m.row == kBaseline) base = m.ns;
      for (auto& m : cell) {
        m.ratio = base > 0 ? m.ns / base : std::nan("");
        const std::string fresh = uncached_name(m.row);
        if (!fresh.empty() && answers.count(fresh)) {
          m.same_as = fresh;
          m.differences = count_differences(answers[fresh], answers[m.row]);
        }
        print_row(m);
        all.push_back(m);
      }
      std::printf("\n");
    }
  }
  const auto targets = evaluate(all);
  print_targets(targets);
  std::printf("\nTraversal walk counters (float, plain, pre-posed; mean per query):\n");
  for (const auto& l : counters) std::printf("%s", l.c_str());
  std::printf("(contact points built: %zu)\n", g_contact_points);
  if (!o.json.empty()) {
    nlohmann::ordered_json j;
    j["baseline"] = kBaseline;
    j["rows"] = nlohmann::ordered_json::array();
    for (const auto& m : all) j["rows"].push_back(to_json(m));
    j["targets"] = nlohmann::ordered_json::array();
    for (const auto& t : targets) j["targets"].push_back(to_json(t));
    std::ofstream f(o.json);
    f << j.dump(1) << "\n";
    if (!f) {
      std::fprintf(stderr, "sepax_bench: cannot write %s\n", o.json.c_str());
      return 3;
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"sepax_bench: sepax's SATs against Bullet, libccd and FCL on the same pairs (docs/bench.md)",
               "sepax_bench"};
  app.set_version_flag("--version", std::string("sepax_bench ") + SEPAX_BENCH_VERSION);
  std::vector<std::string> workload_names,
      pose_names{"overlapping", "separated", "moving", "resting", "sliding", "rolling", "hovering"};
  for (const auto& w : workloads(false)) workload_names.push_back(w.name);
  app.add_flag("--quick", o.quick, "sphere hulls up to N = 64 only");
  app.add_option("--pairs", o.pairs,
                 "pairs per pose set (moving: pairs/16 trajectories of 32 steps; resting, sliding, rolling, "
                 "hovering: pairs/32 of 120 steps)")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  app.add_option("--min-time", o.min_time, "seconds per row for the repeated timing passes (at least 2)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--max-pass", o.max_pass,
                 "a row whose first pass takes longer stops there (after at least 16 pairs) and is timed on "
                 "that prefix")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--filter", o.filter, "only rows whose name contains this text (and the baseline row)");
  app.add_option("--workload", o.workload, "one workload")->check(CLI::IsMember(workload_names));
  app.add_option("--poses", o.poses, "one pose set")->check(CLI::IsMember(pose_names));
  app.add_option("--json", o.json, "also write the rows and the targets as JSON to this file");
  auto* cg = app.add_flag(
      "--callgrind", o.callgrind,
      "run one row only (--row, --workload, --poses), K passes inside callgrind client requests");
  app.add_option("--row", o.row, "the row for --callgrind")->needs(cg);
  app.add_option("--passes", o.passes, "passes over the pairs for --callgrind")
      ->needs(cg)
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  app.add_flag("--list-targets", o.list, "print the targets (tab-separated) and exit");
  try {
    app.parse(argc, argv);
    if (o.callgrind && (o.row.empty() || o.workload.empty()))
      throw CLI::ValidationError("--callgrind", "needs --row and --workload");
    for (const auto& w : workloads(false)) {
      const auto sets = pose_sets(w);
      if (w.name == o.workload && !o.poses.empty() &&
          std::find(sets.begin(), sets.end(), o.poses) == sets.end())
        throw CLI::ValidationError("--poses", "workload " + w.name + " has no pose set " + o.poses);
    }
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // help and version on stdout, errors on stderr
    return code == 0 ? 0 : 2;
  }
  if (o.list) {
    list_targets();
    return 0;
  }
  if (o.callgrind) return run_callgrind(o);
  return run(o);
}
