#ifndef tribodyn_tests_homogenization_image_tools_h
#define tribodyn_tests_homogenization_image_tools_h

#include "homogenization_test_tools.h"

#include <string>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/morphology_sources/image.h>
#include <tribodyn/core/phase_materials.h>

namespace tribodyn_test
{
  /// The test images (tests/homogenization/images, written by
  /// scripts/make_synthetic_images), found next to this header's source.
  inline std::string
  image_path(const std::string &name)
  {
    const std::string here = __FILE__;
    return here.substr(0, here.rfind('/')) + "/images/" + name;
  }

  /// The repository's root (for prm/homogenization/micrograph.png).
  inline std::string
  repository_path(const std::string &name)
  {
    const std::string here = __FILE__;
    return here.substr(0, here.rfind("/tests/")) + "/" + name;
  }

  /// Morphology parameters of an image segmented by Otsu's method.
  inline MorphologyParameters
  image_parameters(const std::string &file,
                   const unsigned int n_phases,
                   const double       pixel_size = 0)
  {
    MorphologyParameters p;
    ImageParameters     &image = p.use<ImageMorphology>().image;
    image.file                 = file;
    image.segmentation         = ImageParameters::Segmentation::otsu;
    image.n_otsu_phases        = n_phases;
    image.pixel_size           = pixel_size;
    return p;
  }

  /// Phases from (E, nu) pairs; E = 0 is a pore with the ersatz of
  /// @p pore_ratio.
  inline std::vector<ElasticPhase>
  named_phases(const std::vector<std::pair<double, double>> &constants,
               const double                                  pore_ratio = 1e-6)
  {
    PhaseMaterials m;
    m.pore_stiffness_ratio = pore_ratio;
    for (const auto &[E, nu] : constants)
      {
        m.names.push_back("phase " + std::to_string(m.names.size()));
        m.materials.push_back(IsotropicElasticMaterial{E, nu, 1000.});
        m.pore.push_back(E == 0);
      }
    return m.phases();
  }
} // namespace tribodyn_test

#endif
