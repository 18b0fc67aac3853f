// Checkpoints of the long-running problems (contact, mca): the Checkpoint
// parameters, the store of a run's saved states (two slots and an
// atomically replaced pointer file), the reading of a checkpoint's blobs,
// and the CSV truncation of a resumed run (doc/user_guide.md,
// "Checkpoints"). What makes a stored run the same run is
// resumable_parameters.h; the signals that end a run with a checkpoint,
// interruption.h.
#ifndef tribodyn_core_checkpoint_h
#define tribodyn_core_checkpoint_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <string>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/resumable_parameters.h>
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

  /// What a checkpoint says about itself (the `checkpoint/latest` file).
  struct CheckpointInfo
  {
    std::string   problem;
    unsigned long step    = 0;
    double        time    = 0;
    unsigned int  n_ranks = 0;
    unsigned int  slot    = 0;
    /// The run's resumable_parameter_lines() as the checkpoint stored them
    /// (ResumableParameters::differing() reads them in today's names).
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

} // namespace tribodyn

#endif
