// <sepax/version.hpp> against the version CMake's project() has
// (EXPECTED_*, from the consumer project): a mismatch does not compile.
#include <cstdio>
#include <string_view>

#include <sepax/version.hpp>

static_assert(SEPAX_VERSION_MAJOR == EXPECTED_MAJOR, "SEPAX_VERSION_MAJOR differs from project(VERSION)");
static_assert(SEPAX_VERSION_MINOR == EXPECTED_MINOR, "SEPAX_VERSION_MINOR differs from project(VERSION)");
static_assert(SEPAX_VERSION_PATCH == EXPECTED_PATCH, "SEPAX_VERSION_PATCH differs from project(VERSION)");
static_assert(std::string_view(SEPAX_VERSION_STRING) == EXPECTED_STRING,
              "SEPAX_VERSION_STRING differs from project(VERSION)");
static_assert(sepax::version.major == SEPAX_VERSION_MAJOR && sepax::version.minor == SEPAX_VERSION_MINOR &&
              sepax::version.patch == SEPAX_VERSION_PATCH);

int main() {
  std::printf("sepax %s\n", sepax::version_string);
  return 0;
}
