// Laminates (layers through the whole cell, on element edges) have an exact
// effective stiffness: uniform traction across the layers and uniform strain
// along them. The exact field is piecewise affine, hence in the Q1 space,
// and satisfies the periodic boundary conditions, so the periodic cell
// problem reproduces the laminate formulas up to the CG tolerance (1e-12):
// tolerance relative 1e-6 (issue #2) on every entry of C, on c_z and on the
// five constants, for layers normal to x and to y. KUBC and SUBC must
// bracket the exact stiffness (Huet): C^K - C_exact and C_exact - C^S are
// positive semi-definite (to round-off: -1e-9 |C|).

#include "homogenization_test_tools.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace tribodyn_test;

  const std::vector<ElasticPhase> phases
    = {IsotropicElasticMaterial{30e9, 0.2, 1770.},
       IsotropicElasticMaterial{80e9, 0.35, 1770.}};

  for (const auto normal :
       {LaminateMorphology::Normal::x, LaminateMorphology::Normal::y})
    {
      const Morphology   morphology = laminate_map(normal);
      const double       f          = morphology.heterogeneity_fraction();
      const unsigned int axis = normal == LaminateMorphology::Normal::x ? 0 : 1;
      const std::string  name
        = std::string("layers normal to ") + (axis == 0 ? "x" : "y") + ": ";
      const ApparentProperties exact = laminate_exact(phases, {1 - f, f}, axis);

      const CellProblemResult periodic
        = solve_cell(morphology, phases, BoundaryCondition::periodic);
      check_relative(matrix_relative_difference(periodic.properties.C, exact.C),
                     0,
                     1e-6,
                     name + "periodic C vs exact laminate C (all 9 entries)",
                     1.);
      for (unsigned int i = 0; i < 2; ++i)
        check_relative(periodic.properties.c_z[i],
                       exact.c_z[i],
                       1e-6,
                       name + "periodic c_z[" + std::to_string(i) + "]");
      const auto &c = periodic.properties.constants;
      const auto &e = exact.constants;
      check_relative(c.E_L, e.E_L, 1e-6, name + "E_L");
      check_relative(c.E_T, e.E_T, 1e-6, name + "E_T");
      check_relative(c.G_LT, e.G_LT, 1e-6, name + "G_LT");
      check_relative(c.nu_LT, e.nu_LT, 1e-6, name + "nu_LT");
      check_relative(c.nu_TT, e.nu_TT, 1e-6, name + "nu_TT");

      const CellProblemResult kubc
        = solve_cell(morphology, phases, BoundaryCondition::kubc);
      const CellProblemResult subc
        = solve_cell(morphology, phases, BoundaryCondition::subc);
      const double scale = exact.C.norm();
      const double lower
        = min_eigenvalue_of_symmetric_part(kubc.properties.C - exact.C) / scale;
      const double upper
        = min_eigenvalue_of_symmetric_part(exact.C - subc.properties.C) / scale;
      check(lower >= -1e-9,
            name
              + "C^KUBC - C_exact is positive semi-definite (min "
                "eigenvalue / |C| = "
              + std::to_string(lower) + ")");
      check(upper >= -1e-9,
            name
              + "C_exact - C^SUBC is positive semi-definite (min "
                "eigenvalue / |C| = "
              + std::to_string(upper) + ")");
    }
  return result();
}
