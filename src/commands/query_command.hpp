// src/commands/query_command.hpp
//
// The `query` and `info` verbs of the sepax program.
//
//   sepax query A B [--pose tx ty tz [qw qx qy qz]] [--number float|double|exact]
//                   [--algorithm brute|gauss|traversal] [--robust] [--json]
//   sepax query --batch FILE|- [--number ...] [--algorithm ...] [--robust]
//   sepax info SHAPE [--number ...] [--pose ...] [--json]
//
// Exit status: 0 success; 1 bad input (a shape that cannot be read or built;
// in batch mode: at least one line answered with an error); 2 usage error.
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

extern const char* const query_usage;
extern const char* const info_usage;
extern const char* const render_usage;

}  // namespace sepax::cli
