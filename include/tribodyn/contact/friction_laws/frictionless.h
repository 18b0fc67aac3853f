// Contact friction law "frictionless": no tangential force.
#ifndef tribodyn_contact_friction_laws_frictionless_h
#define tribodyn_contact_friction_laws_frictionless_h

#include <tribodyn/contact/friction_law.h>

namespace tribodyn
{
  namespace contact
  {
    struct Frictionless : FrictionLawBase
    {
      static constexpr const char *name = "frictionless";

      using Parameters = NoLawParameters;

      template <class ContactLawParameters>
      Frictionless(const ContactLawParameters &, const Parameters &, double)
      {
      }

      double
      tangential(const ContactNode &,
                 const double,
                 const double,
                 ContactStatus &status) const
      {
        status = slip;
        return 0.;
      }
    };
  } // namespace contact
} // namespace tribodyn

#endif
