// No bond breaking, no bond formation (Interaction/Bond breaking and Bond
// formation false, the defaults): the bonds of the set-up stay as they are.
#ifndef tribodyn_mca_bond_laws_none_h
#define tribodyn_mca_bond_laws_none_h

#include <functional>
#include <tribodyn/mca/pair_fields.h>
#include <tribodyn/mca/switched_law_list.h>

namespace tribodyn
{
  namespace mca
  {
    class NoBondBreaking
    {
    public:
      static constexpr const char *name   = "none";
      static constexpr bool        active = false;
      using Parameters                    = AlwaysChosen;

      explicit NoBondBreaking(const Parameters &)
      {
      }
      void
      register_pair_fields(PairFieldTable &, const std::function<bool()> &)
      {
      }
    };

    class NoBondFormation
    {
    public:
      static constexpr const char *name   = "none";
      static constexpr bool        active = false;
      using Parameters                    = AlwaysChosen;

      explicit NoBondFormation(const Parameters &)
      {
      }
      void
      register_pair_fields(PairFieldTable &, const std::function<bool()> &)
      {
      }
    };
  } // namespace mca
} // namespace tribodyn

#endif
