// src/commands/query_command.hpp
//
// The `query`, `info` and `render` verbs of the sepax program.
//
//   sepax query A B [--pose tx ty tz [qw qx qy qz]] [--number float|double|exact]
//                   [--algorithm brute|gauss|traversal] [--robust] [--hull] [--json]
//   sepax query FILE.case [--number ...] [--algorithm ...] [--robust] [--hull] [--json]
//   sepax query --batch FILE|- [--number ...] [--algorithm ...] [--robust]
//                   [--no-manifold] [--jobs N]
//   sepax info SHAPE [--number ...] [--pose ...] [--hull] [--json]
//   sepax render A B|FILE.case --svg FILE|- [--pose ...] [--algorithm ...] [--robust] [--hull]
//
// Exit status (command_line.hpp): 0 success; 1 in batch mode, at least one
// line answered with an error; 2 usage error; 3 an input that cannot be read,
// parsed or built (or an SVG file that cannot be written).
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace sepax::cli {

/// args excludes the verb.  in is read by --batch -.
int run_query(const std::vector<std::string>& args, std::istream& in, std::ostream& out, std::ostream& err);
int run_info(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int run_render(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// Entry points for the verb table: argv[0] is the verb.
int query_main(int argc, char** argv);
int info_main(int argc, char** argv);
int render_main(int argc, char** argv);

}  // namespace sepax::cli
