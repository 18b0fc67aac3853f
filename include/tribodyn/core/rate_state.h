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
#include <tribodyn/core/parameter_binding.h>
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

    /// The constants of the law, in the subsection `Rate and state
    /// friction` of an engine's (the engine's law sets the defaults of mu0
    /// and D_c, its scale, in its constructor).
    struct Parameters
    {
      double   mu0 = 0.3, a = 0.01, b = 0.005, V0 = 1, Dc = 1e-9, V_min = 1e-6;
      StateLaw state_law = StateLaw::aging;
      /// A new contact starts at the steady state of this slip rate (0:
      /// V0).
      double V_initial = 0;

      /// The entries, each written once, in the subsection `Rate and state
      /// friction` of @p outer (the engine's subsection, which the handler
      /// is in when they are declared and read).
      ParameterBinding
      binding(const std::string &outer)
      {
        using dealii::Patterns::Double;
        const double     inf = std::numeric_limits<double>::infinity();
        ParameterBinding e("Rate and state friction", outer);
        e.add("Reference friction coefficient",
              mu0,
              "mu0: the steady coefficient at the reference slip rate.",
              Double(),
              Interval{0, inf, false, true});
        e.add("Direct effect",
              a,
              "a >= 0: the jump of mu per unit of ln V at a step of the slip "
              "rate.",
              Double(),
              Interval{0, inf, false, true});
        e.add_spelled(
          "Evolution effect",
          b,
          "0.005",
          "b >= 0: the evolution of mu with the state; a - b > 0 is "
          "velocity strengthening, a - b < 0 velocity weakening.",
          Double(),
          Interval{0, inf, false, true});
        e.add("Reference slip rate",
              V0,
              "V0 > 0 (m/s).",
              Double(),
              Interval{0, inf, true, true});
        e.add("Critical slip distance",
              Dc,
              "D_c > 0 (m): the slip over which the state relaxes to its new "
              "steady value.",
              Double(),
              Interval{0, inf, true, true});
        e.add("Minimum slip rate",
              V_min,
              "V_min > 0 (m/s): below it mu is evaluated at V_min (the static "
              "friction of a stuck contact, which grows with its age theta "
              "under the aging law).",
              Double(),
              Interval{0, inf, true, true});
        e.add("State evolution law",
              state_law,
              "aging: dtheta/dt = 1 - V theta / D_c (a contact at rest "
              "strengthens); slip: dtheta/dt = -(V theta / D_c) ln(V theta / "
              "D_c) (it evolves only with slip).",
              state_law_choices);
        e.add("Initial slip rate",
              V_initial,
              "A new contact starts at the steady state of this slip rate, "
              "theta = D_c / V (m/s); 0: the reference slip rate.",
              Double(0));
        return e;
      }
    };

    /// The law's functions for one set of constants.
    class Law
    {
    public:
      explicit Law(const Parameters &p)
          : prm(p)
          , theta_new(p.Dc / (p.V_initial > 0 ? p.V_initial : p.V0))
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
