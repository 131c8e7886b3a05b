// src/commands/query_command.cpp -- see query_command.hpp.
#include "commands/query_command.hpp"

#include <charconv>
#include <cmath>
#include <exception>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>

#include <sepax/error.hpp>

#include "commands/batch.hpp"
#include "commands/query_output.hpp"
#include "commands/render_command.hpp"
#include "commands/sat_runner.hpp"
#include "io/open_file.hpp"
#include "io/shape_source.hpp"

namespace sepax::cli {

const char* const query_usage =
    "usage: sepax query A B [options]\n"
    "       sepax query --batch FILE|- [options]\n"
    "\n"
    "Separating axis test of two convex shapes A and B.\n"
    "\n"
    "options:\n"
    "  --pose tx ty tz [qw qx qy qz]   move B: rotate by the quaternion (normalised;\n"
    "                                  default identity), then translate\n"
    "  --number float|double|exact     arithmetic (default double; exact = GMP rationals)\n"
    "  --algorithm brute|gauss|traversal   SAT algorithm (default gauss)\n"
    "  --robust                        float/double with every decision made exactly\n"
    "  --json                          print one JSON object\n"
    "  --batch FILE|-                  JSON lines in (FILE or stdin), JSON lines out\n"
    "\n"
    "shapes:\n";

const char* const render_usage =
    "usage: sepax render A B --svg FILE|- [--pose ...] [--algorithm brute|gauss|traversal] [--robust]\n"
    "\n"
    "Draw A, B (B moved by --pose), their contact manifold and the overlaid Gauss maps of\n"
    "A and -B (arcs, Minkowski edge-edge faces, the chosen axis) as an SVG picture.\n"
    "The case is computed in double (robust policy with --robust).\n"
    "\n"
    "shapes:\n";

const char* const info_usage =
    "usage: sepax info SHAPE [--number float|double|exact] [--pose ...] [--json]\n"
    "\n"
    "Build SHAPE as sepax would for a query and print its size.\n";

namespace {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::optional<double> as_number(const std::string& s) {
  std::string_view t = s;
  if (!t.empty() && t[0] == '+') t.remove_prefix(1);
  double v = 0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || t[0] == '+' || r.ec != std::errc() || r.ptr != t.data() + t.size()) return std::nullopt;
  return v;
}

struct Options {
  std::vector<std::string> positional;
  std::optional<Pose> pose;
  RunConfig cfg;
  bool json = false;
  bool help = false;
  std::optional<std::string> batch;
  std::optional<std::string> svg;
};

Options parse_options(const std::vector<std::string>& args, bool allow_batch, bool allow_svg = false) {
  Options o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string a = args[i];
    std::optional<std::string> inline_value;
    if (a.starts_with("--") && a.find('=') != std::string::npos) {
      inline_value = a.substr(a.find('=') + 1);
      a = a.substr(0, a.find('='));
    }
    const auto value = [&](const char* what) -> std::string {
      if (inline_value) return *inline_value;
      if (i + 1 >= args.size()) throw UsageError(a + " needs " + what);
      return args[++i];
    };
    if (a == "-h" || a == "--help") {
      o.help = true;
    } else if (a == "--json") {
      o.json = true;
    } else if (a == "--robust") {
      o.cfg.robust = true;
    } else if (a == "--number") {
      const std::string v = value("a value: float, double or exact");
      const auto k = parse_number_kind(v);
      if (!k) throw UsageError("--number: unknown number type '" + v + "' (float, double or exact)");
      o.cfg.number = *k;
    } else if (a == "--algorithm") {
      const std::string v = value("a value: brute, gauss or traversal");
      const auto k = parse_algorithm_kind(v);
      if (!k) throw UsageError("--algorithm: unknown algorithm '" + v + "' (brute, gauss or traversal)");
      o.cfg.algorithm = *k;
    } else if (a == "--svg" && allow_svg) {
      o.svg = value("a file name (or - for standard output)");
    } else if (a == "--batch" && allow_batch) {
      o.batch = value("a file name (or - for standard input)");
    } else if (a == "--pose") {
      if (inline_value) throw UsageError("--pose takes 3 or 7 separate numbers: --pose tx ty tz [qw qx qy qz]");
      double v[7];
      for (int k = 0; k < 3; ++k) {
        if (i + 1 >= args.size()) throw UsageError("--pose needs 3 numbers (tx ty tz), optionally followed by 4 (qw qx qy qz)");
        const auto x = as_number(args[++i]);
        if (!x) throw UsageError("--pose: '" + args[i] + "' is not a number");
        v[k] = *x;
      }
      int n = 3;
      if (i + 1 < args.size() && as_number(args[i + 1])) {
        for (int k = 3; k < 7; ++k) {
          if (i + 1 >= args.size() || !as_number(args[i + 1])) {
            throw UsageError("--pose: a rotation needs 4 numbers (qw qx qy qz) after the translation");
          }
          v[k] = *as_number(args[++i]);
        }
        n = 7;
      }
      try {
        o.pose = n == 7 ? Pose::make(Vec3<double>(v[0], v[1], v[2]), {v[3], v[4], v[5], v[6]})
                        : Pose::make(Vec3<double>(v[0], v[1], v[2]));
      } catch (const InvalidInput& e) {
        throw UsageError(e.what());
      }
    } else if (a.size() > 1 && a[0] == '-' && !as_number(a) && !a.starts_with("-:") && !a.starts_with("-#")) {
      throw UsageError("unknown option '" + args[i] + "'");
    } else {
      o.positional.push_back(args[i]);
    }
  }
  return o;
}

int usage_error(std::ostream& err, const char* verb, const std::string& what) {
  err << "sepax " << verb << ": " << what << "\n(run 'sepax " << verb << " --help' for usage)\n";
  return 2;
}

int input_error(std::ostream& out, std::ostream& err, bool json, const std::string& what) {
  err << "sepax: error: " << what << "\n";
  if (json) out << json::write(json::Value(json::Object{{"error", what}})) << "\n";
  return 1;
}

int batch(const Options& o, std::istream& in, std::ostream& out, std::ostream& err) {
  if (!o.positional.empty()) return usage_error(err, "query", "--batch takes no shape arguments");
  if (o.pose) return usage_error(err, "query", "--pose cannot be used with --batch (points are in one world frame)");
  if (const std::string why = unsupported_reason(o.cfg); !why.empty()) return usage_error(err, "query", why);
  BatchSummary s;
  if (*o.batch == "-") {
    s = run_batch(in, out, o.cfg);
  } else {
    std::ifstream file;
    try {
      file = io::open_input(*o.batch);
    } catch (const std::exception& e) {
      err << "sepax: error: " << e.what() << "\n";
      return 2;
    }
    s = run_batch(file, out, o.cfg);
    if (file.bad()) {
      err << "sepax: error: " << *o.batch << ": read error\n";
      return 2;
    }
  }
  if (s.errors > 0) {
    err << "sepax query --batch: " << s.errors << " of " << s.queries << " queries failed\n";
    return 1;
  }
  return 0;
}

}  // namespace

int run_query(const std::vector<std::string>& args, std::istream& in, std::ostream& out, std::ostream& err) {
  Options o;
  try {
    o = parse_options(args, /*allow_batch=*/true);
  } catch (const UsageError& e) {
    return usage_error(err, "query", e.what());
  }
  if (o.help) {
    out << query_usage << io::builtin_shapes_help();
    return 0;
  }
  if (o.batch) return batch(o, in, out, err);
  if (o.positional.size() != 2) {
    return usage_error(err, "query", "expected two shapes A and B, got " + std::to_string(o.positional.size()));
  }
  if (const std::string why = unsupported_reason(o.cfg); !why.empty()) return usage_error(err, "query", why);
  try {
    const io::ShapeData a = io::load_shape(o.positional[0], in);
    const io::ShapeData b = io::load_shape(o.positional[1], in);
    const RunOutcome r = run_sat(a, b, o.pose ? &*o.pose : nullptr, o.cfg);
    if (o.json) {
      out << json::write(query_json(r, o.cfg)) << "\n";
    } else {
      print_query_text(out, r, o.cfg, a.name, b.name);
    }
    return 0;
  } catch (const std::bad_alloc&) {
    return input_error(out, err, o.json, "out of memory");
  } catch (const std::exception& e) {
    return input_error(out, err, o.json, e.what());
  }
}

int run_info(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  Options o;
  try {
    o = parse_options(args, /*allow_batch=*/false);
  } catch (const UsageError& e) {
    return usage_error(err, "info", e.what());
  }
  if (o.help) {
    out << info_usage << "\nshapes:\n" << io::builtin_shapes_help();
    return 0;
  }
  if (o.positional.size() != 1) {
    return usage_error(err, "info", "expected one shape, got " + std::to_string(o.positional.size()));
  }
  if (o.cfg.robust) return usage_error(err, "info", "--robust does not apply to info");
  try {
    if (const auto listing = io::object_listing(o.positional[0]); listing && !o.json) {
      out << *listing;
      return 0;
    }
    const io::ShapeData s = io::load_shape(o.positional[0]);
    const ShapeCounts c = shape_counts(s, o.cfg.number, o.pose ? &*o.pose : nullptr);
    if (o.json) {
      out << json::write(json::Value(json::Object{{"shape", s.name},
                                                  {"number", name(o.cfg.number)},
                                                  {"vertices", c.vertices},
                                                  {"edges", c.edges},
                                                  {"faces", c.faces},
                                                  {"flat", c.flat}}))
          << "\n";
    } else {
      out << s.name << ": " << c.vertices << " vertices, " << c.edges << " edges, " << c.faces << " faces"
          << (c.flat ? " (flat: a double-sided polygon)" : "") << " [" << name(o.cfg.number) << "]\n";
    }
    return 0;
  } catch (const std::exception& e) {
    return input_error(out, err, o.json, e.what());
  }
}

int run_render(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  Options o;
  try {
    o = parse_options(args, /*allow_batch=*/false, /*allow_svg=*/true);
  } catch (const UsageError& e) {
    return usage_error(err, "render", e.what());
  }
  if (o.help) {
    out << render_usage << io::builtin_shapes_help();
    return 0;
  }
  if (o.positional.size() != 2) {
    return usage_error(err, "render", "expected two shapes A and B, got " + std::to_string(o.positional.size()));
  }
  if (!o.svg) return usage_error(err, "render", "--svg FILE is required (- for standard output)");
  if (o.json) return usage_error(err, "render", "--json does not apply to render");
  try {
    const io::ShapeData a = io::load_shape(o.positional[0]);
    const io::ShapeData b = io::load_shape(o.positional[1]);
    const std::string svg = render_case_svg(a, b, o.pose ? &*o.pose : nullptr, o.cfg, a.name + "  vs  " + b.name);
    if (*o.svg == "-") {
      out << svg;
    } else {
      std::ofstream f(*o.svg, std::ios::binary);
      if (!(f << svg) || !f.flush()) return input_error(out, err, false, "cannot write " + *o.svg);
      err << "sepax render: wrote " << *o.svg << "\n";
    }
    return 0;
  } catch (const std::exception& e) {
    return input_error(out, err, false, e.what());
  }
}

namespace {
std::vector<std::string> rest(int argc, char** argv) {
  std::vector<std::string> v;
  for (int i = 1; i < argc; ++i) v.emplace_back(argv[i]);
  return v;
}
}  // namespace

int query_main(int argc, char** argv) { return run_query(rest(argc, argv), std::cin, std::cout, std::cerr); }
int info_main(int argc, char** argv) { return run_info(rest(argc, argv), std::cout, std::cerr); }
int render_main(int argc, char** argv) { return run_render(rest(argc, argv), std::cout, std::cerr); }

}  // namespace sepax::cli
