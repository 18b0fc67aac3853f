// Amontons-Coulomb friction of unbonded pairs: |tau| <= mu |sigma| on each
// side of a pair, mu constant (seed 000, Sec. 2.1).
#ifndef tribodyn_mca_friction_laws_coulomb_h
#define tribodyn_mca_friction_laws_coulomb_h

#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <limits>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/law_selection.h>
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

      struct Parameters : BoundLawParameters<Parameters>
      {
        double mu = 0.3;

        ParameterBinding
        binding()
        {
          ParameterBinding e("", "Interaction");
          e.add(
            "Friction coefficient",
            mu,
            "Amontons-Coulomb coefficient of unbonded pairs (|tau| <= mu "
            "|sigma|), >= 0 (Friction law = Coulomb).",
            dealii::Patterns::Double(),
            Interval{0, std::numeric_limits<double>::infinity(), false, true});
          return e;
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
