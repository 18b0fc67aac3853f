// A block pressed on the plane moving at V = -2 m/s, Coulomb friction
// mu = 0.25 (references: rigid-body dynamics with Coulomb's law).
// (a) Top face held in x: once every contact node slides, the reaction
//     of the top face is mu P W (time average after the waves have been
//     damped: tolerance 1 %), the contact multipliers satisfy
//     |sum lambda_T| = mu sum lambda_N to round-off (1e-12), and every
//     node slips.
// (b) Top face free: friction accelerates the block until it moves with
//     the plane. While every node slides, the momentum balance with
//     Coulomb's law gives m v_x = -mu (m v_y + impulse of P W) exactly
//     (tolerance 1e-9). Rigid-body reference v(t) = -mu W int P dt / m up
//     to t_s = t_r/2 + |V| m / (mu P W): followed within 4 % of |V| until
//     the first node sticks (the elastic waves modulate N); the mean
//     velocity after t_s + 2 us is V within 2 %.

#include "contact_test_tools.h"

#include <cmath>

int
main(int argc, char **argv)
{
  using namespace tribodyn_test;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double      P = 5e6, W = 4e-3, H = 2e-3, rho = 1770, mu = 0.25, V = -2;
  const std::string common = R"(
    subsection Geometry
      set Width = 4e-3
      set Height = 2e-3
      set Mesh size = 0.25e-3
    end
    subsection Loading
      set Pressure = 5e6
      set Sliding velocity = -2
    end
    subsection Contact
      set Friction law = Coulomb
      set Friction coefficient = 0.25
    end
    subsection Output
      set Sample interval = 5
      set Averaging start time = 0
    end
  )";
  {
    ContactRun  run(common + R"(
      subsection Loading
        set Ramp time = 5e-6
      end
      subsection Time
        set Damping coefficient = 2e-8
        set Automatic time step = true
        set Time step = 5e-9
        set End time = 30e-6
      end)");
    const auto &samples = run.run();
    double      mean = 0, n = 0, worst = 0, slip = 1, stick = 0;
    for (const auto &s : samples)
      if (s.time >= 15e-6)
        {
          mean += s.mu_global;
          n += 1;
          worst = std::max(worst,
                           std::abs(std::abs(s.contact_tangential_force)
                                    - mu * s.contact_normal_force)
                             / s.contact_normal_force);
          slip  = std::min(slip, s.slip_fraction);
          stick = std::max(stick, s.stick_fraction);
        }
    check_relative(mean / n,
                   mu,
                   0.01,
                   "held block: top reaction / (P W) averaged over 15-30 us");
    check(worst < 1e-12,
          "held block: |sum lambda_T| = mu sum lambda_N ("
            + std::to_string(worst) + ")");
    check(stick == 0. && slip > 0.9,
          "held block: no node sticks after 15 us, >= 90 % slip (the "
          "trailing corner node separates at times)");
  }
  {
    ContactRun   run(common + R"(
      subsection Loading
        set Ramp time = 2e-6
        set Top face held in x = false
      end
      subsection Time
        set Damping coefficient = 2e-8
        set Time step = 5e-9
        set End time = 14e-6
      end
      subsection Output
        set Sample interval = 1
      end)");
    const auto  &samples = run.run();
    const double m       = run.solver->total_mass();
    const double dt      = run.solver->time_step();
    const double b2      = run.parameters.time.beta2;
    check_relative(m, rho * W * H, 1e-12, "block mass (kg/m)");
    // Exact momentum identity while every node slides or is separated:
    // m v_x = -mu (m v_y + W [dt sum_{k<n} P(t_k) + dt beta2 P(t_n)]).
    double       impulse = 0, worst = 0, t_first_stick = -1;
    unsigned int n_checked = 0;
    for (const auto &s : samples)
      {
        const double load = s.time / dt > 0.5 ? impulse : 0.;
        if (t_first_stick < 0 && s.stick_fraction > 0)
          t_first_stick = s.time;
        if (t_first_stick < 0)
          {
            const double expected
              = -mu
                * (s.momentum_y
                   + W
                       * (load
                          + dt * b2
                              * run.parameters.loading.pressure_at(s.time)));
            worst = std::max(worst,
                             std::abs(s.momentum_x - expected)
                               / (mu * P * W * 1e-6));
            ++n_checked;
          }
        impulse += dt * run.parameters.loading.pressure_at(s.time);
      }
    check(worst < 1e-9 && n_checked > 100,
          "free block, all nodes sliding: m v_x = -mu (m v_y + impulse of P W) "
          "to 1e-9 over "
            + std::to_string(n_checked) + " steps (" + std::to_string(worst)
            + ")");
    // Rigid-body reference (N = P W): v(t) = -mu W int_0^t P / m until
    // it reaches V at t_s = t_r/2 + |V| m / (mu P W). The elastic block's
    // normal force oscillates around P W, so v_x follows it within 4 % of
    // |V| up to the first stick.
    const double t_s         = 1e-6 + std::abs(V) * m / (mu * P * W);
    double       rigid_error = 0, rigid_impulse = 0;
    for (const auto &s : samples)
      {
        if (s.time <= t_first_stick)
          rigid_error
            = std::max(rigid_error,
                       std::abs(s.momentum_x / m + mu * W * rigid_impulse / m)
                         / std::abs(V));
        rigid_impulse += dt * run.parameters.loading.pressure_at(s.time);
      }
    check(rigid_error < 0.04 && t_first_stick > 0.5 * t_s,
          "free block: v_x follows the rigid-body solution within 4 % of |V| "
          "up to the first stick at "
            + std::to_string(t_first_stick) + " s (t_s = " + std::to_string(t_s)
            + " s; error " + std::to_string(rigid_error) + ")");
    double mean_after = 0, n_after = 0;
    for (const auto &s : samples)
      if (s.time > t_s + 2e-6)
        {
          mean_after += s.momentum_x / m;
          n_after += 1;
        }
    check_relative(mean_after / n_after,
                   V,
                   0.02,
                   "free block then moves with the plane (mean v_x, m/s)");
  }
  return result();
}
