// Rate-and-state friction (Dieterich 1979, Ruina 1983), shared by the
// automata's unbonded pairs (mca, `Interaction/Rate and state friction`) and
// the contact pin's nodes (contact, `Contact/Rate and state friction`):
//
//   mu(V, theta) = mu0 + a ln(V / V0) + b ln(V0 theta / D_c),
//   aging law:     dtheta/dt = 1 - V theta / D_c,
//   slip law:      dtheta/dt = -(V theta / D_c) ln(V theta / D_c),
//
// V the slip rate, theta the state (the contact's age, s). Both laws have
// the steady state theta = D_c / V, so mu_ss(V) = mu0 + (a - b) ln(V / V0);
// after a step of V the state relaxes over the slip D_c. Below the minimum
// slip rate V_min the coefficient is taken at V_min (ln V -> -infinity at
// rest: a stuck contact has the static coefficient mu(V_min, theta), which
// grows with its age), and mu is kept >= 0. evolve() advances theta
// exactly for a slip rate constant over the step (no step limit of its
// own). doc/theory/mca.md Sec. 3 and doc/theory/contact.md Sec. 4.
#ifndef tribodyn_core_rate_state_h
#define tribodyn_core_rate_state_h

#include <algorithm>
#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <limits>
#include <string>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/selection.h>

namespace tribodyn
{
  namespace rate_state
  {
    /// The evolution law of the state.
    enum class StateLaw
    {
      aging, ///< Dieterich's: a contact at rest ages, theta' = 1
      slip   ///< Ruina's: the state evolves only with slip
    };
    inline constexpr SelectionTable<StateLaw, 2> state_law_choices{
      {{"aging", StateLaw::aging}, {"slip", StateLaw::slip}}};

    /// The constants of the law, declared in the caller's subsection.
    struct Parameters
    {
      double   mu0 = 0.3, a = 0.01, b = 0.005, V0 = 1, Dc = 1e-9, V_min = 1e-6;
      StateLaw state_law = StateLaw::aging;
      /// A new contact starts at the steady state of this slip rate.
      double V_initial = 1;

      /// Declare the entries in the current subsection; @p mu0, @p Dc:
      /// their defaults (the scale of the engine).
      static void
      declare_entries(dealii::ParameterHandler &prm,
                      const std::string        &mu0,
                      const std::string        &Dc)
      {
        using dealii::Patterns::Double;
        prm.declare_entry("Reference friction coefficient",
                          mu0,
                          Double(),
                          "mu0: the steady coefficient at the reference "
                          "slip rate.");
        prm.declare_entry("Direct effect",
                          "0.01",
                          Double(),
                          "a >= 0: the jump of mu per unit of ln V at a "
                          "step of the slip rate.");
        prm.declare_entry("Evolution effect",
                          "0.005",
                          Double(),
                          "b >= 0: the evolution of mu with the state; "
                          "a - b > 0 is velocity strengthening, a - b < 0 "
                          "velocity weakening.");
        prm.declare_entry("Reference slip rate",
                          "1",
                          Double(),
                          "V0 > 0 (m/s).");
        prm.declare_entry("Critical slip distance",
                          Dc,
                          Double(),
                          "D_c > 0 (m): the slip over which the state "
                          "relaxes to its new steady value.");
        prm.declare_entry("Minimum slip rate",
                          "1e-6",
                          Double(),
                          "V_min > 0 (m/s): below it mu is evaluated at "
                          "V_min (the static friction of a stuck contact, "
                          "which grows with its age theta under the aging "
                          "law).");
        prm.declare_entry("State evolution law",
                          "aging",
                          selection_pattern(state_law_choices),
                          "aging: dtheta/dt = 1 - V theta / D_c (a contact "
                          "at rest strengthens); slip: dtheta/dt = -(V theta "
                          "/ D_c) ln(V theta / D_c) (it evolves only with "
                          "slip).");
        prm.declare_entry("Initial slip rate",
                          "0",
                          Double(0),
                          "A new contact starts at the steady state of this "
                          "slip rate, theta = D_c / V (m/s); 0: the reference "
                          "slip rate.");
      }

      /// Declare the entries in the subsection @p name of the current one.
      static void
      declare_in(dealii::ParameterHandler &prm,
                 const std::string        &name,
                 const std::string        &mu0,
                 const std::string        &Dc)
      {
        prm.enter_subsection(name);
        declare_entries(prm, mu0, Dc);
        prm.leave_subsection();
      }

      /// Read them from the subsection @p name; @p path: as below.
      void
      parse_in(dealii::ParameterHandler &prm,
               const std::string        &name,
               const std::string        &path)
      {
        prm.enter_subsection(name);
        parse_entries(prm, path);
        prm.leave_subsection();
      }

      /// Read the entries of the current subsection; @p path (e.g.
      /// "Interaction/Rate and state friction/") names them in errors.
      void
      parse_entries(dealii::ParameterHandler &prm, const std::string &path)
      {
        mu0   = prm.get_double("Reference friction coefficient");
        a     = prm.get_double("Direct effect");
        b     = prm.get_double("Evolution effect");
        V0    = prm.get_double("Reference slip rate");
        Dc    = prm.get_double("Critical slip distance");
        V_min = prm.get_double("Minimum slip rate");
        state_law
          = get_selection(prm, "State evolution law", state_law_choices);
        V_initial        = prm.get_double("Initial slip rate");
        const double inf = std::numeric_limits<double>::infinity();
        check_parameter_range(
          path + "Reference friction coefficient", mu0, 0, inf, false, true);
        check_parameter_range(path + "Direct effect", a, 0, inf, false, true);
        check_parameter_range(
          path + "Evolution effect", b, 0, inf, false, true);
        check_parameter_range(
          path + "Reference slip rate", V0, 0, inf, true, true);
        check_parameter_range(
          path + "Critical slip distance", Dc, 0, inf, true, true);
        check_parameter_range(
          path + "Minimum slip rate", V_min, 0, inf, true, true);
        if (V_initial == 0)
          V_initial = V0;
      }
    };

    /// The law's functions for one set of constants.
    class Law
    {
    public:
      explicit Law(const Parameters &p)
          : prm(p)
          , theta_new(p.Dc / p.V_initial)
          , mu_shift(p.mu0 - p.a * std::log(p.V0) + p.b * std::log(p.V0 / p.Dc))
      {
      }

      /// The state of a new contact.
      double
      initial_state() const
      {
        return theta_new;
      }

      /// theta after @p dt at the slip rate @p V, constant over the step.
      double
      evolve(const double theta, const double V, const double dt) const
      {
        const double x = V * dt / prm.Dc;
        if (prm.state_law == StateLaw::aging)
          {
            // theta' = theta e^-x + (D_c / V)(1 - e^-x); (1 - e^-x) / x ->
            // 1 at rest (theta' = theta + dt: aging)
            const double one = -std::expm1(-x);
            return theta * (1 - one) + dt * (x > 0 ? one / x : 1.);
          }
        // ln(V theta / D_c) decays as e^-x: theta' = theta exp(phi (e^-x
        // - 1)), phi = ln(V theta / D_c); at rest theta' = theta
        if (!(V > 0))
          return theta;
        return theta * std::exp(std::log(V * theta / prm.Dc) * std::expm1(-x));
      }

      /// mu at the slip rate @p V and the state @p theta.
      double
      mu(const double V, const double theta) const
      {
        return std::max(0.,
                        mu_shift + prm.a * std::log(std::max(V, prm.V_min))
                          + prm.b * std::log(theta));
      }

      /// The steady coefficient mu0 + (a - b) ln(V / V0) (V >= V_min).
      double
      steady_mu(const double V) const
      {
        return mu(V, prm.Dc / V);
      }

      const Parameters &
      parameters() const
      {
        return prm;
      }

    private:
      Parameters prm;
      /// State of a new contact: the steady state at V_initial.
      double theta_new;
      /// mu0 - a ln V0 + b ln(V0 / D_c): mu = mu_shift + a ln V + b ln theta
      double mu_shift;
    };
  } // namespace rate_state
} // namespace tribodyn

#endif
