#ifndef tribodyn_core_problem_h
#define tribodyn_core_problem_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <tribodyn/core/output_directory.h>
#include <vector>

namespace tribodyn
{
  /**
   * What every problem gets from the driver: the communicator, where to
   * write, and how the run was called. The ParameterHandler itself does not
   * travel past the driver: each problem parses it into its own parameter
   * structs when it is created.
   */
  struct RunContext
  {
    MPI_Comm    mpi_communicator = MPI_COMM_WORLD;
    std::string output_directory;
    std::string parameter_file;
    /// Minimum wall time between two progress lines, in seconds.
    double progress_interval = 5.0;
    /// The text of parameters.prm, made when the output directory is
    /// claimed (so that values a problem sets while parsing, such as the
    /// pixels of a grid file, are those recorded); none for runs a driver
    /// builds from parameter structs (a study's cases).
    std::function<std::string()> parameters_text;

    /**
     * Claim the output directory (collective): called by a problem once it
     * has passed every check and before it writes its first file. See
     * claim_output_directory().
     */
    void
    claim_output(const OutputClaim               how  = OutputClaim::fresh,
                 const std::vector<std::string> &kept = {}) const
    {
      claim_output_directory(output_directory,
                             how,
                             parameters_text ? parameters_text() : "",
                             mpi_communicator,
                             kept);
    }
  };

  /**
   * A problem users choose with `set Problem = NAME`. It is built from the
   * parsed parameters and runs to completion (or throws InputError or
   * RunError with a message for the user).
   */
  class Problem
  {
  public:
    virtual ~Problem() = default;

    virtual void
    run()
      = 0;
  };

  /**
   * How the driver knows a problem: its name, a one-line description, the
   * function declaring its parameters (besides the global ones) and the
   * factory creating it from the parsed parameters.
   */
  struct ProblemDescription
  {
    std::string                                     name;
    std::string                                     description;
    std::function<void(dealii::ParameterHandler &)> declare_parameters;
    std::function<std::unique_ptr<Problem>(dealii::ParameterHandler &,
                                           const RunContext &)>
      create;
    /// Optional: print, without running, how the problem's scene would be
    /// partitioned over a number of MPI ranks (`--partition-report N`).
    std::function<void(dealii::ParameterHandler &,
                       const unsigned int n_ranks,
                       std::ostream      &out)>
      partition_report = {};
    /// Optional: declare the parameters that depend on values of the file
    /// (the subsections of user-named materials, mca). Called after a first
    /// lenient reading of the file into the handler (unknown entries
    /// skipped), before the strict one; declare_parameters declares them
    /// for the default values (what --print-parameters shows).
    std::function<void(dealii::ParameterHandler &)> declare_dependent_parameters
      = {};
  };

  /**
   * The problems this build of tribodyn knows, sorted by name. Each module
   * registers its problem from its own source file (see
   * register_problem()), so adding a problem touches no shared file.
   */
  const std::vector<ProblemDescription> &
  registered_problems();

  /**
   * Add @p description to the registry. Called during static
   * initialization of the shared library, typically as
   * `static const bool name_registered = register_problem({...});` in the
   * problem's source file (named after the file: unity builds). Returns
   * true.
   */
  bool
  register_problem(const ProblemDescription &description);

  /// The problem called @p name; throws InputError listing the known ones.
  const ProblemDescription &
  find_problem(const std::string &name);
} // namespace tribodyn

#endif
