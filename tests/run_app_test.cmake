# Run tribodyn on PRM inside a fresh OUTPUT_DIR (prm files of tests write to
# a relative 'Output directory'), then the python CHECK script with the
# directory as argument. Called by tribodyn_add_app_test().
file(REMOVE_RECURSE ${OUTPUT_DIR})
file(MAKE_DIRECTORY ${OUTPUT_DIR})
separate_arguments(LAUNCHER)
execute_process(COMMAND ${LAUNCHER} ${TRIBODYN} ${PRM}
                WORKING_DIRECTORY ${OUTPUT_DIR}
                RESULT_VARIABLE run_result
                OUTPUT_FILE ${OUTPUT_DIR}/stdout.txt
                ERROR_FILE ${OUTPUT_DIR}/stderr.txt)
file(READ ${OUTPUT_DIR}/stdout.txt run_stdout)
file(READ ${OUTPUT_DIR}/stderr.txt run_stderr)
message("${run_stdout}")
if(NOT run_result EQUAL 0)
  message(FATAL_ERROR "tribodyn exited with ${run_result}:\n${run_stderr}")
endif()
execute_process(COMMAND ${PYTHON3} ${CHECK} ${OUTPUT_DIR}
                WORKING_DIRECTORY ${OUTPUT_DIR}
                RESULT_VARIABLE check_result)
if(NOT check_result EQUAL 0)
  message(FATAL_ERROR "check ${CHECK} failed")
endif()
