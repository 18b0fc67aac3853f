# Writes OUTPUT (version.cc) with the version and the git revision of
# SOURCE_DIR, run at every build (target tribodyn_version): the revision a
# binary reports (summary.json's tribodyn_version) is the commit it was
# built from, not the one of the last CMake run. configure_file() rewrites
# the file only when its text changes, so an unchanged revision recompiles
# nothing.
execute_process(COMMAND git describe --always --dirty
  WORKING_DIRECTORY ${SOURCE_DIR}
  OUTPUT_VARIABLE TRIBODYN_GIT_REVISION OUTPUT_STRIP_TRAILING_WHITESPACE
  ERROR_QUIET)
if(NOT TRIBODYN_GIT_REVISION)
  set(TRIBODYN_GIT_REVISION "unknown")
endif()
configure_file(${SOURCE_DIR}/include/tribodyn/core/version.cc.in ${OUTPUT} @ONLY)
