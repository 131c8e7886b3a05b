// src/commands/query_command.cpp -- see query_command.hpp.
#include "commands/query_command.hpp"

#include <exception>
#include <fstream>
#include <iostream>
#include <optional>

#include <sepax/error.hpp>

#include "commands/batch.hpp"
#include "commands/command_line.hpp"
#include "commands/query_output.hpp"
#include "commands/render_command.hpp"
#include "commands/sat_runner.hpp"
#include "commands/shape_pair.hpp"
#include "io/open_file.hpp"
#include "io/shape_source.hpp"

namespace sepax::cli {

namespace {

// The exit statuses of query (with --batch's status 1) and of info and render.
constexpr const char* kQueryExitText =
    "\nExit status: 0 success, 1 a batch line answered with an error, 2 usage error,\n"
    "3 an input that cannot be read, parsed or built, 4 internal error.\n";
constexpr const char* kExitText =
    "\nExit status: 0 success, 2 usage error, 3 an input that cannot be read, parsed or built,\n"
    "4 internal error.\n";

std::string shapes_footer(const char* extra = "", const char* exit_text = kExitText) {
  return std::string("shapes (A, B, SHAPE):\n") + io::builtin_shapes_help() +
         "FILE.case as the only argument: a fuzzer reproducer (A and B, B placed by the case)\n" + extra +
         exit_text;
}

const char* const kPoseHelp =
    "move B: rotate by the quaternion (normalised; default identity), then translate";

int batch(const CommandLine& cl, const std::string& file, const BatchOptions& opt, std::istream& in,
          std::ostream& out, std::ostream& err) {
  BatchSummary s;
  if (file == "-") {
    s = run_batch(in, out, opt);
  } else {
    std::ifstream f;
    try {
      f = io::open_input(file);
    } catch (const InvalidInput& e) {
      return input_error(out, err, false, cl.verb(), e.what());
    }
    s = run_batch(f, out, opt);
    if (f.bad()) return input_error(out, err, false, cl.verb(), file + ": read error");
  }
  if (s.errors > 0) {
    err << "sepax query --batch: " << s.errors << " of " << s.queries << " queries failed\n";
    return kExitFinding;
  }
  return kExitOk;
}

}  // namespace

int run_query(const std::vector<std::string>& args, std::istream& in, std::ostream& out, std::ostream& err) {
  std::vector<std::string> shapes;
  RunConfig cfg;
  bool json = false, hull = false, manifold = true;
  std::string batch_file;
  int jobs = 0;
  CommandLine cl(
      "query", "Separating axis test of two convex shapes A and B, or of a batch of JSON lines.",
      shapes_footer("\n--batch: one JSON object per line, {\"id\": ID, \"a\": [[x,y,z], ...], \"b\": [...]} "
                    "(point sets, hulled);\none JSON object per line out, in input order, with the contact "
                    "manifold unless --no-manifold.\n",
                    kQueryExitText));
  auto& app = cl.app;
  app.add_option("shapes", shapes, "A B, or one FILE.case")->type_name("");
  cl.add_pose(kPoseHelp);
  cl.add_number(cfg);
  cl.add_algorithm(cfg);
  cl.add_robust(cfg);
  app.add_flag("--hull", hull, "use the convex hull of each shape file's vertices");
  app.add_flag("--json", json, "print one JSON object");
  app.add_option("--batch", batch_file, "JSON lines in (FILE, or - for standard input), JSON lines out")
      ->type_name("FILE|-");
  cl.describe_value("--batch", "a file name (or - for standard input)");
  app.add_flag("--manifold,!--no-manifold", manifold,
               "with --batch: the contact manifold in every answer (default on)");
  cl.add_unsigned("--jobs", jobs,
                  "with --batch: threads answering lines (default 0: all cores; at most " +
                      std::to_string(kMaxJobs) + "; same output)",
                  kMaxJobs);
  if (const auto status = cl.parse(args, out, err)) return *status;
  try {
    const std::optional<Pose> pose = cl.pose();
    if (const std::string why = unsupported_reason(cfg); !why.empty()) throw UsageError(why);
    if (app.count("--batch")) {
      if (!shapes.empty()) throw UsageError("--batch takes no shape arguments");
      if (pose) throw UsageError("--pose cannot be used with --batch (points are in one world frame)");
      if (json) throw UsageError("--json is implied by --batch (JSON lines out)");
      if (hull) throw UsageError("--hull is implied by --batch (every point set is hulled)");
      BatchOptions opt;
      opt.cfg = cfg;
      opt.manifold = manifold;
      opt.jobs = jobs;
      return batch(cl, batch_file, opt, in, out, err);
    }
    for (const char* only : {"--manifold", "--no-manifold", "--jobs"})
      if (app.count(only)) throw UsageError(std::string(only) + " applies to --batch only");
    ShapePair p;
    try {
      p = load_pair(shapes, hull, in);
      if (pose && p.from_case)
        throw UsageError("--pose cannot be used with a .case file (the case places B)");
      const RunOutcome r = run_sat(p.a, p.b, pose ? &*pose : nullptr, cfg);
      if (json)
        out << json::write(query_json(r, cfg)) << "\n";
      else
        print_query_text(out, r, cfg, p.a.name, p.b.name);
      return kExitOk;
    } catch (const InvalidInput& e) {
      return input_error(out, err, json, "query", e.what());
    }
  } catch (const UsageError& e) {
    return cl.usage_error(err, e.what());
  }
}

int run_info(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::vector<std::string> shapes;
  RunConfig cfg;
  bool json = false, hull = false;
  CommandLine cl("info", "Build SHAPE as sepax would for a query and print its vertex, edge and face counts.",
                 shapes_footer());
  auto& app = cl.app;
  app.add_option("shape", shapes, "the shape")->type_name("SHAPE");
  cl.add_pose("move the shape: rotate by the quaternion (normalised; default identity), then translate");
  cl.add_number(cfg);
  app.add_flag("--hull", hull, "use the convex hull of the shape file's vertices");
  app.add_flag("--json", json, "print one JSON object");
  if (const auto status = cl.parse(args, out, err)) return *status;
  try {
    const std::optional<Pose> pose = cl.pose();
    if (shapes.size() != 1) throw UsageError("expected one shape, got " + std::to_string(shapes.size()));
    try {
      std::optional<io::ShapeData> read;
      if (!hull) {
        if (const auto listing = io::object_listing(shapes[0], &read)) {
          if (json) {
            json::Value objects = json::Value::array();
            for (const auto& e : listing->objects)
              objects.push_back(json::Value{{"name", e.name}, {"vertices", e.vertices}, {"faces", e.faces}});
            out << json::write(json::Value{{"shape", listing->spec}, {"objects", std::move(objects)}})
                << "\n";
          } else {
            out << listing->text();
          }
          return kExitOk;
        }
      }
      const io::ShapeData s = read ? std::move(*read) : io::load_shape(shape_argument(shapes[0], hull));
      const ShapeCounts c = shape_counts(s, cfg.number, pose ? &*pose : nullptr);
      if (json) {
        out << json::write(json::Value{{"shape", s.name},
                                       {"number", name(cfg.number)},
                                       {"vertices", c.vertices},
                                       {"edges", c.edges},
                                       {"faces", c.faces},
                                       {"flat", c.flat}})
            << "\n";
      } else {
        out << s.name << ": " << c.vertices << " vertices, " << c.edges << " edges, " << c.faces << " faces"
            << (c.flat ? " (flat: a double-sided polygon)" : "") << " [" << name(cfg.number) << "]\n";
      }
      return kExitOk;
    } catch (const InvalidInput& e) {
      return input_error(out, err, json, "info", e.what());
    }
  } catch (const UsageError& e) {
    return cl.usage_error(err, e.what());
  }
}

int run_render(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::vector<std::string> shapes;
  RunConfig cfg;
  bool hull = false;
  std::string svg;
  CommandLine cl(
      "render",
      "Draw A, B (B moved by --pose), their contact manifold and the overlaid Gauss maps of A and -B "
      "(arcs, Minkowski edge-edge faces, the chosen axis) as an SVG picture.  The case is computed in "
      "double (robust policy with --robust), so its feature indices match "
      "`sepax query --number double`.",
      shapes_footer());
  auto& app = cl.app;
  app.add_option("shapes", shapes, "A B, or one FILE.case")->type_name("");
  app.add_option("--svg", svg, "write the picture to FILE (- for standard output); required")
      ->type_name("FILE|-");
  cl.describe_value("--svg", "a file name (or - for standard output)");
  cl.add_pose(kPoseHelp);
  cl.add_algorithm(cfg);
  cl.add_robust(cfg);
  app.add_flag("--hull", hull, "use the convex hull of each shape file's vertices");
  if (const auto status = cl.parse(args, out, err)) return *status;
  try {
    const std::optional<Pose> pose = cl.pose();
    if (const std::string why = unsupported_reason(cfg); !why.empty()) throw UsageError(why);
    if (!app.count("--svg")) throw UsageError("--svg FILE is required (- for standard output)");
    try {
      const ShapePair p = load_pair(shapes, hull);
      if (pose && p.from_case)
        throw UsageError("--pose cannot be used with a .case file (the case places B)");
      const std::string picture =
          render_case_svg(p.a, p.b, pose ? &*pose : nullptr, cfg, p.a.name + "  vs  " + p.b.name);
      if (svg == "-") {
        out << picture;
      } else {
        std::ofstream f(svg, std::ios::binary);
        if (!(f << picture) || !f.flush())
          return input_error(out, err, false, "render", "cannot write " + svg);
        err << "sepax render: wrote " << svg << "\n";
      }
      return kExitOk;
    } catch (const InvalidInput& e) {
      return input_error(out, err, false, "render", e.what());
    }
  } catch (const UsageError& e) {
    return cl.usage_error(err, e.what());
  }
}

int query_main(int argc, char** argv) {
  return run_query(arguments(argc, argv), std::cin, std::cout, std::cerr);
}
int info_main(int argc, char** argv) { return run_info(arguments(argc, argv), std::cout, std::cerr); }
int render_main(int argc, char** argv) { return run_render(arguments(argc, argv), std::cout, std::cerr); }

}  // namespace sepax::cli
