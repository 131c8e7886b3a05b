# Checks that include/sepax/version.hpp says the version project() says.
# Included by CMakeLists.txt at configure time, and run as
#   cmake -D SEPAX_VERSION_HEADER=... -D SEPAX_EXPECTED_VERSION=X.Y.Z -P sepaxCheckVersion.cmake
# by the ctest cmake/version_header.
foreach(_v SEPAX_VERSION_HEADER SEPAX_EXPECTED_VERSION)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "sepaxCheckVersion.cmake: ${_v} is not set")
  endif()
endforeach()
file(STRINGS ${SEPAX_VERSION_HEADER} _sepax_version_lines REGEX "^#define SEPAX_VERSION_")
foreach(_part MAJOR MINOR PATCH STRING)
  set(_sepax_header_${_part} "")
  foreach(_line IN LISTS _sepax_version_lines)
    if(_line MATCHES "^#define SEPAX_VERSION_${_part} +\"?([0-9.]+)\"?$")
      set(_sepax_header_${_part} ${CMAKE_MATCH_1})
    endif()
  endforeach()
endforeach()
set(_sepax_header_version "${_sepax_header_MAJOR}.${_sepax_header_MINOR}.${_sepax_header_PATCH}")
if(NOT _sepax_header_version STREQUAL SEPAX_EXPECTED_VERSION
   OR NOT _sepax_header_STRING STREQUAL SEPAX_EXPECTED_VERSION)
  message(FATAL_ERROR "${SEPAX_VERSION_HEADER}: SEPAX_VERSION_MAJOR/MINOR/PATCH say "
                      "${_sepax_header_version} and SEPAX_VERSION_STRING \"${_sepax_header_STRING}\", "
                      "project() says ${SEPAX_EXPECTED_VERSION}: update them together")
endif()
