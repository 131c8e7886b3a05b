// sepax_fuzz: the sepax program with `fuzz` as the default verb.
//   sepax_fuzz [options]             == sepax fuzz [options]
//   sepax_fuzz fuzz|audit ...        == sepax fuzz|audit ...
#include <cstring>
#include <vector>

#include "dispatch.hpp"

int main(int argc, char** argv) {
  if (argc >= 2 && (std::strcmp(argv[1], "fuzz") == 0 || std::strcmp(argv[1], "audit") == 0 ||
                    std::strcmp(argv[1], "help") == 0 || std::strcmp(argv[1], "--version") == 0))
    return sepax::cli::run(argc, argv);
  char verb[] = "fuzz";
  std::vector<char*> args{argv[0], verb};
  for (int i = 1; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  return sepax::cli::run(argc + 1, args.data());
}
