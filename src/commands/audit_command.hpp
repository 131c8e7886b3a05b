// src/commands/audit_command.hpp
//
// The `audit` verb of the sepax program: the fuzzer's audit
// (fuzz/include/sepax/fuzz/cli.hpp) of two shapes resolved like `sepax query`
// resolves them -- built-in names, mesh files, points files (hulled) -- or of
// a fuzzer reproducer (FILE.case, or --case FILE).
//
//   sepax audit A B [--pose tx ty tz [qw qx qy qz]] [--number float|double] [--hull] [--json]
//   sepax audit FILE.case [--number float|double] [--json]
//
// The audit runs float, double and exact arithmetic on the same input, so the
// input must be float-valued: every coordinate is rounded to the nearest float
// (a note on stderr says how many changed), and a points file is hulled by
// sepax::convex_hull<float> (fuzz::hull_of).  A face list whose float image is
// no longer a valid convex polyhedron is reported as the face-list error it
// is, naming the file.
//
// Exit status (command_line.hpp): 0 no unexplained disagreement in the
// differential check of the case, 1 at least one, 2 usage error, 3 an input
// that cannot be read, parsed or built.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <sepax/fuzz/case.hpp>

namespace sepax::cli {

/// The audit's ShapeSpec for a command-line shape argument; notes about
/// rounding go to `note`.  Throws InvalidInput naming the argument.
fuzz::ShapeSpec audit_shape(const std::string& spec, std::ostream& note);

int run_audit(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// Entry point for the verb table: argv[0] is the verb.
int audit_main(int argc, char** argv);

}  // namespace sepax::cli
