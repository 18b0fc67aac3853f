// Contact friction law "regularized": the simplified Prakash-Clifton law
// of seed 001 eq. (4): during slip tau relaxes towards alpha mu |sigma|
// with the time constant t* = L*/|V| (`Contact/Regularization time`,
// `Regularization rate`, `State on re-contact`; doc/theory/contact.md).
#ifndef tribodyn_contact_friction_laws_regularized_h
#define tribodyn_contact_friction_laws_regularized_h

#include <tribodyn/contact/friction_law.h>

namespace tribodyn
{
  namespace contact
  {
    struct Regularized : FrictionLawBase
    {
      static constexpr const char *name = "regularized";

      /// (its entries are in Contact: Friction coefficient, Regularization
      /// time, Regularization rate, State on re-contact)
      using Parameters = NoLawParameters;

      template <class ContactLawParameters>
      Regularized(const ContactLawParameters &contact,
                  const Parameters &,
                  const double dt)
          : mu(contact.friction_coefficient)
          , regularization_time(contact.regularization_time)
          , rate(contact.regularization_rate)
          , recontact(contact.recontact_state)
          , decay_of_dt(std::exp(-dt / contact.regularization_time))
          , step_decay(decay_of_dt)
      {
      }

      /// The decay of the step for the plane's motion: exp(-dt/t*) with
      /// t* = L*/|V(t)|, L* = Regularization time x |V| (the relaxation
      /// stops while the plane is at rest).
      void
      begin_step(const PlaneStep &s)
      {
        dt = s.dt;
        if (s.constant_velocity)
          step_decay = decay_of_dt;
        else
          step_decay
            = s.speed > 0
                ? std::exp(-std::abs(s.slide) / (s.speed * regularization_time))
                : decay_of_dt;
        slip_length = regularization_time * s.speed;
      }

      double
      tangential(const ContactNode &before,
                 const double       trial,
                 const double       lambda_n,
                 ContactStatus     &status) const
      {
        const double limit = mu * lambda_n;
        if (std::abs(trial) <= limit)
          {
            status = stick;
            return trial;
          }
        status             = slip;
        const double alpha = trial >= 0 ? 1. : -1.;
        // Exact solution of the relaxation over the step, with |sigma|
        // frozen at its value of this step.
        const double decay = rate == RegularizationRate::local_slip_rate
                               ? std::exp(-dt * before.slip_rate / slip_length)
                               : step_decay;
        const double tau
          = alpha * limit
            + (previous_tau(before, trial, lambda_n) - alpha * limit) * decay;
        // Never more friction than needed to stick (that would reverse the
        // slip): then the point sticks.
        if (alpha * tau >= alpha * trial)
          {
            status = stick;
            return trial;
          }
        return tau;
      }

      /// tau before the step: that of the last step in contact, or on
      /// re-contact the state `State on re-contact` says.
      double
      previous_tau(const ContactNode &node,
                   const double       trial,
                   const double       lambda_n) const
      {
        if (node.status != separated)
          return node.tau;
        switch (recontact)
          {
            case RecontactState::keep:
              return node.tau;
            case RecontactState::reset_to_mu_sigma:
              return (trial >= 0 ? 1. : -1.) * mu * lambda_n;
            default:
              return 0.;
          }
      }

      double             mu, regularization_time;
      RegularizationRate rate;
      RecontactState     recontact;
      /// exp(-dt / Regularization time): the decay at the nominal speed.
      double decay_of_dt;
      double step_decay, slip_length = 0, dt = 0;
    };
  } // namespace contact
} // namespace tribodyn

#endif
