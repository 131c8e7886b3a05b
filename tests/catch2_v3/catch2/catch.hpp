// Catch2 v3 under the name of v2's single header.  The tests are written
// against Catch2 v2 (#include <catch2/catch.hpp>); tests/CMakeLists.txt puts
// this directory on the include path only when it found Catch2 v3, so that
// the same test sources compile against either.  It adds the v2 names the
// tests use that v3 moved:
//   Approx                    v3: Catch::Approx
//   Catch::Contains(string)   v3: Catch::Matchers::ContainsSubstring
//   Catch::StartsWith, Catch::Matches (regex), ...   v3: only in Catch::Matchers
//   Catch::Matchers::Contains(string literal): v3's Contains is the range
//                             matcher; a non-template overload for strings
//                             is preferred to it.
#pragma once

#include <catch2/catch_all.hpp>

#include <string>
#include <utility>

using Catch::Approx;

namespace Catch {
namespace Matchers {
inline StringContainsMatcher Contains(const char* substring, CaseSensitive cs = CaseSensitive::Yes) {
  return ContainsSubstring(substring, cs);
}
}  // namespace Matchers

template <class S>
Matchers::StringContainsMatcher Contains(S&& substring, CaseSensitive cs = CaseSensitive::Yes) {
  return Matchers::ContainsSubstring(std::string(std::forward<S>(substring)), cs);
}
using Matchers::EndsWith;
using Matchers::Equals;
using Matchers::Matches;
using Matchers::StartsWith;
}  // namespace Catch
