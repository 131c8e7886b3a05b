// `sepax fuzz`: the standalone campaign and corpus replay (see sepax/fuzz/cli.hpp).
#include <sepax/fuzz/campaign.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include <unistd.h>

#include <sepax/error.hpp>
#include <sepax/fuzz/check_manifold.hpp>
#include <sepax/fuzz/cli.hpp>
#include <sepax/fuzz/generators.hpp>
#include <sepax/fuzz/shrink.hpp>
#include <sepax/fuzz/workers.hpp>

namespace sepax::fuzz {

std::int64_t Report::unexplained() const {
  std::int64_t n = 0;
  for (const auto& [k, c] : comparisons) n += c[Klass::unexplained];
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
    path = dir + "/unexplained-" + c.family + "-" + std::to_string(c.seed) + (k ? "-" + std::to_string(k) : "") + ".case";
    if (!std::filesystem::exists(path)) break;
  }
  std::ostringstream s;
  s << "sepax fuzz reproducer: " << r.unexplained_count << " unexplained disagreement(s)\n";
  for (const auto& f : r.unexplained) s << "[" << f.comparison << " " << f.config << " " << f.sat << "] " << f.detail << "\n";
  s << "replay: sepax fuzz --replay " << path << "\n";
  s << "audit:  sepax audit --case " << path;
  write_case_file(path, c, s.str());
  return path;
}

namespace {

std::string jstr(const std::string& s) {
  std::string o = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') o += '\\', o += ch;
    else if (static_cast<unsigned char>(ch) < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", ch);
      o += b;
    } else o += ch;
  }
  return o + "\"";
}

std::string jskips(const std::map<std::string, std::int64_t>& m) {
  std::string o = "{";
  for (const auto& [k, n] : m) o += (o.size() > 1 ? "," : "") + jstr(k) + ":" + std::to_string(n);
  return o + "}";
}

std::string jcounts(const Counts& c) {
  std::string o = "{";
  for (int k = 0; k < kKlassCount; ++k) {
    if (k) o += ",";
    o += jstr(klass_name(static_cast<Klass>(k))) + ":" + std::to_string(c.n[static_cast<std::size_t>(k)]);
  }
  return o + "}";
}

}  // namespace

void print_json(std::ostream& out, const Report& r) {
  out << "{\"cases\":" << r.cases << ",\"rejected\":" << r.rejected << ",\"seconds\":" << r.seconds
      << ",\"cases_per_second\":" << (r.seconds > 0 ? static_cast<double>(r.cases) / r.seconds : 0.0)
      << ",\"seed\":" << r.seed << ",\"unexplained\":" << r.unexplained()
      << ",\"robust_policy\":" << (has_robust_policy() ? "true" : "false")
      << ",\"traversal_sat\":" << (has_traversal_sat() ? "true" : "false") << ",\"families\":{";
  bool first = true;
  for (const auto& [name, f] : r.families) {
    out << (first ? "" : ",") << jstr(name) << ":{\"cases\":" << f.cases << ",\"rejected\":" << f.rejected
        << ",\"unexplained\":" << f.unexplained << ",\"skipped\":" << jskips(f.skipped) << "}";
    first = false;
  }
  out << "},\"comparisons\":{";
  first = true;
  for (const auto& [name, c] : r.comparisons) {
    out << (first ? "" : ",") << jstr(name) << ":" << jcounts(c);
    first = false;
  }
  out << "},\"by_config\":{";
  first = true;
  for (const auto& [name, c] : r.by_config) {
    out << (first ? "" : ",") << jstr(name) << ":" << jcounts(c);
    first = false;
  }
  out << "},\"manifold\":";
  print_manifold_json(out, r.comparisons, r.by_config, r.details, r.maxima);
  out << ",\"skipped_total\":" << r.skipped_total() << ",\"skipped\":" << jskips(r.skipped);
  out << ",\"reproducers\":[";
  for (std::size_t i = 0; i < r.reproducers.size(); ++i) out << (i ? "," : "") << jstr(r.reproducers[i]);
  out << "],\"findings\":[";
  for (std::size_t i = 0; i < r.findings.size(); ++i) {
    const auto& f = r.findings[i];
    out << (i ? "," : "") << "{\"comparison\":" << jstr(f.comparison) << ",\"config\":" << jstr(f.config)
        << ",\"sat\":" << jstr(f.sat) << ",\"detail\":" << jstr(f.detail) << "}";
  }
  out << "]}\n";
}

void print_text(std::ostream& out, const Report& r) {
  char line[256];
  out << "sepax differential fuzz report\n";
  std::snprintf(line, sizeof line, "  %lld cases checked (+%lld rejected by validation) in %.1f s: %.1f cases/s, seed %llu\n",
                static_cast<long long>(r.cases), static_cast<long long>(r.rejected), r.seconds,
                r.seconds > 0 ? static_cast<double>(r.cases) / r.seconds : 0.0,
                static_cast<unsigned long long>(r.seed));
  out << line;
  out << "  configurations: float_plain double_plain" << (has_robust_policy() ? " float_robust double_robust" : "")
      << " mpq gmpq epeck; SATs: brute_force gauss_map" << (has_traversal_sat() ? " traversal" : "") << "\n";
  if (!has_robust_policy()) out << "  (robust policy not built in: robust_kernel.hpp not found)\n";
  if (!has_traversal_sat()) out << "  (traversal SAT not built in: sat_traversal.hpp not found)\n";
  out << "\n  family       cases  rejected  unexplained\n";
  for (const auto& [name, f] : r.families) {
    std::snprintf(line, sizeof line, "  %-10s %7lld  %8lld  %11lld\n", name.c_str(), static_cast<long long>(f.cases),
                  static_cast<long long>(f.rejected), static_cast<long long>(f.unexplained));
    out << line;
  }
  auto table = [&](const std::map<std::string, Counts>& m, const char* title) {
    std::snprintf(line, sizeof line, "\n  %-30s %12s %10s %10s %8s %11s %9s\n", title, "agree", "exact_zero",
                  "explained", "tie", "unexplained", "nonconvex");
    out << line;
    for (const auto& [name, c] : m) {
      std::snprintf(line, sizeof line, "  %-30s %12lld %10lld %10lld %8lld %11lld %9lld\n", name.c_str(),
                    static_cast<long long>(c[Klass::agree]), static_cast<long long>(c[Klass::exact_zero]),
                    static_cast<long long>(c[Klass::explained]), static_cast<long long>(c[Klass::tie]),
                    static_cast<long long>(c[Klass::unexplained]), static_cast<long long>(c[Klass::nonconvex]));
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
  for (const auto& f : r.findings) out << "    [" << f.comparison << " " << f.config << " " << f.sat << "] " << f.detail << "\n";
  if (!r.reproducers.empty()) {
    out << "  reproducers written:\n";
    for (const auto& p : r.reproducers) out << "    " << p << "\n";
  } else {
    out << "  reproducers written: none\n";
  }
}

namespace {

int usage(const char* msg) {
  std::cerr << "sepax fuzz: " << msg << "\n"
            << "usage: sepax fuzz [--seconds S] [--cases N] [--seed K] [--jobs N] [--families a,b,...] [--out DIR] [--json]\n"
            << "                  [--quiet]\n"
            << "                  [--shrink-steps N] [--shrink-seconds S] [--shrink-max N]\n"
            << "       sepax fuzz --replay FILE_OR_DIR... [--bytes] [--json] [--shrink] [--out DIR]\n"
            << "       (--bytes: the files are libFuzzer inputs, decoded as sepax_libfuzzer decodes them;\n"
            << "        with --out DIR each is also written there as a readable DIR/NAME.case)\n"
            << "families:";
  for (const auto& f : family_names()) std::cerr << " " << f;
  std::cerr << "\n";
  return 2;
}

bool parse_number(const char* s, double& out) {
  char* end = nullptr;
  out = std::strtod(s, &end);
  return end != s && *end == '\0' && std::isfinite(out) && out >= 0;
}

}  // namespace

int fuzz_main(int argc, char** argv) {
  double seconds = 30, max_cases = 0, seed_d = 1, jobs = 0;
  bool json = false, quiet = false, replay = false, shrink_replays = false, bytes = false, out_given = false;
  // Shrinking (shrink.hpp): each unexplained finding, up to shrink_max per
  // run, is shrunk within this budget; the original reproducer is kept too.
  ShrinkOptions shrink_opt;
  double shrink_steps = shrink_opt.max_steps, shrink_max = 5;
  std::string out_dir = "fuzz-reproducers";
  std::vector<std::string> families = family_names(), files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](double& x) {
      if (i + 1 >= argc || !parse_number(argv[i + 1], x)) return false;
      ++i;
      return true;
    };
    if (a == "--seconds") {
      if (!value(seconds)) return usage("--seconds needs a non-negative number");
    } else if (a == "--cases") {
      if (!value(max_cases)) return usage("--cases needs a non-negative number");
    } else if (a == "--jobs") {
      if (!value(jobs) || jobs != std::floor(jobs) || jobs > 4096) return usage("--jobs needs a whole number of workers (0: every core)");
    } else if (a == "--seed") {
      if (!value(seed_d)) return usage("--seed needs a non-negative integer");
    } else if (a == "--families") {
      if (i + 1 >= argc) return usage("--families needs a comma-separated list");
      families.clear();
      std::stringstream ss(argv[++i]);
      for (std::string f; std::getline(ss, f, ',');) {
        if (std::find(family_names().begin(), family_names().end(), f) == family_names().end())
          return usage(("unknown family '" + f + "'").c_str());
        families.push_back(f);
      }
      if (families.empty()) return usage("--families is empty");
    } else if (a == "--out") {
      if (i + 1 >= argc) return usage("--out needs a directory");
      out_dir = argv[++i];
      out_given = true;
    } else if (a == "--shrink-steps") {
      if (!value(shrink_steps)) return usage("--shrink-steps needs a non-negative integer (0: no shrinking)");
    } else if (a == "--shrink-seconds") {
      if (!value(shrink_opt.max_seconds)) return usage("--shrink-seconds needs a non-negative number");
    } else if (a == "--shrink-max") {
      if (!value(shrink_max)) return usage("--shrink-max needs a non-negative integer");
    } else if (a == "--shrink") {
      shrink_replays = true;
    } else if (a == "--bytes") {
      bytes = true;
    } else if (a == "--json") {
      json = true;
    } else if (a == "--quiet") {
      quiet = true;
    } else if (a == "--replay") {
      replay = true;
    } else if (a == "--help" || a == "-h") {
      usage("help");
      return 0;
    } else if (replay && !a.empty() && a[0] != '-') {
      files.push_back(a);
    } else {
      return usage(("unknown argument '" + a + "'").c_str());
    }
  }
  shrink_opt.max_steps = static_cast<int>(std::min(shrink_steps, 1e9));
  int shrunk = 0;
  // Shrink a finding (its original reproducer is `original`) and record the
  // shrunk reproducer; a failure to shrink never hides the finding.
  auto shrink_finding = [&](Report& rep, const std::string& original, const std::string& dir, const FuzzCase& c,
                            const CaseReport& r) {
    if (shrink_opt.max_steps <= 0 || shrunk >= shrink_max) return;
    ++shrunk;
    try {
      const std::string path = shrunk_path(original, dir);
      ShrinkStats st;
      if (!quiet) std::fprintf(stderr, "\n[sepax fuzz] shrinking %s ...", original.c_str());
      if (write_shrunk_reproducer(path, original, c, r, shrink_opt, &st)) {
        rep.reproducers.push_back(path);
        if (!quiet)
          std::fprintf(stderr, " %d of %d steps kept in %.1f s -> %s\n", st.kept, st.steps, st.seconds, path.c_str());
      }
    } catch (const std::exception& e) {
      std::cerr << "sepax fuzz: could not shrink " << original << ": " << e.what() << "\n";
    }
  };
  Report rep;
  rep.seed = static_cast<std::uint64_t>(seed_d);
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };

  if (replay) {
    if (files.empty()) return usage("--replay needs at least one case file or directory");
    std::vector<std::string> paths;
    for (const auto& f : files) {
      if (std::filesystem::is_directory(f)) {
        std::vector<std::string> in_dir;
        for (const auto& e : std::filesystem::directory_iterator(f))
          if (e.path().extension() == ".case") in_dir.push_back(e.path().string());
        std::sort(in_dir.begin(), in_dir.end());
        paths.insert(paths.end(), in_dir.begin(), in_dir.end());
      } else {
        paths.push_back(f);
      }
    }
    int status = 0;
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
            const auto to = std::filesystem::path(out_dir) / (std::filesystem::path(p).stem().string() + ".case");
            write_case_file(to.string(), c, "decoded from the libFuzzer input " + p);
            if (!quiet) std::cerr << p << ": decoded to " << to.string() << "\n";
          }
        } else {
          c = read_case_file(p);
        }
      } catch (const InvalidInput& e) {
        std::cerr << "sepax fuzz: " << e.what() << "\n";
        status = 2;
        continue;
      }
      const CaseReport r = check_case_guarded(c);
      rep.add(c.family, r);
      if (!quiet) {
        std::cerr << p << ": " << (r.valid ? (r.unexplained_count ? "UNEXPLAINED" : "ok") : "rejected: " + r.reject_reason)
                  << "\n";
      }
      if (r.unexplained_count) {
        for (const auto& f : r.unexplained) std::cerr << "  [" << f.comparison << " " << f.config << " " << f.sat << "] " << f.detail << "\n";
        if (status == 0) status = 1;
        if (shrink_replays) shrink_finding(rep, p, out_dir, c, r);
      }
    }
    rep.seconds = elapsed();
    if (json) print_json(std::cout, rep);
    else print_text(std::cout, rep);
    return status != 0 ? status : (rep.unexplained() ? 1 : 0);
  }

  // The progress line rewrites itself with '\r': only on a terminal, never in a CI log.
  const bool progress = !quiet && isatty(fileno(stderr));
  double last_progress = 0;
  const auto n_cases = static_cast<std::uint64_t>(max_cases);
  run_in_order(
      static_cast<int>(jobs),
      [&](std::uint64_t index) { return n_cases > 0 ? index < n_cases : elapsed() < seconds; },
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
                       static_cast<long long>(rep.cases), now > 0 ? static_cast<double>(rep.cases) / now : 0.0,
                       static_cast<long long>(rep.unexplained()));
          std::fflush(stderr);
        }
      });
  rep.seconds = elapsed();
  if (progress) std::fprintf(stderr, "\n");
  if (json) print_json(std::cout, rep);
  else print_text(std::cout, rep);
  return rep.unexplained() ? 1 : 0;
}

}  // namespace sepax::fuzz
