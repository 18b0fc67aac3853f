# tribodyn must refuse PRM: non-zero exit code, EXPECTED on stderr, and no
# crash dump. Called by tribodyn_add_failure_test().
file(REMOVE_RECURSE ${OUTPUT_DIR})
file(MAKE_DIRECTORY ${OUTPUT_DIR})
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
