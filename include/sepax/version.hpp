// sepax's version, the same as project(sepax VERSION ...) in CMakeLists.txt
// (the configure step refuses to run when they differ, and the ctest
// cmake/version_header checks it too).  Semantic versioning: the major
// version changes when a release breaks the API.
#pragma once

#define SEPAX_VERSION_MAJOR 0
#define SEPAX_VERSION_MINOR 1
#define SEPAX_VERSION_PATCH 0
#define SEPAX_VERSION_STRING "0.1.0"

namespace sepax {

struct Version {
  int major;
  int minor;
  int patch;
};

/// The version of the sepax headers in use.
inline constexpr Version version{SEPAX_VERSION_MAJOR, SEPAX_VERSION_MINOR, SEPAX_VERSION_PATCH};
inline constexpr const char* version_string = SEPAX_VERSION_STRING;

}  // namespace sepax
