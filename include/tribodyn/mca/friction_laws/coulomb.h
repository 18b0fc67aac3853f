// Amontons-Coulomb friction of unbonded pairs: |tau| <= mu |sigma| on each
// side of a pair, mu constant (seed 000, Sec. 2.1).
#ifndef tribodyn_mca_friction_laws_coulomb_h
#define tribodyn_mca_friction_laws_coulomb_h

#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <limits>
#include <tribodyn/core/errors.h>
#include <tribodyn/mca/pair_fields.h>

namespace tribodyn
{
  namespace mca
  {
    class Coulomb
    {
    public:
      static constexpr const char *name     = "Coulomb";
      static constexpr bool        stateful = false;

      struct Parameters
      {
        double mu = 0.3;

        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          prm.declare_entry("Friction coefficient",
                            "0.3",
                            dealii::Patterns::Double(),
                            "Amontons-Coulomb coefficient of unbonded pairs "
                            "(|tau| <= mu |sigma|), >= 0 (Friction law = "
                            "Coulomb).");
        }

        void
        parse_parameters(dealii::ParameterHandler &prm)
        {
          mu = prm.get_double("Friction coefficient");
          check_parameter_range("Interaction/Friction coefficient",
                                mu,
                                0,
                                std::numeric_limits<double>::infinity(),
                                false,
                                true);
        }
      };

      explicit Coulomb(const Parameters &p)
          : mu(p.mu)
      {
      }

      void
      register_pair_fields(PairFieldTable &, const std::function<bool()> &)
      {
      }

      void
      start_contact(const unsigned int)
      {
      }

      double
      coefficient() const
      {
        return mu;
      }

    private:
      double mu;
    };
  } // namespace mca
} // namespace tribodyn

#endif
