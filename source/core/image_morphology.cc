// Micrographs as morphologies (issue #19 item 1): the parameters, cropping,
// and segmenting the pixels into phases by grey-level thresholds, Otsu's
// method or a colour table. The files are read in image_reader.cc. The theory
// is in doc/theory/homogenization.md, "Images as morphologies".
#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/image_morphology.h>
#include <tribodyn/core/number_list.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/selection.h>

namespace tribodyn
{
  namespace
  {
    using Segmentation = ImageParameters::Segmentation;
    constexpr SelectionTable<Segmentation, 3> segmentation_choices{
      {{"thresholds", Segmentation::thresholds},
       {"Otsu", Segmentation::otsu},
       {"colour table", Segmentation::colour_table}}};

    const std::string section = "Morphology/Image/";
  } // namespace


  void
  SegmentationParameters::add_to(ParameterBinding &b)
  {
    using dealii::Patterns::Anything;
    b.add("Segmentation",
          segmentation,
          "How pixels become phases (material ids 0, 1, ...): 'thresholds' "
          "(grey-level thresholds, see 'Thresholds'), 'Otsu' (thresholds by "
          "Otsu's method, see 'Otsu phases'), 'colour table' (one colour per "
          "phase, see 'Colour table'). RGB and indexed pixels are thresholded "
          "on their luma 0.299 R + 0.587 G + 0.114 B.",
          segmentation_choices);
    b.add("Thresholds",
          "",
          "Increasing grey levels t1, t2, ... (in the image's levels: 0-255 "
          "for 8 bits, 0-65535 for 16 bits): phase 0 is below t1, phase 1 in "
          "[t1, t2), ..., the last phase at or above the last threshold.",
          Anything(),
          [this, path = b.path("Thresholds")](const std::string &text) {
            thresholds = parse_number_list(text, path);
          });
    b.add("Otsu phases",
          n_otsu_phases,
          "Number of phases Otsu's method separates (2 to 4), darkest first.",
          dealii::Patterns::Integer(2, 4));
    b.add("Colour table",
          "",
          "Colours of phases 0, 1, ... separated by ';': one number (grey "
          "level of a grey image, palette index of an indexed one, or the "
          "grey R = G = B of an RGB one) or three (red green blue). Example: "
          "'0 0 0; 128 128 128; 255 255 255'. A pixel of another colour is an "
          "error.",
          Anything(),
          [this, path = b.path("Colour table")](const std::string &text) {
            colour_table.clear();
            for (const std::string &entry :
                 dealii::Utilities::split_string_list(text, ';'))
              {
                const std::vector<double> c = parse_number_list(entry, path);
                check_parameter(
                  (c.size() == 1 || c.size() == 3)
                    && std::all_of(c.begin(),
                                   c.end(),
                                   [](const double v) {
                                     return v >= 0 && v <= 65535
                                            && v == std::floor(v);
                                   }),
                  path,
                  "the entry '" + entry
                    + "' is not a colour: give one whole number (grey level "
                      "or palette index) or three (red green blue) per "
                      "phase, entries separated by ';'.");
                colour_table.emplace_back(c.begin(), c.end());
              }
          });
  }


  void
  SegmentationParameters::check(const ParameterBinding &b) const
  {
    if (segmentation == Segmentation::thresholds)
      {
        check_parameter(!thresholds.empty(),
                        b.path("Thresholds"),
                        "'Segmentation = thresholds' needs at least one "
                        "grey level (two phases).");
        for (unsigned int k = 1; k < thresholds.size(); ++k)
          check_parameter(thresholds[k] > thresholds[k - 1],
                          b.path("Thresholds"),
                          "the thresholds must increase.");
      }
    if (segmentation == Segmentation::colour_table)
      check_parameter(colour_table.size() >= 2,
                      b.path("Colour table"),
                      "'Segmentation = colour table' needs the colours of at "
                      "least two phases, separated by ';'.");
  }


  ParameterBinding
  ImageParameters::binding()
  {
    using dealii::Patterns::Anything;
    ParameterBinding b(section);
    b.add("File",
          file,
          "PNG or TIFF micrograph ('Generator = image'): 8- or 16-bit grey, "
          "indexed (palette) or RGB; alpha is ignored; a TIFF must be in "
          "strips (not tiles). Each image pixel is one pixel of the "
          "morphology; the top row of the image is the top of the rectangle.");
    b.add("Pixel size",
          pixel_size,
          "Size of an image pixel in m; 0 takes it from the image's "
          "resolution tag (TIFF XResolution/YResolution with ResolutionUnit "
          "inch or cm, PNG pHYs in pixels per metre). Sets the rectangle's "
          "size: 'Width' and 'Height' are not used.",
          dealii::Patterns::Double(0));
    add_to(b);
    b.add("Crop",
          "",
          "Optional window of the image, in pixels: left column, top row "
          "(from the image's top-left corner), width, height. Empty: the "
          "whole image.",
          Anything(),
          [this, path = b.path("Crop")](const std::string &text) {
            const std::vector<double> c = parse_number_list(text, path);
            check_parameter(c.empty()
                              || (c.size() == 4 && c[0] >= 0 && c[1] >= 0
                                  && c[2] >= 1 && c[3] >= 1),
                            path,
                            "give four whole numbers (left column, top row, "
                            "width >= 1, height >= 1) or nothing for the "
                            "whole image.");
            crop = {{0, 0, 0, 0}};
            for (unsigned int k = 0; k < c.size(); ++k)
              crop[k] = static_cast<unsigned int>(c[k]);
          });
    b.add("Rotation",
          "0",
          "Placement of the (cropped) image on the rectangle: turned by this "
          "many degrees counter-clockwise (0, 90, 180 or 270) before it "
          "becomes the map, so that any side of a micrograph can face the "
          "sliding plane (a pin's bottom row; x is the sliding direction). "
          "90 and 270 swap the map's width and height.",
          dealii::Patterns::Selection("0|90|180|270"),
          [this](const std::string &text) {
            rotation = static_cast<unsigned int>(std::stoi(text));
          });
    return b;
  }


  void
  ImageParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    ImageParameters().binding().declare(prm);
  }


  void
  ImageParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    const ParameterBinding b = binding();
    b.parse(prm);
    check_parameter(!file.empty(),
                    b.path("File"),
                    "'Generator = image' needs the path of a PNG or TIFF "
                    "file.");
    check(b);
  }


  std::vector<double>
  otsu_thresholds(const std::vector<unsigned int> &grey,
                  const unsigned int               max_grey,
                  const unsigned int               n_phases)
  {
    // Histogram of 256 bins (a 16-bit image's levels 256 to a bin), then
    // the class boundaries b_1 < ... < b_{N-1} (class k holds the bins
    // [b_k, b_{k+1})) that maximise sum_k w_k m_k^2, the between-class
    // variance up to a constant (w_k: weight, m_k: mean bin of class k).
    const unsigned int  n_bins = 256;
    const double        scale  = (max_grey + 1.) / n_bins;
    std::vector<double> w(n_bins + 1, 0.), m(n_bins + 1, 0.); // prefix sums
    {
      std::vector<double> histogram(n_bins, 0.);
      for (const unsigned int g : grey)
        histogram[std::min(n_bins - 1, static_cast<unsigned int>(g / scale))]
          += 1;
      for (unsigned int b = 0; b < n_bins; ++b)
        {
          w[b + 1] = w[b] + histogram[b];
          m[b + 1] = m[b] + b * histogram[b];
        }
    }
    const auto term = [&](const unsigned int from, const unsigned int to) {
      const double weight = w[to] - w[from];
      return weight > 0 ? (m[to] - m[from]) * (m[to] - m[from]) / weight : 0.;
    };
    std::vector<unsigned int> best(n_phases - 1), current(n_phases - 1);
    double                    best_value = -1;
    // Exhaustive search over the boundaries (C(255, N-1) sets: 2.7e6 for 4
    // phases, a fraction of a second).
    const auto search = [&](auto             &&self,
                            const unsigned int level,
                            const unsigned int from,
                            const double       value) -> void {
      if (level == n_phases - 1)
        {
          const double total = value + term(from, n_bins);
          if (total > best_value)
            {
              best_value = total;
              best       = current;
            }
          return;
        }
      for (unsigned int b = from + 1; b + (n_phases - 2 - level) < n_bins; ++b)
        {
          current[level] = b;
          self(self, level + 1, b, value + term(from, b));
        }
    };
    search(search, 0, 0, 0.);
    std::vector<double> thresholds;
    for (const unsigned int b : best)
      thresholds.push_back(b * scale);
    return thresholds;
  }


  PixelPhases
  segment_pixels(const RasterImage            &image,
                 const PixelWindow            &w,
                 const SegmentationParameters &p,
                 const std::string            &section,
                 const std::string            &file)
  {
    // the image row (from the top of the first page) of row r of page z
    // of the window
    const auto row = [&](const unsigned int z, const unsigned int r) {
      return (w.z0 + z) * image.height + w.y0 + r;
    };
    std::vector<unsigned int> grey(std::size_t(w.nx) * w.ny * w.nz);
    for (unsigned int z = 0, k = 0; z < w.nz; ++z)
      for (unsigned int r = 0; r < w.ny; ++r)
        for (unsigned int i = 0; i < w.nx; ++i, ++k)
          grey[k] = image.grey(w.x0 + i, row(z, r));

    PixelPhases                s;
    std::vector<unsigned int> &ids = s.ids;
    ids.resize(grey.size());
    std::ostringstream       how;
    std::vector<std::string> phase_rule; // for the empty-phase message
    if (p.segmentation == Segmentation::colour_table)
      {
        s.n_phases = p.colour_table.size();
        for (const auto &c : p.colour_table)
          phase_rule.push_back("colour '"
                               + (c.size() == 1 ? std::to_string(c[0])
                                                : std::to_string(c[0]) + " "
                                                    + std::to_string(c[1]) + " "
                                                    + std::to_string(c[2]))
                               + "'");
        for (unsigned int z = 0, n = 0; z < w.nz; ++z)
          for (unsigned int r = 0; r < w.ny; ++r)
            for (unsigned int i = 0; i < w.nx; ++i, ++n)
              {
                const std::size_t k
                  = std::size_t(row(z, r)) * image.width + w.x0 + i;
                std::array<unsigned int, 3> rgb;
                unsigned int                single;
                if (image.kind == RasterImage::Kind::rgb)
                  {
                    rgb    = {{image.samples[3 * k],
                               image.samples[3 * k + 1],
                               image.samples[3 * k + 2]}};
                    single = (rgb[0] == rgb[1] && rgb[1] == rgb[2]) ? rgb[0]
                                                                    : 1u << 20;
                  }
                else if (image.kind == RasterImage::Kind::indexed)
                  {
                    single = image.samples[k];
                    rgb    = image.palette.at(single);
                  }
                else
                  {
                    single = image.samples[k];
                    rgb    = {{single, single, single}};
                  }
                unsigned int phase = s.n_phases;
                for (unsigned int q = 0; q < s.n_phases && phase == s.n_phases;
                     ++q)
                  {
                    const auto &c = p.colour_table[q];
                    if ((c.size() == 1 && c[0] == single)
                        || (c.size() == 3 && c[0] == rgb[0] && c[1] == rgb[1]
                            && c[2] == rgb[2]))
                      phase = q;
                  }
                if (phase == s.n_phases)
                  throw InputError(
                    "Pixel (column " + std::to_string(w.x0 + i) + ", row "
                    + std::to_string(w.y0 + r) + " from the top"
                    + (image.n_pages > 1 ? ", page " + std::to_string(w.z0 + z)
                                         : std::string())
                    + ") of the image '" + file + "' has the colour "
                    + (image.kind == RasterImage::Kind::grey
                         ? "grey " + std::to_string(single)
                         : std::to_string(rgb[0]) + " " + std::to_string(rgb[1])
                             + " " + std::to_string(rgb[2])
                             + (image.kind == RasterImage::Kind::indexed
                                  ? " (index " + std::to_string(single) + ")"
                                  : ""))
                    + ", which is in no entry of '" + section
                    + "Colour table'. Add it to the entry of its phase's "
                      "colour or use 'Segmentation = thresholds'.");
                ids[n] = phase;
              }
        how << "colour table of " << s.n_phases << " colours";
      }
    else
      {
        std::vector<double> t = p.thresholds;
        if (p.segmentation == Segmentation::otsu)
          {
            t = otsu_thresholds(grey, image.max_grey(), p.n_otsu_phases);
            how << "Otsu thresholds";
          }
        else
          how << "thresholds";
        for (unsigned int k = 0; k < t.size(); ++k)
          how << (k == 0 ? " " : ", ") << t[k];
        s.n_phases = t.size() + 1;
        for (unsigned int k = 0; k <= t.size(); ++k)
          phase_rule.push_back(
            "grey levels "
            + (k == 0 ? std::string("below ") + format_number(t[0])
               : k == t.size()
                 ? std::string("at or above ") + format_number(t[k - 1])
                 : "in [" + format_number(t[k - 1]) + ", " + format_number(t[k])
                     + ")"));
        for (std::size_t k = 0; k < grey.size(); ++k)
          ids[k]
            = std::upper_bound(t.begin(), t.end(), double(grey[k])) - t.begin();
      }
    s.how = how.str();

    const bool cropped
      = w.nx < image.width || w.ny < image.height || w.nz < image.n_pages;
    std::vector<std::size_t> count(s.n_phases, 0);
    for (const unsigned int id : ids)
      ++count[id];
    for (unsigned int k = 0; k < s.n_phases; ++k)
      if (count[k] == 0)
        throw InputError(
          "The segmentation of the image '" + file + "' (" + s.how
          + ") leaves phase " + std::to_string(k) + " (" + phase_rule[k]
          + ") empty: no pixel"
          + (cropped ? " of the crop window" : std::string())
          + " falls in it. Change '" + section
          + (p.segmentation == Segmentation::colour_table ? "Colour table"
             : p.segmentation == Segmentation::otsu       ? "Otsu phases"
                                                          : "Thresholds")
          + "' (the image's grey levels span "
          + std::to_string(*std::min_element(grey.begin(), grey.end())) + " to "
          + std::to_string(*std::max_element(grey.begin(), grey.end()))
          + ") so that every phase has pixels.");
    return s;
  }


  SegmentedImage
  segment_image(const ImageParameters &p)
  {
    const RasterImage image = read_raster_image(p.file, section + "File");

    // Crop window (image rows counted from the top).
    unsigned int x0 = 0, y0 = 0, nx = image.width, ny = image.height;
    if (p.crop[2] > 0)
      {
        x0 = p.crop[0];
        y0 = p.crop[1];
        nx = p.crop[2];
        ny = p.crop[3];
        check_parameter(std::size_t(x0) + nx <= image.width
                          && std::size_t(y0) + ny <= image.height,
                        section + "Crop",
                        "the window (" + std::to_string(x0) + ", "
                          + std::to_string(y0) + ", " + std::to_string(nx)
                          + ", " + std::to_string(ny)
                          + ") does not fit in the image '" + p.file + "' of "
                          + std::to_string(image.width) + " x "
                          + std::to_string(image.height)
                          + " pixels. Give left column, top row, width and "
                            "height inside the image.");
      }

    SegmentedImage s;
    s.n_x          = nx;
    s.n_y          = ny;
    s.pixel_width  = p.pixel_size > 0 ? p.pixel_size : image.pixel_width;
    s.pixel_height = p.pixel_size > 0 ? p.pixel_size : image.pixel_height;
    check_parameter(s.pixel_width > 0 && s.pixel_height > 0,
                    section + "Pixel size",
                    "the image '" + p.file
                      + "' has no resolution tag (in inch, cm or m), so its "
                        "pixel size is unknown. Give the size of a pixel in "
                        "m.");

    // Ids in image order (top row first), then turned and flipped to
    // bottom-first.
    PixelPhases phases = segment_pixels(
      image, PixelWindow{x0, y0, 0, nx, ny, 1}, p, section, p.file);
    const std::vector<unsigned int> &ids = phases.ids;
    s.n_phases                           = phases.n_phases;

    // Turned counter-clockwise by 'Rotation' (pixel (i, r) of the window,
    // r from the top, goes to (i', r') of the turned one), then stored from
    // the bottom row up.
    const bool quarter = p.rotation == 90 || p.rotation == 270;
    s.n_x              = quarter ? ny : nx;
    s.n_y              = quarter ? nx : ny;
    if (quarter)
      std::swap(s.pixel_width, s.pixel_height);
    s.ids.resize(ids.size());
    for (unsigned int r = 0; r < ny; ++r)
      for (unsigned int i = 0; i < nx; ++i)
        {
          const unsigned int i_turned = p.rotation == 90    ? r
                                        : p.rotation == 180 ? nx - 1 - i
                                        : p.rotation == 270 ? ny - 1 - r
                                                            : i;
          const unsigned int r_turned = p.rotation == 90    ? nx - 1 - i
                                        : p.rotation == 180 ? ny - 1 - r
                                        : p.rotation == 270 ? i
                                                            : r;
          s.ids[std::size_t(s.n_y - 1 - r_turned) * s.n_x + i_turned]
            = ids[std::size_t(r) * nx + i];
        }
    std::ostringstream d;
    d << "image " << p.file << " (" << image.description();
    if (p.crop[2] > 0)
      d << ", crop " << x0 << " " << y0 << " " << nx << " " << ny;
    if (p.rotation != 0)
      d << ", turned " << p.rotation << " degrees counter-clockwise";
    d << "; " << phases.how << ")";
    s.description = d.str();
    return s;
  }
} // namespace tribodyn
