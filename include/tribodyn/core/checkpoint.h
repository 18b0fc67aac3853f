#ifndef tribodyn_core_checkpoint_h
#define tribodyn_core_checkpoint_h

#include <csignal>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <istream>
#include <stdexcept>
#include <string>
#include <tribodyn/core/parameter_binding.h>
#include <vector>

namespace boost
{
  namespace archive
  {
    class binary_iarchive;
  } // namespace archive
} // namespace boost

namespace tribodyn
{
  /**
   * Subsection "Checkpoint" of the long-running problems (contact, mca):
   * how often the run's state is saved and whether a run continues from
   * the latest saved state in its output directory.
   */
  struct CheckpointParameters
  {
    /// Simulated time between two checkpoints (s); 0: no periodic
    /// checkpoints (SIGTERM/SIGINT still write one).
    double interval = 0;
    /// Continue from the latest checkpoint of the output directory.
    bool resume = false;

    /// The entries, each written once (core/parameter_binding.h).
    ParameterBinding
    binding();
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * What identifies a run for a resume or a reuse: its resumable parameter
   * lines (resumable_parameter_lines() below, what a checkpoint stores) and the
   * lines of every entry at its default value in this version. A stored
   * run (a checkpoint, a finished study scene's parameters.prm) is the
   * same run where the two agree but for entries at their defaults: an
   * entry a later version added (absent from the stored lines) is the
   * same as long as this run leaves it at its default, and an entry a
   * stored run left at a default that is still the default is the same
   * whether or not this version lists it.
   */
  struct ResumableParameters
  {
    /// resumable_parameter_lines() of the run (sorted).
    std::vector<std::string> lines;
    /// Every entry at its default, as comparable lines (sorted).
    std::vector<std::string> defaults;
    /// The paths of the entries that only analyse the run's record
    /// (ParameterBinding::analysis_only(); sorted).
    std::vector<std::string> analysis_only;
    /// The paths of the entries of the work's layout only
    /// (ParameterBinding::layout_only(); sorted): never a difference.
    std::vector<std::string> layout_only;

    /// The names of the entries in which the stored lines @p stored
    /// (resumable_parameter_lines() of a stored run, any version) differ
    /// from this run's, but for the layout-only ones: empty for the same
    /// run.
    std::vector<std::string>
    differing(const std::vector<std::string> &stored) const;

    /// differing() without the analysis-only entries: the names of the
    /// entries that change the run's steps. Empty: a checkpoint of
    /// @p stored may be resumed by this run.
    std::vector<std::string>
    differing_in_run(const std::vector<std::string> &stored) const;

    /// The same run as @p stored?
    bool
    same_as(const std::vector<std::string> &stored) const
    {
      return differing(stored).empty();
    }
  };

  /// Entry names (those differing() returns) as a message lists them:
  /// 'A', 'B', 'C'.
  std::string
  quoted_names(const std::vector<std::string> &names);

  /// The ResumableParameters of @p prm (declared and read).
  ResumableParameters
  resumable_parameters(dealii::ParameterHandler &prm,
                       const std::string        &end_time_entry);

  /**
   * The parameters of the text @p short_prm of a run's parameters.prm
   * (ShortPRM, as the application writes it) as "Section/Name = value"
   * lines, without those a resumed run may change: @p end_time_entry (the
   * problem's end time), the Checkpoint subsection, the global Progress
   * interval and the Output directory (a run directory copied to another
   * path or machine continues there). Sorted, in the current names of
   * renamed parameters (with_current_names()), and a value that is one
   * number written in one spelling (0.5e6 and 5e5 are one line), so that a
   * run of a version before a rename or with other spellings of the
   * defaults is recognised. @p end_time, if given, receives the value of
   * @p end_time_entry. What a checkpoint stores (of the run's own
   * parameters: ResumableParameters::lines).
   */
  std::vector<std::string>
  resumable_parameter_lines(std::istream      &short_prm,
                            const std::string &end_time_entry,
                            double            *end_time = nullptr);

  /// What a checkpoint says about itself (the `checkpoint/latest` file).
  struct CheckpointInfo
  {
    std::string              problem;
    unsigned long            step    = 0;
    double                   time    = 0;
    unsigned int             n_ranks = 0;
    unsigned int             slot    = 0;
    std::vector<std::string> parameters;
  };

  /**
   * What the latest checkpoint of the run in @p output_directory says about
   * itself (rank-local file read, no MPI); false when there is none or its
   * `latest` file is damaged. A study uses it to decide whether a scene
   * resumes; CheckpointStore::read() does the full checks.
   */
  bool
  read_latest_checkpoint_info(const std::string &output_directory,
                              CheckpointInfo    &info);

  /**
   * Checkpoints of a run in `OUTPUT/checkpoint/`: two slots `slot_0/` and
   * `slot_1/` hold one file per rank (`rank_NNNN.bin`, a Boost binary
   * archive written by the problem), and the small text file `latest`
   * names the slot of the last complete checkpoint. A new checkpoint goes
   * to the other slot (each file written under a temporary name, flushed to
   * disk, renamed), then every rank reports success and rank 0 replaces
   * `latest` atomically: a crash at any moment leaves the previous
   * checkpoint usable.
   */
  class CheckpointStore
  {
  public:
    CheckpointStore(const std::string &output_directory,
                    const std::string &problem,
                    const MPI_Comm     comm);

    /// Fresh run: forget older checkpoints of the directory (so that a
    /// later Resume cannot pick up another run's state).
    void
    discard();

    /// Collective: store this rank's @p blob as the checkpoint of
    /// (@p step, @p time) with the run's @p parameters (their lines).
    void
    write(const std::string         &blob,
          const unsigned long        step,
          const double               time,
          const ResumableParameters &parameters);

    /**
     * Collective: this rank's share of the latest checkpoint, which may
     * have been written by another number of ranks N (info.n_ranks): the
     * blobs of the writing ranks r, r + M, r + 2M, ... (M: ranks of this
     * run, r: this rank), in that order; on the same number of ranks, the
     * one blob this rank wrote. Throws InputError with the fix when there
     * is no checkpoint, when it belongs to another problem, when a rank's
     * file is missing or damaged, or when @p parameters differ from the
     * checkpointed run's (naming the parameters; entries at their defaults
     * as ResumableParameters::differing() says).
     */
    std::vector<std::string>
    read(const ResumableParameters &parameters, CheckpointInfo &info);

    /// Directory of the checkpoints.
    const std::string &
    directory() const
    {
      return path;
    }

  private:
    std::string
    rank_file(const unsigned int slot, const unsigned int rank) const;

    std::string  path;
    std::string  problem;
    MPI_Comm     comm;
    unsigned int next_slot = 0;
  };

  /**
   * Collective: call @p read on a Boost binary archive of each of @p blobs
   * (this rank's share of a checkpoint, CheckpointStore::read(), or data
   * derived from it). If it fails on any rank, every rank throws InputError
   * with the message of the lowest failing rank: that of an InputError
   * @p read threw, or, for any other exception (an archive's on damaged
   * data or on another version's format), "cannot be read".
   */
  void
  read_checkpoint_blobs(
    const MPI_Comm                                                comm,
    const std::vector<std::string>                               &blobs,
    const std::function<void(boost::archive::binary_iarchive &)> &read);

  /**
   * Keep the header and the first @p n_rows data lines of the CSV file
   * @p path (resumed runs: the rows written after the checkpoint are
   * dropped, so that the series has neither duplicates nor gaps). Reads
   * @p path, or `path + ".part"` if it does not exist and @p partial_ok.
   * Returns the text kept; throws InputError if the file has fewer rows.
   */
  std::string
  read_csv_rows(const std::string &path,
                const std::size_t  n_rows,
                const bool         partial_ok = false);

  // ---- interruptions

  /**
   * While an object of this class lives (the time loop of a long run),
   * SIGTERM and SIGINT only set a flag: the loop polls it between steps
   * (agree_on_health()), writes a checkpoint, flushes its outputs and
   * throws Interrupted. The destructor restores the previous handlers and,
   * if a signal arrived but was not acted upon, re-raises it. Handlers
   * nest (a study's around its scenes' time loops): the inner ones keep a
   * signal the outer ones recorded and leave an unacted one to them.
   */
  class InterruptHandlers
  {
  public:
    InterruptHandlers();
    ~InterruptHandlers();
    InterruptHandlers(const InterruptHandlers &) = delete;
    InterruptHandlers &
    operator=(const InterruptHandlers &)
      = delete;

    /// The run acted upon the signal (Interrupted thrown).
    static void
    acknowledge();

  private:
    struct sigaction previous_term, previous_int;
  };

  /// The signal received (SIGTERM, SIGINT) on this process, or 0.
  int
  local_interrupt_signal();

  /// A run ended by SIGTERM or SIGINT after saving its state; exit code
  /// 128 + signal.
  class Interrupted : public std::runtime_error
  {
  public:
    Interrupted(const int signal, const std::string &message);
    int signal_number;
  };

  /**
   * Health of a run as agreed by all ranks at a check: the largest
   * "badness" of the ranks (0: fine) and the interrupt signal if any rank
   * received one. One MPI_Allreduce (none on one rank). A caller with one
   * more quantity to agree on by its maximum passes it in @p shared_max,
   * which is replaced by the ranks' maximum in the same reduction.
   */
  struct RunHealth
  {
    double badness = 0;
    int    signal  = 0;
  };
  RunHealth
  agree_on_health(const double   local_badness,
                  const MPI_Comm comm,
                  double        *shared_max = nullptr);
} // namespace tribodyn

#endif
