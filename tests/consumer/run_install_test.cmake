# cmake -P script behind the ctest cli/install_and_consume:
#   1. cmake --install BUILD_DIR into WORK_DIR/staging, then move it to
#      WORK_DIR/prefix (relocatable: the exported targets must hold no
#      absolute library paths nor the old location)
#   2. the installed bin/sepax answers a query
#   3. configure tests/consumer against the prefix (find_package(sepax)),
#      build it, and run its programs
# Variables: BUILD_DIR CONSUMER_DIR WORK_DIR GENERATOR CXX_COMPILER BUILD_TYPE WITH_ROBUST
foreach(v BUILD_DIR CONSUMER_DIR WORK_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_install_test.cmake: ${v} is not set")
  endif()
endforeach()
if(NOT DEFINED WITH_ROBUST)
  set(WITH_ROBUST ON)
endif()

function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "[${step}] ${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "[${step}] failed (${rc}):\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

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
foreach(f include/sepax/convex_polyhedron.hpp lib/cmake/sepax/sepaxConfig.cmake
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
message(STATUS "install + consumer test passed")
