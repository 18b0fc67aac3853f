// The morphology source 'homogeneous': the matrix only.
#include <memory>
#include <tribodyn/core/morphology_source.h>

namespace tribodyn
{
  namespace
  {
    class HomogeneousMorphology : public MorphologySource
    {
    public:
      Morphology
      create(const MorphologyParameters &p) const override
      {
        const unsigned int nx = p.n_pixels_x, ny = p.n_pixels_y;
        return Morphology(p.width,
                          p.height,
                          nx,
                          ny,
                          std::vector<unsigned int>(static_cast<std::size_t>(nx)
                                                      * ny,
                                                    material_id::matrix),
                          "homogeneous matrix");
      }
    };
  } // namespace

  static const bool homogeneous_morphology_registered = MorphologySources::add(
    {"homogeneous", 1, "matrix only", [] {
       return std::make_unique<HomogeneousMorphology>();
     }});
} // namespace tribodyn
