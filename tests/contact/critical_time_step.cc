// The critical time step (element eigenvalue bound on omega_max and the
// damped beta2 bound dt_crit = (sqrt(2 beta2 + xi^2) - xi) / (beta2
// omega_max), xi = beta omega_max / 2) is safe: a free block loaded by a
// pressure step (which excites every mode) and integrated over 20 000 steps
// at dt = 0.999 dt_crit stays bounded (kinetic + elastic energy below 10 x
// the work of the load) for beta2 = 0.5, 0.75, 1 with and without damping.
// Also checked: dt_crit for beta2 = 0.5 and beta = 0 is 2 / omega_max
// (1e-12), and damping or a larger beta2 lowers it.

#include "contact_test_tools.h"

#include <cmath>

namespace
{
  using namespace tribodyn_test;

  std::string
  parameters(const std::string &beta2, const std::string &beta)
  {
    return R"(
      subsection Geometry
        set Width = 2e-3
        set Height = 1e-3
        set Mesh size = 0.25e-3
      end
      subsection Loading
        set Pressure = 1e6
        set Ramp time = 0
        set Top face held in x = false
        set Initial gap = 1
      end
      subsection Time
        set Time step = 1e-6
        set Automatic time step = true
        set Safety factor = 0.999
        set End time = 1e-3
        set Beta2 = )"
           + beta2 + R"(
        set Damping coefficient = )"
           + beta + R"(
      end
      subsection Output
        set Sample interval = 100
        set Averaging start time = 0
      end)";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  double                                   undamped = 0;
  for (const auto &c : std::vector<std::pair<std::string, std::string>>{
         {"0.5", "0"}, {"0.5", "2e-8"}, {"0.75", "0"}, {"1", "1e-8"}})
    {
      ContactRun   run(parameters(c.first, c.second));
      const double dt_crit = run.solver->critical_time_step();
      const double omega   = run.solver->omega_max();
      if (c.first == "0.5" && c.second == "0")
        {
          undamped = dt_crit;
          check_relative(dt_crit * omega,
                         2.,
                         1e-12,
                         "beta2 = 0.5, no damping: omega_max dt_crit = 2");
        }
      else
        check(dt_crit < undamped,
              "beta2 = " + c.first + ", beta = " + c.second
                + " lowers dt_crit");
      // 20 000 steps at 0.999 dt_crit.
      run.parameters.time.end_time = 20000 * run.solver->time_step();
      const auto   &samples        = run.run();
      const Sample &end            = samples.back();
      // Energy in the frame of the centre of mass (the load accelerates
      // the block as a whole): subtract the rigid kinetic energy.
      const double m     = run.solver->total_mass();
      double       worst = 0, work = 0;
      for (const auto &s : samples)
        {
          const double internal
            = s.kinetic_energy
              - 0.5
                  * (s.momentum_x * s.momentum_x + s.momentum_y * s.momentum_y)
                  / m
              + s.elastic_energy;
          worst = std::max(worst, std::abs(internal));
          work  = std::max(work, s.external_work);
        }
      check(std::isfinite(end.kinetic_energy) && worst < 10 * work,
            "beta2 = " + c.first + ", beta = " + c.second
              + ": bounded at 0.999 dt_crit = " + std::to_string(dt_crit * 1e9)
              + " ns over 20000 steps");
    }
  return result();
}
