// src/commands/audit_command.cpp -- see audit_command.hpp.
#include "commands/audit_command.hpp"

#include <cmath>
#include <cstddef>
#include <iostream>
#include <vector>

#include <sepax/error.hpp>
#include <sepax/fuzz/cli.hpp>
#include <sepax/fuzz/generators.hpp>

#include "commands/command_line.hpp"
#include "commands/shape_pair.hpp"
#include "io/shape_source.hpp"

namespace sepax::cli {

namespace {

fuzz::ShapeSpec audit_spec(const io::ShapeData& d, std::ostream& note) {
  fuzz::ShapeSpec tmp{d.vertices, {}};
  fuzz::round_to_float(tmp);
  std::size_t changed = 0;
  for (std::size_t i = 0; i < d.vertices.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(tmp.vertices[i][c])) {
        throw InvalidInput(ErrorCode::BadScale, d.name + ": coordinate " + "xyz"[c] + " of " +
                                                    (d.kind == io::ShapeData::Kind::Points ? "point " : "vertex ") +
                                                    std::to_string(i) + " (" + format_number(d.vertices[i][c]) +
                                                    ") overflows float, which the audit's input must be");
      }
      if (tmp.vertices[i][c] != d.vertices[i][c]) ++changed;
    }
  }
  if (changed != 0) {
    note << "sepax audit: note: " << d.name << ": " << changed
         << " coordinate(s) rounded to float (float, double and exact runs see the same float-valued input)\n";
  }
  if (d.kind == io::ShapeData::Kind::Points) {
    try {
      return fuzz::hull_of(tmp.vertices);
    } catch (const InvalidInput& e) {
      throw InvalidInput(e.code(), d.name + ": " + e.what());
    }
  }
  tmp.faces = d.closed_faces();
  return tmp;
}

}  // namespace

fuzz::ShapeSpec audit_shape(const std::string& spec, std::ostream& note) { return audit_spec(io::load_shape(spec), note); }

namespace {

fuzz::ShapeSpec audit_spec(const io::ShapeData& d, std::ostream& note);

}  // namespace

int run_audit(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::vector<std::string> shapes;
  std::string case_file;
  RunConfig cfg;
  cfg.number = NumberKind::Float;
  bool json = false, hull = false;
  CommandLine cl("audit",
                 "Every decision the SATs make for one pair, in float (or double) against exact mpq arithmetic: "
                 "the triple products of every edge pair, every candidate axis with its error bound, the features "
                 "every configuration chooses, the contact manifold; then the full differential check of the case.",
                 std::string("shapes: ") + io::builtin_shapes_help() +
                     "\nCoordinates are rounded to float; points files are hulled in float; the pose applies to B.\n"
                     "\nExit status: 0 no unexplained disagreement, 1 at least one, 2 usage error, 3 an input that "
                     "cannot be read, parsed or built, 4 internal error.\n");
  auto& app = cl.app;
  app.add_option("shapes", shapes, "A B, or one FILE.case")->type_name("");
  app.add_option("--case", case_file, "audit the fuzzer reproducer FILE (the same as giving FILE.case as the pair)")
      ->type_name("FILE");
  cl.describe_value("--case", "a case file");
  app.add_option_function<std::string>(
         "--number,--type",
         [&cfg](const std::string& v) { cfg.number = *parse_number_kind(v); },
         "the audited arithmetic: float or double (default float), against exact")
      ->type_name("float|double")
      ->check(
          [](const std::string& v) {
            const auto k = parse_number_kind(v);
            return k && *k != NumberKind::Exact ? std::string()
                                                 : "'" + v + "': the audit compares float or double against exact";
          },
          "");
  cl.describe_value("--number", "a value: float or double");
  cl.add_pose("move B: rotate by the quaternion (normalised; default identity), then translate");
  app.add_flag("--hull", hull, "use the convex hull of every shape's vertices");
  app.add_flag("--json", json, "print the audit as one JSON object");
  if (const auto status = cl.parse(args, out, err)) return *status;
  try {
    const std::optional<Pose> pose = cl.pose();
    fuzz::FuzzCase c;
    if (!case_file.empty() && !shapes.empty()) throw UsageError("give either --case FILE or the shapes, not both");
    if (!case_file.empty() || (shapes.size() == 1 && is_case_file(shapes[0]))) {
      if (pose) throw UsageError("--pose cannot be used with a case file (the case places B)");
      c = fuzz::read_case_file(case_file.empty() ? shapes[0] : case_file);
      if (hull) {
        c.a = fuzz::hull_of(c.a.vertices);
        c.b = fuzz::hull_of(c.b.vertices);
      }
    } else {
      const ShapePair p = load_pair(shapes, hull);  // UsageError for a wrong count
      c.a = audit_spec(p.a, err);
      c.b = audit_spec(p.b, err);
      c.family = "audit";
      if (pose) {
        const double t[3] = {pose->translation[0], pose->translation[1], pose->translation[2]};
        c.b = fuzz::posed(c.b, t, pose->rotation.data());
      }
    }
    fuzz::AuditOptions opt;
    opt.use_double = cfg.number == NumberKind::Double;
    opt.json = json;
    return fuzz::run_audit(c, opt, out);
  } catch (const UsageError& e) {
    return cl.usage_error(err, e.what());
  } catch (const InvalidInput& e) {
    err << "sepax audit: " << e.what() << "\n";
    return kExitInput;
  }
}

int audit_main(int argc, char** argv) { return run_audit(arguments(argc, argv), std::cout, std::cerr); }

}  // namespace sepax::cli
