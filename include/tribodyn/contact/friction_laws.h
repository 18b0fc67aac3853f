// The friction laws of the contact pin (`Contact/Friction law`): one header
// each in friction_laws/, listed here once.
#ifndef tribodyn_contact_friction_laws_h
#define tribodyn_contact_friction_laws_h

#include <tribodyn/contact/friction_laws/coulomb.h>
#include <tribodyn/contact/friction_laws/frictionless.h>
#include <tribodyn/contact/friction_laws/rate_and_state.h>
#include <tribodyn/contact/friction_laws/regularized.h>
#include <tribodyn/contact/friction_laws/tabulated.h>

namespace tribodyn
{
  namespace contact
  {
    /// The first is the default.
    using FrictionLaws = FrictionLawList<Regularized,
                                         Frictionless,
                                         Coulomb,
                                         Tabulated,
                                         RateAndState>;
  } // namespace contact
} // namespace tribodyn

#endif
