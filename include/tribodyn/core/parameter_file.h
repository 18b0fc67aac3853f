#ifndef tribodyn_core_parameter_file_h
#define tribodyn_core_parameter_file_h

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <tribodyn/core/problem.h>

namespace tribodyn
{
  /**
   * Read the parameter file @p file into @p prm, which must be empty: the
   * global parameters and those of the problem the file names (`set
   * Problem`) are declared, the parameters that depend on the file's values
   * too (ProblemDescription::declare_dependent_parameters), and the file is
   * checked strictly. Returns the problem's description. Throws InputError
   * naming the file, the line and the parameter on any fault. A line
   * 'include NAME' with a relative NAME reads NAME from the directory of
   * @p file (deal.II alone looks in the working directory), so a file can
   * build on a neighbour: 'include friction_composite.prm' and then the
   * entries that differ (prm/mca/friction_composite_4.prm). An included
   * file's own includes are deal.II's (working directory).
   *
   * The driver reads the file of a run with it; a study reads its base
   * scenes with it, then changes entries with set_parameter_by_path().
   */
  const ProblemDescription &
  read_parameter_file(const std::string &file, dealii::ParameterHandler &prm);

  /**
   * Set the entry at @p path ("Subsection/.../Name", the form the
   * parameter reference and the error messages use) of @p prm to @p value.
   * Throws InputError naming @p source (the parameter that asked for the
   * change) when the path names no entry or the value does not fit the
   * entry's pattern.
   */
  void
  set_parameter_by_path(dealii::ParameterHandler &prm,
                        const std::string        &path,
                        const std::string        &value,
                        const std::string        &source);

  /// The value of the entry at @p path of @p prm (see
  /// set_parameter_by_path(); InputError naming @p source if there is none).
  std::string
  get_parameter_by_path(dealii::ParameterHandler &prm,
                        const std::string        &path,
                        const std::string        &source);
} // namespace tribodyn

#endif
