#include <algorithm>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/problem.h>

namespace tribodyn
{
  namespace
  {
    /// Function-local static: safe to use from other translation units'
    /// static initializers (no initialization-order fiasco).
    std::vector<ProblemDescription> &
    problem_list()
    {
      static std::vector<ProblemDescription> problems;
      return problems;
    }
  } // namespace


  bool
  register_problem(const ProblemDescription &description)
  {
    auto &problems = problem_list();
    problems.push_back(description);
    std::sort(problems.begin(),
              problems.end(),
              [](const ProblemDescription &a, const ProblemDescription &b) {
                return a.name < b.name;
              });
    return true;
  }


  const std::vector<ProblemDescription> &
  registered_problems()
  {
    return problem_list();
  }


  const ProblemDescription &
  find_problem(const std::string &name)
  {
    std::string known;
    for (const auto &p : registered_problems())
      {
        if (p.name == name)
          return p;
        known += (known.empty() ? "" : ", ") + p.name;
      }
    throw InputError("Unknown problem '" + name
                     + "'. The problems this build knows are: " + known + ".");
  }
} // namespace tribodyn
