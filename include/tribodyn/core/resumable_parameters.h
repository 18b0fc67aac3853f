// What identifies a run, for a resume from a checkpoint (checkpoint.h)
// or the reuse of a finished study scene (study/mca_study.cc): its
// parameters as comparable lines, and which entries may differ
// (doc/user_guide.md, "Checkpoints").
#ifndef tribodyn_core_resumable_parameters_h
#define tribodyn_core_resumable_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <istream>
#include <string>
#include <vector>

namespace tribodyn
{
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
} // namespace tribodyn

#endif
