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
            "(0, 0.5]. 0.5 is the limit of a uniform lattice; where an "
            "automaton is stiffer for its inertia than the lattice's (at a "
            "change of size: larger faces and relative-rotation moments), "
            "the scene allows less, and a larger factor is refused naming "
            "that limit (the log and summary.json's courant_limit give it; "
            "0.448 for the graded scenes at the seed's heights, "
            "doc/stability.md).",
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
