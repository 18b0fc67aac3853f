// Rate-and-state friction of the pin's contact nodes (`Friction law = rate
// and state`, include/tribodyn/contact/friction_laws/rate_and_state.h),
// against the law's closed forms (written out here, not taken from the
// code under test):
//   mu(V, theta) = mu0 + a ln(V/V0) + b ln(V0 theta/D_c),
//   steady state theta = D_c/V: mu_ss(V) = mu0 + (a - b) ln(V/V0).
// (a) Steady state on the held block of block_drag.cc (4 x 2 mm, P = 5
//     MPa) at plane speeds 0.5, 2 and 8 m/s (a = 0.015, b = 0.01, V0 = 2,
//     D_c = 1 um: 60 D_c of slip per run): every slipping node carries
//     |lambda_T| = mu(V, theta') lambda_N with its own slip rate and state
//     to round-off (1e-10: the slip rate of the implicit solve against the
//     one of the displacements; measured 1e-16), and the contact's mu =
//     |sum lambda_T| / sum lambda_N over 20-30 us is mu_ss(V) within 2e-4
//     (measured 2e-5 to 4e-5: the block's vibration moves the nodes' slip
//     rates by up to 3 % of V, mu by a times that, and averages out; the
//     three speeds differ by (a - b) ln 4 = 6.9e-3).
// (b) Transient after a velocity step |V| 1 -> 4 m/s at 15 us (D_c = 10
//     um, steady at 1 m/s before; damping 2e-7 s to quiet the block's
//     vibration): mu jumps by a ln 4 and relaxes over the slip D_c to
//     mu_ss(4). Slip law: mu = mu_ss(V2) + b ln(V2/V1) e^(-s/D_c), s = V2
//     (t - t_step); aging law: theta = D_c/V2 + (D_c/V1 - D_c/V2)
//     e^(-s/D_c). From 0.2 us after the step the contact's mu follows each
//     curve within 2 % of the transient's amplitude b ln 4 (measured 0.9
//     and 1.1 %: the block's elastic response to the jump of friction); for
//     the slip law a least-squares fit of ln(mu - mu_ss(V2)) over 0-3 D_c
//     gives the decay length D_c and the amplitude within 2 % (measured
//     0.6 % and 0.06 %), and the two laws differ (by more than 10 % of the
//     amplitude; measured 17 %).
// (c) Critical stiffness (Ruina 1983): a block of stiffness k = G/H per unit
//     area (held top, uniform shear) sliding steadily is unstable below
//     k_c = sigma (b - a)/D_c (quasi-static: the inertia term M V^2/(sigma
//     a D_c) is about 0.01 here). Velocity weakening (a = 0.05, b = 0.1),
//     sigma = 50 MPa, V = 0.1 m/s, G/H = 6.25e12 Pa/m: with D_c = 1.6 um (k
//     = 4 k_c) the sliding settles (over 300-500 us mu varies by < 1e-3, its
//     mean is mu_ss(V) within 3e-6, and point M slips at V within 2e-3;
//     measured 1.3e-4, 3.1e-7 and 2.7e-4: tolerances within 10x; a
//     reference friction coefficient 1e-5 off fails it);
//     with D_c = 0.1 um (k = k_c/4) it stick-slips: M's slip rate swings
//     below 0.1 V and above 3 V (measured 7e-4 V to 22 V; the nodes creep
//     rather than stick, as rate and state does) and mu by > 10 %. The
//     factor 4 on each side: the free sides of the 4 x 2 mm block make its
//     shear stiffness lower than G/H (measured: stick-slip persists up to k
//     = 1.25 k_c, steady sliding from 2-4 k_c; doc/theory/contact.md).
// (d) The implicit slip-rate solve at any force scale: one slipping node
//     (m = 1e-3 kg/m, dt = 1e-8 s, h = dt^2/2: c = h/(m dt) = 5e-6 m/s
//     per N/m) whose trial is T = 0.3 lambda_N + 1/c (it would slip at
//     about 1 m/s), lambda_N from 1e-10 to 1e6 N/m: |lambda_T| = mu(V,
//     theta') lambda_N with V = c (T - |lambda_T|) and theta' the aging
//     law's closed form, to 1e-12 relative (measured 1.8e-16; the solve
//     for V instead of |lambda_T|, as before, gave 7e-2 at 1e-10 N/m:
//     |lambda_T| = T - V/c cancels), and no solve is counted unconverged.

#include "contact_test_tools.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tribodyn/contact/friction_laws/rate_and_state.h>

namespace
{
  /// The held block with the rate-and-state law of the lines @p law.
  std::string
  held_block(const double       V,
             const double       end_time,
             const std::string &law,
             const double       damping = 2e-8)
  {
    return tribodyn_test::held_block_prm(V, end_time, damping, 1) + R"(
    subsection Contact
      set Friction law = rate and state
      subsection Rate and state friction
)" + law + R"(
      end
    end)";
  }


  double
  contact_mu(const tribodyn::contact::Sample &s)
  {
    return std::abs(s.contact_tangential_force) / s.contact_normal_force;
  }
} // namespace


int
main(int argc, char **argv)
{
  using namespace tribodyn_test;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // (a)
  {
    const double mu0 = 0.25, a = 0.015, b = 0.01, V0 = 2, Dc = 1e-6;
    for (const double V : {0.5, 2., 8.})
      {
        ContactRun  run(held_block(V,
                                  30e-6,
                                  R"(set Reference friction coefficient = 0.25
          set Direct effect = 0.015
          set Evolution effect = 0.01
          set Reference slip rate = 2
          set Critical slip distance = 1e-6)"));
        const auto &samples = run.run();
        double      mean = 0, n = 0;
        for (const auto &s : samples)
          if (s.time >= 20e-6)
            {
              mean += contact_mu(s);
              n += 1;
            }
        mean /= n;
        double       worst = 0, rate_deviation = 0;
        unsigned int n_slip = 0;
        for (const ContactNode &node : run.solver->contact_node_states())
          {
            if (node.status != slip)
              continue;
            ++n_slip;
            const double theta = node.law_state[0];
            const double mu    = mu0 + a * std::log(node.slip_rate / V0)
                              + b * std::log(V0 * theta / Dc);
            worst
              = std::max(worst,
                         std::abs(std::abs(node.lambda_t) - mu * node.lambda_n)
                           / node.lambda_n);
            rate_deviation
              = std::max(rate_deviation, std::abs(node.slip_rate / V - 1));
          }
        const double expected = mu0 + (a - b) * std::log(V / V0);
        check(n_slip >= 15 && worst < 1e-10,
              "V = " + std::to_string(V)
                + " m/s: |lambda_T| = mu(V, theta') lambda_N at the "
                + std::to_string(n_slip) + " slipping nodes (worst "
                + format_number(worst) + "; slip rates within "
                + format_number(rate_deviation) + " of V)");
        check(std::abs(mean - expected) < 2e-4,
              "V = " + std::to_string(V) + " m/s: mu " + std::to_string(mean)
                + " = mu_ss(V) = " + std::to_string(expected) + " within 2e-4");
      }
  }

  // (b)
  {
    const double mu0 = 0.25, a = 0.015, b = 0.01, V0 = 2, Dc = 10e-6, V1 = 1,
                 V2 = 4, t_step = 15e-6;
    const double        amplitude = b * std::log(V2 / V1);
    const double        mu_ss2    = mu0 + (a - b) * std::log(V2 / V0);
    std::vector<double> curves[2];
    for (const std::string law : {"slip", "aging"})
      {
        ContactRun  run(held_block(V1,
                                  30e-6,
                                  R"(set Reference friction coefficient = 0.25
          set Direct effect = 0.015
          set Evolution effect = 0.01
          set Reference slip rate = 2
          set Critical slip distance = 10e-6
          set Initial slip rate = 1
          set State evolution law = )"
                                    + law,
                                  2e-7)
                       + R"(
          subsection Loading
            set Sliding velocity step time = 15e-6
            set Sliding velocity after step = -4
          end)");
        const auto &samples = run.run();
        double      worst   = 0;
        // least squares of ln(mu - mu_ss(V2)) against s/D_c over 0-3 D_c
        double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
        for (const auto &s : samples)
          {
            if (s.time < t_step + 0.2e-6)
              continue;
            const double slip_distance = V2 * (s.time - t_step);
            const double decay         = std::exp(-slip_distance / Dc);
            const double theta
              = law == "slip" ? Dc / V2 * std::exp(std::log(V2 / V1) * decay)
                              : Dc / V2 + (Dc / V1 - Dc / V2) * decay;
            const double expected
              = mu0 + a * std::log(V2 / V0) + b * std::log(V0 * theta / Dc);
            const double mu = contact_mu(s);
            worst           = std::max(worst, std::abs(mu - expected));
            curves[law == "aging"].push_back(mu);
            if (slip_distance < 3 * Dc)
              {
                const double x = slip_distance / Dc, y = std::log(mu - mu_ss2);
                sx += x;
                sy += y;
                sxx += x * x;
                sxy += x * y;
                n += 1;
              }
          }
        check(worst < 0.02 * amplitude,
              law + " law: mu after the step follows the closed form within "
                + std::to_string(worst / amplitude * 100)
                + " % of b ln(V2/V1)");
        if (law == "slip")
          {
            const double slope  = (n * sxy - sx * sy) / (n * sxx - sx * sx);
            const double excess = std::exp((sy - slope * sx) / n);
            check(std::abs(-1 / slope - 1) < 0.02
                    && std::abs(excess / amplitude - 1) < 0.02,
                  "slip law: mu - mu_ss(V2) = A e^(-s/L) with L = "
                    + std::to_string(-1 / slope) + " D_c, A = "
                    + std::to_string(excess / amplitude) + " b ln(V2/V1)");
          }
      }
    double difference = 0;
    for (std::size_t k = 0; k < std::min(curves[0].size(), curves[1].size());
         ++k)
      difference = std::max(difference, std::abs(curves[0][k] - curves[1][k]));
    check(difference > 0.1 * amplitude,
          "aging and slip laws differ after the step ("
            + std::to_string(difference / amplitude * 100) + " %)");
  }

  // (c)
  {
    const double mu0 = 0.3, a = 0.05, b = 0.1, V = 0.1, V0 = 0.1;
    for (const double Dc : {1.6e-6, 0.1e-6})
      {
        ContactRun  run(held_block(V,
                                  500e-6,
                                  R"(set Reference friction coefficient = 0.3
          set Direct effect = 0.05
          set Evolution effect = 0.1
          set Reference slip rate = 0.1
          set Critical slip distance = )"
                                    + format_number(Dc) + R"(
          set Minimum slip rate = 1e-9)",
                                  2e-7)
                       + R"(
          subsection Loading
            set Pressure = 50e6
          end
          subsection Output
            set Sample interval = 20
          end)");
        const auto &samples = run.run();
        double      lo = 1e300, hi = 0, slow = 1e300, fast = 0, mean = 0, n = 0;
        for (const auto &s : samples)
          if (s.time >= 300e-6)
            {
              const double mu = contact_mu(s);
              lo              = std::min(lo, mu);
              hi              = std::max(hi, mu);
              // point M's slip rate on the plane moving at -V
              const double rate = std::abs(s.M_vx + V) / V;
              slow              = std::min(slow, rate);
              fast              = std::max(fast, rate);
              mean += mu;
              n += 1;
            }
        mean /= n;
        const double      k_ratio = 12.5e9 / 2e-3 / (50e6 * (b - a) / Dc);
        const std::string what    = "k/k_c = " + std::to_string(k_ratio)
                                 + ": mu from " + std::to_string(lo) + " to "
                                 + std::to_string(hi) + ", slip rate of M from "
                                 + std::to_string(slow) + " to "
                                 + std::to_string(fast) + " V";
        const double deviation
          = std::abs(mean - mu0 - (a - b) * std::log(V / V0));
        if (k_ratio > 1)
          check((hi - lo) / mean < 1e-3 && fast - slow < 2e-3
                  && deviation < 3e-6,
                "steady sliding above k_c (" + what
                  + "; mean - mu_ss(V) = " + format_number(deviation) + ")");
        else
          check((hi - lo) / mean > 0.1 && slow < 0.1 && fast > 3,
                "stick-slip below k_c (" + what + ")");
      }
  }

  // (d)
  {
    using tribodyn::contact::RateAndState;
    RateAndState::Parameters p;
    p.mu0 = 0.31, p.a = 0.01, p.b = 0.005, p.V0 = 1, p.Dc = 1e-6;
    // (the first argument, Contact's shared entries, is not read by this
    // law)
    RateAndState                 law(p, p, 1e-8);
    tribodyn::contact::PlaneStep step;
    step.dt = 1e-8, step.h = 0.5 * step.dt * step.dt, step.speed = 1;
    law.begin_step(step);
    ContactNode node;
    node.m             = 1e-3;
    node.length        = 1e-4;
    node.law_state[0]  = 2 * p.Dc; // steady at 0.5 m/s
    const double c     = step.h / (node.m * step.dt);
    double       worst = 0, worst_at = 0;
    for (double lambda_n = 1e-10; lambda_n < 2e6; lambda_n *= 10)
      {
        ContactStatus status   = separated;
        const double  T        = 0.3 * lambda_n + 1 / c;
        const double  lambda_t = law.tangential(node, T, lambda_n, status);
        const double  V        = c * (T - std::abs(lambda_t));
        const double  x        = V * step.dt / p.Dc;
        const double  theta
          = node.law_state[0] * std::exp(-x) + p.Dc / V * (1 - std::exp(-x));
        const double mu = p.mu0 + p.a * std::log(V / p.V0)
                          + p.b * std::log(p.V0 * theta / p.Dc);
        const double error
          = std::abs(lambda_t - mu * lambda_n) / (mu * lambda_n);
        if (status != slip || !(error <= worst))
          worst_at = lambda_n;
        worst = status != slip ? 1. : std::max(worst, error);
      }
    tribodyn::JsonValue summary;
    std::ostringstream  figures;
    law.report(summary, figures, MPI_COMM_WORLD);
    // the law's own line: "...; N slip-rate solve(s) not converged..."
    const bool converged
      = figures.str().find("; 0 slip-rate solve(s)") != std::string::npos;
    check(worst < 1e-12 && converged,
          "slip-rate solve at lambda_N 1e-10 to 1e6 N/m: |lambda_T| = mu(V, "
          "theta') lambda_N to "
            + format_number(worst) + " (worst at " + format_number(worst_at)
            + " N/m; 1e-12 allowed); " + figures.str());
  }
  return result();
}
