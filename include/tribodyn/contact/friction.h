#ifndef tribodyn_contact_friction_h
#define tribodyn_contact_friction_h

#include <cmath>
#include <tribodyn/contact/contact_parameters.h>

namespace tribodyn
{
  namespace contact
  {
    /// Status of a contact node after the step (values written in the
    /// outputs).
    enum ContactStatus : unsigned char
    {
      separated = 0,
      stick     = 1,
      slip      = 2
    };

    /**
     * Constants of a friction law for one time step: the friction
     * coefficient and, for the regularized law, the factor
     * exp(-dt / t*) of the exact integration of
     * d tau/dt = -(tau - alpha mu |sigma|) / t* over a step with
     * t* = L* / |V| (seed 001, eq. (4)).
     */
    struct FrictionStep
    {
      double mu    = 0.25;
      double decay = 0.;
    };

    /**
     * The tangential multiplier of one contact point, given the normal
     * multiplier @p lambda_n >= 0 (force, per unit thickness) and the
     * stick trial @p trial (the tangential force that keeps the point stuck
     * to the plane over the step). @p tau_old is the tangential force of the
     * previous step (state of the regularized law). Sets @p status to
     * stick or slip and returns the tangential force. Compiled per law (no
     * run-time dispatch in the contact loop).
     */
    template <FrictionLaw law>
    inline double
    tangential_multiplier(const double        trial,
                          const double        lambda_n,
                          const double        tau_old,
                          const FrictionStep &f,
                          ContactStatus      &status)
    {
      if constexpr (law == FrictionLaw::frictionless)
        {
          (void)trial;
          (void)lambda_n;
          (void)tau_old;
          (void)f;
          status = slip;
          return 0.;
        }
      const double limit = f.mu * lambda_n;
      if (std::abs(trial) <= limit)
        {
          status = stick;
          return trial;
        }
      status             = slip;
      const double alpha = trial >= 0 ? 1. : -1.;
      if constexpr (law == FrictionLaw::coulomb)
        {
          (void)tau_old;
          return alpha * limit;
        }
      else
        {
          // Exact solution of the relaxation over the step, with |sigma|
          // frozen at its value of this step.
          const double tau
            = alpha * limit + (tau_old - alpha * limit) * f.decay;
          // Never more friction than needed to stick (that would reverse the
          // slip): then the point sticks.
          if (alpha * tau >= alpha * trial)
            {
              status = stick;
              return trial;
            }
          return tau;
        }
    }
  } // namespace contact
} // namespace tribodyn

#endif
