#ifndef tribodyn_core_errors_h
#define tribodyn_core_errors_h

#include <mpi.h>
#include <stdexcept>
#include <string>

namespace tribodyn
{
  /**
   * An error caused by the user's input (parameter file, data file, command
   * line) or by a run that cannot go on (unstable time step, NaN). Its
   * message is one paragraph meant for the user: it names the cause and
   * the fix. The application catches it at top level, prints it on stderr
   * and exits with a non-zero code, without a crash dump.
   */
  class InputError : public std::runtime_error
  {
  public:
    explicit InputError(const std::string &message);
  };

  /**
   * A run aborted mid-way for a numerical reason (NaN, divergence, an
   * unstable time step discovered during the run). Exit code differs from
   * InputError so that scripts can tell the two apart.
   */
  class RunError : public std::runtime_error
  {
  public:
    explicit RunError(const std::string &message);
  };

  /// Collective: throw a RunError on every rank of @p comm if any rank
  /// @p failed; the message is that of the lowest failing rank.
  void
  throw_collectively(const MPI_Comm     comm,
                     const bool         failed,
                     const std::string &message);

  /// The same with an InputError (exit code 2): input that does not fit
  /// the run, found by one rank (e.g. a checkpoint of another mesh).
  void
  refuse_collectively(const MPI_Comm     comm,
                      const bool         failed,
                      const std::string &message);

  /// Exit codes of the tribodyn executable.
  namespace exit_code
  {
    constexpr int success        = 0;
    constexpr int input_error    = 2;
    constexpr int run_error      = 3;
    constexpr int internal_error = 4;
    /// A run stopped by a signal after saving its state exits with
    /// 128 + the signal number (130 for SIGINT, 143 for SIGTERM), as a
    /// shell reports a process killed by that signal.
    constexpr int interrupted_base = 128;
  } // namespace exit_code

  /**
   * Throw an InputError naming parameter @p name (with its section path)
   * when @p value is not in the interval described by @p lower and
   * @p upper. Open or closed ends are chosen by the two flags.
   */
  void
  check_parameter_range(const std::string &name,
                        const double       value,
                        const double       lower,
                        const double       upper,
                        const bool         lower_open,
                        const bool         upper_open,
                        const std::string &hint = "");

  /// Throw an InputError naming parameter @p name unless @p condition.
  void
  check_parameter(const bool         condition,
                  const std::string &name,
                  const std::string &what_is_allowed);

  /// Format a double for messages with enough digits to be unambiguous.
  std::string
  format_number(const double value);

  /// @p value with the fewest significant digits that read back to it
  /// exactly, as one writes a number by hand (0.9, 0.028, 500, 5e5, 2.5e-4,
  /// 1.1e-9): the default of a bound parameter (parameter_binding.h), the
  /// one spelling of a number in a checkpoint's parameter lines.
  std::string
  exact_number(const double value);
} // namespace tribodyn

#endif
