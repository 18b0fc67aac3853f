// Dieterich's rate-and-state friction of unbonded pairs (Dieterich 1979,
// Ruina 1983; seed 000 names it beside Amontons' law), with the aging law
// of the state (doc/theory/mca.md Sec. 3):
//
//   mu(V, theta)   = mu0 + a ln(V / V0) + b ln(V0 theta / D_c),
//   dtheta/dt      = 1 - V theta / D_c,
//
// V the slip rate of the contact (the relative tangential speed of the
// two contact points), theta the contact's state (its age, s). In steady
// sliding theta = D_c / V and mu_ss(V) = mu0 + (a - b) ln(V / V0); after a
// step of V the state relaxes over the slip length D_c. Below `Minimum slip
// rate` the coefficient is taken at that rate (ln V -> -infinity at rest);
// mu is kept >= 0. The state is advanced exactly for a slip rate constant
// over the step (no step limit of its own), per pair, and carried with the
// pair (PairFieldTable: rebuilds, migration, checkpoints).
#ifndef tribodyn_mca_friction_laws_dieterich_h
#define tribodyn_mca_friction_laws_dieterich_h

#include <algorithm>
#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <limits>
#include <tribodyn/core/errors.h>
#include <tribodyn/mca/pair_fields.h>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    class Dieterich
    {
    public:
      static constexpr const char *name     = "Dieterich";
      static constexpr bool        stateful = true;

      struct Parameters
      {
        double mu0 = 0.3, a = 0.01, b = 0.005, V0 = 1, Dc = 1e-9, V_min = 1e-6;

        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          using dealii::Patterns::Double;
          prm.enter_subsection("Dieterich");
          prm.declare_entry("Reference friction coefficient",
                            "0.3",
                            Double(),
                            "mu0: the steady coefficient at the reference "
                            "slip rate (Friction law = Dieterich).");
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
                            "1e-9",
                            Double(),
                            "D_c > 0 (m): the slip over which the state "
                            "relaxes to its new steady value. A new contact "
                            "starts at the steady state of V0, theta = "
                            "D_c / V0.");
          prm.declare_entry("Minimum slip rate",
                            "1e-6",
                            Double(),
                            "V_min > 0 (m/s): below it mu is evaluated at "
                            "V_min (the static friction of a stuck contact, "
                            "which grows with its age theta).");
          prm.leave_subsection();
        }

        void
        parse_parameters(dealii::ParameterHandler &prm)
        {
          prm.enter_subsection("Dieterich");
          mu0   = prm.get_double("Reference friction coefficient");
          a     = prm.get_double("Direct effect");
          b     = prm.get_double("Evolution effect");
          V0    = prm.get_double("Reference slip rate");
          Dc    = prm.get_double("Critical slip distance");
          V_min = prm.get_double("Minimum slip rate");
          prm.leave_subsection();
          const double      inf  = std::numeric_limits<double>::infinity();
          const std::string path = "Interaction/Dieterich/";
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
        }
      };

      explicit Dieterich(const Parameters &p)
          : prm(p)
          , theta_new(p.Dc / p.V0)
          , mu_shift(p.mu0 - p.a * std::log(p.V0) + p.b * std::log(p.V0 / p.Dc))
      {
      }

      void
      register_pair_fields(PairFieldTable              &table,
                           const std::function<bool()> &in_use)
      {
        // the state of a contact: the same seen from either side
        table.add({"rate_state_theta",
                   Relabel::even,
                   theta_new,
                   {&theta},
                   nullptr,
                   in_use,
                   {}});
      }

      void
      start_contact(const unsigned int p)
      {
        theta[p] = theta_new;
      }

      /// The state of contact @p p over a step @p dt at slip rate @p V
      /// (exact for V constant over the step); returns the step's mu.
      double
      advance(const unsigned int p, const double V, const double dt)
      {
        // theta' = theta e^-x + (D_c / V)(1 - e^-x), x = V dt / D_c;
        // (1 - e^-x) / x -> 1 at rest (theta' = theta + dt: aging)
        const double x   = V * dt / prm.Dc;
        const double one = -std::expm1(-x);
        const double t   = theta[p] * (1 - one) + dt * (x > 0 ? one / x : 1.);
        theta[p]         = t;
        return std::max(0.,
                        mu_shift + prm.a * std::log(std::max(V, prm.V_min))
                          + prm.b * std::log(t));
      }

    private:
      Parameters prm;
      /// State of a new contact: the steady state at V0.
      double theta_new;
      /// mu0 - a ln V0 + b ln(V0 / D_c): mu = mu_shift + a ln V + b ln theta
      double mu_shift;
      /// State theta of each pair (persistent).
      std::vector<double> theta;
    };
  } // namespace mca
} // namespace tribodyn

#endif
