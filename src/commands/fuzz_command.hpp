// src/commands/fuzz_command.hpp
//
// The `fuzz` verb: the command line of the differential fuzz campaign
// (fuzz/include/sepax/fuzz/campaign.hpp runs it).
//
//   sepax fuzz [--seconds S | --cases N] [--seed K] [--families a,b,...]
//              [--jobs N] [--out DIR] [--json] [--quiet]
//              [--shrink-steps N] [--shrink-seconds S] [--shrink-max N]
//   sepax fuzz --replay FILE_OR_DIR... [--bytes] [--shrink] [--out DIR] [--json] [--quiet]
//
// Exit status (command_line.hpp): 0 no unexplained disagreement, 1 at least
// one (reproducers written), 2 usage error, 3 a replay file that cannot be
// read or parsed.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace sepax::cli {

int run_fuzz(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// Entry point for the verb table: argv[0] is the verb.
int fuzz_main(int argc, char** argv);

}  // namespace sepax::cli
