// The error of the pores' ersatz stiffness (issue #19 item 2). Pores (E =
// 0) get E = r E_min (E_min: softest solid phase), nu = 0. On the example
// micrograph (prm/homogenization/micrograph.png: pores, matrix 30 GPa,
// fibres 230 GPa; no pore touches the edges) the periodic, KUBC and SUBC
// apparent stiffnesses are computed for r = 1e-4, 1e-6 and 1e-8. The
// error of r = 1e-6 is measured as |C(1e-6) - C(1e-8)| / |C(1e-8)| (largest
// entry difference over largest entry), and must be below 1e-6; the
// change from 1e-4 to 1e-6 must be about 100 times larger (between 30
// and 300 times): the error is linear in r, so r = 1e-8 stands for the
// zero-stiffness limit to 1 % of the measured error.

#include "image_test_tools.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace tribodyn_test;

  const Morphology morphology = Morphology::create(
    image_parameters(repository_path("prm/homogenization/micrograph.png"), 3));
  const auto f = morphology.phase_fractions();
  std::cout << "phase fractions " << f[0] << ", " << f[1] << ", " << f[2]
            << std::endl;
  check(f[0] > 0.01 && f[0] < 0.1, "micrograph: pore fraction in (0.01, 0.1)");

  for (const auto bc : {BoundaryCondition::periodic,
                        BoundaryCondition::kubc,
                        BoundaryCondition::subc})
    {
      std::vector<VoigtMatrix> C;
      for (const double r : {1e-4, 1e-6, 1e-8})
        {
          const auto phases
            = named_phases({{0, 0}, {30e9, 0.35}, {230e9, 0.2}}, r);
          const CellProblemResult result
            = solve_cell(morphology, phases, bc, 1, 1e-12);
          C.push_back(result.properties.C);
          std::cout << to_string(bc) << ", r = " << r << ": C11 "
                    << C.back()[0][0] / 1e9 << " GPa, C22 "
                    << C.back()[1][1] / 1e9 << " GPa, C66 "
                    << C.back()[2][2] / 1e9 << " GPa, CG iterations "
                    << result.load_cases[0].cg_iterations << ", "
                    << result.load_cases[1].cg_iterations << ", "
                    << result.load_cases[2].cg_iterations << std::endl;
        }
      const double      error_6 = matrix_relative_difference(C[1], C[2]);
      const double      error_4 = matrix_relative_difference(C[0], C[2]);
      const std::string name    = to_string(bc);
      const auto        sci     = [](const double v) {
        std::ostringstream o;
        o << std::scientific << std::setprecision(3) << v;
        return o.str();
      };
      check(error_6 < 1e-6,
            name + ": error of r = 1e-6, |C(1e-6) - C(1e-8)|/|C| = "
              + sci(error_6) + " < 1e-6 (r = 1e-4: " + sci(error_4) + ")");
      check(error_4 > 30 * error_6 && error_4 < 300 * error_6,
            name + ": linear in r: error(1e-4)/error(1e-6) = "
              + std::to_string(error_4 / error_6) + " in (30, 300)");
    }
  return result();
}
