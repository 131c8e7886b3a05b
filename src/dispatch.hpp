// src/dispatch.hpp
//
// The verb table of the sepax program: `sepax VERB args...` runs the verb's
// entry point with argv[0] = VERB.  Adding a verb is one line in verbs()
// (dispatch.cpp).  The fuzzer's verbs (fuzz, audit) are present when the
// build has sepax_fuzz_lib (compile definition SEPAX_HAVE_FUZZ).
#pragma once

#include <ostream>
#include <span>

namespace sepax::cli {

struct Verb {
  const char* name;
  int (*run)(int argc, char** argv);  // argv[0] is the verb
  const char* summary;
};

/// Every verb this build offers, in the order `sepax help` lists them.
std::span<const Verb> verbs();

/// The verb named name, or nullptr.
const Verb* find_verb(const char* name);

/// Prints the top-level help.
void print_help(std::ostream& out);

/// main(): dispatch on argv[1].  Exit status: the verb's
/// (commands/command_line.hpp); 2 for an unknown verb or missing arguments;
/// 4 for an exception escaping a verb (internal error).
int run(int argc, char** argv);

}  // namespace sepax::cli
