// `sepax fuzz`: the campaign and corpus replay (see sepax/fuzz/campaign.hpp).
#include <sepax/fuzz/campaign.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include <unistd.h>

#include <nlohmann/json.hpp>
#include <sepax/error.hpp>
#include <sepax/fuzz/check_manifold.hpp>
#include <sepax/fuzz/cli.hpp>
#include <sepax/fuzz/generators.hpp>
#include <sepax/fuzz/shrink.hpp>
#include <sepax/fuzz/workers.hpp>

namespace sepax::fuzz {

std::int64_t Report::unexplained() const {
  std::int64_t n = 0;
  for (const auto& [k, c] : comparisons) n += c[Classification::unexplained];
  return n;
}

std::int64_t Report::skipped_total() const {
  std::int64_t n = 0;
  for (const auto& [k, c] : skipped) n += c;
  return n;
}

void Report::add(const std::string& family, const CaseReport& r) {
  auto& f = families[family];
  if (!r.valid) {
    ++f.rejected;
    ++rejected;
    return;
  }
  ++f.cases;
  ++cases;
  f.unexplained += r.unexplained_count;
  for (const auto& [k, c] : r.by_comparison) comparisons[k] += c;
  for (const auto& [k, c] : r.by_config) by_config[k] += c;
  for (const auto& [k, n] : r.skipped) {
    skipped[k] += n;
    f.skipped[k] += n;
  }
  for (const auto& [k, c] : r.details) details[k] += c;
  for (const auto& [k, v] : r.maxima) maxima[k] = std::max(maxima[k], v);
  for (const auto& x : r.unexplained)
    if (findings.size() < 20) findings.push_back(x);
}

std::string write_reproducer(const std::string& dir, const FuzzCase& c, const CaseReport& r) {
  std::filesystem::create_directories(dir);
  std::string path;
  for (int k = 0;; ++k) {
    path = dir + "/unexplained-" + c.family + "-" + std::to_string(c.seed) +
           (k ? "-" + std::to_string(k) : "") + ".case";
    if (!std::filesystem::exists(path)) break;
  }
  std::ostringstream s;
  s << "sepax fuzz reproducer: " << r.unexplained_count << " unexplained disagreement(s)\n";
  for (const auto& f : r.unexplained)
    s << "[" << f.comparison << " " << f.config << " " << f.sat << "] " << f.detail << "\n";
  s << "replay: sepax fuzz --replay " << path << "\n";
  s << "audit:  sepax audit --case " << path;
  write_case_file(path, c, s.str());
  return path;
}

namespace {

// Counts as {"agree": n, "exact_zero": n, ...} in Classification order.
nlohmann::ordered_json counts_json(const Counts& c) {
  nlohmann::ordered_json o = nlohmann::ordered_json::object();
  for (int k = 0; k < kClassificationCount; ++k)
    o[classification_name(static_cast<Classification>(k))] = c.n[static_cast<std::size_t>(k)];
  return o;
}

// The report's "manifold" value: {"classes", "by_config", "aspects", "max_error_over_bound"}.
nlohmann::ordered_json manifold_json(const std::map<std::string, Counts>& comparisons,
                                     const std::map<std::string, Counts>& by_config,
                                     const std::map<std::string, Counts>& details,
                                     const std::map<std::string, double>& maxima) {
  using Json = nlohmann::ordered_json;
  const auto it = comparisons.find("manifold");
  Json configs = Json::object(), aspects = Json::object(), ratios = Json::object();
  for (const auto& [k, c] : by_config)
    if (k.rfind("manifold/", 0) == 0) configs[k.substr(9)] = counts_json(c);
  for (const auto& [k, c] : details)
    if (k.rfind("manifold.", 0) == 0) aspects[k.substr(9)] = counts_json(c);
  for (const auto& [k, v] : maxima)
    if (k.rfind("manifold.", 0) == 0) ratios[k.substr(9)] = v;
  return Json{{"classes", counts_json(it == comparisons.end() ? Counts{} : it->second)},
              {"by_config", std::move(configs)},
              {"aspects", std::move(aspects)},
              {"max_error_over_bound", std::move(ratios)}};
}

}  // namespace

void print_json(std::ostream& out, const Report& r) {
  using Json = nlohmann::ordered_json;
  Json families = Json::object(), comparisons = Json::object(), by_config = Json::object(),
       findings = Json::array();
  for (const auto& [name, f] : r.families)
    families[name] = Json{
        {"cases", f.cases}, {"rejected", f.rejected}, {"unexplained", f.unexplained}, {"skipped", f.skipped}};
  for (const auto& [name, c] : r.comparisons) comparisons[name] = counts_json(c);
  for (const auto& [name, c] : r.by_config) by_config[name] = counts_json(c);
  for (const auto& f : r.findings)
    findings.push_back(
        Json{{"comparison", f.comparison}, {"config", f.config}, {"sat", f.sat}, {"detail", f.detail}});
  const Json j{{"cases", r.cases},
               {"rejected", r.rejected},
               {"seconds", r.seconds},
               {"cases_per_second", r.seconds > 0 ? static_cast<double>(r.cases) / r.seconds : 0.0},
               {"seed", r.seed},
               {"unexplained", r.unexplained()},
               {"robust_policy", has_robust_policy()},
               {"traversal_sat", has_traversal_sat()},
               {"families", std::move(families)},
               {"comparisons", std::move(comparisons)},
               {"by_config", std::move(by_config)},
               {"manifold", manifold_json(r.comparisons, r.by_config, r.details, r.maxima)},
               {"skipped_total", r.skipped_total()},
               {"skipped", r.skipped},
               {"reproducers", r.reproducers},
               {"findings", std::move(findings)}};
  out << j.dump() << "\n";
}

void print_text(std::ostream& out, const Report& r) {
  char line[256];
  out << "sepax differential fuzz report\n";
  std::snprintf(line, sizeof line,
                "  %lld cases checked (+%lld rejected by validation) in %.1f s: %.1f cases/s, seed %llu\n",
                static_cast<long long>(r.cases), static_cast<long long>(r.rejected), r.seconds,
                r.seconds > 0 ? static_cast<double>(r.cases) / r.seconds : 0.0,
                static_cast<unsigned long long>(r.seed));
  out << line;
  out << "  configurations: float_plain double_plain"
      << (has_robust_policy() ? " float_robust double_robust" : "")
      << " mpq gmpq epeck; SATs: brute_force gauss_map" << (has_traversal_sat() ? " traversal" : "") << "\n";
  if (!has_robust_policy()) out << "  (robust policy not built in: robust_kernel.hpp not found)\n";
  if (!has_traversal_sat()) out << "  (traversal SAT not built in: sat_traversal.hpp not found)\n";
  out << "\n  family       cases  rejected  unexplained\n";
  for (const auto& [name, f] : r.families) {
    std::snprintf(line, sizeof line, "  %-10s %7lld  %8lld  %11lld\n", name.c_str(),
                  static_cast<long long>(f.cases), static_cast<long long>(f.rejected),
                  static_cast<long long>(f.unexplained));
    out << line;
  }
  auto table = [&](const std::map<std::string, Counts>& m, const char* title) {
    std::snprintf(line, sizeof line, "\n  %-30s %12s %10s %10s %8s %11s %9s\n", title, "agree", "exact_zero",
                  "explained", "tie", "unexplained", "nonconvex");
    out << line;
    for (const auto& [name, c] : m) {
      std::snprintf(line, sizeof line, "  %-30s %12lld %10lld %10lld %8lld %11lld %9lld\n", name.c_str(),
                    static_cast<long long>(c[Classification::agree]),
                    static_cast<long long>(c[Classification::exact_zero]),
                    static_cast<long long>(c[Classification::explained]),
                    static_cast<long long>(c[Classification::tie]),
                    static_cast<long long>(c[Classification::unexplained]),
                    static_cast<long long>(c[Classification::nonconvex]));
      out << line;
    }
  };
  table(r.comparisons, "comparison");
  table(r.by_config, "comparison/configuration");
  // Comparisons not made above a size budget (CheckOptions), per family.
  out << "\n  skipped above size budgets (not compared): " << r.skipped_total() << "\n";
  for (const auto& [key, n] : r.skipped) {
    std::snprintf(line, sizeof line, "    %-36s %9lld  (", key.c_str(), static_cast<long long>(n));
    out << line;
    bool first = true;
    for (const auto& [fam, f] : r.families)
      if (auto it = f.skipped.find(key); it != f.skipped.end()) {
        out << (first ? "" : ", ") << fam << " " << it->second;
        first = false;
      }
    out << ")\n";
  }
  print_manifold_text(out, r.comparisons, r.by_config, r.details, r.maxima);
  out << "\n  unexplained disagreements: " << r.unexplained() << "\n";
  for (const auto& f : r.findings)
    out << "    [" << f.comparison << " " << f.config << " " << f.sat << "] " << f.detail << "\n";
  if (!r.reproducers.empty()) {
    out << "  reproducers written:\n";
    for (const auto& p : r.reproducers) out << "    " << p << "\n";
  } else {
    out << "  reproducers written: none\n";
  }
}

int run_campaign(const CampaignOptions& opt, std::ostream& out) {
  const double seconds = opt.seconds;
  const bool json = opt.json, quiet = opt.quiet, replay = opt.replay, shrink_replays = opt.shrink_replays,
             bytes = opt.bytes, out_given = opt.out_given;
  // Shrinking (shrink.hpp): each unexplained finding, up to shrink_max per
  // run, is shrunk within this budget; the original reproducer is kept too.
  const ShrinkOptions shrink_opt = opt.shrink;
  const int shrink_max = opt.shrink_max;
  const std::string& out_dir = opt.out_dir;
  const std::vector<std::string> families = opt.families.empty() ? family_names() : opt.families;
  const std::vector<std::string>& files = opt.replay_files;
  int shrunk = 0;
  // Shrink a finding (its original reproducer is `original`) and record the
  // shrunk reproducer; a failure to shrink never hides the finding.
  auto shrink_finding = [&](Report& rep, const std::string& original, const std::string& dir,
                            const FuzzCase& c, const CaseReport& r) {
    if (shrink_opt.max_steps <= 0 || shrunk >= shrink_max) return;
    ++shrunk;
    try {
      const std::string path = shrunk_path(original, dir);
      ShrinkStats st;
      if (!quiet) std::fprintf(stderr, "\n[sepax fuzz] shrinking %s ...", original.c_str());
      if (write_shrunk_reproducer(path, original, c, r, shrink_opt, &st)) {
        rep.reproducers.push_back(path);
        if (!quiet)
          std::fprintf(stderr, " %d of %d steps kept in %.1f s -> %s\n", st.kept, st.steps, st.seconds,
                       path.c_str());
      }
    } catch (const std::exception& e) {
      std::cerr << "sepax fuzz: could not shrink " << original << ": " << e.what() << "\n";
    }
  };
  Report rep;
  rep.seed = opt.seed;
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };

  if (replay) {
    // A directory contributes its .case files, or with --bytes every regular
    // file (libFuzzer names its corpus files by hash, without extension); a
    // directory that contributes nothing is an error, not "0 cases checked".
    std::vector<std::string> paths;
    int status = 0;
    for (const auto& f : files) {
      if (std::filesystem::is_directory(f)) {
        std::vector<std::string> in_dir;
        for (const auto& e : std::filesystem::directory_iterator(f))
          if (e.is_regular_file() && (bytes || e.path().extension() == ".case"))
            in_dir.push_back(e.path().string());
        if (in_dir.empty()) {
          std::cerr << "sepax fuzz: the directory '" << f << "' holds no "
                    << (bytes ? "files" : ".case files") << " to replay\n";
          status = 3;
        }
        std::sort(in_dir.begin(), in_dir.end());
        paths.insert(paths.end(), in_dir.begin(), in_dir.end());
      } else {
        paths.push_back(f);
      }
    }
    std::size_t read = 0;  // the cases read (checked, or rejected as invalid)
    for (const auto& p : paths) {
      FuzzCase c;
      try {
        if (bytes) {
          std::ifstream in(p, std::ios::binary);
          if (!in) throw InvalidInput(ErrorCode::Parse, "cannot open libFuzzer input '" + p + "'");
          const std::vector<char> raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
          c = decode_bytes(reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size());
          if (out_given) {
            std::filesystem::create_directories(out_dir);
            const auto to =
                std::filesystem::path(out_dir) / (std::filesystem::path(p).stem().string() + ".case");
            write_case_file(to.string(), c, "decoded from the libFuzzer input " + p);
            if (!quiet) std::cerr << p << ": decoded to " << to.string() << "\n";
          }
        } else {
          c = read_case_file(p);
        }
      } catch (const InvalidInput& e) {
        std::cerr << "sepax fuzz: " << e.what() << "\n";
        status = 3;
        continue;
      }
      ++read;
      CheckOptions check;
      check.inject_fault = opt.inject_fault;
      const CaseReport r = check_case_guarded(c, check);
      rep.add(c.family, r);
      if (!quiet) {
        std::cerr << p << ": "
                  << (r.valid ? (r.unexplained_count ? "UNEXPLAINED" : "ok") : "rejected: " + r.reject_reason)
                  << "\n";
      }
      if (r.unexplained_count) {
        for (const auto& f : r.unexplained)
          std::cerr << "  [" << f.comparison << " " << f.config << " " << f.sat << "] " << f.detail << "\n";
        if (status == 0) status = 1;
        if (shrink_replays) shrink_finding(rep, p, out_dir, c, r);
      }
    }
    rep.seconds = elapsed();
    if (read == 0) return status;  // (no case read: the errors above, and no report of zero cases)
    if (json)
      print_json(out, rep);
    else
      print_text(out, rep);
    return status != 0 ? status : (rep.unexplained() ? 1 : 0);
  }

  // The progress line rewrites itself with '\r': only on a terminal, never in a CI log.
  const bool progress = !quiet && isatty(fileno(stderr));
  double last_progress = 0;
  const std::uint64_t n_cases = opt.cases;
  run_in_order(
      opt.jobs, [&](std::uint64_t index) { return n_cases > 0 ? index < n_cases : elapsed() < seconds; },
      [&](std::uint64_t index) { return run_case(families, rep.seed, index); },
      [&](CaseOutcome&& o) {
        const FuzzCase& c = o.c;
        const CaseReport& r = o.r;
        rep.add(o.family, r);
        if (r.unexplained_count) {
          try {
            const std::string original = write_reproducer(out_dir, c, r);
            rep.reproducers.push_back(original);
            shrink_finding(rep, original, "", c, r);
          } catch (const std::exception& e) {
            std::cerr << "sepax fuzz: could not write a reproducer: " << e.what() << "\n";
          }
        }
        const double now = elapsed();
        if (progress && now - last_progress >= 1.0) {
          last_progress = now;
          std::fprintf(stderr, "\r[sepax fuzz] %6.1f s  %8lld cases  %7.1f cases/s  unexplained %lld   ", now,
                       static_cast<long long>(rep.cases),
                       now > 0 ? static_cast<double>(rep.cases) / now : 0.0,
                       static_cast<long long>(rep.unexplained()));
          std::fflush(stderr);
        }
      });
  rep.seconds = elapsed();
  if (progress) std::fprintf(stderr, "\n");
  if (json)
    print_json(out, rep);
  else
    print_text(out, rep);
  return rep.unexplained() ? 1 : 0;
}

}  // namespace sepax::fuzz
