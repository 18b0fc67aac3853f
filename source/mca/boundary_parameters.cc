// Parameters of the boundary groups (constraints, loads, damping).

#include "parameter_tools.h"

#include <cmath>
#include <deal.II/base/patterns.h>
#include <limits>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/selection.h>
#include <tribodyn/mca/parameters.h>

namespace tribodyn
{
  namespace mca
  {
    using dealii::ParameterHandler;
    using dealii::Patterns::Double;
    namespace Patterns = dealii::Patterns;

    using namespace parameter_tools;

    ParameterBinding
    BoundaryParameters::binding()
    {
      ParameterBinding b("Boundary conditions");
      b.add(
        "Groups",
        "",
        "Groups of automata with a boundary condition, separated by ';': "
        "'NAME TYPE x0 y0 z0 x1 y1 z1 [v1 v2 v3] [then T w1 w2 w3]'. "
        "Automata whose centre lies in the box belong to the group (an "
        "automaton may belong to several). TYPE: fixed (velocity zero), "
        "velocity (prescribed velocity components v, '*' leaves one "
        "free), force (total force v on the group; the group moves as a "
        "rigid loading plate under it and its reaction), damping (F = -v_k m "
        "u_k per component, coefficients in 1/s). "
        "'then T w' switches to the value w at time T (ramped smoothly "
        "over the ramp time); 'then contact w' switches when the two "
        "bodies first touch (an unbonded pair in contact). A component "
        "given before 'then' may be '*' after it: it is released at the "
        "switch.",
        Patterns::Anything(),
        [this, p = b.path("Groups")](const std::string &text) {
          parse_groups(text, p);
        });
      b.add("Ramp time",
            ramp_time,
            "Prescribed velocities and forces rise smoothly (C1, 3s^2 - 2s^3) "
            "from zero over this time (s).",
            Double(),
            Interval{0, inf, false, true});
      b.add("Global damping",
            global_damping,
            "Viscous damping of every automaton, F = -c m v (1/s), >= 0.",
            Double(),
            Interval{0, inf, false, true});
      return b;
    }


    void
    BoundaryParameters::declare_parameters(ParameterHandler &prm)
    {
      BoundaryParameters().binding().declare(prm);
    }


    void
    BoundaryParameters::parse_parameters(ParameterHandler &prm)
    {
      binding().parse(prm);
    }


    void
    BoundaryParameters::parse_groups(const std::string &text,
                                     const std::string &p)
    {
      groups.clear();
      for (const std::string &entry : split(text, ';'))
        {
          const auto    t = tokens(entry);
          BoundaryGroup g;
          if (t.size() < 8)
            throw InputError("Parameter '" + p + "': the entry '" + entry
                             + "' must read 'NAME TYPE x0 y0 z0 x1 y1 z1 "
                               "[v1 v2 v3] [then T w1 w2 w3]'.");
          g.name = t[0];
          for (const auto &other : groups)
            check_parameter(other.name != g.name,
                            p,
                            "the group name '" + g.name + "' is used twice.");
          const SelectionTable<BoundaryGroup::Type, 4> types{
            {{"fixed", BoundaryGroup::Type::fixed},
             {"velocity", BoundaryGroup::Type::velocity},
             {"force", BoundaryGroup::Type::force},
             {"damping", BoundaryGroup::Type::damping}}};
          const auto *type = find_selection(types, t[1]);
          if (type == nullptr)
            throw InputError("Parameter '" + p + "': unknown type '" + t[1]
                             + "' in '" + entry + "'; use "
                             + selection_choices(types) + ".");
          g.type  = *type;
          g.lower = read_point(t, 2, p, entry);
          g.upper = read_point(t, 5, p, entry);
          const std::size_t expected
            = g.type == BoundaryGroup::Type::fixed ? 8 : 11;
          if (t.size() != expected && t.size() != expected + 5)
            throw InputError("Parameter '" + p + "': the entry '" + entry
                             + "' has " + std::to_string(t.size())
                             + " fields; type " + t[1] + " takes "
                             + std::to_string(expected)
                             + " (or 5 more with 'then T w1 w2 w3').");
          if (expected == 11)
            for (unsigned int d = 0; d < 3; ++d)
              g.value[d] = to_double(t[8 + d], p, entry);
          if (g.type == BoundaryGroup::Type::damping
              || g.type == BoundaryGroup::Type::force)
            for (unsigned int d = 0; d < 3; ++d)
              check_parameter(!std::isnan(g.value[d]),
                              p,
                              "'*' is only allowed for velocity groups ('"
                                + entry + "').");
          if (g.type == BoundaryGroup::Type::damping)
            for (unsigned int d = 0; d < 3; ++d)
              check_parameter(g.value[d] >= 0,
                              p,
                              "damping coefficients must be >= 0 ('" + entry
                                + "').");
          if (t.size() == expected + 5)
            {
              check_parameter(t[expected] == "then",
                              p,
                              "expected 'then' in '" + entry + "'.");
              g.switch_on_contact = t[expected + 1] == "contact";
              g.switch_time       = g.switch_on_contact
                                      ? 0
                                      : to_double(t[expected + 1], p, entry);
              for (unsigned int d = 0; d < 3; ++d)
                g.second_value[d] = to_double(t[expected + 2 + d], p, entry);
              // A component may be released at the switch (prescribed
              // before, '*' after), not taken over (its value before
              // the switch would be unknown).
              for (unsigned int d = 0; d < 3; ++d)
                check_parameter(!std::isnan(g.value[d])
                                  || std::isnan(g.second_value[d]),
                                p,
                                "a component free ('*') before 'then' must "
                                "stay free after it ('"
                                  + entry + "').");
            }
          groups.push_back(g);
        }
      check_parameter(groups.size() <= 32, p, "at most 32 groups.");
    }


  } // namespace mca
} // namespace tribodyn
