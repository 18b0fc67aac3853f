// The shear memory of a pair between two materials: series springs are
// exact for a bimaterial under simple shear (issue #7, item 6).
//
// Exact solution: two bonded half-spaces, steel (G1) below z0 and carbon
// (G2 = G1 / 5.6) above, under simple shear carry one uniform shear stress
// tau0 = G1 gamma1 = G2 gamma2; the displacement u_x = gamma1 (z - z0)
// below z0 and gamma2 (z - z0) above is piecewise linear with its kink on
// the interface plane z0, midway between the last steel and the first
// carbon layer of automata.
//
// In the automata, a pair across the interface has two halves of lengths
// r0 (q_i = q_j = r/2) and stiffnesses k = 2G/r0 in series; its relative
// tangential displacement is (gamma1 + gamma2) dz / 2, so its shear stress
// is (gamma1 + gamma2)/2 dz / (r0/(2 G1) + r0/(2 G2)) = tau0 dz / r0: the
// same as a pair inside either material. The stress of every automaton,
// the interface layers included, must then be the uniform tau0 (and no
// normal stress: the least-squares volumetric strain of a neighbourhood
// with mirror symmetry in x and y vanishes under this shear). Averaging the
// two sides' stiffnesses arithmetically instead would give the interface
// pairs a shear stress off by (k1 + k2)^2 / (4 k1 k2) - 1 = 95 % here.
//
// Checked on the automata whose neighbours all have complete
// neighbourhoods (periodic in x and y; the z faces are excluded): sigma_xz
// = tau0 and the other components below tau0 times the tolerance, 1e-6:
// the imposed shear strains (gamma2 = 5.6e-8 in carbon) make the
// second-order terms of the finite pair kinematics ~1e-7 tau0, and the
// rounding of the positions (ulp 1.7e-18 m of x ~ 1e-2 m against pair
// displacements ~6e-11 m) ~3e-8.

#include "mca_test_tools.h"

using namespace tribodyn_test;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double d = 1e-3, a = d * std::sqrt(2.), H = 8 * a, z0 = H / 2;
  Parameters   p             = block_parameters(4, d, 0, true);
  p.geometry.domain_upper[2] = H;
  p.geometry.bodies[0].upper = p.geometry.domain_upper;
  Region carbon;
  carbon.shape             = Region::Shape::box;
  carbon.a                 = Point3(-1, -1, z0);
  carbon.b                 = Point3(1, 1, 1);
  carbon.material          = 1;
  p.geometry.regions       = {carbon};
  p.materials[0].hardening = Hardening::elastic;
  p.materials[1].hardening = Hardening::elastic;
  const double G1          = p.materials[0].shear_modulus();
  const double G2          = p.materials[1].shear_modulus();
  const double tau0 = 1e-8 * G1, gamma1 = tau0 / G1, gamma2 = tau0 / G2;

  AutomatonSystem system(p, MPI_COMM_WORLD);
  system.setup();
  const auto counts = system.bonded_neighbour_counts();
  std::map<std::uint32_t, unsigned int> index;
  for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
    index[system.ids()[k]] = k;
  std::vector<bool> deep(system.n_owned_automata());
  for (unsigned int k = 0; k < deep.size(); ++k)
    deep[k] = counts[k] == 12;
  for (const auto &pv : system.pair_views())
    {
      if (counts[index[pv.id_i]] < 12)
        deep[index[pv.id_j]] = false;
      if (counts[index[pv.id_j]] < 12)
        deep[index[pv.id_i]] = false;
    }

  system.impose_motion(
    [&](const Point3 &x, Vec3 &du, Vec3 &dtheta) {
      const double z = x[2] - z0;
      du             = {{(z < 0 ? gamma1 : gamma2) * z, 0, 0}};
      dtheta         = {{0, 0, 0}};
    },
    1e-9);

  double       worst_shear = 0, worst_other = 0;
  unsigned int n_checked = 0, n_interface = 0, n_carbon = 0;
  for (unsigned int k = 0; k < deep.size(); ++k)
    {
      if (!deep[k])
        continue;
      ++n_checked;
      const double z = system.positions()[k][2] - z0;
      if (std::abs(z) < a / 2)
        ++n_interface;
      if (system.materials()[k] == 1)
        ++n_carbon;
      const Sym3 s = system.automaton_stress(k);
      worst_shear  = std::max(worst_shear, std::abs(s[4] - tau0) / tau0);
      for (const unsigned int c : {0u, 1u, 2u, 3u, 5u})
        worst_other = std::max(worst_other, std::abs(s[c]) / tau0);
    }
  check(n_interface > 0 && n_carbon > 0 && n_carbon < n_checked,
        "deep automata on both sides (" + std::to_string(n_carbon)
          + " carbon of " + std::to_string(n_checked) + ") and "
          + std::to_string(n_interface) + " in the two interface layers");
  check_relative(worst_shear, 0, 1e-6, "sigma_xz = tau0 everywhere", 1.);
  check_relative(worst_other, 0, 1e-6, "other stress components / tau0", 1.);
  return result();
}
