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
// scheme's update Delta u = h lambda / m), so its slip rate V solves
//
//   g(V) = V m dt / h + lambda_n mu(V, theta'(V)) - |T| = 0,
//
// one scalar equation per node, solved by TOMS 748 (bracketed, to
// round-off) on [0, h |T| / (m dt)]. No step size limit comes from the law
// (an explicit mu(V_n) is stable only while a lambda_n h / (m dt V) < 1,
// which fails as V -> 0); the node sticks when |T| <= mu(V_min, theta'(0))
// lambda_n, the static coefficient of its age.
#ifndef tribodyn_contact_friction_laws_rate_and_state_h
#define tribodyn_contact_friction_laws_rate_and_state_h

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <deal.II/base/mpi.h>
#include <tribodyn/contact/friction_law.h>
#include <tribodyn/core/rate_state.h>

namespace tribodyn
{
  namespace contact
  {
    struct RateAndState : FrictionLawBase
    {
      static constexpr const char *name = "rate and state";

      /// Subsection `Rate and state friction` of Contact.
      struct Parameters : rate_state::Parameters
      {
        Parameters()
        {
          mu0 = 0.25;
          Dc  = 1e-6;
        }

        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          declare_in(prm, "Rate and state friction", "0.25", "1e-6");
        }

        void
        parse_parameters(dealii::ParameterHandler &prm)
        {
          parse_in(prm,
                   "Rate and state friction",
                   "Contact/Rate and state friction/");
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
        const auto   g = [&](const double V) {
          return V / c + lambda_n * law.mu(V, law.evolve(theta, V, dt)) - T;
        };
        const double V_max = c * T;
        const double g_max = g(V_max);
        double       V     = V_max;
        if (g_max > 0)
          {
            std::uintmax_t iterations = max_iterations;
            const auto     bracket    = boost::math::tools::toms748_solve(
              g,
              0.,
              V_max,
              stuck,
              g_max,
              boost::math::tools::eps_tolerance<double>(50),
              iterations);
            if (iterations >= max_iterations)
              ++unconverged;
            V = 0.5 * (bracket.first + bracket.second);
          }
        return (trial >= 0 ? 1. : -1.) * (T - V / c);
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
        const unsigned long long n
          = dealii::Utilities::MPI::sum(unconverged, comm);
        const double mu_ss
          = law.steady_mu(std::max(plane_speed, law.parameters().V_min));
        summary["rate_and_state_mu_steady_at_plane_speed"] = mu_ss;
        summary["rate_and_state_unconverged_solves"]       = n;
        figures << "Rate and state: steady mu at the plane's speed " << mu_ss
                << "; " << n << " slip-rate solve(s) not converged to round-off"
                << std::endl;
      }

      rate_state::Law law;

    private:
      static constexpr std::uintmax_t max_iterations = 100;
      double                          dt = 0, h = 0, plane_speed = 0;
      mutable unsigned long long      unconverged = 0;
    };
  } // namespace contact
} // namespace tribodyn

#endif
