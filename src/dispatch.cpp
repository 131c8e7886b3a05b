// src/dispatch.cpp -- see dispatch.hpp.
#include "dispatch.hpp"

#include <cstring>
#include <exception>
#include <iostream>
#include <new>

#include "commands/query_command.hpp"

#ifdef SEPAX_HAVE_FUZZ
#include <sepax/fuzz/cli.hpp>

#include "commands/audit_command.hpp"
#endif

namespace sepax::cli {

namespace {

int help_main(int, char**) {
  print_help(std::cout);
  return 0;
}

constexpr Verb kVerbs[] = {
    {"query", &query_main, "separating axis test of two shapes, or a batch of JSON lines"},
    {"info", &info_main, "build a shape and print its vertex, edge and face counts"},
    {"render", &render_main, "draw two shapes, their contacts and overlaid Gauss maps as SVG"},
#ifdef SEPAX_HAVE_FUZZ
    {"fuzz", &sepax::fuzz::fuzz_main, "random differential testing of the SATs (see 'sepax fuzz --help')"},
    {"audit", &audit_main, "audit float results against exact arithmetic (see 'sepax audit --help')"},
#endif
    {"help", &help_main, "this message"},
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
  out << "sepax: separating axis tests between convex polyhedra, with exact predicates\n\n"
         "usage: sepax VERB [arguments]   ('sepax VERB --help' for a verb's options)\n\nverbs:\n";
  for (const Verb& v : kVerbs) {
    out << "  " << v.name << std::string(10 - std::min<std::size_t>(9, std::strlen(v.name)), ' ') << v.summary
        << "\n";
  }
  out << "\nexample: sepax query cube tetra --pose 2.5 0 0\n";
}

int run(int argc, char** argv) {
  if (argc < 2) {
    print_help(std::cerr);
    return 2;
  }
  const char* verb = argv[1];
  if (std::strcmp(verb, "--help") == 0 || std::strcmp(verb, "-h") == 0) return help_main(0, nullptr);
  if (std::strcmp(verb, "--version") == 0) {
#ifdef SEPAX_VERSION
    std::cout << "sepax " << SEPAX_VERSION << "\n";
#else
    std::cout << "sepax\n";
#endif
    return 0;
  }
  const Verb* v = find_verb(verb);
  if (!v) {
    std::cerr << "sepax: unknown verb '" << verb << "'\n\n";
    print_help(std::cerr);
    return 2;
  }
  try {
    return v->run(argc - 1, argv + 1);
  } catch (const std::bad_alloc&) {
    std::cerr << "sepax " << verb << ": out of memory\n";
  } catch (const std::exception& e) {
    std::cerr << "sepax " << verb << ": error: " << e.what() << "\n";
  } catch (...) {
    std::cerr << "sepax " << verb << ": unknown error\n";
  }
  return 1;
}

}  // namespace sepax::cli
