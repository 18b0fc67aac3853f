// The morphology source 'image': a segmented PNG or TIFF micrograph.
#include <tribodyn/core/morphology_sources/image.h>

namespace tribodyn
{
  void
  ImageMorphology::declare_subsections(dealii::ParameterHandler &prm) const
  {
    ImageParameters::declare_parameters(prm);
  }


  void
  ImageMorphology::parse(dealii::ParameterHandler &prm,
                         const ParameterBinding &,
                         MorphologyParameters &common)
  {
    image.parse_parameters(prm);
    // Read and segment the image now, so that a bad file is refused before
    // any output, and record its size as for a grid file.
    const SegmentedImage segmented = segment_image(image);
    common.n_pixels_x              = segmented.n_x;
    common.n_pixels_y              = segmented.n_y;
    common.width                   = segmented.n_x * segmented.pixel_width;
    common.height                  = segmented.n_y * segmented.pixel_height;
    prm.enter_subsection("Morphology");
    prm.set("Pixels in x", static_cast<long int>(common.n_pixels_x));
    prm.set("Pixels in y", static_cast<long int>(common.n_pixels_y));
    prm.set("Width", common.width);
    prm.set("Height", common.height);
    prm.leave_subsection();
  }


  Morphology
  ImageMorphology::create(const MorphologyParameters &) const
  {
    const SegmentedImage s = segment_image(image);
    return Morphology(s.n_x * s.pixel_width,
                      s.n_y * s.pixel_height,
                      s.n_x,
                      s.n_y,
                      s.ids,
                      s.description,
                      Morphology::connected_groups);
  }


  bool
  ImageMorphology::is_map() const
  {
    return true;
  }


  std::string
  ImageMorphology::phases_set_by() const
  {
    return "Morphology/Image/Segmentation";
  }


  static const bool image_morphology_registered = MorphologySources::add(
    {"image",
     5,
     "a segmented PNG or TIFF micrograph, any number of phases, see the "
     "subsection 'Image'",
     [] { return std::make_unique<ImageMorphology>(); }});
} // namespace tribodyn
