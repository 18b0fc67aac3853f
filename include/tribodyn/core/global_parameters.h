#ifndef tribodyn_core_global_parameters_h
#define tribodyn_core_global_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <tribodyn/core/parameter_binding.h>

namespace tribodyn
{
  /// The top-level parameters every `.prm` file has.
  struct GlobalParameters
  {
    /// Name of the problem to run (homogenization, ...).
    std::string problem = "homogenization";
    /// Directory receiving every output of the run.
    std::string output_directory = "output";
    /// Minimum wall time between two progress lines (s).
    double progress_interval = 5.0;

    /// The entries, each written once (core/parameter_binding.h).
    ParameterBinding
    binding();
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace tribodyn

#endif
