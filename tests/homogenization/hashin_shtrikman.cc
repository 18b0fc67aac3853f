// Hashin-Shtrikman bounds for N isotropic phases in plane strain (issue
// #19), see doc/theory/homogenization.md, "Bounds for N phases".
//
// 1. The N-phase formula (Walpole's form) reduces for two phases to
//    Hashin's (1965) bounds on the plane-strain bulk modulus k_23 and the
//    transverse shear modulus G_23 of fibre composites, written out here
//    independently: to 1e-12.
// 2. They lie within the Voigt and Reuss values of kappa and mu, and
//    collapse onto the phase's moduli for one phase: to 1e-12.
// 3. A random, nearly isotropic three-phase map (random_isotropic.png: 96 x
//    96 pixels, 208 overlapping discs (radius 3.2 pixels) of two kinds in a
//    matrix, E = 10, 80, 300
//    GPa): the isotropic projections kappa, mu of the periodic, KUBC and
//    SUBC apparent stiffnesses lie within the HS bounds (the bounds hold
//    for the effective tensor of an in-plane isotropic medium; the
//    anisotropy |C - C_iso|/|C| of each apparent tensor is printed and must
//    stay below 0.05 for the check to be meaningful).

#include "image_test_tools.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace tribodyn_test;

  // 1. Two phases: Hashin's explicit formulas, phase 1 softer.
  {
    const auto   phases = named_phases({{30e9, 0.2}, {80e9, 0.35}});
    const double f1 = 0.7, f2 = 0.3;
    const auto   k = [&](const unsigned int i) {
      return phases[i].isotropic->lambda() + phases[i].isotropic->mu();
    };
    const auto m
      = [&](const unsigned int i) { return phases[i].isotropic->mu(); };
    // Lower bounds: reference phase 0 (soft); upper: phase 1 (stiff).
    const double k_lower = k(0) + f2 / (1 / (k(1) - k(0)) + f1 / (k(0) + m(0)));
    const double k_upper = k(1) + f1 / (1 / (k(0) - k(1)) + f2 / (k(1) + m(1)));
    const double g_lower
      = m(0)
        + f2
            / (1 / (m(1) - m(0))
               + f1 * (k(0) + 2 * m(0)) / (2 * m(0) * (k(0) + m(0))));
    const double g_upper
      = m(1)
        + f1
            / (1 / (m(0) - m(1))
               + f2 * (k(1) + 2 * m(1)) / (2 * m(1) * (k(1) + m(1))));
    const PlaneModuliBounds hs = hashin_shtrikman_bounds(phases, {f1, f2});
    check_relative(hs.lower.kappa,
                   k_lower,
                   1e-12,
                   "two phases: kappa lower = Hashin");
    check_relative(hs.upper.kappa,
                   k_upper,
                   1e-12,
                   "two phases: kappa upper = Hashin");
    check_relative(hs.lower.mu,
                   g_lower,
                   1e-12,
                   "two phases: mu lower = Hashin");
    check_relative(hs.upper.mu,
                   g_upper,
                   1e-12,
                   "two phases: mu upper = Hashin");
  }

  // 2. Order with Voigt and Reuss; one phase.
  const auto phases = named_phases({{10e9, 0.3}, {80e9, 0.2}, {300e9, 0.25}});
  {
    const std::vector<double> f  = {0.5, 0.3, 0.2};
    const PlaneModuliBounds   hs = hashin_shtrikman_bounds(phases, f);
    const PlaneModuli voigt = isotropic_projection(voigt_estimate(phases, f).C);
    const PlaneModuli reuss = isotropic_projection(reuss_estimate(phases, f).C);
    check(reuss.kappa <= hs.lower.kappa && hs.lower.kappa <= hs.upper.kappa
            && hs.upper.kappa <= voigt.kappa,
          "Reuss <= HS- <= HS+ <= Voigt for kappa");
    check(reuss.mu <= hs.lower.mu && hs.lower.mu <= hs.upper.mu
            && hs.upper.mu <= voigt.mu,
          "Reuss <= HS- <= HS+ <= Voigt for mu");
    const PlaneModuliBounds one = hashin_shtrikman_bounds({phases[1]}, {1.});
    check_relative(one.lower.kappa,
                   plane_moduli(*phases[1].isotropic).kappa,
                   1e-12,
                   "one phase: kappa lower");
    check_relative(one.upper.mu,
                   plane_moduli(*phases[1].isotropic).mu,
                   1e-12,
                   "one phase: mu upper");
  }

  // 3. The random isotropic-ish map.
  const Morphology morphology = Morphology::create(
    image_parameters(image_path("random_isotropic.png"), 3));
  const std::vector<double> f  = morphology.phase_fractions();
  const PlaneModuliBounds   hs = hashin_shtrikman_bounds(phases, f);
  std::cout << "fractions " << f[0] << ", " << f[1] << ", " << f[2]
            << "; HS kappa [" << hs.lower.kappa / 1e9 << ", "
            << hs.upper.kappa / 1e9 << "] GPa, mu [" << hs.lower.mu / 1e9
            << ", " << hs.upper.mu / 1e9 << "] GPa" << std::endl;
  for (const auto bc : {BoundaryCondition::periodic,
                        BoundaryCondition::kubc,
                        BoundaryCondition::subc})
    {
      const CellProblemResult r = solve_cell(morphology, phases, bc, 2, 1e-10);
      const PlaneModuli       m = isotropic_projection(r.properties.C);
      const double            a = anisotropy(r.properties.C);
      const std::string       name = to_string(bc);
      check(a < 0.05,
            name + ": anisotropy |C - C_iso|/|C| = " + std::to_string(a)
              + " < 0.05");
      const auto within = [&](const double       value,
                              const double       lower,
                              const double       upper,
                              const std::string &what) {
        check(lower <= value && value <= upper,
              name + ": " + what + " = " + std::to_string(value / 1e9)
                + " GPa in the HS bounds [" + std::to_string(lower / 1e9) + ", "
                + std::to_string(upper / 1e9) + "] (margins "
                + std::to_string((value - lower) / (upper - lower)) + ", "
                + std::to_string((upper - value) / (upper - lower))
                + " of the gap)");
      };
      within(m.kappa, hs.lower.kappa, hs.upper.kappa, "kappa");
      within(m.mu, hs.lower.mu, hs.upper.mu, "mu");
    }
  return result();
}
