// One map in every supported format gives one morphology (issue #19): the
// small noisy three-level map of scripts/make_synthetic_images as PNG and
// TIFF, each 8-bit grey, 16-bit grey, indexed and RGB, plus Deflate, LZW
// and PackBits TIFFs, a big-endian 16-bit TIFF, a MinIsWhite TIFF, a 2-bit
// palette PNG, grey + alpha and RGBA PNGs (a varying alpha, which the
// reader drops) and an Adam7-interlaced PNG.
// Segmented by Otsu's method into three phases, all seventeen must give the
// material map of the 8-bit grey PNG pixel for pixel, and the pixel size of
// their resolution tags (PNG pHYs 1e6 per m, TIFF 1e4 per cm) must be 1 um.
// (The 16-bit files hold the 8-bit level in the high byte and a varying low
// byte, so a wrong byte order changes the map.) Also: 16-bit thresholds in
// 16-bit levels, and a crop window, which must give the window of the full
// map.

#include "image_test_tools.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace tribodyn_test;

  const Morphology reference
    = Morphology::create(image_parameters(image_path("formats_grey8.png"), 3));
  const auto fractions = reference.phase_fractions();
  check(reference.n_pixels_x() == 32 && reference.n_pixels_y() == 24
          && fractions.size() == 3 && fractions[0] > 0.2 && fractions[1] > 0.2
          && fractions[2] > 0.2,
        "formats_grey8.png: 32 x 24 pixels, three phases of fractions "
          + std::to_string(fractions[0]) + ", " + std::to_string(fractions[1])
          + ", " + std::to_string(fractions[2]));

  const auto same = [&](const Morphology &m, const std::string &what) {
    unsigned int differences = 0;
    if (m.n_pixels_x() != reference.n_pixels_x()
        || m.n_pixels_y() != reference.n_pixels_y())
      differences = 1u << 30;
    else
      for (unsigned int j = 0; j < m.n_pixels_y(); ++j)
        for (unsigned int i = 0; i < m.n_pixels_x(); ++i)
          differences += m.pixel(i, j) != reference.pixel(i, j);
    check(differences == 0,
          what + ": same material map as formats_grey8.png ("
            + std::to_string(differences) + " pixels differ)");
    check_relative(m.pixel_width(), 1e-6, 1e-9, what + ": pixel width (m)");
    check_relative(m.pixel_height(), 1e-6, 1e-9, what + ": pixel height (m)");
  };
  for (const std::string ext : {"png", "tif"})
    for (const std::string kind : {"grey8", "grey16", "indexed", "rgb"})
      {
        const std::string name = "formats_" + kind + "." + ext;
        same(Morphology::create(image_parameters(image_path(name), 3)), name);
      }
  // Other layouts: Deflate, LZW and PackBits strips, big-endian 16 bits,
  // MinIsWhite, a 2-bit palette PNG of the three classes, alpha channels,
  // interlacing.
  for (const std::string name : {"formats_deflate.tif",
                                 "formats_lzw.tif",
                                 "formats_packbits.tif",
                                 "formats_grey16_big_endian.tif",
                                 "formats_min_is_white.tif",
                                 "formats_indexed2.png",
                                 "formats_grey_alpha.png",
                                 "formats_rgba.png",
                                 "formats_interlaced.png"})
    same(Morphology::create(image_parameters(image_path(name), 3)), name);

  // Thresholds of a 16-bit image are in 16-bit levels.
  {
    const RasterImage image
      = read_raster_image(image_path("formats_grey16.tif"), "test");
    check(image.bit_depth == 16 && image.max_grey() == 65535,
          "formats_grey16.tif reads as 16-bit grey");
    MorphologyParameters p
      = image_parameters(image_path("formats_grey16.png"), 3);
    ImageParameters &segmented = p.edit<ImageMorphology>().image;
    segmented.segmentation     = ImageParameters::Segmentation::thresholds;
    segmented.thresholds       = {80 * 256, 175 * 256};
    same(Morphology::create(p), "formats_grey16.png, thresholds 20480, 44800");
  }

  // A crop window is the window of the full map (rows from the top).
  {
    MorphologyParameters p
      = image_parameters(image_path("formats_grey8.png"), 3);
    ImageParameters &image = p.edit<ImageMorphology>().image;
    image.segmentation     = ImageParameters::Segmentation::thresholds;
    image.thresholds       = {80, 175};
    image.crop             = {{5, 3, 20, 12}};
    const Morphology m     = Morphology::create(p);
    bool             ok    = m.n_pixels_x() == 20 && m.n_pixels_y() == 12;
    for (unsigned int j = 0; ok && j < 12; ++j)
      for (unsigned int i = 0; ok && i < 20; ++i)
        ok = m.pixel(i, j) == reference.pixel(5 + i, 24 - 3 - 12 + j);
    check(ok, "crop 5 3 20 12 is the window of the full map");
  }
  return result();
}
