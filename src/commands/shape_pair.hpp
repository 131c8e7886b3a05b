// src/commands/shape_pair.hpp
//
// The shape arguments of query, render and audit:
//
//   A B        two shape arguments (io/shape_source.hpp: built-ins, mesh files);
//   FILE.case  one fuzzer reproducer (fuzz/include/sepax/fuzz/case.hpp): A and
//              B in one world frame, B already placed, so `sepax query X.case`
//              and `sepax render X.case --svg -` show a finding directly.
//
// --hull asks for the convex hull of every shape's vertices: a file argument
// gets the `hull:` prefix that io::load_shape understands (built-ins are
// convex already and are left as they are); the shapes of a .case become
// their point sets.
#pragma once

#include <iostream>

#include <string>
#include <vector>

#include "io/shape_data.hpp"

namespace sepax::cli {

struct ShapePair {
  io::ShapeData a, b;
  bool from_case = false;  // read from a .case file (B is placed by the case)
};

/// True for a FILE.case argument.
bool is_case_file(const std::string& arg);

/// The argument io::load_shape is given for `arg` (with `hull:` when hull is set).
std::string shape_argument(const std::string& arg, bool hull);

/// The two shapes of the fuzzer reproducer at path (named "PATH A" and "PATH
/// B"; points when hull).  Throws UsageError in a build without the fuzzer,
/// InvalidInput for an unreadable case.
ShapePair load_case(const std::string& path, bool hull);

/// Throws UsageError (command_line.hpp) for a wrong number of arguments or a
/// .case in a build without the fuzzer, InvalidInput for unreadable input.
/// `-` arguments read `standard_input`.
ShapePair load_pair(const std::vector<std::string>& positional, bool hull,
                    std::istream& standard_input = std::cin);

/// The one-line description of the accepted arguments, for usage errors.
const char* pair_arguments_help();

}  // namespace sepax::cli
