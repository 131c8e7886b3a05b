// src/commands/audit_command.hpp
//
// The `audit` verb of the sepax program: the fuzzer's audit (fuzz/src/audit.cpp)
// with the shapes resolved like `sepax query` resolves them -- built-in names,
// OFF and OBJ face lists, points files (hulled).
//
// The audit runs float, double and exact arithmetic on the same input, so the
// input must be float-valued: every coordinate is rounded to the nearest float
// (a note on stderr says how many changed), and a points file is hulled by
// sepax::convex_hull<float> (fuzz::hull_of).  A face list whose float image is
// no longer a valid convex polyhedron is reported as the face-list error it
// is, naming the file.
#pragma once

#include <ostream>
#include <string>

#include <sepax/fuzz/case.hpp>

namespace sepax::cli {

/// The audit's ShapeSpec for a command-line shape argument; notes about
/// rounding go to `note`.  Throws InvalidInput naming the argument.
fuzz::ShapeSpec audit_shape(const std::string& spec, std::ostream& note);

/// Entry point for the verb table: argv[0] is the verb.
int audit_main(int argc, char** argv);

}  // namespace sepax::cli
