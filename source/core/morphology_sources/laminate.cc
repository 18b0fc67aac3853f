// The morphology source 'laminate': layers through the whole rectangle.
#include <cmath>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/morphology_sources/laminate.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/selection.h>

namespace tribodyn
{
  namespace
  {
    using Normal = LaminateMorphology::Normal;
    constexpr SelectionTable<Normal, 2> normal_choices{
      {{"x", Normal::x}, {"y", Normal::y}}};
  } // namespace


  void
  LaminateMorphology::bind(ParameterBinding &b)
  {
    b.add("Laminate normal",
          normal,
          "Stacking direction of a laminate: 'x' gives vertical layers, 'y' "
          "horizontal ones.",
          normal_choices);
    b.add("Laminate periods",
          n_periods,
          "Number of (matrix, heterogeneity) layer pairs of a laminate.",
          dealii::Patterns::Integer(1));
  }


  void
  LaminateMorphology::parse(dealii::ParameterHandler &,
                            const ParameterBinding &b,
                            MorphologyParameters   &common)
  {
    common.check_volume_fraction(b);
  }


  Morphology
  LaminateMorphology::create(const MorphologyParameters &p) const
  {
    const unsigned int nx = p.n_pixels_x, ny = p.n_pixels_y;
    const bool         along_x = normal == Normal::x;
    const unsigned int n       = along_x ? nx : ny;
    check_parameter(n % n_periods == 0,
                    "Morphology/Laminate periods",
                    "the number of pixels along the stacking direction ("
                      + std::to_string(n)
                      + ") must be a multiple of the number of periods ("
                      + std::to_string(n_periods) + ").");
    const unsigned int period = n / n_periods;
    const unsigned int layer
      = static_cast<unsigned int>(std::lround(p.volume_fraction * period));
    check_parameter(layer >= 1 && layer < period,
                    "Morphology/Volume fraction",
                    "a laminate period of " + std::to_string(period)
                      + " pixels cannot hold a heterogeneity layer of "
                        "fraction "
                      + format_number(p.volume_fraction)
                      + "; use more pixels or fewer periods.");
    std::vector<unsigned int> ids(static_cast<std::size_t>(nx) * ny,
                                  material_id::matrix);
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        {
          const unsigned int k = along_x ? i : j;
          // The heterogeneity layer sits in the middle of each period.
          const unsigned int offset = (period - layer) / 2;
          if (k % period >= offset && k % period < offset + layer)
            ids[j * nx + i] = material_id::heterogeneity;
        }
    return Morphology(p.width,
                      p.height,
                      nx,
                      ny,
                      ids,
                      std::string("laminate, layers normal to ")
                        + (along_x ? "x" : "y"),
                      n_periods);
  }


  static const bool laminate_morphology_registered = MorphologySources::add(
    {"laminate", 3, "layers through the whole rectangle", [] {
       return std::make_unique<LaminateMorphology>();
     }});
} // namespace tribodyn
