# cmake -P script behind the ctests consumer/subproject_add_subdirectory and
# consumer/subproject_fetchcontent: configure tests/consumer/subproject (a
# project that pulls in the sepax source tree SEPAX_SOURCE_DIR by MODE),
# whose configure step checks what sepax defined; build it; run its
# programs; install it and check that no sepax file was installed.
# Variables: SEPAX_SOURCE_DIR CONSUMER_DIR WORK_DIR MODE EXPECTED_VERSION
#            GENERATOR CXX_COMPILER [Eigen3_DIR]
foreach(v SEPAX_SOURCE_DIR CONSUMER_DIR WORK_DIR MODE EXPECTED_VERSION GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_subproject_test.cmake: ${v} is not set")
  endif()
endforeach()

include(${CMAKE_CURRENT_LIST_DIR}/run_step.cmake)

file(REMOVE_RECURSE ${WORK_DIR})
set(_extra "")
if(Eigen3_DIR)
  list(APPEND _extra -DEigen3_DIR=${Eigen3_DIR})
endif()
# No CMAKE_BUILD_TYPE: the consumer checks that sepax leaves it unset.
run(configure ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/build -G ${GENERATOR}
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DSEPAX_SOURCE_DIR=${SEPAX_SOURCE_DIR} -DMODE=${MODE}
    -DEXPECTED_VERSION=${EXPECTED_VERSION} ${_extra})
run(build ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(float-consumer ${WORK_DIR}/build/float_consumer)
run(version-consumer ${WORK_DIR}/build/version_consumer)
if(NOT last_output STREQUAL "sepax ${EXPECTED_VERSION}\n")
  message(FATAL_ERROR "version_consumer printed '${last_output}'")
endif()
run(install ${CMAKE_COMMAND} --install ${WORK_DIR}/build --prefix ${WORK_DIR}/prefix)
file(GLOB_RECURSE _installed RELATIVE ${WORK_DIR}/prefix ${WORK_DIR}/prefix/*)
if(NOT _installed STREQUAL "bin/float_consumer")
  message(FATAL_ERROR "installing the consumer installed '${_installed}', expected bin/float_consumer only "
                      "(a subproject sepax installs nothing unless SEPAX_INSTALL is on)")
endif()
message(STATUS "subproject (${MODE}) consumer test passed")
