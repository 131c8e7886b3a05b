# Whole-program tests, included by tests/CMakeLists.txt.
#   cli/run/*      run the sepax binary on built-in shapes and on tests/data/
#   cli/install    install the build tree to a temporary prefix, then
#                  configure, build and run tests/consumer/ against it
#                  (find_package(sepax) with sepax::sepax and sepax::robust)
if(NOT TARGET sepax_cli)
  return()
endif()
set(_sepax_data ${CMAKE_CURRENT_SOURCE_DIR}/data)

function(sepax_cli_test name regex)
  add_test(NAME cli/run/${name} COMMAND sepax_cli ${ARGN})
  set_tests_properties(cli/run/${name} PROPERTIES PASS_REGULAR_EXPRESSION "${regex}" TIMEOUT 300)
endfunction()

# Built-in shapes: separated, overlapping, exact, brute force, flat shapes.
sepax_cli_test(query_builtin_separated "overlap: +no\nseparation: 0.5\n"
  query cube cube --pose 2.5 0 0)
sepax_cli_test(query_builtin_overlap_exact_json "^\\{\"overlap\":true,\"separation\":-0\\.5,.*\"number\":\"exact\""
  query cube cube --pose 1.5 0 0 --number exact --json)
sepax_cli_test(query_builtin_rotated_brute "overlap: +no\n"
  query prism:6 tetra --pose 3 0.5 0.2 0.9 0.1 0.3 0.2 --algorithm brute --number float)
sepax_cli_test(query_flat_touching "overlap: +yes\nseparation: 0\n"
  query cube triangle --pose 0 0 1)
sepax_cli_test(help "query.*info.*help" help)

# Files: OFF and OBJ face lists, a points file (hulled), a batch file.
sepax_cli_test(query_files_off_obj "\"overlap\":false,\"separation\":1,"
  query ${_sepax_data}/cube.off ${_sepax_data}/tetra.obj --pose 3 0 0 --json)
sepax_cli_test(info_points_hull "6 vertices, 12 edges, 8 faces"
  info ${_sepax_data}/octahedron.pts --number exact)
sepax_cli_test(batch_file
  "^\\{\"id\":1,\"overlap\":false,\"separation\":1,[^\n]*\n\\{\"id\":\"overlap\",\"overlap\":true,[^\n]*\n\\{\"id\":3,\"error\":\"line 3: a: [^\n]*\n\\{\"id\":null,\"error\":\"line 4: invalid JSON at column"
  query --batch ${_sepax_data}/batch.jsonl)

# Malformed input: the message names FILE:LINE, and the exit status is non-zero.
sepax_cli_test(malformed_off_message "malformed\\.off:5: bad number 'oops' for coordinate z of vertex 2"
  query cube ${_sepax_data}/malformed.off)
add_test(NAME cli/run/malformed_off_status COMMAND sepax_cli query cube ${_sepax_data}/malformed.off)
set_tests_properties(cli/run/malformed_off_status PROPERTIES WILL_FAIL TRUE)
add_test(NAME cli/run/batch_with_bad_line_status COMMAND sepax_cli query --batch ${_sepax_data}/batch.jsonl)
set_tests_properties(cli/run/batch_with_bad_line_status PROPERTIES WILL_FAIL TRUE)
add_test(NAME cli/run/unknown_verb_status COMMAND sepax_cli frobnicate)
set_tests_properties(cli/run/unknown_verb_status PROPERTIES WILL_FAIL TRUE)

# Install + consumer project.
add_test(NAME cli/install_and_consume
  COMMAND ${CMAKE_COMMAND}
    -D BUILD_DIR=${PROJECT_BINARY_DIR}
    -D CONSUMER_DIR=${CMAKE_CURRENT_SOURCE_DIR}/consumer
    -D WORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/install_test
    -D GENERATOR=${CMAKE_GENERATOR}
    -D CXX_COMPILER=${CMAKE_CXX_COMPILER}
    -D BUILD_TYPE=${CMAKE_BUILD_TYPE}
    -D WITH_ROBUST=${SEPAX_BUILD_ROBUST}
    -P ${CMAKE_CURRENT_SOURCE_DIR}/consumer/run_install_test.cmake)
set_tests_properties(cli/install_and_consume PROPERTIES TIMEOUT 1200 RUN_SERIAL TRUE)

# Contact manifolds in the query output (text and JSON) and the render verb.
sepax_cli_test(query_manifold_box_on_box
  "manifold: +face contact, 4 points \\(reference face 1 of A, incident face 0 of B"
  query cube cube --pose 0 0 1.5)
sepax_cli_test(query_manifold_crossed_edges_exact_json
  "\"manifold\":\\{\"kind\":\"edge\",\"points\":\\[\\{\"position\":\\[0,0,0\\.95\\],\"separation\":-0\\.1[0-9]*,\"id\":\"A:edge 3/B:edge 1\"\\}\\]\\}"
  query tetra tetra --pose 0 0 1.9 --number exact --json)
sepax_cli_test(render_svg_stdout "^<svg .*Gauss maps.*</svg>"
  render cube polygon:3 --pose 0.1 0 1 --svg -)
sepax_cli_test(render_needs_svg "--svg FILE is required"
  render cube cube)
