// A rigid rotation produces no stress (issue #4).
//
// A block of 4 x 4 x 4 FCC cells is turned rigidly by 200 increments of
// 1e-3 rad about the axis (1, 2, 3)/sqrt(14): every automaton moves by
// (R - I)(x - c) and turns by the same angle. Pair distances are kept
// exactly, and the tangential increments use the relative velocity of the
// contact points including the automata's rotations, so no stress may
// appear. Over a finite increment the chord (2 sin(d/2)) and the arc (d)
// of the contact-point motion differ by d^3/24: the stress left is
// O(G d^2 theta), ~1e-7 G theta (200 d^3 / 24 = 4e-8 of theta; measured
// 7.8e-8 G theta). Tolerance: max |sigma| <= 3e-7 G theta.
// Control: the same motion with 'Rotations = false' (no rotational term)
// must produce a stress of the order of G theta (> 1e-2 G theta).

#include "mca_test_tools.h"

using namespace tribodyn_test;

namespace
{
  double
  max_stress_after_rotation(const bool rotations)
  {
    Parameters p            = block_parameters(4, 1e-3, 0);
    p.interaction.rotations = rotations;
    AutomatonSystem system(p, MPI_COMM_WORLD);
    system.setup();
    const double a = 4 * 1e-3 * std::sqrt(2.);
    const Point3 c(a / 2, a / 2, a / 2);
    const double len = std::sqrt(14.);
    const Vec3   axis{{1 / len, 2 / len, 3 / len}};
    const double delta = 1e-3;
    // rotation matrix of angle delta about axis (Rodrigues)
    double       R[3][3];
    const double cs = std::cos(delta), sn = std::sin(delta);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        R[i][j] = (i == j ? cs : 0) + (1 - cs) * axis[i] * axis[j];
    R[0][1] -= sn * axis[2];
    R[0][2] += sn * axis[1];
    R[1][0] += sn * axis[2];
    R[1][2] -= sn * axis[0];
    R[2][0] -= sn * axis[1];
    R[2][1] += sn * axis[0];
    for (unsigned int s = 0; s < 200; ++s)
      system.impose_motion(
        [&](const Point3 &x, Vec3 &du, Vec3 &dtheta) {
          for (unsigned int i = 0; i < 3; ++i)
            {
              double y = 0;
              for (unsigned int j = 0; j < 3; ++j)
                y += R[i][j] * (x[j] - c[j]);
              du[i]     = y - (x[i] - c[i]);
              dtheta[i] = delta * axis[i];
            }
        },
        1e-9);
    const auto stress = system.stresses();
    double     worst  = 0;
    for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
      worst = std::max(worst, sym_norm(stress[k]));
    return worst;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Parameters                         defaults;
  const double G       = defaults.materials[0].shear_modulus();
  const double theta   = 0.2;
  const double with    = max_stress_after_rotation(true);
  const double without = max_stress_after_rotation(false);
  check_relative(with,
                 0,
                 3e-7,
                 "max |stress| after a rigid rotation of 0.2 rad, relative "
                 "to G theta",
                 G * theta);
  check(without > 1e-2 * G * theta,
        "control without the rotational term: max |stress| / (G theta) = "
          + std::to_string(without / (G * theta)) + " > 1e-2");
  return result();
}
