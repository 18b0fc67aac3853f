// The friction laws of unbonded pairs a run can choose (Interaction/
// Friction law): one header each in friction_laws/, listed here once.
#ifndef tribodyn_mca_friction_laws_h
#define tribodyn_mca_friction_laws_h

#include <tribodyn/mca/friction_law.h>
#include <tribodyn/mca/friction_laws/amontons_coulomb.h>
#include <tribodyn/mca/friction_laws/dieterich.h>

namespace tribodyn
{
  namespace mca
  {
    /// The first is the default.
    using FrictionLaws = FrictionLawList<AmontonsCoulomb, Dieterich>;
  } // namespace mca
} // namespace tribodyn

#endif
