#ifndef tribodyn_core_output_directory_h
#define tribodyn_core_output_directory_h

#include <deal.II/base/mpi.h>
#include <string>
#include <vector>

namespace tribodyn
{
  /**
   * @name Claiming an output directory
   *
   * A run touches its output directory only once it has passed every check
   * (parameters, time step, resume compatibility, memory, input files):
   * then it *claims* the directory. Before that moment a refusal leaves the
   * directory byte for byte as it was.
   *
   * Claiming for a fresh run never mixes two runs in one directory:
   * - if the directory holds a finished run (its `summary.json`), that run
   *   is moved, whole, into `previous_run/` (replacing an older one there);
   * - if it holds an unfinished run (files but no `summary.json`: an
   *   interrupted, crashed or killed run), those files are moved, whole,
   *   into `previous_run/unfinished/`;
   * so that the directory then holds only the new run's files, and a crash
   * of the new run leaves a directory of that run alone (without a
   * `summary.json`), next to the last finished one.
   *
   * Claiming to resume keeps every file (the run continues its own series)
   * and renames a `summary.json` of the previous leg to
   * `summary.previous_leg.json`, since the series it summarised are about to
   * grow.
   *
   * In both cases the claim then writes `parameters.prm`.
   */
  //@{

  /// How a run takes its output directory.
  enum class OutputClaim
  {
    /// A new run: an earlier run's files are moved aside, whole.
    fresh,
    /// A run continuing from a checkpoint of this directory.
    resume
  };

  /// The folder of a claimed directory that holds the run before.
  inline constexpr const char *previous_run_folder = "previous_run";

  /**
   * Collective over @p comm: create @p directory if needed and claim it for
   * a run (see above). Rank 0 moves the files; an error (unwritable
   * directory, failed rename) is thrown on every rank as InputError.
   * @p parameters_text is written to `parameters.prm` unless empty.
   * Entries named in @p kept (folders the problem manages itself, such as a
   * study's `cases/`, whose runs claim their own directories) stay where
   * they are.
   */
  void
  claim_output_directory(const std::string              &directory,
                         const OutputClaim               how,
                         const std::string              &parameters_text,
                         const MPI_Comm                  comm,
                         const std::vector<std::string> &kept = {});

  /**
   * From this call on (the driver makes it before creating the problem),
   * writing a file with write_file_atomically() or a checkpoint outside a
   * claimed directory is an internal error: a run that would write before
   * its checks are done fails loudly in the tests instead of silently
   * touching an earlier run's results.
   */
  void
  guard_unclaimed_output_writes();

  /// Ends the run (MPI_Abort, exit code 4: an internal error) if the guard
  /// is on and @p path lies in no claimed directory.
  void
  assert_output_claimed(const std::string &path);

  //@}
} // namespace tribodyn

#endif
