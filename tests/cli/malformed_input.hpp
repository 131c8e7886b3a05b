// tests/cli/malformed_input.hpp -- the table test the text readers' tests
// share: every malformed input is refused with InvalidInput(Parse) whose
// message starts "NAME:LINE: " and names the problem.
#pragma once

#include <catch2/catch.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <sepax/error.hpp>

namespace sepax::cli::test {

struct Malformed {
  std::string text;
  std::size_t line;     // the line the error names
  const char* problem;  // what the message says
};

/// read(text) throws for every case; name is the file name it reads under.
inline void check_malformed(const std::vector<Malformed>& cases,
                            const std::function<void(const std::string&)>& read, const std::string& name) {
  for (const Malformed& b : cases) {
    INFO("input:\n" << b.text);
    try {
      read(b.text);
      FAIL("accepted a malformed file");
    } catch (const InvalidInput& e) {
      CHECK(e.code() == ErrorCode::Parse);
      CHECK_THAT(e.what(), Catch::StartsWith(name + ":" + std::to_string(b.line) + ": "));
      CHECK_THAT(e.what(), Catch::Contains(b.problem));
    }
  }
}

}  // namespace sepax::cli::test
