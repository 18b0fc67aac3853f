// Bond formation by plastic heat (seed 000 Sec. 2.1, doc/theory/mca.md
// Sec. 5): on with Interaction/Bond formation. An unbonded pair in contact,
// in compression at the yield stress, whose plastic heat (booked while it
// is unbonded) reaches a fraction (seed: one half) of its bond energy
// becomes bonded. A policy of the pair kernel (pair_law.h), called per
// unbonded contact by AutomatonSystem::bond_switching().
#ifndef tribodyn_mca_bond_laws_plastic_heat_formation_h
#define tribodyn_mca_bond_laws_plastic_heat_formation_h

#include <algorithm>
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
    class PlasticHeatBondFormation
    {
    public:
      static constexpr const char *name   = "plastic heat";
      static constexpr bool        active = true;

      struct Parameters : BoundLawParameters<Parameters>
      {
        bool on = false;
        /// Fraction of the bond-breaking energy the plastic heat of an
        /// unbonded pair must reach to bond (seed: one half).
        double heat_fraction = 0.5;

        ParameterBinding
        binding()
        {
          ParameterBinding e("", "Interaction");
          e.add("Bond formation",
                on,
                "Unbonded pairs in compression at the yield stress whose "
                "plastic heat reaches the fraction below of the bond energy "
                "become bonded.");
          e.add(
            "Bond formation heat fraction",
            heat_fraction,
            "Plastic heat of a pair needed to bond, as a fraction of its "
            "bond energy (seed: 1/2), >= 0.",
            dealii::Patterns::Double(),
            Interval{0, std::numeric_limits<double>::infinity(), false, true});
          return e;
        }
        bool
        chosen() const
        {
          return on;
        }
      };

      explicit PlasticHeatBondFormation(const Parameters &p)
          : heat_fraction(p.heat_fraction)
      {
      }
      void
      register_pair_fields(PairFieldTable &, const std::function<bool()> &)
      {
      }

      /// Does an unbonded contact bond? @p sn: its normal stress; @p sy_i,
      /// @p sy_j: the current yield stresses of its automata; @p heat: its
      /// plastic heat; @p w_b_i, @p w_b_j: the materials' bond energy
      /// densities; @p area, @p r: its contact area and distance.
      bool
      forms(const double sn,
            const double sy_i,
            const double sy_j,
            const double heat,
            const double w_b_i,
            const double w_b_j,
            const double area,
            const double r) const
      {
        const double sy = std::min(sy_i, sy_j);
        const double Eb = std::min(w_b_i, w_b_j) * area * r;
        return sn <= -sy && heat >= heat_fraction * Eb;
      }

    private:
      double heat_fraction;
    };
  } // namespace mca
} // namespace tribodyn

#endif
