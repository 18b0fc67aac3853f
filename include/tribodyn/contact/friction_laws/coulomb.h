// Contact friction law "Coulomb": |tau| <= mu |sigma|, slip at mu |sigma|
// (`Contact/Friction coefficient`).
#ifndef tribodyn_contact_friction_laws_coulomb_h
#define tribodyn_contact_friction_laws_coulomb_h

#include <tribodyn/contact/friction_law.h>

namespace tribodyn
{
  namespace contact
  {
    struct Coulomb : FrictionLawBase
    {
      static constexpr const char *name = "Coulomb";

      /// (its Friction coefficient is an entry of Contact)
      using Parameters = NoLawParameters;

      template <class ContactLawParameters>
      Coulomb(const ContactLawParameters &contact, const Parameters &, double)
          : mu(contact.friction_coefficient)
      {
      }

      /// Stick while the trial is within the cone, else slip at its edge.
      double
      tangential(const ContactNode &,
                 const double   trial,
                 const double   lambda_n,
                 ContactStatus &status) const
      {
        return coulomb_tangential(trial, mu * lambda_n, status);
      }

      double mu;
    };
  } // namespace contact
} // namespace tribodyn

#endif
