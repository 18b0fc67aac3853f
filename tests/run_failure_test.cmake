# tribodyn must refuse PRM: exit code EXIT_CODE (2, a refusal, unless
# given), EXPECTED on stderr, no crash dump, and (for refusals) nothing
# touched: the output directory 'output/' of the working directory holds a
# finished run's files before, which must be byte for byte the same after,
# and no other file may appear. Called by tribodyn_add_failure_test().
if(NOT DEFINED EXIT_CODE OR EXIT_CODE STREQUAL "")
  set(EXIT_CODE 2)
endif()
file(REMOVE_RECURSE ${OUTPUT_DIR})
file(MAKE_DIRECTORY ${OUTPUT_DIR}/output)
set(sentinel "{\"problem\": \"a finished run that a refusal must keep\"}\n")
file(WRITE ${OUTPUT_DIR}/output/summary.json "${sentinel}")
file(WRITE ${OUTPUT_DIR}/output/parameters.prm "# the finished run's\n")
file(GLOB_RECURSE files_before RELATIVE ${OUTPUT_DIR} ${OUTPUT_DIR}/*)
execute_process(COMMAND ${TRIBODYN} ${PRM}
                WORKING_DIRECTORY ${OUTPUT_DIR}
                RESULT_VARIABLE run_result
                OUTPUT_VARIABLE run_stdout
                ERROR_VARIABLE run_stderr)
message("exit code: ${run_result}\nstderr: ${run_stderr}")
if(run_result EQUAL 0)
  message(FATAL_ERROR "tribodyn accepted ${PRM}; it should have refused it")
endif()
if(NOT run_result MATCHES "^[0-9]+$")
  message(FATAL_ERROR "tribodyn did not exit cleanly: ${run_result}")
endif()
if(NOT run_result EQUAL EXIT_CODE)
  message(FATAL_ERROR "exit code ${run_result}, expected ${EXIT_CODE}")
endif()
string(FIND "${run_stderr}" "${EXPECTED}" position)
if(position EQUAL -1)
  message(FATAL_ERROR "stderr does not contain '${EXPECTED}'")
endif()
foreach(crash_marker "Stacktrace" "Aborting!" "internal error" "terminate called")
  string(FIND "${run_stderr}" "${crash_marker}" position)
  if(NOT position EQUAL -1)
    message(FATAL_ERROR "stderr shows a crash ('${crash_marker}')")
  endif()
endforeach()
if(EXIT_CODE EQUAL 2)
  file(GLOB_RECURSE files_after RELATIVE ${OUTPUT_DIR} ${OUTPUT_DIR}/*)
  if(NOT "${files_after}" STREQUAL "${files_before}")
    message(FATAL_ERROR "the refusal touched the outputs: files before "
                        "'${files_before}', after '${files_after}'")
  endif()
  file(READ ${OUTPUT_DIR}/output/summary.json after)
  if(NOT after STREQUAL sentinel)
    message(FATAL_ERROR "the refusal changed output/summary.json")
  endif()
  file(READ ${OUTPUT_DIR}/output/parameters.prm after)
  if(NOT after STREQUAL "# the finished run's\n")
    message(FATAL_ERROR "the refusal changed output/parameters.prm")
  endif()
endif()
