#ifndef tribodyn_core_morphology_sources_image_h
#define tribodyn_core_morphology_sources_image_h

#include <tribodyn/core/image_morphology.h>
#include <tribodyn/core/morphology_source.h>

namespace tribodyn
{
  /**
   * The morphology source 'image': a PNG or TIFF micrograph, segmented into
   * any number of phases (its subsection `Morphology/Image`:
   * ImageParameters), each image pixel one pixel of the map; the image sets
   * the rectangle's size and pixels.
   */
  class ImageMorphology : public MorphologySource
  {
  public:
    /// File, pixel size, segmentation, crop, placement.
    ImageParameters image;

    void
    declare_subsections(dealii::ParameterHandler &prm) const override;
    void
    parse(dealii::ParameterHandler &prm,
          const ParameterBinding   &b,
          MorphologyParameters     &common) override;
    Morphology
    create(const MorphologyParameters &common) const override;
    bool
    is_map() const override;
    std::string
    phases_set_by() const override;
  };
} // namespace tribodyn

#endif
