// src/dispatch.cpp -- see dispatch.hpp.
#include "dispatch.hpp"

#include <cstring>
#include <exception>
#include <iostream>
#include <new>

#include "commands/command_line.hpp"
#include "commands/query_command.hpp"

#ifdef SEPAX_HAVE_FUZZ
#include "commands/audit_command.hpp"
#include "commands/fuzz_command.hpp"
#endif

#if __has_include(<sepax/version.hpp>)
#include <sepax/version.hpp>
#endif

namespace sepax::cli {

namespace {

int help_main(int argc, char** argv) {
  if (argc <= 1) {
    print_help(std::cout);
    return kExitOk;
  }
  if (argc > 2) {
    std::cerr << "sepax help: expected at most one verb\n(run 'sepax help' for usage)\n";
    return kExitUsage;
  }
  const Verb* v = find_verb(argv[1]);
  if (!v) {
    std::cerr << "sepax help: unknown verb '" << argv[1] << "'\n(run 'sepax help' for the list)\n";
    return kExitUsage;
  }
  if (std::strcmp(v->name, "help") == 0) {
    print_help(std::cout);
    return kExitOk;
  }
  char help_flag[] = "--help";
  char* args[] = {argv[1], help_flag, nullptr};
  return v->run(2, args);
}

const char* version_text() {
#if defined(SEPAX_VERSION_STRING)
  return SEPAX_VERSION_STRING;
#elif defined(SEPAX_VERSION)
  return SEPAX_VERSION;
#else
  return "unknown";
#endif
}

constexpr Verb kVerbs[] = {
    {"query", &query_main, "separating axis test of two shapes, or a batch of JSON lines"},
    {"info", &info_main, "build a shape and print its vertex, edge and face counts"},
    {"render", &render_main, "draw two shapes, their contacts and overlaid Gauss maps as SVG"},
#ifdef SEPAX_HAVE_FUZZ
    {"fuzz", &fuzz_main, "random differential testing of the SATs against exact arithmetic"},
    {"audit", &audit_main, "every decision of the SAT for one pair, float or double against exact"},
#endif
    {"help", &help_main, "this message, or 'sepax help VERB' for a verb's options"},
};

}  // namespace

std::span<const Verb> verbs() { return kVerbs; }

const Verb* find_verb(const char* name) {
  for (const Verb& v : kVerbs) {
    if (std::strcmp(v.name, name) == 0) return &v;
  }
  return nullptr;
}

void print_help(std::ostream& out) {
  out << "sepax " << version_text()
      << ": separating axis tests between convex polyhedra, with exact predicates\n\n"
         "usage: sepax VERB [arguments]     ('sepax help VERB' or 'sepax VERB --help' for a verb's options)\n"
         "       sepax --version\n\nverbs:\n";
  for (const Verb& v : kVerbs) {
    out << "  " << v.name << std::string(10 - std::min<std::size_t>(9, std::strlen(v.name)), ' ') << v.summary
        << "\n";
  }
  out << "\nexit status (every verb):\n"
         "  0  success\n"
         "  1  a finding (an unexplained disagreement), or a batch line answered with an error\n"
         "  2  usage error\n"
         "  3  an input that cannot be read, parsed or built (or an output file that cannot be written)\n"
         "  4  internal error\n"
         "\nexample: sepax query cube tetra --pose 2.5 0 0\n";
}

int run(int argc, char** argv) {
  if (argc < 2) {
    print_help(std::cerr);
    return kExitUsage;
  }
  const char* verb = argv[1];
  // `sepax --help` and `sepax --version`: output that cannot be written is status 3, as for every verb
  auto written = [](int status) -> int {
    if (std::cout.flush()) return status;
    std::cerr << "sepax: error: cannot write standard output\n";
    return kExitInput;
  };
  if (std::strcmp(verb, "--help") == 0 || std::strcmp(verb, "-h") == 0) return written(help_main(0, nullptr));
  if (std::strcmp(verb, "--version") == 0) {
    if (argc > 2) {
      std::cerr << "sepax: --version takes no arguments\n";
      return kExitUsage;
    }
    std::cout << "sepax " << version_text() << "\n";
    return written(kExitOk);
  }
  const Verb* v = find_verb(verb);
  if (!v) {
    std::cerr << "sepax: unknown verb '" << verb << "'\n\n";
    print_help(std::cerr);
    return kExitUsage;
  }
  int status = kExitInternal;
  try {
    status = v->run(argc - 1, argv + 1);
  } catch (const std::bad_alloc&) {
    std::cerr << "sepax " << verb << ": internal error: out of memory\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "sepax " << verb << ": internal error: " << e.what() << "\n";
    return kExitInternal;
  } catch (...) {
    std::cerr << "sepax " << verb << ": internal error: unknown exception\n";
    return kExitInternal;
  }
  // Output that did not reach standard output (a full disk, a closed pipe)
  // is not a success; nor is a finding (status 1) whose report was lost.
  if (!std::cout.flush()) {
    std::cerr << "sepax " << verb << ": error: cannot write standard output\n";
    if (status == kExitOk || status == kExitFinding) status = kExitInput;
  }
  return status;
}

}  // namespace sepax::cli
