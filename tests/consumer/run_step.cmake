# run(STEP COMMAND...) for the consumer test scripts (cmake -P): runs the
# command, prints its output under [STEP], stops the test if it fails, and
# leaves its standard output in last_output.
function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "[${step}] ${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "[${step}] failed (${rc}):\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()
