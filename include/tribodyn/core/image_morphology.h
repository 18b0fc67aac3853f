#ifndef tribodyn_core_image_morphology_h
#define tribodyn_core_image_morphology_h

#include <array>
#include <cstdint>
#include <deal.II/base/parameter_handler.h>
#include <string>
#include <tribodyn/core/parameter_binding.h>
#include <vector>

namespace tribodyn
{
  /**
   * How the pixels of an image (or the voxels of an image stack) become
   * phases: grey-level thresholds, Otsu's method or a colour table. The
   * entries are the same in "Morphology/Image" (2D) and "Morphology/Image
   * stack" (3D); add_to() adds them to either subsection's binding.
   */
  struct SegmentationParameters
  {
    enum class Segmentation
    {
      thresholds,  ///< grey-level thresholds given in the parameter file
      otsu,        ///< thresholds by Otsu's method (multi-level)
      colour_table ///< one colour (grey level, palette index, RGB) per phase
    };

    Segmentation segmentation = Segmentation::otsu;
    /// Increasing grey levels t_1 < ... < t_{N-1}: phase k holds the grey
    /// levels g with t_k <= g < t_{k+1} (t_0 = -inf, t_N = +inf).
    std::vector<double> thresholds;
    /// Number of phases Otsu's method separates (2 to 4).
    unsigned int n_otsu_phases = 2;
    /// Colour table: phase k is every pixel of colour colour_table[k]
    /// (one number: grey level, or palette index of an indexed image;
    /// three numbers: red, green, blue).
    std::vector<std::vector<unsigned int>> colour_table;

    /// Add the entries Segmentation, Thresholds, Otsu phases and Colour
    /// table to @p b, bound to the members above.
    void
    add_to(ParameterBinding &b);
    /// The checks that relate the entries (after @p b's parse): at least
    /// one threshold, increasing; at least two colours.
    void
    check(const ParameterBinding &b) const;
  };


  /**
   * Parameters of the subsection "Morphology/Image": a micrograph (PNG or
   * TIFF) turned into a material map. Each image pixel becomes one pixel
   * of the morphology; its material id is the phase the segmentation gives
   * it: 0, 1, 2, ... in the order of the thresholds (darkest first) or of
   * the entries of the colour table. The ids name the materials of
   * "Materials/Names" in the same order (theory and user guide:
   * doc/theory/homogenization.md, "Images as morphologies",
   * doc/user_guide/homogenization.md).
   */
  struct ImageParameters : SegmentationParameters
  {
    /// Path of the PNG or TIFF file (relative to the working directory).
    std::string file;
    /// Size of a pixel (m); 0 takes it from the image's resolution tag.
    double pixel_size = 0;
    /// Crop window in image pixels: left column, top row (from the image's
    /// top-left corner), width, height; all zero: the whole image.
    std::array<unsigned int, 4> crop = {{0, 0, 0, 0}};
    /// Placement: the cropped image turned by 0, 90, 180 or 270 degrees
    /// counter-clockwise before it becomes the map.
    unsigned int rotation = 0;

    /// The entries of "Morphology/Image", bound to the members above
    /// (their initial values are the defaults).
    ParameterBinding
    binding();

    /// Declare the subsection "Morphology/Image" (@p prm at the top level).
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Parse and check it (@p prm at the top level).
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };


  /**
   * A raster image as read from a PNG or TIFF file: grey, indexed
   * (palette) or RGB samples of 8 or 16 bits; alpha channels are dropped.
   * A multi-page TIFF read as a stack holds its pages one below the other:
   * page p's row r is row p height + r.
   */
  struct RasterImage
  {
    enum class Kind
    {
      grey,
      indexed,
      rgb
    };
    std::string  format; ///< "PNG" or "TIFF"
    Kind         kind      = Kind::grey;
    unsigned int width     = 0;
    unsigned int height    = 0;
    unsigned int bit_depth = 8; ///< of the samples after reading: 8 or 16
    unsigned int n_pages   = 1; ///< pages of a stack, each width x height
    /// Samples row-major, top row first (page after page): one per pixel (grey
    /// level or palette index) or three (R, G, B).
    std::vector<std::uint16_t> samples;
    /// Palette of an indexed image, 8-bit R, G, B.
    std::vector<std::array<unsigned int, 3>> palette;
    /// Pixel size from the resolution tag (m); 0 when the file has none.
    double pixel_width  = 0;
    double pixel_height = 0;

    /// Largest grey level: 255 or 65535 (255 for indexed images, whose
    /// grey level is that of the palette colour).
    unsigned int
    max_grey() const;
    /// Grey level of pixel (i, r), r counted from the top: the sample of a
    /// grey image, the luma 0.299 R + 0.587 G + 0.114 B (rounded) of an
    /// RGB pixel or of a palette colour.
    unsigned int
    grey(const unsigned int i, const unsigned int r) const;
    /// "PNG, 8-bit grey, 120 x 80 pixels", "TIFF, 16-bit grey, 32 x 32
    /// pixels, 24 pages" and so on.
    std::string
    description() const;
  };

  /// Read a PNG or TIFF file (told apart by their signatures, not by the
  /// file name): its first page, or with @p all_pages every page of a
  /// multi-page TIFF (a PNG has one). Throws InputError naming the file,
  /// @p parameter and the cause for a missing, unreadable, corrupt or
  /// unsupported file, and for pages of different sizes or pixel types.
  RasterImage
  read_raster_image(const std::string &file_name,
                    const std::string &parameter,
                    const bool         all_pages = false);

  /// Thresholds of Otsu's method for @p n_phases classes (2 to 4) on the
  /// 256-bin histogram of the grey levels @p grey (levels 0..@p max_grey):
  /// the n_phases - 1 thresholds (in grey levels) that maximise the
  /// between-class variance.
  std::vector<double>
  otsu_thresholds(const std::vector<unsigned int> &grey,
                  const unsigned int               max_grey,
                  const unsigned int               n_phases);

  /// A box of pixels of a RasterImage: columns x0 to x0 + nx - 1, rows y0
  /// to y0 + ny - 1 (from the top) of the pages z0 to z0 + nz - 1.
  struct PixelWindow
  {
    unsigned int x0 = 0, y0 = 0, z0 = 0, nx = 0, ny = 0, nz = 1;
  };

  /// The phases of the pixels of a window.
  struct PixelPhases
  {
    /// Material id of each pixel, page by page, each page row by row from
    /// the top, each row from the left.
    std::vector<unsigned int> ids;
    unsigned int              n_phases = 0;
    /// "Otsu thresholds 85, 170", "colour table of 3 colours", ...
    std::string how;
  };

  /**
   * Segment the pixels of @p window of @p image as @p parameters say (the
   * entries of the subsection @p section, e.g. "Morphology/Image/", of the
   * image file @p file). Throws InputError for a pixel in no entry of the
   * colour table and for a phase left empty.
   */
  PixelPhases
  segment_pixels(const RasterImage            &image,
                 const PixelWindow            &window,
                 const SegmentationParameters &parameters,
                 const std::string            &section,
                 const std::string            &file);

  /// A segmented image: material ids row-major from the bottom row, as
  /// Morphology stores them.
  struct SegmentedImage
  {
    unsigned int              n_x = 0, n_y = 0;
    double                    pixel_width = 0, pixel_height = 0;
    unsigned int              n_phases = 0;
    std::vector<unsigned int> ids;
    /// "image micrograph.png (PNG, 8-bit grey, ...), Otsu thresholds 85,
    /// 170".
    std::string description;
  };

  /// Read, crop and segment the image @p parameters describe. Throws
  /// InputError for a bad file, a crop window outside the image, a
  /// missing pixel size, a pixel in no entry of the colour table, or a
  /// phase left empty.
  SegmentedImage
  segment_image(const ImageParameters &parameters);
} // namespace tribodyn

#endif
