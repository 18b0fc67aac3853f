// Friction laws of unbonded pairs as policies (issue #17 items 1-2): the
// pair kernel is instantiated on the law a scene uses, chosen once per
// step in AutomatonSystem::evaluate_pairs(); the law's coefficient is an
// inline call in the kernel's loops, without run-time flags per pair.
//
// A law is a class with
//  - `static constexpr const char *name`: its name in `Interaction/Friction
//    law`;
//  - `struct Parameters` with `static declare_parameters(prm)` and
//    `parse_parameters(prm)` (called inside subsection Interaction: a law
//    with several constants declares a subsection of its own);
//  - a constructor from its Parameters;
//  - `static constexpr bool stateful`: whether it has a state per pair and
//    needs the slip rate of each contact;
//  - `register_pair_fields(table, in_use)`: its persistent pair fields
//    (carried over rebuilds, migration and checkpoints by PairFieldTable);
//  - `start_contact(p)`: pair p became a contact (it touched, or its bond
//    broke);
//  - stateful laws: `advance(p, slip_rate, dt)`: the state of contact p
//    over a step at its slip rate; returns the step's mu;
//  - laws without state: `coefficient()`: their mu.
// The kernel keeps what every law needs (the slip rate, mu of the step,
// the sides' shear stresses at the start of a step for the friction work).
// A new law is one header in include/tribodyn/mca/friction_laws/ and its
// name in the list of friction_laws.h.
#ifndef tribodyn_mca_friction_law_h
#define tribodyn_mca_friction_law_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <string>
#include <tribodyn/core/law_selection.h>
#include <tribodyn/core/selection.h>
#include <tribodyn/mca/chosen_law_list.h>
#include <tuple>
#include <utility>

namespace tribodyn
{
  namespace mca
  {
    /**
     * The friction laws a run may choose from, as a list of types, and
     * the one the parameters chose. Parameters holds every law's own
     * parameter struct; the list itself holds one object of each law (only
     * the chosen one allocates pair state).
     */
    template <class... Laws>
    class FrictionLawList : public ChosenLawList<Laws...>
    {
    public:
      using Selection                     = LawSelection<Laws...>;
      static constexpr std::size_t n_laws = Selection::n_laws;

      /// Names in Interaction/Friction law, by index.
      static SelectionTable<unsigned int, n_laws>
      table()
      {
        return Selection::table();
      }

      /// The choice (`Interaction/Friction law`) and every law's own
      /// parameters.
      struct Parameters : Selection::Parameters
      {
        /// The entry that chooses the law, in subsection Interaction.
        static constexpr const char *entry = "Friction law";

        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          Selection::Parameters::declare_parameters(
            prm,
            entry,
            table()[0].first,
            "Friction law of the unbonded pairs in contact "
            "(doc/theory/mca.md Sec. 5); each law's constants are in its "
            "own entries.");
        }

        void
        parse_parameters(dealii::ParameterHandler &prm)
        {
          Selection::Parameters::parse_parameters(prm, entry);
        }
      };

      explicit FrictionLawList(const Parameters &p)
          : ChosenLawList<Laws...>(p.selected, p.laws)
      {
      }
    };
  } // namespace mca
} // namespace tribodyn

#endif
