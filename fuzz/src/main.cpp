// sepax_fuzz: the fuzzer's own driver, for builds without the sepax CLI.
//   sepax_fuzz [fuzz] [options]      == sepax fuzz [options]
//   sepax_fuzz audit ...             == sepax audit ...
#include <cstring>

#include <sepax/fuzz/cli.hpp>

int main(int argc, char** argv) {
  if (argc >= 2 && std::strcmp(argv[1], "audit") == 0) return sepax::fuzz::audit_main(argc - 1, argv + 1);
  if (argc >= 2 && std::strcmp(argv[1], "fuzz") == 0) return sepax::fuzz::fuzz_main(argc - 1, argv + 1);
  return sepax::fuzz::fuzz_main(argc, argv);
}
