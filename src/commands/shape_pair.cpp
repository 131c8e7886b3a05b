// src/commands/shape_pair.cpp -- see shape_pair.hpp.
#include "commands/shape_pair.hpp"

#include "commands/command_line.hpp"
#include "io/shape_source.hpp"

#include <utility>

#ifdef SEPAX_HAVE_FUZZ
#include <sepax/fuzz/case.hpp>
#endif

namespace sepax::cli {

bool is_case_file(const std::string& arg) { return arg.size() > 5 && arg.ends_with(".case"); }

std::string shape_argument(const std::string& arg, bool hull) {
  if (!hull || arg.starts_with("hull:") || io::is_builtin_shape(arg)) return arg;
  return "hull:" + arg;
}

const char* pair_arguments_help() {
  return "two shapes A and B (built-ins, OFF, OBJ, PLY or STL meshes, points files; 'sepax query --help' "
         "lists them), or one fuzzer reproducer FILE.case";
}

namespace {

#ifdef SEPAX_HAVE_FUZZ
io::ShapeData from_spec(const fuzz::ShapeSpec& s, const std::string& name, bool hull) {
  io::ShapeData d;
  d.kind = hull ? io::ShapeData::Kind::Points : io::ShapeData::Kind::Faces;
  d.name = name;
  d.vertices = s.vertices;
  if (!hull) d.faces = s.faces;
  return d;
}
#endif

}  // namespace

ShapePair load_case(const std::string& path, bool hull) {
#ifdef SEPAX_HAVE_FUZZ
  const fuzz::FuzzCase c = fuzz::read_case_file(path);
  return {from_spec(c.a, path + " A", hull), from_spec(c.b, path + " B", hull), true};
#else
  (void)hull;
  throw UsageError("'" + path + "': .case files need the fuzzer library, which this build does not have");
#endif
}

ShapePair load_pair(const std::vector<std::string>& positional, bool hull, std::istream& standard_input) {
  if (positional.size() == 1 && is_case_file(positional[0])) return load_case(positional[0], hull);
  if (positional.size() != 2)
    throw UsageError("expected two shapes A and B, got " + std::to_string(positional.size()) +
                     " (arguments: " + pair_arguments_help() + ")");
  io::ShapeData first = io::load_shape(shape_argument(positional[0], hull), standard_input);
  io::ShapeData second = io::load_shape(shape_argument(positional[1], hull), standard_input);
  return {std::move(first), std::move(second), false};
}

}  // namespace sepax::cli
