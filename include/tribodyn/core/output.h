#ifndef tribodyn_core_output_h
#define tribodyn_core_output_h

#include <deal.II/base/mpi.h>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DataOutInterface;
}

namespace tribodyn
{
  /**
   * Write @p content to @p path so that a crash never leaves a truncated
   * file in place of a good one: the text goes to a temporary file in the
   * same directory, which is then renamed over @p path (rename is atomic on
   * POSIX file systems). Throws InputError if the file cannot be written.
   */
  void
  write_file_atomically(const std::string &path, const std::string &content);

  /**
   * Write the patches of @p data_out, spread over the ranks of @p comm, to
   * the one VTU file @p path: with MPI I/O on several ranks (deal.II's
   * write_vtu_in_parallel()), and through write_file_atomically() on one.
   * Not MPI I/O on one rank: Open MPI's shared file pointer (sharedfp/sm)
   * keeps a memory-mapped file in the job's session directory, and runs
   * started without mpirun at the same moment share that directory, so one
   * finishing removes it under the other, whose MPI_File_open fails (seen
   * when the tests ran two such runs side by side).
   */
  template <int dim, int spacedim>
  void
  write_vtu_file(const dealii::DataOutInterface<dim, spacedim> &data_out,
                 const std::string                             &path,
                 const MPI_Comm                                 comm);

  /// Create @p directory (and parents) if it does not exist; clear error if
  /// it cannot be created or is not writable.
  void
  create_output_directory(const std::string &directory);

  /// Is @p path an existing regular file?
  bool
  file_exists(const std::string &path);

  /**
   * Draw the figures of a run: run the matplotlib script @p script on
   * @p directory with /usr/bin/python3 (Debian's python3-matplotlib belongs
   * to it; another python3 first in PATH may lack it). @p script is "none"
   * (nothing), a path, or "auto": scripts/@p default_script next to the
   * executable's directory. A missing script or matplotlib, or a failing
   * script, is said on the screen (naming @p parameter, the prm entry that
   * sets the script) and does not stop the run: the tables are written.
   */
  void
  run_plot_script(const std::string &script,
                  const std::string &default_script,
                  const std::string &parameter,
                  const std::string &directory);

  /// Join a directory and a file name.
  std::string
  join_path(const std::string &directory, const std::string &file);

  /**
   * The columns @p names of the CSV file @p path (a CsvWriter's series: a
   * header line, then rows of numbers), in that order, into @p columns.
   * Reading stops at the first row with another number of fields than the
   * header (a partly written last line). False, with @p columns empty,
   * when the file cannot be read, lacks one of the columns or holds a
   * field that is not a number: the caller says what that means.
   */
  bool
  read_csv_columns(const std::string                &path,
                   const std::vector<std::string>   &names,
                   std::vector<std::vector<double>> &columns);

  /**
   * A CSV time series: a header line, then one row per record. Rows are kept
   * in memory and the whole file is rewritten atomically by flush(), so the
   * file on disk is always complete (every line whole) even if the run dies.
   * flush() is rate limited by @p min_seconds_between_flushes unless forced;
   * the destructor flushes what was recorded (so an aborted run keeps its
   * series). Only the process that is given `active = true` (rank 0) writes.
   */
  class CsvWriter
  {
  public:
    CsvWriter() = default;
    CsvWriter(const std::string              &path,
              const std::vector<std::string> &columns,
              const bool                      active,
              const double min_seconds_between_flushes = 2.0);
    /**
     * A resumed series: keep the first @p rows_kept rows of the existing
     * file @p path (written by the checkpointed run; its later rows are
     * dropped) and continue after them. InputError if the file has fewer
     * rows or another header.
     */
    CsvWriter(const std::string              &path,
              const std::vector<std::string> &columns,
              const bool                      active,
              const std::size_t               rows_kept,
              const double min_seconds_between_flushes = 2.0);
    ~CsvWriter();

    CsvWriter(const CsvWriter &) = delete;
    CsvWriter &
    operator=(const CsvWriter &)
      = delete;

    /// Append a row; its size must equal the number of columns.
    void
    add_row(const std::vector<double> &values);

    /// Append a row whose first entries are strings (e.g. labels).
    void
    add_row(const std::vector<std::string> &labels,
            const std::vector<double>      &values);

    /// Rewrite the file if enough time has passed since the last flush (or
    /// always when @p force).
    void
    flush(const bool force = false);

    const std::string &
    path() const;

    /// Rows in the series (kept from a checkpointed run plus added), on
    /// every process.
    std::size_t
    n_rows() const
    {
      return row_count;
    }

  private:
    std::string path_name;
    std::size_t n_columns       = 0;
    std::size_t row_count       = 0;
    bool        is_active       = false;
    double      min_interval    = 2.0;
    double      last_flush_time = -1e300;
    bool        dirty           = false;
    std::string text;
  };

  /**
   * The `.pvd` index of a series of parallel VTU files, rewritten atomically
   * each time a record is added so that ParaView can open it mid-run.
   */
  class PvdWriter
  {
  public:
    PvdWriter() = default;
    PvdWriter(const std::string &path, const bool active);

    /// Record that @p file_name (relative to the pvd's directory) holds the
    /// fields at time @p time.
    void
    add(const double time, const std::string &file_name);

    /// The records so far (checkpoints).
    const std::vector<std::pair<double, std::string>> &
    entries() const
    {
      return records;
    }

    /// Resumed runs: start from the records of the checkpointed run
    /// (nothing is written: call write() once the directory is claimed).
    void
    restore(const std::vector<std::pair<double, std::string>> &entries);

    /// Rewrite the index with the records so far (on the active process;
    /// nothing while there are none).
    void
    write() const;

  private:
    std::string                                 path_name;
    bool                                        is_active = false;
    std::vector<std::pair<double, std::string>> records;
  };

  class JsonValue;

  /// The keys every run's summary.json begins with: "problem" (@p problem),
  /// "tribodyn_version" and "n_mpi_ranks" (the ranks of @p comm).
  JsonValue
  summary_header(const std::string &problem, const MPI_Comm comm);
} // namespace tribodyn

#endif
