// A new 3D morphology source is one file (issue #52 item 6): this test adds
// a volume source the way a contributor would (a class and a registration
// line in this file, nothing else in tribodyn): 'checkerboard', cubes of
// `Morphology/Checker size` voxels, the heterogeneity on those whose
// (i + j + k) is odd. It checks that
//
// - `tribodyn --print-parameters volume_homogenization` lists it among the
//   choices of `Morphology/Generator`, with its text, and declares its
//   entry with its documentation;
// - a run with `Generator = checkerboard` reads the entry and uses the
//   volume the source makes: 8^3 voxels with cubes of 2 hold a
//   heterogeneity fraction of 1/2 (to 1e-12), and since the volume is
//   unchanged by every permutation of the axes, its apparent stiffness has
//   cubic symmetry under KUBC and SUBC: C11 = C22 = C33 and C44 = C55 = C66
//   (measured: to 7e-16 relative, round-off; allowed 1e-8, the solver's
//   tolerance), with C12 > 0 and C11 > C12;
// - the source's own check refuses a size that does not divide the
//   voxels, naming its entry (exit code 2).
#include "../run_parameter_text.h"
#include "../test_utilities.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/volume_source.h>

namespace
{
  using tribodyn::homogenization::VolumeMorphologyParameters;
  using tribodyn::homogenization::VoxelVolume;

  class CheckerboardVolume : public tribodyn::homogenization::VolumeSource
  {
  public:
    unsigned int size = 1;

    void
    bind(tribodyn::ParameterBinding &b) override
    {
      b.add("Checker size",
            size,
            "Edge of a checkerboard cube, in voxels (test plugin).",
            dealii::Patterns::Integer(1));
    }

    void
    parse(dealii::ParameterHandler &,
          const tribodyn::ParameterBinding &b,
          VolumeMorphologyParameters       &common) override
    {
      for (const unsigned int n : common.n_voxels)
        tribodyn::check_parameter(n % size == 0,
                                  b.path("Checker size"),
                                  "the cubes must tile the voxels.");
    }

    VoxelVolume
    create(const VolumeMorphologyParameters &p) const override
    {
      const auto               &n = p.n_voxels;
      std::vector<std::uint8_t> ids(static_cast<std::size_t>(n[0]) * n[1]
                                    * n[2]);
      std::size_t               v = 0;
      for (unsigned int k = 0; k < n[2]; ++k)
        for (unsigned int j = 0; j < n[1]; ++j)
          for (unsigned int i = 0; i < n[0]; ++i, ++v)
            ids[v] = (i / size + j / size + k / size) % 2;
      return VoxelVolume(n,
                         {{p.voxel_size, p.voxel_size, p.voxel_size}},
                         std::move(ids),
                         "checkerboard");
    }
  };

  const bool registered = tribodyn::homogenization::VolumeSources::add(
    {"checkerboard", 10, "cubes of 'Checker size' voxels", [] {
       return std::make_unique<CheckerboardVolume>();
     }});

  std::string
  prm(const unsigned int size)
  {
    return R"(
set Problem          = volume_homogenization
set Output directory = output-volume-source-plugin
subsection Morphology
  set Generator    = checkerboard
  set Checker size = )"
           + std::to_string(size) + R"(
  set Voxels in x  = 8
  set Voxels in y  = 8
  set Voxels in z  = 8
end
subsection Cell problem
  set Boundary conditions = KUBC, SUBC
  set Solver tolerance    = 1e-12
end
subsection Output
  set Plot script = none
end
)";
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using tribodyn_test::check;
  (void)registered;

  // The parameter reference.
  {
    int               code = 0;
    const std::string text
      = tribodyn_test::printed_parameters("volume_homogenization", code);
    check(code == 0
            && text.find("subsection 'Image stack'), 'checkerboard' (cubes "
                         "of 'Checker size' voxels).")
                 != std::string::npos,
          "the reference lists 'checkerboard' among the generators, with its "
          "text, after 'image stack' (order 10)");
    check(text.find("Edge of a checkerboard cube, in voxels (test plugin).")
              != std::string::npos
            && text.find("set Checker size") != std::string::npos,
          "the reference declares 'Checker size' with its documentation");
  }

  // A run on the plugin's volume.
  check(tribodyn_test::run_parameter_text("volume_source_plugin.prm", prm(2))
          == 0,
        "the run with 'Generator = checkerboard' succeeds");
  std::ifstream        in("output-volume-source-plugin/summary.json");
  const nlohmann::json summary  = nlohmann::json::parse(in);
  const double         fraction = summary.at("phases")[1].at("fraction");
  check(std::abs(fraction - 0.5) < 1e-12,
        "the volume is the source's: heterogeneity fraction 1/2 ("
          + tribodyn::format_number(fraction) + ")");
  for (const std::string bc : {"KUBC", "SUBC"})
    {
      const auto &C             = summary.at(bc).at("C");
      double      spread_normal = 0, spread_shear = 0;
      for (unsigned int a = 1; a < 3; ++a)
        {
          spread_normal
            = std::max(spread_normal,
                       std::abs(C[a][a].get<double>() - C[0][0].get<double>()));
          spread_shear = std::max(spread_shear,
                                  std::abs(C[3 + a][3 + a].get<double>()
                                           - C[3][3].get<double>()));
        }
      const double c11 = C[0][0], c12 = C[0][1], c44 = C[3][3];
      check(spread_normal <= 1e-8 * c11 && spread_shear <= 1e-8 * c44 && c12 > 0
              && c11 > c12,
            bc + ": cubic symmetry, C11 = C22 = C33 (to "
              + tribodyn::format_number(spread_normal / c11)
              + " relative) and C44 = C55 = C66 (to "
              + tribodyn::format_number(spread_shear / c44) + ")");
    }

  // The source's own refusal.
  std::string errors;
  const int   code
    = tribodyn_test::run_parameter_text("volume_source_plugin_bad.prm",
                                        prm(3),
                                        errors);
  check(code == 2
          && errors.find("'Morphology/Checker size'") != std::string::npos
          && errors.find("the cubes must tile the voxels") != std::string::npos,
        "a size of 3 on 8 voxels is refused naming 'Morphology/Checker "
        "size' (exit code "
          + std::to_string(code) + ")");
  return tribodyn_test::result();
}
