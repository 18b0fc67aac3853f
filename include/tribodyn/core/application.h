#ifndef tribodyn_core_application_h
#define tribodyn_core_application_h

namespace tribodyn
{
  /**
   * The tribodyn command line: `tribodyn FILE.prm`,
   * `tribodyn --print-parameters [PROBLEM]`, `tribodyn --help`,
   * `tribodyn --version`. Returns the process exit code (see exit_code).
   * MPI must be initialized by the caller.
   */
  int
  run_application(int argc, char **argv);
} // namespace tribodyn

#endif
