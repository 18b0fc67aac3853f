// The bond breaking and bond formation criteria (seed 000 Sec. 2.1): one
// header each in bond_laws/, listed here once per family. The first law
// whose parameters choose it acts; the last, "none", is the default.
#ifndef tribodyn_mca_bond_laws_h
#define tribodyn_mca_bond_laws_h

#include <tribodyn/mca/bond_laws/none.h>
#include <tribodyn/mca/bond_laws/plastic_heat_formation.h>
#include <tribodyn/mca/bond_laws/von_mises_breaking.h>
#include <tribodyn/mca/switched_law_list.h>

namespace tribodyn
{
  namespace mca
  {
    using BondBreakingLaws
      = SwitchedLawList<VonMisesBondBreaking, NoBondBreaking>;
    using BondFormationLaws
      = SwitchedLawList<PlasticHeatBondFormation, NoBondFormation>;
  } // namespace mca
} // namespace tribodyn

#endif
