// The morphology source 'random vertical': random non-overlapping vertical
// heterogeneities (seed 001, Fig. 1).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deal.II/base/utilities.h>
#include <limits>
#include <random>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/morphology_sources/random_vertical.h>
#include <tribodyn/core/output.h>

namespace tribodyn
{
  namespace
  {
    /// Uniform integer in [low, high] from a 32-bit generator (the bias of
    /// the multiply-shift method is below 1e-9 for the ranges used here).
    unsigned int
    uniform_integer(std::mt19937      &rng,
                    const unsigned int low,
                    const unsigned int high)
    {
      const std::uint64_t range = static_cast<std::uint64_t>(high) - low + 1;
      return low
             + static_cast<unsigned int>(
               (static_cast<std::uint64_t>(rng()) * range) >> 32);
    }


    /// Number of whole pixels of size @p pixel in @p length, checking that
    /// @p length is a multiple of @p pixel.
    unsigned int
    pixels_exact(const double       length,
                 const double       pixel,
                 const std::string &name)
    {
      const double       ratio = length / pixel;
      const unsigned int n     = static_cast<unsigned int>(std::lround(ratio));
      check_parameter(n >= 1 && std::abs(ratio - n) < 1e-6 * ratio,
                      name,
                      "the value " + format_number(length)
                        + " m is not a whole number of pixels of "
                        + format_number(pixel)
                        + " m. Change it or the number of pixels so that the "
                          "heterogeneity boundaries fall on pixel edges.");
      return n;
    }
  } // namespace


  void
  RandomVerticalMorphology::bind(ParameterBinding &b)
  {
    using dealii::Patterns::Double;
    // The reference spells the defaults 0.0001, 0.0012, 0.0036, where
    // exact_number() would write 1e-4, ...: they are written by
    // format_number() from the members and read as
    // ParameterHandler::get_double() reads.
    const auto number = [](double &value) {
      return [&value](const std::string &text) {
        value = dealii::Utilities::string_to_double(text);
      };
    };
    b.add("Heterogeneity width",
          format_number(inclusion_width),
          "Width (along x) of each random vertical heterogeneity, in m; a "
          "multiple of the pixel width.",
          Double(),
          number(inclusion_width));
    b.add("Heterogeneity min height",
          format_number(inclusion_min_height),
          "Smallest height of a random vertical heterogeneity, in m (rounded "
          "up to whole pixels).",
          Double(),
          number(inclusion_min_height));
    b.add("Heterogeneity max height",
          format_number(inclusion_max_height),
          "Largest height of a random vertical heterogeneity, in m (rounded "
          "down to whole pixels).",
          Double(),
          number(inclusion_max_height));
  }


  void
  RandomVerticalMorphology::parse(dealii::ParameterHandler &,
                                  const ParameterBinding &b,
                                  MorphologyParameters   &common)
  {
    common.check_volume_fraction(b);
    check_parameter_range(b.path("Heterogeneity width"),
                          inclusion_width,
                          0,
                          common.width,
                          true,
                          false);
    check_parameter_range(b.path("Heterogeneity min height"),
                          inclusion_min_height,
                          0,
                          common.height,
                          true,
                          false);
    check_parameter_range(b.path("Heterogeneity max height"),
                          inclusion_max_height,
                          inclusion_min_height,
                          common.height,
                          false,
                          false,
                          "It must be at least the min height and at most "
                          "the rectangle's height.");
  }


  bool
  RandomVerticalMorphology::uses_seed() const
  {
    return true;
  }


  Morphology
  RandomVerticalMorphology::create(const MorphologyParameters &p) const
  {
    // Each heterogeneity is a rectangle of w pixels by a random number of
    // pixels in [h_min, h_max]; a candidate is rejected if it touches or
    // overlaps one already placed (a one-pixel gap keeps them distinct).
    // Placement stops when the area is closest to the target.
    const unsigned int        nx = p.n_pixels_x, ny = p.n_pixels_y;
    std::vector<unsigned int> ids(static_cast<std::size_t>(nx) * ny,
                                  material_id::matrix);
    const double              hx = p.width / nx, hy = p.height / ny;
    const unsigned int        w
      = pixels_exact(inclusion_width, hx, "Morphology/Heterogeneity width");
    const unsigned int h_min
      = static_cast<unsigned int>(std::ceil(inclusion_min_height / hy - 1e-9));
    const unsigned int h_max
      = static_cast<unsigned int>(std::floor(inclusion_max_height / hy + 1e-9));
    check_parameter(h_min >= 1 && h_min <= h_max && h_max <= ny,
                    "Morphology/Heterogeneity min height",
                    "the height range [" + format_number(inclusion_min_height)
                      + ", " + format_number(inclusion_max_height)
                      + "] m holds no whole number of pixels of height "
                      + format_number(hy) + " m.");
    check_parameter(w + 2 <= nx,
                    "Morphology/Heterogeneity width",
                    "the heterogeneities are as wide as the rectangle.");

    const double target_area = p.volume_fraction * static_cast<double>(nx) * ny;
    std::vector<bool>   occupied_or_near(static_cast<std::size_t>(nx) * ny,
                                       false);
    std::mt19937        rng(p.random_seed);
    double              area         = 0;
    unsigned int        n_placed     = 0;
    unsigned long       attempts     = 0;
    const unsigned long max_attempts = 1000000;
    while (attempts < max_attempts)
      {
        ++attempts;
        const unsigned int h  = uniform_integer(rng, h_min, h_max);
        const unsigned int x0 = uniform_integer(rng, 0, nx - w);
        const unsigned int y0 = uniform_integer(rng, 0, ny - h);
        if (area + w * h > target_area + 0.5 * w * h)
          {
            // This one would overshoot more than it helps: stop if even the
            // smallest one would overshoot, else draw another.
            if (area + 0.5 * w * h_min >= target_area)
              break;
            continue;
          }
        bool free = true;
        for (unsigned int j = y0; j < y0 + h && free; ++j)
          for (unsigned int i = x0; i < x0 + w && free; ++i)
            free = !occupied_or_near[j * nx + i];
        if (!free)
          continue;
        for (unsigned int j = y0; j < y0 + h; ++j)
          for (unsigned int i = x0; i < x0 + w; ++i)
            ids[j * nx + i] = material_id::heterogeneity;
        // Mark the placed rectangle grown by one pixel as unavailable.
        for (unsigned int j = (y0 > 0 ? y0 - 1 : 0);
             j < std::min(ny, y0 + h + 1);
             ++j)
          for (unsigned int i = (x0 > 0 ? x0 - 1 : 0);
               i < std::min(nx, x0 + w + 1);
               ++i)
            occupied_or_near[j * nx + i] = true;
        area += w * h;
        ++n_placed;
      }
    if (attempts >= max_attempts && std::abs(area - target_area) > w * h_max)
      throw InputError(
        "Could not place non-overlapping heterogeneities up to the volume "
        "fraction "
        + format_number(p.volume_fraction) + " (reached "
        + format_number(area / (static_cast<double>(nx) * ny)) + " after "
        + std::to_string(max_attempts)
        + " attempts). Lower 'Morphology/Volume fraction' or the "
          "heterogeneity size, or use more pixels.");
    return Morphology(p.width,
                      p.height,
                      nx,
                      ny,
                      ids,
                      "random vertical heterogeneities, seed "
                        + std::to_string(p.random_seed),
                      n_placed);
  }


  static const bool random_vertical_morphology_registered
    = MorphologySources::add(
      {"random vertical",
       2,
       "random non-overlapping vertical heterogeneities, seed 001 Fig. 1",
       [] { return std::make_unique<RandomVerticalMorphology>(); }});
} // namespace tribodyn
