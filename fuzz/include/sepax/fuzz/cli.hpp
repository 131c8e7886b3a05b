// sepax/fuzz/cli.hpp
//
// Entry points the `sepax` program dispatches to (argv[0] is the verb):
//
//   sepax fuzz [--seconds S] [--cases N] [--seed K] [--families a,b,...]
//              [--out DIR] [--json] [--quiet]
//   sepax fuzz --replay FILE...   [--json]
//   sepax audit A B [--pose tx ty tz [qw qx qy qz]] [--type float|double]
//   sepax audit --case FILE       [--type float|double]
//
// Exit status: 0 no unexplained disagreement, 1 at least one (reproducers were
// written), 2 bad usage or unreadable input.
#pragma once

namespace sepax::fuzz {

int fuzz_main(int argc, char** argv);
int audit_main(int argc, char** argv);

}  // namespace sepax::fuzz
