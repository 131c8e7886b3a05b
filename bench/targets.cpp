#include "targets.hpp"

#include <cmath>
#include <cstdio>

namespace bench {

namespace {

const Measured* find(const std::vector<Measured>& all, const std::string& w, const std::string& poses,
                     const std::string& row) {
  for (const auto& m : all)
    if (m.workload == w && m.poses == poses && m.row == row) return &m;
  return nullptr;
}

std::string sphere(int n) { return "sphere" + std::to_string(n); }

// null for NaN and infinities (JSON has neither)
nlohmann::ordered_json num(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
}

}  // namespace

std::vector<Target> target_list() {
  std::vector<Target> t;
  auto add = [&](std::string name, std::string w, std::string poses, std::string slower, std::string faster,
                 bool at_least, double bound, bool identical = false) {
    t.push_back(Target{std::move(name) + ", " + w + (poses == "overlapping" ? "" : " " + poses), w, poses,
                       std::move(slower), std::move(faster), at_least, bound, identical});
  };
  const int all_n[] = {8, 16, 32, 64, 128, 256};
  // the engine's query path
  for (int n : all_n)
    add("bullet gjk+epa over posed traversal+manifold", sphere(n), "overlapping",
        "bullet gjk+epa posed (float)", "traversal+manifold float posed", true, 3);
  add("bullet gjk+epa over posed traversal+manifold", "box", "overlapping", "bullet gjk+epa posed (float)",
      "traversal+manifold float posed", true, 3);
  add("bullet boxbox over posed traversal+manifold", "box", "overlapping", "bullet boxbox posed (float)",
      "traversal+manifold float posed", true, 1);
  add("bullet gjk+epa over posed traversal+manifold", "cylinder32", "overlapping",
      "bullet gjk+epa posed (float)", "traversal+manifold float posed", true, 1);
  for (int n : all_n)
    add("posed over pre-posed traversal+manifold", sphere(n), "overlapping", "traversal+manifold float posed",
        "traversal+manifold float", false, 1.2);
  for (int n : all_n)
    add("bullet gjk+epa over traversal+manifold, margin", sphere(n), "separated",
        "bullet gjk+epa posed margin (float)", "traversal+manifold float posed margin", true, 3);
  for (int n : all_n)
    add("bullet gjk+epa over traversal+manifold, no margin", sphere(n), "separated",
        "bullet gjk+epa posed (float)", "traversal+manifold float posed", true, 1);
  for (const char* motion : {"resting", "sliding", "rolling", "hovering"})
    for (int n : {16, 32, 64, 128, 256})
      add("fresh over warm (cached) posed traversal", sphere(n), motion, "traversal float posed margin",
          "traversal float posed margin cached", true, 3, true);
  // the SATs on pre-posed shapes
  const int gb_n[] = {4, 8, 16, 32};
  const double gb_bound[] = {3, 8, 25, 50};
  for (int i = 0; i < 4; ++i)
    add("brute over gauss, plain", sphere(gb_n[i]), "overlapping", "brute float plain", "gauss float plain",
        true, gb_bound[i]);
  add("gauss over traversal, plain", sphere(32), "overlapping", "gauss float plain", "traversal float plain",
      true, 5);
  add("gauss over traversal, plain", sphere(128), "overlapping", "gauss float plain", "traversal float plain",
      true, 20);
  for (int n : all_n)
    add("bullet gjk+epa over traversal, pre-posed", sphere(n), "overlapping", "bullet gjk+epa (float)",
        "traversal float", true, 3);
  for (int n : {16, 32, 64})
    add("robust over plain traversal", sphere(n), "overlapping", "traversal float", "traversal float plain",
        false, 1.15);
  for (int n : {16, 32, 64})
    add("traversal+manifold over traversal, plain", sphere(n), "overlapping",
        "traversal+manifold float plain", "traversal float plain", false, 1.3);
  return t;
}

std::vector<Target> evaluate(const std::vector<Measured>& rows) {
  auto t = target_list();
  for (auto& x : t) {
    const auto* s = find(rows, x.workload, x.poses, x.slower);
    const auto* f = find(rows, x.workload, x.poses, x.faster);
    x.ratio = s && f && f->ns > 0 ? s->ns / f->ns : std::nan("");
    x.differences = f && f->same_as == x.slower ? f->differences : -1;
    x.met = !std::isnan(x.ratio) && (x.at_least ? x.ratio >= x.bound : x.ratio <= x.bound) &&
            (!x.identical || x.differences == 0);
  }
  return t;
}

void print_targets(const std::vector<Target>& targets) {
  std::printf("\nTargets (ratios of ns/query in this run: the first row named over the second):\n");
  for (const auto& t : targets) {
    const bool missing = std::isnan(t.ratio);
    std::string note;
    if (t.identical && !missing)
      note = t.differences < 0 ? "  (answers not compared)"
                               : "  (" + std::to_string(t.differences) + " answers differ)";
    std::printf("  %-72s %8.2f  (%s %.2f)  %s%s\n", t.name.c_str(), t.ratio,
                t.at_least ? ">=" : "<=", t.bound, missing ? "NOT MEASURED" : (t.met ? "met" : "MISSED"),
                note.c_str());
  }
}

void list_targets() {
  for (const auto& t : target_list())
    std::printf("%s\t%s\t%s\t%s\t%s\t%s\t%g\n", t.name.c_str(), t.workload.c_str(), t.poses.c_str(),
                t.slower.c_str(), t.faster.c_str(), t.at_least ? "at_least" : "at_most", t.bound);
}

nlohmann::ordered_json to_json(const Measured& m) {
  nlohmann::ordered_json j{{"workload", m.workload},
                           {"n", m.n},
                           {"poses", m.poses},
                           {"row", m.row},
                           {"group", m.group},
                           {"ns", num(m.ns)},
                           {"ratio_to_traversal", num(m.ratio)},
                           {"queries", m.queries},
                           {"verdict_disagreements", m.disagree},
                           {"failed", m.failed},
                           {"depth_pairs", m.depth_count},
                           {"depth_err_median", num(m.depth_med)},
                           {"depth_err_max", num(m.depth_max)},
                           {"exact_fallbacks_per_query", num(m.exact_fallbacks)}};
  if (!m.same_as.empty()) {
    j["same_results_as"] = m.same_as;
    j["result_differences"] = m.differences;
  }
  return j;
}

nlohmann::ordered_json to_json(const Target& t) {
  nlohmann::ordered_json j{
      {"name", t.name},     {"workload", t.workload}, {"poses", t.poses},
      {"slower", t.slower}, {"faster", t.faster},     {"bound", t.at_least ? "at_least" : "at_most"},
      {"value", t.bound},   {"ratio", num(t.ratio)},  {"met", t.met}};
  if (t.identical)
    j["result_differences"] =
        t.differences < 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(t.differences);
  return j;
}

}  // namespace bench
