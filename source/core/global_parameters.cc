#include <tribodyn/core/global_parameters.h>
#include <tribodyn/core/problem.h>

namespace tribodyn
{
  void
  GlobalParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    std::string names;
    std::string documentation
      = "The problem to solve. Each problem reads the subsections documented "
        "under its name:";
    for (const auto &p : registered_problems())
      {
        names += (names.empty() ? "" : "|") + p.name;
        documentation += " '" + p.name + "': " + p.description + ".";
      }
    // homogenization is the default when this build has it.
    std::string default_problem = "homogenization";
    if (names.find(default_problem) == std::string::npos
        && !registered_problems().empty())
      default_problem = registered_problems().front().name;
    prm.declare_entry("Problem",
                      default_problem,
                      dealii::Patterns::Selection(names),
                      documentation);
    prm.declare_entry("Output directory",
                      "output",
                      dealii::Patterns::Anything(),
                      "Directory receiving every output of the run "
                      "(created if missing; relative paths are relative to "
                      "the working directory).");
    prm.declare_entry("Progress interval",
                      "5",
                      dealii::Patterns::Double(0.),
                      "Minimum wall time between two progress lines, in "
                      "seconds.");
  }


  void
  GlobalParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    problem           = prm.get("Problem");
    output_directory  = prm.get("Output directory");
    progress_interval = prm.get_double("Progress interval");
  }
} // namespace tribodyn
