// Subsection "Time" of the automata engine: how long and with which step.

#include "parameter_tools.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>
#include <tribodyn/mca/parameters.h>

namespace tribodyn
{
  namespace mca
  {
    using dealii::ParameterHandler;
    using dealii::Patterns::Double;
    using namespace parameter_tools;

    void
    TimeParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      {
        prm.declare_entry("End time",
                          "1e-6",
                          Double(),
                          "Simulated time (s), > 0.");
        prm.declare_entry("Time step",
                          "0",
                          Double(),
                          "Time step (s). 0 chooses Courant factor * "
                          "d_min / c_p,max. A larger step than 0.5 d_min / "
                          "c_p,max (the sound-crossing time of the "
                          "smallest automaton) is refused.");
        prm.declare_entry("Courant factor",
                          "0.2",
                          Double(),
                          "alpha in dt = alpha d_min / c_p,max when the "
                          "time step is 0; in (0, 0.5].");
      }
      prm.leave_subsection();
    }


    void
    TimeParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      {
        end_time  = prm.get_double("End time");
        time_step = prm.get_double("Time step");
        courant   = prm.get_double("Courant factor");
        check_parameter_range("Time/End time", end_time, 0, inf, true, true);
        check_parameter_range("Time/Time step", time_step, 0, inf, false, true);
        check_parameter_range("Time/Courant factor",
                              courant,
                              0,
                              max_courant,
                              true,
                              false,
                              "The time step must stay below the "
                              "sound-crossing time of an automaton.");
      }
      prm.leave_subsection();
    }
  } // namespace mca
} // namespace tribodyn
