// src/commands/audit_command.cpp -- see audit_command.hpp.
#include "commands/audit_command.hpp"

#include <cstddef>
#include <iostream>
#include <optional>
#include <vector>

#include <sepax/error.hpp>
#include <sepax/fuzz/cli.hpp>

#include "commands/command_line.hpp"
#include "commands/shape_builder.hpp"
#include "io/shape_source.hpp"

namespace sepax::cli {

namespace {

fuzz::ShapeSpec spec_of(const ConvexPolyhedron<float>& p) {
  fuzz::ShapeSpec s;
  s.vertices.reserve(p.vertices().size());
  for (const auto& v : p.vertices()) s.vertices.push_back(vec_to_double(v));
  for (int f = 0; f < p.face_count(); ++f) s.faces.push_back(p.face_vertices(f));
  return s;
}

/// How many coordinates of d are not float values (d builds in float, so
/// every coordinate is within float's range).
std::size_t rounded_coordinates(const io::ShapeData& d) {
  std::size_t n = 0;
  for (const auto& v : d.vertices)
    for (int c = 0; c < 3; ++c)
      if (static_cast<double>(static_cast<float>(v[c])) != v[c]) ++n;
  return n;
}

/// A shape of a .case as the case holds it (validated in float first, so
/// that an error names the case); its hull with --hull.
fuzz::ShapeSpec case_spec(const io::ShapeData& d) {
  const ConvexPolyhedron<float> built = build_shape<float>(d);
  if (d.kind == io::ShapeData::Kind::Points) return spec_of(built);
  return fuzz::ShapeSpec{d.vertices, d.closed_faces()};
}

}  // namespace

fuzz::FuzzCase audit_case(const ShapePair& p, const Pose* pose_b, std::ostream& note) {
  fuzz::FuzzCase c;
  c.family = "audit";
  if (p.from_case) {
    c.a = case_spec(p.a);
    c.b = case_spec(p.b);
    return c;
  }
  const BuiltPair<float> built = build_pair<float>(p.a, p.b, pose_b);
  for (const io::ShapeData* d : {&p.a, &p.b}) {
    if (const std::size_t n = rounded_coordinates(*d); n != 0) {
      note << "sepax audit: note: " << d->name << ": " << n
           << " coordinate(s) rounded to float (float, double and exact runs see the same float-valued "
              "input)\n";
    }
  }
  const Vec3<double> o = vec_to_double(built.origin);
  if (o[0] != 0 || o[1] != 0 || o[2] != 0) {
    note << "sepax audit: note: the shapes are audited moved by -(" << format_number(o[0]) << ", "
         << format_number(o[1]) << ", " << format_number(o[2])
         << "), an exact translation near them (as sepax query builds them): positions are relative to that "
            "point\n";
  }
  c.a = spec_of(built.a);
  c.b = spec_of(built.b);
  return c;
}

int run_audit(const std::vector<std::string>& args, std::istream& in, std::ostream& out, std::ostream& err) {
  std::vector<std::string> shapes;
  std::string case_file;
  RunConfig cfg;
  cfg.number = NumberKind::Float;
  bool json = false, hull = false;
  CommandLine cl(
      "audit",
      "Every decision the SATs make for one pair, in float (or double) against exact mpq arithmetic: "
      "the triple products of every edge pair, every candidate axis with its error bound, the features "
      "every configuration chooses, the contact manifold; then the full differential check of the case.",
      std::string("shapes (A, B):\n") + io::builtin_shapes_help() +
          "FILE.case as the only argument: a fuzzer reproducer, audited as it is\n"
          "\nA and B are built as 'sepax query A B --number float' builds them: coordinates rounded to "
          "float,\npoints hulled in float, B posed, both moved by an exact centre near them.\n"
          "\nExit status: 0 no unexplained disagreement, 1 at least one, 2 usage error, 3 an input that "
          "cannot be read, parsed or built, 4 internal error.\n");
  auto& app = cl.app;
  app.add_option("shapes", shapes, "A B, or one FILE.case")->type_name("");
  app.add_option("--case", case_file,
                 "audit the fuzzer reproducer FILE (the same as giving FILE.case as the pair)")
      ->type_name("FILE");
  cl.describe_value("--case", "a case file");
  app.add_option_function<std::string>(
         "--number,--type", [&cfg](const std::string& v) { cfg.number = *parse_number_kind(v); },
         "the audited arithmetic: float or double (default float), against exact")
      ->type_name("float|double")
      ->check(
          [](const std::string& v) {
            const auto k = parse_number_kind(v);
            return k && *k != NumberKind::Exact
                       ? std::string()
                       : "'" + v + "': the audit compares float or double against exact";
          },
          "");
  cl.describe_value("--number", "a value: float or double");
  cl.add_pose("move B: rotate by the quaternion (normalised; default identity), then translate");
  app.add_flag("--hull", hull, "use the convex hull of every shape's vertices");
  app.add_flag("--json", json, "print the audit as one JSON object");
  bool inject_fault = false;
  app.add_flag("--inject-fault", inject_fault,
               "check the checker: float_robust's Gauss map reports the opposite overlap verdict, which the "
               "differential check must report as unexplained (exit status 1)");
  if (const auto status = cl.parse(args, out, err)) return *status;
  try {
    const std::optional<Pose> pose = cl.pose();
    if (!case_file.empty() && !shapes.empty())
      throw UsageError("give either --case FILE or the shapes, not both");
    try {
      const ShapePair p = case_file.empty() ? load_pair(shapes, hull, in) : load_case(case_file, hull);
      if (pose && p.from_case) throw UsageError("--pose cannot be used with a case file (the case places B)");
      fuzz::AuditOptions opt;
      opt.use_double = cfg.number == NumberKind::Double;
      opt.json = json;
      opt.inject_fault = inject_fault;
      return fuzz::run_audit(audit_case(p, pose ? &*pose : nullptr, err), opt, out);
    } catch (const InvalidInput& e) {
      return input_error(out, err, json, "audit", e.what());
    }
  } catch (const UsageError& e) {
    return cl.usage_error(err, e.what());
  }
}

int audit_main(int argc, char** argv) {
  return run_audit(arguments(argc, argv), std::cin, std::cout, std::cerr);
}

}  // namespace sepax::cli
