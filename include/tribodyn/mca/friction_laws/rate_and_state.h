// Dieterich's rate-and-state friction of unbonded pairs (Dieterich 1979,
// Ruina 1983; seed 000 names it beside Amontons' law), doc/theory/mca.md
// Sec. 3: the law of core/rate_state.h,
//
//   mu(V, theta) = mu0 + a ln(V / V0) + b ln(V0 theta / D_c),
//
// with the aging (default) or slip law of the state, V the slip rate of
// the contact (the relative tangential speed of the two contact points),
// theta the contact's state. In steady sliding mu_ss(V) = mu0 + (a - b)
// ln(V / V0); after a step of V the state relaxes over the slip length
// D_c. The state is advanced exactly for a slip rate constant over the
// step, per pair, and carried with the pair (PairFieldTable: rebuilds,
// migration, checkpoints).
#ifndef tribodyn_mca_friction_laws_rate_and_state_h
#define tribodyn_mca_friction_laws_rate_and_state_h

#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <tribodyn/core/law_selection.h>
#include <tribodyn/core/rate_state.h>
#include <tribodyn/mca/pair_fields.h>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    class RateAndState
    {
    public:
      static constexpr const char *name     = "rate and state";
      static constexpr bool        stateful = true;

      /// Subsection `Rate and state friction` of Interaction.
      struct Parameters : rate_state::Parameters, BoundLawParameters<Parameters>
      {
        ParameterBinding
        binding()
        {
          return rate_state::Parameters::binding("Interaction");
        }
      };

      explicit RateAndState(const Parameters &p)
          : law(p)
      {
      }

      void
      register_pair_fields(PairFieldTable              &table,
                           const std::function<bool()> &in_use)
      {
        // the state of a contact: the same seen from either side
        table.add({"rate_state_theta",
                   Relabel::even,
                   law.initial_state(),
                   {&theta},
                   nullptr,
                   in_use,
                   {}});
      }

      void
      start_contact(const unsigned int p)
      {
        theta[p] = law.initial_state();
      }

      /// The state of contact @p p over a step @p dt at slip rate @p V
      /// (exact for V constant over the step); returns the step's mu.
      double
      advance(const unsigned int p, const double V, const double dt)
      {
        theta[p] = law.evolve(theta[p], V, dt);
        return law.mu(V, theta[p]);
      }

    private:
      rate_state::Law law;
      /// State theta of each pair (persistent).
      std::vector<double> theta;
    };
  } // namespace mca
} // namespace tribodyn

#endif
