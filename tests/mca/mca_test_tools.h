#ifndef tribodyn_tests_mca_test_tools_h
#define tribodyn_tests_mca_test_tools_h

#include "../test_utilities.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/parameters.h>

namespace tribodyn_test
{
  using namespace tribodyn::mca;

  /// A block of n x n x n FCC cells of automata of size d (one body).
  inline Parameters
  block_parameters(const unsigned int n,
                   const double       d,
                   const int          material    = 0,
                   const bool         periodic_xy = false)
  {
    Parameters   p;
    const double a   = d * std::sqrt(2.);
    auto        &g   = p.geometry;
    g.automaton_size = d;
    g.domain_lower   = Point3(0, 0, 0);
    g.domain_upper   = Point3(n * a, n * a, n * a);
    g.periodic       = {{periodic_xy, periodic_xy, false}};
    Body b;
    b.lower                                                    = g.domain_lower;
    b.upper                                                    = g.domain_upper;
    b.material                                                 = material;
    g.bodies                                                   = {b};
    p.interaction.rotations                                    = true;
    p.interaction.plasticity                                   = false;
    p.interaction.bond_breaking.get<VonMisesBondBreaking>().on = false;
    p.interaction.bond_formation.get<PlasticHeatBondFormation>().on = false;
    return p;
  }

  /// Two automata of size @p d, bonded as packed, at the contact distance
  /// along (1, 1, 0)/sqrt 2: one body of half an FCC cell in a box with
  /// room around it (two_automata.cc, rate_state_pair.cc).
  inline Parameters
  two_automata_parameters(const double d)
  {
    const double a             = d * std::sqrt(2.);
    Parameters   p             = block_parameters(1, d, 0);
    p.geometry.domain_lower    = Point3(-2 * a, -2 * a, -2 * a);
    p.geometry.domain_upper    = Point3(3 * a, 3 * a, 3 * a);
    p.geometry.bodies[0].lower = Point3(0, 0, 0);
    p.geometry.bodies[0].upper = Point3(a, a, a / 2);
    return p;
  }

  /// Two steel blocks of automata of size @p d across a flat interface (a
  /// rough interface of zero amplitude: the pairs across it start
  /// unbonded) at z = 2a, 3 x 3 FCC cells periodic in x and y, 4 cells high;
  /// plasticity and bond formation by plastic heat on, friction
  /// coefficient @p mu (plastic_heat.cc, bond_criterion_stresses.cc).
  inline Parameters
  interface_blocks_parameters(const double d, const double mu)
  {
    const double a                 = d * std::sqrt(2.);
    Parameters   p                 = block_parameters(3, d, 0, true);
    p.geometry.domain_upper[2]     = 4 * a;
    p.geometry.bodies[0].upper[2]  = 4 * a;
    p.geometry.rough_interface     = true;
    p.geometry.interface_height    = 2 * a;
    p.geometry.roughness_amplitude = 0;
    p.interaction.plasticity       = true;
    p.interaction.bond_formation.get<PlasticHeatBondFormation>().on = true;
    p.interaction.friction.get<Coulomb>().mu                        = mu;
    return p;
  }

  /// The 'Geometry' subsection of the staged friction scenes
  /// (friction_loading.cc, deferred_kicks.cc): automata of size @p d, a box
  /// of 4 x 4 FCC cells periodic in x and y, one steel body of 8 cells
  /// high split by a rough interface at 4 cells (amplitude 1.5 d, one
  /// wavelength over the box, seed 3), 2 cells of room below and 4 above.
  inline std::string
  rough_interface_geometry(const double d)
  {
    const double       a = d * std::sqrt(2.), W = 4 * a;
    std::ostringstream text;
    text << std::setprecision(17) << "subsection Geometry\n"
         << "set Automaton size = " << d << "\n"
         << "set Domain lower = 0, 0, " << -2 * a << "\n"
         << "set Domain upper = " << W << ", " << W << ", " << 12 * a << "\n"
         << "set Periodic x = true\nset Periodic y = true\n"
         << "set Bodies = 0 0 0 " << W << " " << W << " " << 8 * a << " steel\n"
         << "subsection Rough interface\nset Enabled = true\n"
         << "set Height = " << 4 * a << "\nset Amplitude = " << 1.5 * d
         << "\nset Wavelength = " << W << "\nset Seed = 3\nend\nend\n";
    return text.str();
  }

  /// The parameters of prm text @p text (the rest at their defaults).
  inline Parameters
  parameters_from_text(const std::string &text)
  {
    dealii::ParameterHandler handler;
    Parameters::declare_parameters(handler);
    handler.parse_input_from_string(text);
    Parameters p;
    p.parse_parameters(handler);
    return p;
  }

  /// Hooke's stress (xx yy zz yz xz xy) for strain eps.
  inline Sym3
  hooke(const MaterialParameters &m, const double eps[3][3])
  {
    const double G      = m.shear_modulus();
    const double lambda = m.bulk_modulus() - 2 * G / 3;
    const double tr     = eps[0][0] + eps[1][1] + eps[2][2];
    return {{lambda * tr + 2 * G * eps[0][0],
             lambda * tr + 2 * G * eps[1][1],
             lambda * tr + 2 * G * eps[2][2],
             2 * G * eps[1][2],
             2 * G * eps[0][2],
             2 * G * eps[0][1]}};
  }

  /// A general strain with all six components, of size @p amplitude.
  inline void
  general_strain(double eps[3][3], const double amplitude)
  {
    const double shape[3][3]
      = {{1.0, 0.3, -0.2}, {0.3, -0.7, 0.5}, {-0.2, 0.5, 0.4}};
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        eps[i][j] = amplitude * shape[i][j];
  }

  /// Impose u = sign * eps x on every automaton in one pseudo-step (no
  /// rotation) and evaluate the pairs.
  inline void
  impose_affine_strain(AutomatonSystem &system,
                       const double     eps[3][3],
                       const double     sign)
  {
    system.impose_motion(
      [&](const Point3 &x, Vec3 &du, Vec3 &dtheta) {
        for (unsigned int i = 0; i < 3; ++i)
          {
            du[i]     = 0;
            dtheta[i] = 0;
            for (unsigned int j = 0; j < 3; ++j)
              du[i] += sign * eps[i][j] * x[j];
          }
      },
      1e-9);
  }

  inline double
  sym_norm(const Sym3 &s)
  {
    return std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]
                     + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
  }
} // namespace tribodyn_test

#endif
