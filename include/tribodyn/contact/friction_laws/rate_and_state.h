// Contact friction law "rate and state": Dieterich-Ruina friction of the
// pin's contact nodes (core/rate_state.h; subsection `Contact/Rate and
// state friction`; doc/theory/contact.md Sec. 4.4):
//
//   |lambda_t| = mu(V, theta') lambda_n while the node slips at V > 0,
//
// theta' the state at the end of the step (evolved exactly at V), theta
// carried per node (law_state[0], checkpointed with the node; 0 before
// the first contact and after a separation: the node then starts as a new
// contact, at the steady state of `Initial slip rate`).
//
// The step's slip rate is implicit. A node of lumped mass m whose stick
// trial is T slips by h (|T| - |lambda_t|) / m over the step (the beta2
// scheme's update Delta u = h lambda / m), so its slip rate is V = c (|T|
// - |lambda_t|), c = h / (m dt), and its tangential force x = |lambda_t|
// solves
//
//   f(x) = x - lambda_n mu(V(x), theta'(V(x))) = 0,  x in [0, |T|],
//
// one scalar equation per node, solved by TOMS 748 (bracketed, to
// round-off in x: relative to the force whatever its scale; solving for
// V instead left x = |T| - V/c to cancel when the contact is light: 7e-2
// relative at lambda_n = 1e-10 N/m in tests/contact/rate_and_state.cc
// (d)). No step size limit comes
// from the law (an explicit mu(V_n) is stable only while a lambda_n h /
// (m dt V) < 1, which fails as V -> 0); the node sticks when |T| <=
// mu(V_min, theta'(0)) lambda_n, the static coefficient of its age.
#ifndef tribodyn_contact_friction_laws_rate_and_state_h
#define tribodyn_contact_friction_laws_rate_and_state_h

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <deal.II/base/mpi.h>
#include <tribodyn/contact/friction_law.h>
#include <tribodyn/core/law_selection.h>
#include <tribodyn/core/rate_state.h>

namespace tribodyn
{
  namespace contact
  {
    struct RateAndState : FrictionLawBase
    {
      static constexpr const char *name = "rate and state";

      /// Subsection `Rate and state friction` of Contact.
      struct Parameters : rate_state::Parameters, BoundLawParameters<Parameters>
      {
        Parameters()
        {
          mu0 = 0.25;
          Dc  = 1e-6;
        }

        ParameterBinding
        binding()
        {
          return rate_state::Parameters::binding("Contact");
        }
      };

      template <class ContactLawParameters>
      RateAndState(const ContactLawParameters &, const Parameters &p, double)
          : law(p)
      {
      }

      void
      begin_step(const PlaneStep &s)
      {
        dt          = s.dt;
        h           = s.h;
        plane_speed = s.dt > 0 ? std::abs(s.slide) / s.dt : s.speed;
      }

      /// The state of @p node before the step (a new contact's if none).
      double
      state(const ContactNode &node) const
      {
        return node.law_state[0] > 0 ? node.law_state[0] : law.initial_state();
      }

      double
      tangential(const ContactNode &before,
                 const double       trial,
                 const double       lambda_n,
                 ContactStatus     &status) const
      {
        const double theta = state(before);
        const double T     = std::abs(trial);
        // static limit: the coefficient at V_min of the state after the
        // step at rest
        const double stuck
          = lambda_n * law.mu(0., law.evolve(theta, 0., dt)) - T;
        if (stuck >= 0)
          {
            status = stick;
            return trial;
          }
        status         = slip;
        const double c = h / (before.m * dt); // V per unit of |T| - |lambda_t|
        const auto   f = [&](const double x) {
          const double V = c * (T - x);
          return x - lambda_n * law.mu(V, law.evolve(theta, V, dt));
        };
        // f(|T|) = -stuck > 0; f(0) = -lambda_n mu(c |T|) <= 0
        const double f_0 = f(0.);
        double       x   = 0;
        if (f_0 < 0)
          {
            boost::math::tools::eps_tolerance<double> converged(50);
            std::uintmax_t iterations = max_iterations;
            const auto     bracket    = boost::math::tools::toms748_solve(
              f, 0., T, f_0, -stuck, converged, iterations);
            if (!converged(bracket.first, bracket.second))
              ++unconverged.leg;
            x = 0.5 * (bracket.first + bracket.second);
          }
        return (trial >= 0 ? 1. : -1.) * x;
      }

      /// The node's state after the step, at its slip rate of the step
      /// (law_state[1]: the step's mu, for the outputs).
      void
      end_step(ContactNode &node, const double step) const
      {
        if (node.status == separated)
          {
            node.law_state = {{0., 0.}};
            return;
          }
        const double theta = law.evolve(state(node), node.slip_rate, step);
        node.law_state     = {{theta, law.mu(node.slip_rate, theta)}};
      }

      void
      report(JsonValue     &summary,
             std::ostream  &figures,
             const MPI_Comm comm) const
      {
        const unsigned long long n = unconverged.total(comm);
        const double             mu_ss
          = law.steady_mu(std::max(plane_speed, law.parameters().V_min));
        summary["rate_and_state_mu_steady_at_plane_speed"] = mu_ss;
        summary["rate_and_state_unconverged_solves"]       = n;
        figures << "Rate and state: steady mu at the plane's speed " << mu_ss
                << "; " << n << " slip-rate solve(s) not converged to round-off"
                << std::endl;
      }

      template <class F>
      void
      for_each_counter(const F &f) const
      {
        f("rate_and_state_unconverged_solves", unconverged);
      }

      rate_state::Law law;

    private:
      static constexpr std::uintmax_t max_iterations = 100;
      double                          dt = 0, h = 0, plane_speed = 0;
      mutable RunCounter              unconverged;
    };
  } // namespace contact
} // namespace tribodyn

#endif
