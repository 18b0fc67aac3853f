// Subsection "Time" of the automata engine: how long and with which step.

#include "parameter_tools.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/mca/parameters.h>

namespace tribodyn
{
  namespace mca
  {
    using dealii::ParameterHandler;
    using dealii::Patterns::Double;
    using namespace parameter_tools;

    ParameterBinding
    TimeParameters::binding()
    {
      ParameterBinding b("Time");
      b.add("End time",
            end_time,
            "Simulated time (s), > 0.",
            Double(),
            Interval{0, inf, true, true});
      b.add("Time step",
            time_step,
            "Time step (s). 0 chooses Courant factor * d_min / c_p,max. A "
            "larger step than 0.5 d_min / c_p,max (the sound-crossing time "
            "of the smallest automaton) is refused.",
            Double(),
            Interval{0, inf, false, true});
      b.add("Courant factor",
            courant,
            "alpha in dt = alpha d_min / c_p,max when the time step is 0; in "
            "(0, 0.5]. 0.5 is the limit of a uniform lattice: the graded "
            "friction scenes at the seed's heights "
            "(prm/mca/friction_seed_heights_*.prm) left their symmetric "
            "state after 3 ns at 0.5 and stayed in it at 0.35 and 0.42 "
            "(doc/performance.md).",
            Double(),
            Interval{0,
                     max_courant,
                     true,
                     false,
                     "The time step must stay below the sound-crossing time "
                     "of an automaton."});
      return b;
    }


    void
    TimeParameters::declare_parameters(ParameterHandler &prm)
    {
      TimeParameters().binding().declare(prm);
    }


    void
    TimeParameters::parse_parameters(ParameterHandler &prm)
    {
      binding().parse(prm);
    }
  } // namespace mca
} // namespace tribodyn
