// src/commands/audit_command.hpp
//
// The `audit` verb of the sepax program: the fuzzer's audit
// (fuzz/include/sepax/fuzz/cli.hpp) of two shapes given as `sepax query`
// takes them (commands/shape_pair.hpp: built-ins, mesh files with #NAME
// selectors, hull:, points files, - for standard input), or of a fuzzer
// reproducer (FILE.case, or --case FILE).
//
//   sepax audit A B [--pose tx ty tz [qw qx qy qz]] [--number float|double] [--hull] [--json]
//   sepax audit FILE.case [--number float|double] [--hull] [--json]
//
// The audit runs float, double and exact arithmetic on the same input, so the
// input must be float-valued.  Two shapes are built exactly as
// `sepax query A B --number float` builds them (build_pair<float>,
// commands/shape_builder.hpp): coordinates rounded to float once (a note on
// stderr says how many changed), a closed convex mesh (a triangulated cube)
// as the polyhedron it bounds, a point set hulled by convex_hull<float>, B
// posed, and both moved by the exact centre that brings them near the origin
// (io/exact_centre.hpp; a note gives it).  So the audit reports every
// decision of the float computation that `sepax query --number float` runs.
// A .case is audited as it is: it is the fuzzer's own float input.
//
// Exit status (command_line.hpp): 0 no unexplained disagreement in the
// differential check of the case, 1 at least one, 2 usage error, 3 an input
// that cannot be read, parsed or built.
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include <sepax/fuzz/case.hpp>

#include "commands/pose.hpp"
#include "commands/shape_pair.hpp"

namespace sepax::cli {

/// The audit's case for p (B posed by pose_b, which must be null for a
/// .case); notes about rounding and re-centring go to `note`.  Throws
/// InvalidInput naming the shape that cannot be built in float.
fuzz::FuzzCase audit_case(const ShapePair& p, const Pose* pose_b, std::ostream& note);

/// args excludes the verb; `-` shape arguments read `in`.
int run_audit(const std::vector<std::string>& args, std::istream& in, std::ostream& out, std::ostream& err);

/// Entry point for the verb table: argv[0] is the verb.
int audit_main(int argc, char** argv);

}  // namespace sepax::cli
