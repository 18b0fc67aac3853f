// Total-Lagrangian St Venant-Kirchhoff path.
// (a) A rigid rotation by 30 degrees produces no internal force and no
//     stress (tolerances 1e-10 E h and 1e-10 E), while the small-strain
//     path shows the spurious stress of a linearized rotation (> 5 % of E).
// (b) Uniaxial stretch x -> 1.2 x with nu = 0: Cauchy stress
//     sigma_xx = lambda S_xx = lambda E (lambda^2 - 1) / 2 (relative 1e-10).
// (c) Impact at 1 cm/s (strains ~ 2e-6): the large-deformation run gives
//     the small-strain contact force history (relative 1e-4).

#include "contact_test_tools.h"

#include <cmath>

namespace
{
  using namespace tribodyn_test;

  std::string
  block(const std::string &kinematics, const std::string &nu)
  {
    return R"(
      subsection Geometry
        set Width = 2e-3
        set Height = 2e-3
        set Mesh size = 0.25e-3
      end
      subsection Materials
        set Kinematics = )"
           + kinematics + R"(
        subsection Matrix
          set Young modulus = 30e9
          set Poisson ratio = )"
           + nu + R"(
        end
      end
      subsection Loading
        set Top face held in x = false
      end
      subsection Output
        set Averaging start time = 0
      end)";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double E = 30e9, h = 0.25e-3, theta = M_PI / 6;
  const auto   rotation = [&](const dealii::Point<2> &X) {
    dealii::Tensor<1, 2> u;
    u[0] = (std::cos(theta) - 1) * X[0] - std::sin(theta) * X[1];
    u[1] = std::sin(theta) * X[0] + (std::cos(theta) - 1) * X[1];
    return u;
  };
  {
    ContactRun run(block("large deformation", "0.2"));
    run.solver->set_displacement(rotation);
    const double f = run.solver->max_internal_force();
    check(f < 1e-10 * E * h,
          "rigid rotation, large deformation: max |f_int| = "
            + std::to_string(f) + " N/m < 1e-10 E h");
    const double s = run.solver->max_von_mises();
    check(s < 1e-10 * E,
          "rigid rotation, large deformation: von Mises = " + std::to_string(s)
            + " Pa < 1e-10 E");
  }
  {
    ContactRun run(block("small strain", "0.2"));
    run.solver->set_displacement(rotation);
    const double s = run.solver->max_von_mises();
    check(s > 0.05 * E,
          "rigid rotation, small strain: spurious von Mises "
            + std::to_string(s / E) + " E (> 0.05 E)");
  }
  {
    ContactRun   run(block("large deformation", "0"));
    const double stretch = 1.2;
    run.solver->set_displacement([&](const dealii::Point<2> &X) {
      dealii::Tensor<1, 2> u;
      u[0] = (stretch - 1) * X[0];
      return u;
    });
    check_relative(run.solver->max_von_mises(),
                   stretch * E * (stretch * stretch - 1) / 2,
                   1e-10,
                   "uniaxial stretch 1.2: Cauchy sigma_xx (Pa)");
  }
  {
    const std::string impact = R"(
      subsection Loading
        set Pressure = 0
        set Sliding velocity = 0
        set Initial velocity = 0, -0.01
      end
      subsection Time
        set End time = 2e-6
        set Damping coefficient = 0
      end
      subsection Output
        set Sample interval = 10
      end)";
    ContactRun        small(block("small strain", "0.2") + impact);
    ContactRun        large(block("large deformation", "0.2") + impact);
    const auto       &a          = small.run();
    const auto       &b          = large.run();
    double            difference = 0, scale = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      {
        difference = std::max(difference,
                              std::abs(a[i].contact_normal_force
                                       - b[i].contact_normal_force));
        scale      = std::max(scale, std::abs(a[i].contact_normal_force));
      }
    check(scale > 0 && difference < 1e-4 * scale,
          "impact at 1 cm/s: large-deformation contact force = small-strain "
          "one to 1e-4 ("
            + std::to_string(difference / scale) + ")");
  }
  return result();
}
