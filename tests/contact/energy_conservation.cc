// Energy conservation of the beta2 = 0.5 (central difference) scheme
// without damping and friction. The scheme conserves exactly the discrete
// energy E_{n+1/2} = 1/2 v_{n+1/2}^T M v_{n+1/2} + 1/2 u_n^T K u_{n+1},
// v_{n+1/2} = (u_{n+1} - u_n)/dt, up to the work of the loads:
// E_{n+1/2} - E_{-1/2} = W_ext + W_contact (doc/theory/contact.md).
// (a) Free flight: a pin thrown at the plane from a gap it never closes,
//     loaded by a suddenly applied pressure (P = 0.2 MPa, no ramp): the
//     balance holds to 1e-10 relative over 10000 steps, and the damping
//     dissipation (W_int - elastic energy) is zero to 1e-9 of the energy
//     (round-off of K u with the large rigid motion).
// (b) The same with beta2 = 0.75: the scheme dissipates energy numerically
//     (balance error > 1e-6), which shows that (a) checks something.
// (c) Impact on the plane with frictionless contact: the balance including
//     the contact work holds to 1e-10.

#include "contact_test_tools.h"

#include <cmath>
#include <cstdio>

namespace
{
  using namespace tribodyn_test;

  double
  worst_balance(const std::vector<Sample> &samples)
  {
    double worst = 0;
    for (const auto &s : samples)
      worst = std::max(worst, s.energy_balance_error);
    return worst;
  }

  std::string
  parameters(const std::string &beta2, const std::string &gap)
  {
    return R"(
      subsection Geometry
        set Width = 6e-3
        set Height = 2e-3
        set Mesh size = 0.25e-3
      end
      subsection Loading
        set Pressure = 0.2e6
        set Ramp time = 0
        set Top face held in x = false
        set Initial velocity = 0.5, -3
        set Initial gap = )"
           + gap + R"(
      end
      subsection Time
        set Time step = 20e-9
        set End time = 200e-6
        set Damping coefficient = 0
        set Beta2 = )"
           + beta2 + R"(
      end
      subsection Contact
        set Friction law = frictionless
      end
      subsection Output
        set Sample interval = 10
        set Averaging start time = 0
      end)";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  {
    ContactRun  run(parameters("0.5", "1"));
    const auto &samples = run.run();
    check(worst_balance(samples) < 1e-10,
          "beta2 = 0.5, free flight: energy balance to 1e-10 ("
            + std::to_string(worst_balance(samples)) + ")");
    double damping = 0, scale = 0;
    for (const auto &s : samples)
      {
        damping = std::max(damping, std::abs(s.damping_dissipation));
        scale   = std::max(scale, s.kinetic_energy + s.elastic_energy);
      }
    std::printf("damping dissipation %.3e J/m, energy scale %.3e J/m\n",
                damping,
                scale);
    check(damping < 1e-9 * scale,
          "no damping: W_int - elastic energy = 0 to 1e-9 of the energy");
    check(samples.back().contact_normal_force == 0
            && samples.back().external_work > 0,
          "free flight: no contact, the pressure did work");
  }
  {
    ContactRun   run(parameters("0.75", "1"));
    const double worst = worst_balance(run.run());
    check(worst > 1e-6,
          "beta2 = 0.75 dissipates numerically (balance error "
            + std::to_string(worst) + " > 1e-6)");
  }
  {
    ContactRun  run(parameters("0.5", "0"));
    const auto &samples = run.run();
    check(worst_balance(samples) < 1e-10,
          "beta2 = 0.5, impacts on the plane: energy balance with the contact "
          "work to 1e-10 ("
            + std::to_string(worst_balance(samples)) + ")");
    check(samples.back().contact_work != 0,
          "the contact did work during the impacts");
  }
  return result();
}
