// Material input of the contact solver.
// (a) Engineering constants in the isotropic limit (E_L = E_T = E,
//     nu_LT = nu_TT = nu, G_LT = E / (2 (1 + nu))) give the isotropic
//     plane-strain stiffness and sigma_zz row (relative 1e-12).
// (b) The stiffness read from a homogenization summary.json equals the
//     file's numbers (1e-15) for KUBC and SUBC, and a pin built from it
//     has the critical time step of the same stiffness given directly as
//     'anisotropic' (1e-12).

#include "contact_test_tools.h"

#include <cmath>
#include <sstream>
#include <tribodyn/core/elastic_phase.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/material.h>

int
main(int argc, char **argv)
{
  using namespace tribodyn_test;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  {
    const IsotropicElasticMaterial iso{30e9, 0.2, 1770};
    dealii::Tensor<1, 3>           cz;
    const VoigtStiffness           C
      = TransverselyIsotropicConstants{30e9, 30e9, 0.2, 0.2, 30e9 / 2.4, 0}
          .plane_strain_voigt_stiffness(cz, "test");
    const auto reference = iso.plane_strain_voigt_stiffness();
    double     error     = 0;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        error = std::max(error, std::abs(C[i][j] - reference[i][j]));
    check(error < 1e-12 * reference[0][0],
          "isotropic limit of the engineering constants");
    check_relative(cz[0], iso.lambda(), 1e-12, "sigma_zz row c_z[0] = lambda");
    check_relative(cz[1], iso.lambda(), 1e-12, "sigma_zz row c_z[1] = lambda");
  }
  const std::string file
    = std::string(TRIBODYN_CONTACT_TEST_DIR) + "/homogenization_summary.json";
  {
    dealii::Tensor<1, 3> cz;
    const auto           C = read_homogenization_stiffness(file, "KUBC", cz);
    check(C[0][0] == 3.6e10 && C[0][2] == 1.0e7 && C[2][1] == -2.0e7
            && C[2][2] == 1.33e10 && cz[1] == 9.0e9,
          "KUBC stiffness and c_z read from summary.json");
    const auto S = read_homogenization_stiffness(file, "SUBC", cz);
    check(S[1][1] == 3.6e10 && cz[0] == 0, "SUBC stiffness read (no c_z)");
    bool refused = false;
    try
      {
        read_homogenization_stiffness(file, "periodic", cz);
      }
    catch (const InputError &e)
      {
        refused = std::string(e.what()).find("periodic") != std::string::npos;
      }
    check(refused, "a missing key is refused with its name");
  }
  {
    const std::string common = R"(
      subsection Geometry
        set Width = 2e-3
        set Height = 1e-3
      end
      subsection Output
        set Averaging start time = 0
      end
    )";
    ContactRun        from_file(common + R"(
      subsection Materials
        set Type = homogenization summary
        subsection Homogenization summary
          set File = )" + file
                         + R"(
        end
      end)");
    ContactRun        given(common + R"(
      subsection Materials
        set Type = anisotropic
        subsection Anisotropic
          set Stiffness = 3.6e10, 8.9e9, 1.0e7, 8.9e9, 3.7e10, -2.0e7, 1.0e7, -2.0e7, 1.33e10
        end
      end)");
    check_relative(from_file.solver->critical_time_step(),
                   given.solver->critical_time_step(),
                   1e-12,
                   "critical dt of the pin from summary.json");
  }
  return result();
}
