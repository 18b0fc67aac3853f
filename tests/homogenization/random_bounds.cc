// On a random morphology (no exact solution), the exact identities and
// orderings that must hold (Huet 1990; Hill):
// - C is symmetric for each boundary condition (relative 1e-8: the
//   discrete problem is symmetric, the asymmetry is the CG tolerance);
// - C^Voigt >= C^KUBC >= C^periodic >= C^SUBC >= C^Reuss in the sense of
//   quadratic forms (min eigenvalue of each difference >= -1e-9 |C|);
// - the volume averages are exact: <eps> = E under KUBC and periodic,
//   <sigma> = Sigma under SUBC (relative 1e-9).

#include "homogenization_test_tools.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace tribodyn_test;

  const std::vector<ElasticPhase> phases = seed_phases();
  MorphologyParameters            p;
  p.width                     = 0.014;
  p.height                    = 0.004;
  p.n_pixels_x                = 140;
  p.n_pixels_y                = 40;
  p.volume_fraction           = 0.15;
  p.random_seed               = 3;
  const Morphology morphology = Morphology::create(p);
  const double     f          = morphology.heterogeneity_fraction();
  check(std::abs(f - 0.15) < 0.01,
        "random morphology reaches its target fraction (" + std::to_string(f)
          + " vs 0.15 +- 0.01)");

  const CellProblemResult kubc
    = solve_cell(morphology, phases, BoundaryCondition::kubc);
  const CellProblemResult periodic
    = solve_cell(morphology, phases, BoundaryCondition::periodic);
  const CellProblemResult subc
    = solve_cell(morphology, phases, BoundaryCondition::subc);
  const ApparentProperties voigt = voigt_estimate(phases, {1 - f, f});
  const ApparentProperties reuss = reuss_estimate(phases, {1 - f, f});

  for (const auto *r : {&kubc, &periodic, &subc})
    check_relative(matrix_relative_difference(r->properties.C,
                                              transpose(r->properties.C)),
                   0,
                   1e-8,
                   to_string(r->boundary_condition) + " C is symmetric",
                   1.);

  const double scale = kubc.properties.C.norm();
  const std::vector<std::pair<std::string, VoigtMatrix>> differences
    = {{"Voigt - KUBC", voigt.C - kubc.properties.C},
       {"KUBC - periodic", kubc.properties.C - periodic.properties.C},
       {"periodic - SUBC", periodic.properties.C - subc.properties.C},
       {"SUBC - Reuss", subc.properties.C - reuss.C}};
  for (const auto &d : differences)
    {
      const double m = min_eigenvalue_of_symmetric_part(d.second) / scale;
      check(m >= -1e-9,
            d.first + " is positive semi-definite (min eigenvalue / |C| = "
              + std::to_string(m) + ")");
    }

  for (unsigned int k = 0; k < 3; ++k)
    for (unsigned int i = 0; i < 3; ++i)
      {
        const double unit = (i == k ? 1. : 0.);
        check_relative(kubc.load_cases[k].mean_strain[i],
                       unit,
                       1e-9,
                       "KUBC <eps>[" + std::to_string(i) + "] case "
                         + std::to_string(k),
                       1.);
        check_relative(periodic.load_cases[k].mean_strain[i],
                       unit,
                       1e-9,
                       "periodic <eps>[" + std::to_string(i) + "] case "
                         + std::to_string(k),
                       1.);
        check_relative(subc.load_cases[k].mean_stress[i],
                       unit,
                       1e-9,
                       "SUBC <sigma>[" + std::to_string(i) + "] case "
                         + std::to_string(k),
                       1.);
      }
  return result();
}
