// Elastic column hitting the rigid plane (frictionless, no damping, beta2 =
// 0.5). With nu = 0 the plane-strain column is exactly one-dimensional
// (no lateral coupling), so the 1D impact solution is the reference:
// contact force rho c v0 W on the plateau (c = sqrt(E/rho)), contact
// duration 2 L / c, rebound velocity v0 (elastic impact).
// Tolerances: plateau force 5e-5 (measured 7.6e-6: the mean over the
// plateau's samples; a density or modulus 0.1 % off moves rho c by 5e-4 and
// fails it), duration 2 % (measured 0.87 %: 3.4 steps of 10 ns longer
// than 2 L / c), rebound velocity 2 %
// (measured 1.5 %: the column still vibrates after the release),
// energy balance 1e-10 (exact for the scheme), energy lost to the
// forward-increment contact < 3 % of the impact energy.

#include "contact_test_tools.h"

#include <cmath>

int
main(int argc, char **argv)
{
  using namespace tribodyn_test;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double E = 30e9, rho = 1770, v0 = 1., L = 8e-3, W = 1e-3;
  ContactRun   run(column_impact_prm(R"(
      subsection Matrix
        set Young modulus = 30e9
        set Poisson ratio = 0
        set Density = 1770
      end)",
                                   10e-9,
                                   6e-6));
  const auto  &samples = run.run();
  const double c = std::sqrt(E / rho), duration = 2 * L / c;
  const double force = rho * c * v0 * W;
  const double mass  = run.solver->total_mass();

  const ImpactFigures impact
    = impact_figures(samples, run.solver->time_step(), duration);
  const double plateau = impact.plateau_force, last_contact = impact.duration;
  check_relative(plateau,
                 force,
                 5e-5,
                 "plateau contact force rho c v0 W (N/m)");
  check_relative(last_contact, duration, 0.02, "contact duration 2L/c (s)");
  const Sample &end = samples.back();
  check_relative(end.momentum_y / mass, v0, 0.02, "rebound velocity (m/s)");
  double balance = 0;
  for (const auto &s : samples)
    balance = std::max(balance, s.energy_balance_error);
  check(balance < 1e-10,
        "energy balance KE + W_int = E0 + W_ext + W_contact to 1e-10 ("
          + std::to_string(balance) + ")");
  const double e0   = 0.5 * mass * v0 * v0;
  const double lost = -end.contact_work / e0;
  check(lost >= 0 && lost < 0.03,
        "energy absorbed by the forward-increment contact: "
          + std::to_string(100 * lost) + " % of the impact energy (< 3 %)");
  check_relative(end.kinetic_energy + end.elastic_energy,
                 e0 * (1 - lost),
                 1e-9,
                 "energy after rebound = E0 + contact work");
  return result();
}
