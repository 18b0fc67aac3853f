// What every list of pair-law policies holds once its parameters have
// chosen (issue #17 item 1): one object of each law, the chosen one's
// index, and the calls on it. FrictionLawList (chosen by name) and
// SwitchedLawList (chosen by the laws' own parameters) add only how they
// choose.
#ifndef tribodyn_mca_chosen_law_list_h
#define tribodyn_mca_chosen_law_list_h

#include <tribodyn/core/law_selection.h>
#include <tribodyn/mca/pair_fields.h>
#include <tuple>

namespace tribodyn
{
  namespace mca
  {
    template <class... Laws>
    class ChosenLawList
    {
    public:
      using Selection = LawSelection<Laws...>;

      /// Call @p f with the chosen law.
      template <class F>
      void
      with_selected(const F &f)
      {
        Selection::with_selected(selected, laws, f);
      }
      template <class F>
      void
      with_selected(const F &f) const
      {
        Selection::with_selected(selected, laws, f);
      }

      /// The law @p Law of the list (chosen or not).
      template <class Law>
      Law &
      get()
      {
        return std::get<Selection::template index_of<Law>()>(laws);
      }
      template <class Law>
      const Law &
      get() const
      {
        return std::get<Selection::template index_of<Law>()>(laws);
      }

      /// Does the chosen law act (is it not its family's "none" law)?
      bool
      active() const
      {
        const bool on[] = {Laws::active...};
        return on[selected];
      }

      /// Register every law's persistent pair fields, in use only for the
      /// chosen one (the checkpoint layout is the same for every choice).
      void
      register_pair_fields(PairFieldTable &table)
      {
        register_law_pair_fields(table, laws, selected);
      }

    protected:
      /// The list of law @p chosen, each law made from its parameters in
      /// @p parameters (a tuple of the laws' Parameters).
      template <class ParameterTuple>
      ChosenLawList(const unsigned int chosen, const ParameterTuple &parameters)
          : selected(chosen)
          , laws(Laws(std::get<typename Laws::Parameters>(parameters))...)
      {
      }

    private:
      unsigned int        selected;
      std::tuple<Laws...> laws;
    };
  } // namespace mca
} // namespace tribodyn

#endif
