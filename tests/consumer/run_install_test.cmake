# cmake -P script behind the ctest cli/install_and_consume:
#   1. cmake --install BUILD_DIR into WORK_DIR/staging, then move it to
#      WORK_DIR/prefix (relocatable: the exported targets must hold no
#      absolute library paths nor the old location)
#   2. the installed bin/sepax answers a query
#   3. configure tests/consumer against the prefix (find_package(sepax)),
#      build it, and run its programs
#   4. the installed pkg-config file: version, and (when pkg-config is
#      there) float_consumer.cpp compiled with its flags alone
# Variables: BUILD_DIR CONSUMER_DIR WORK_DIR GENERATOR CXX_COMPILER BUILD_TYPE WITH_ROBUST
#            [EXPECTED_VERSION: by default the build's CMAKE_PROJECT_VERSION]
foreach(v BUILD_DIR CONSUMER_DIR WORK_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_install_test.cmake: ${v} is not set")
  endif()
endforeach()
if(NOT DEFINED EXPECTED_VERSION)
  load_cache(${BUILD_DIR} READ_WITH_PREFIX _build_ CMAKE_PROJECT_VERSION)
  set(EXPECTED_VERSION ${_build_CMAKE_PROJECT_VERSION})
endif()
if(NOT DEFINED WITH_ROBUST)
  set(WITH_ROBUST ON)
endif()

include(${CMAKE_CURRENT_LIST_DIR}/run_step.cmake)

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)

# Installed to one place, used from another: the install must be relocatable.
run(install ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/staging)
file(RENAME ${WORK_DIR}/staging ${prefix})
# ... so the exported targets name their dependencies (found by sepaxConfig.cmake
# on the consuming machine) and hold no library paths of the build machine.
file(GLOB _exported ${prefix}/lib/cmake/sepax/sepaxTargets*.cmake)
foreach(f ${_exported})
  file(READ ${f} _text)
  if(_text MATCHES "(/[^\"; ]*lib(gmpxx|gmp|mpfr)[^\"; ]*)")
    message(FATAL_ERROR "${f} links a library by absolute path: ${CMAKE_MATCH_1}")
  endif()
  if(_text MATCHES "${WORK_DIR}/staging|${BUILD_DIR}")
    message(FATAL_ERROR "${f} refers to the install or build directory it came from")
  endif()
endforeach()
foreach(f include/sepax/convex_polyhedron.hpp include/sepax/version.hpp share/pkgconfig/sepax.pc
          lib/cmake/sepax/sepaxConfig.cmake
          lib/cmake/sepax/sepaxConfigVersion.cmake lib/cmake/sepax/sepaxTargets.cmake bin/sepax)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${prefix}/${f}")
  endif()
endforeach()

run(installed-sepax ${prefix}/bin/sepax query cube cube --pose 2.5 0 0 --json)
if(NOT last_output MATCHES "\"overlap\":false,\"separation\":0.5,")
  message(FATAL_ERROR "installed sepax gave an unexpected answer: ${last_output}")
endif()

run(configure ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/build -G ${GENERATOR}
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
    -DCMAKE_PREFIX_PATH=${prefix} -DWITH_ROBUST=${WITH_ROBUST}
    # only the installed copy may be found, not a build tree from the package registry
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
run(build ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(float-consumer ${WORK_DIR}/build/float_consumer)
if(WITH_ROBUST)
  run(exact-consumer ${WORK_DIR}/build/exact_consumer)
endif()

# pkg-config: the core's flags, found relative to the moved prefix.
file(STRINGS ${prefix}/share/pkgconfig/sepax.pc _pc_version REGEX "^Version: ")
if(NOT _pc_version STREQUAL "Version: ${EXPECTED_VERSION}")
  message(FATAL_ERROR "sepax.pc says '${_pc_version}', expected Version: ${EXPECTED_VERSION}")
endif()
find_program(_pkg_config pkg-config)
if(_pkg_config)
  set(ENV{PKG_CONFIG_PATH} ${prefix}/share/pkgconfig)
  run(pkg-config-version ${_pkg_config} --modversion sepax)
  if(NOT last_output STREQUAL "${EXPECTED_VERSION}\n")
    message(FATAL_ERROR "pkg-config --modversion sepax gave '${last_output}'")
  endif()
  run(pkg-config-cflags ${_pkg_config} --cflags sepax)
  string(STRIP "${last_output}" _cflags)
  separate_arguments(_cflags UNIX_COMMAND "${_cflags}")
  run(pkg-config-compile ${CXX_COMPILER} -std=c++20 ${_cflags} ${CONSUMER_DIR}/float_consumer.cpp
      -o ${WORK_DIR}/pc_float_consumer)
  run(pkg-config-consumer ${WORK_DIR}/pc_float_consumer)
else()
  message(STATUS "pkg-config not found: sepax.pc checked for its version only")
endif()
message(STATUS "install + consumer test passed")
