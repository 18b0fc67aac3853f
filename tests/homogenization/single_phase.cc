// A single-phase "composite" must return its own constants under every
// boundary condition: u = E x (KUBC, periodic) and the uniform stress
// (SUBC) are exact discrete solutions, so the only error is the CG
// tolerance (1e-12) and round-off. Tolerance: relative 1e-8 (issue #2).

#include "homogenization_test_tools.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace tribodyn_test;

  const IsotropicElasticMaterial  material{30e9, 0.2, 1770.};
  const std::vector<ElasticPhase> phases = {material, material};
  MorphologyParameters            p;
  p.source                    = MorphologySources::create("homogeneous");
  p.n_pixels_x                = 28;
  p.n_pixels_y                = 8;
  const Morphology morphology = Morphology::create(p);

  const double G = material.youngs_modulus / (2 * (1 + material.poisson_ratio));
  for (const BoundaryCondition bc : {BoundaryCondition::kubc,
                                     BoundaryCondition::subc,
                                     BoundaryCondition::periodic})
    {
      const CellProblemResult r    = solve_cell(morphology, phases, bc);
      const auto             &c    = r.properties.constants;
      const std::string       name = to_string(bc);
      check_relative(c.E_L, material.youngs_modulus, 1e-8, name + " E_L");
      check_relative(c.E_T, material.youngs_modulus, 1e-8, name + " E_T");
      check_relative(c.nu_LT, material.poisson_ratio, 1e-8, name + " nu_LT");
      check_relative(c.nu_TT, material.poisson_ratio, 1e-8, name + " nu_TT");
      check_relative(c.G_LT, G, 1e-8, name + " G_LT");
      check_relative(matrix_relative_difference(
                       r.properties.C, material.plane_strain_voigt_stiffness()),
                     0,
                     1e-8,
                     name + " C equals the plane-strain stiffness",
                     1.);
    }

  // And with a second phase of the same constants but a random layout:
  // the result must not depend on the morphology.
  MorphologyParameters random        = p;
  random.n_pixels_x                  = 56; // pixels of 0.1 mm
  random.n_pixels_y                  = 16;
  random.width                       = 0.0056;
  random.height                      = 0.0016;
  auto &random_source                = random.use<RandomVerticalMorphology>();
  random_source.inclusion_min_height = 0.0004;
  random_source.inclusion_max_height = 0.0012;
  const Morphology        random_morphology = Morphology::create(random);
  const CellProblemResult r
    = solve_cell(random_morphology, phases, BoundaryCondition::kubc);
  check_relative(r.properties.constants.E_L,
                 material.youngs_modulus,
                 1e-8,
                 "KUBC E_L on a random layout of identical phases");
  return result();
}
