// sepax/fuzz/cli.hpp
//
// The audit entry point the `sepax` program dispatches to (argv[0] is the
// verb); `sepax fuzz` is parsed in src/commands/fuzz_command.cpp and run by
// run_campaign (campaign.hpp).
//
//   sepax audit A B [--pose tx ty tz [qw qx qy qz]] [--type float|double]
//   sepax audit --case FILE       [--type float|double]
//
// The standalone driver's audit knows the built-in shapes only; the sepax
// program passes a loader that also reads OFF, OBJ and points files
// (src/commands/audit_command.cpp).
//
// Exit status: 0 no unexplained disagreement, 1 at least one (reproducers were
// written), 2 bad usage or unreadable input.
#pragma once

#include <functional>
#include <string>

#include "case.hpp"

namespace sepax::fuzz {

/// Turns a shape argument of `audit A B` into a ShapeSpec (float-valued
/// vertices and a face list); throws InvalidInput naming the argument.
using ShapeLoader = std::function<ShapeSpec(const std::string&)>;

/// `audit` with the built-in shapes (builtin_shape in generators.hpp).
int audit_main(int argc, char** argv);
/// `audit` with the shapes resolved by `load`; `shapes_help` is the usage
/// line's description of what A and B may be.
int audit_main(int argc, char** argv, const ShapeLoader& load, const std::string& shapes_help);

}  // namespace sepax::fuzz
