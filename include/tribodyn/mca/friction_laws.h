// The friction laws of unbonded pairs a run can choose (Interaction/
// Friction law): one header each in friction_laws/, listed here once.
#ifndef tribodyn_mca_friction_laws_h
#define tribodyn_mca_friction_laws_h

#include <tribodyn/mca/friction_law.h>
#include <tribodyn/mca/friction_laws/coulomb.h>
#include <tribodyn/mca/friction_laws/rate_and_state.h>

namespace tribodyn
{
  namespace mca
  {
    /// The first is the default.
    using FrictionLaws = FrictionLawList<Coulomb, RateAndState>;
  } // namespace mca
} // namespace tribodyn

#endif
