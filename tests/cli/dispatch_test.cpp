// Tests for src/dispatch.cpp: the verb table.
#include <catch2/catch.hpp>

#include <set>
#include <sstream>
#include <string>

#include "dispatch.hpp"

using namespace sepax::cli;

TEST_CASE("dispatch: every verb is found by name, listed in the help, and unique", "[dispatch]") {
  std::ostringstream help;
  print_help(help);
  std::set<std::string> names;
  for (const Verb& v : verbs()) {
    INFO(v.name);
    CHECK(find_verb(v.name) == &v);
    CHECK(v.run != nullptr);
    CHECK(names.insert(v.name).second);
    CHECK_THAT(help.str(), Catch::Contains(std::string("  ") + v.name + " "));
  }
  CHECK(names.count("query") == 1);
  CHECK(names.count("info") == 1);
  CHECK(names.count("help") == 1);
#ifdef SEPAX_HAVE_FUZZ
  CHECK(names.count("fuzz") == 1);
  CHECK(names.count("audit") == 1);
#endif
  CHECK(find_verb("nonsense") == nullptr);
  CHECK(find_verb("") == nullptr);
}

TEST_CASE("dispatch: no verb or an unknown verb is a usage error (status 2)", "[dispatch]") {
  char prog[] = "sepax", bad[] = "frobnicate", version[] = "--version";
  char* argv1[] = {prog, nullptr};
  CHECK(run(1, argv1) == 2);
  char* argv2[] = {prog, bad, nullptr};
  CHECK(run(2, argv2) == 2);
  char* argv3[] = {prog, version, nullptr};
  CHECK(run(2, argv3) == 0);
}
