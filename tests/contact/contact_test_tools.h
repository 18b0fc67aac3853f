#ifndef tribodyn_tests_contact_tools_h
#define tribodyn_tests_contact_tools_h

#include "../test_utilities.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <memory>
#include <string>
#include <tribodyn/contact/contact_parameters.h>
#include <tribodyn/contact/contact_solver.h>

namespace tribodyn_test
{
  using namespace tribodyn;
  using namespace tribodyn::contact;

  /// Contact parameters: the defaults overridden by @p prm_text (a piece of
  /// parameter file), parsed exactly as tribodyn parses a .prm.
  inline ContactParameters
  contact_parameters(const std::string &prm_text)
  {
    dealii::ParameterHandler prm;
    ContactParameters::declare_parameters(prm);
    prm.parse_input_from_string(prm_text);
    ContactParameters p;
    p.parse_parameters(prm);
    return p;
  }

  /// A set-up solver with its parameters and a silent timer.
  struct ContactRun
  {
    ContactParameters                    parameters;
    std::unique_ptr<dealii::TimerOutput> timer;
    std::unique_ptr<ContactSolver>       solver;

    ContactRun(const std::string &prm_text,
               const MPI_Comm     comm = MPI_COMM_WORLD)
        : parameters(contact_parameters(prm_text))
        , timer(std::make_unique<dealii::TimerOutput>(
            comm,
            std::cout,
            dealii::TimerOutput::never,
            dealii::TimerOutput::wall_times))
        , solver(std::make_unique<ContactSolver>(comm, parameters, *timer))
    {
      solver->setup();
    }

    /// Integrate without files or progress lines.
    const std::vector<Sample> &
    run()
    {
      solver->run("", -1);
      return solver->samples();
    }
  };
} // namespace tribodyn_test

#endif
