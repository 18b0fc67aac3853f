#include <tribodyn/core/global_parameters.h>
#include <tribodyn/core/problem.h>

namespace tribodyn
{
  ParameterBinding
  GlobalParameters::binding()
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
    ParameterBinding b("");
    b.add("Problem",
          problem,
          documentation,
          dealii::Patterns::Selection(names));
    b.add("Output directory",
          output_directory,
          "Directory receiving every output of the run (created if missing; "
          "relative paths are relative to the working directory).");
    b.add("Progress interval",
          progress_interval,
          "Minimum wall time between two progress lines, in seconds.",
          dealii::Patterns::Double(0.));
    return b;
  }


  void
  GlobalParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    GlobalParameters defaults;
    // homogenization is the default when this build has it.
    bool has_default = false;
    for (const auto &p : registered_problems())
      has_default = has_default || p.name == defaults.problem;
    if (!has_default && !registered_problems().empty())
      defaults.problem = registered_problems().front().name;
    defaults.binding().declare(prm);
  }


  void
  GlobalParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    binding().parse(prm);
  }
} // namespace tribodyn
