// A family of pair-law policies that the scene's own parameters switch on
// (issue #17 item 1): the relative-rotation moment (on when its stiffness
// is > 0), bond breaking and bond formation (on when their `Bond breaking`,
// `Bond formation` entries say so). Unlike the friction laws, which the
// user chooses by name (FrictionLawList), such a family has no entry of
// its own: each law declares and parses its own entries, and the chosen
// law is the first of the list whose parameters say `chosen()`; the last
// law of a list (a "none" law, chosen always) is the fallback.
//
// A law of such a family is a class with
//  - `static constexpr const char *name` (reports);
//  - `static constexpr bool active`: false for the "none" law, whose
//    calls the kernel then compiles away with `if constexpr`;
//  - `struct Parameters` with `static declare_parameters(prm)`,
//    `parse_parameters(prm)` (inside subsection Interaction) and
//    `bool chosen() const`;
//  - a constructor from its Parameters;
//  - `register_pair_fields(table, in_use)`: its persistent pair fields;
//  - the inline calls of its family (see pair_law.h).
#ifndef tribodyn_mca_switched_law_list_h
#define tribodyn_mca_switched_law_list_h

#include <deal.II/base/parameter_handler.h>
#include <tribodyn/core/law_selection.h>
#include <tribodyn/mca/chosen_law_list.h>
#include <tuple>
#include <utility>

namespace tribodyn
{
  namespace mca
  {
    /// The parameters of a law that is the fallback of its family (no
    /// entries, chosen when no other law is).
    struct AlwaysChosen : NoLawParameters
    {
      bool
      chosen() const
      {
        return true;
      }
    };

    template <class... Laws>
    class SwitchedLawList : public ChosenLawList<Laws...>
    {
    public:
      using Selection = LawSelection<Laws...>;

      /// Every law's own parameters; the chosen law follows from them.
      struct Parameters
      {
        std::tuple<typename Laws::Parameters...> laws;

        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          (Laws::Parameters::declare_parameters(prm), ...);
        }

        void
        parse_parameters(dealii::ParameterHandler &prm)
        {
          std::apply([&](auto &...p) { (p.parse_parameters(prm), ...); }, laws);
        }

        /// Index in Laws of the first law whose parameters choose it.
        unsigned int
        selected() const
        {
          return first_chosen(std::index_sequence_for<Laws...>());
        }

        template <class Law>
        typename Law::Parameters &
        get()
        {
          return std::get<Selection::template index_of<Law>()>(laws);
        }
        template <class Law>
        const typename Law::Parameters &
        get() const
        {
          return std::get<Selection::template index_of<Law>()>(laws);
        }

        /// Is @p Law the chosen one?
        template <class Law>
        bool
        is() const
        {
          return selected() == Selection::template index_of<Law>();
        }

        /// Does the chosen law act (is it not its family's "none" law)?
        bool
        active() const
        {
          const bool on[] = {Laws::active...};
          return on[selected()];
        }

        /// The chosen law's name.
        const char *
        selected_name() const
        {
          return Selection::name(selected());
        }

      private:
        template <std::size_t... I>
        unsigned int
        first_chosen(std::index_sequence<I...>) const
        {
          const bool chosen[] = {std::get<I>(laws).chosen()...};
          for (unsigned int k = 0; k < sizeof...(I); ++k)
            if (chosen[k])
              return k;
          return sizeof...(I) - 1;
        }
      };

      explicit SwitchedLawList(const Parameters &p)
          : ChosenLawList<Laws...>(p.selected(), p.laws)
      {
      }
    };
  } // namespace mca
} // namespace tribodyn

#endif
