// An image of a laminate gives the exact laminate constants (issue #19):
// laminate3.png holds layers normal to x of three grey levels (0, 128,
// 255; 6, 8 and 6 pixels in each of two periods). Segmented by Otsu's
// method into three phases, the periodic cell problem must reproduce
// laminate_exact() for the three phases to 1e-6 (relative to the largest
// entry of C, as tests/homogenization/laminate.cc does for two phases), with
// three solid phases and with the darkest layer a pore (ersatz stiffness
// 1e-6 of the softest solid). The segmentation itself is checked: Otsu's
// thresholds fall between the levels, thresholds and a colour table give
// the same map, and so does the TIFF of the same laminate; 'Rotation' turns
// the map counter-clockwise (pixel by pixel, exact).

#include "image_test_tools.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace tribodyn_test;

  MorphologyParameters otsu
    = image_parameters(image_path("laminate3.png"), 3, 1e-4);
  const Morphology morphology = Morphology::create(otsu);
  check(morphology.n_pixels_x() == 40 && morphology.n_pixels_y() == 10,
        "laminate3.png is 40 x 10 pixels");
  check_relative(morphology.width(), 40 * 1e-4, 1e-12, "width = 40 pixels");
  const std::vector<double> f = morphology.phase_fractions();
  check(f.size() == 3, "three phases");
  check_relative(f[0], 0.3, 1e-12, "fraction of phase 0 (grey 0)");
  check_relative(f[1], 0.4, 1e-12, "fraction of phase 1 (grey 128)");
  check_relative(f[2], 0.3, 1e-12, "fraction of phase 2 (grey 255)");

  // Otsu's thresholds lie between the three levels.
  {
    std::vector<unsigned int> grey;
    for (const unsigned int level : {0u, 128u, 255u})
      grey.insert(grey.end(), 10, level);
    const std::vector<double> t = otsu_thresholds(grey, 255, 3);
    check(t.size() == 2 && t[0] > 0 && t[0] <= 128 && t[1] > 128 && t[1] <= 255,
          "Otsu thresholds " + std::to_string(t[0]) + ", "
            + std::to_string(t[1]) + " separate 0, 128, 255");
  }

  // The same map from thresholds, from a colour table and from the TIFF.
  const auto same_map
    = [&](const MorphologyParameters &p, const std::string &what) {
        const Morphology m     = Morphology::create(p);
        bool             equal = m.n_pixels_x() == morphology.n_pixels_x()
                     && m.n_pixels_y() == morphology.n_pixels_y();
        for (unsigned int j = 0; equal && j < m.n_pixels_y(); ++j)
          for (unsigned int i = 0; equal && i < m.n_pixels_x(); ++i)
            equal = m.pixel(i, j) == morphology.pixel(i, j);
        check(equal, what + " gives the same material map as Otsu");
      };
  MorphologyParameters thresholds = otsu;
  {
    ImageParameters &image = thresholds.edit<ImageMorphology>().image;
    image.segmentation     = ImageParameters::Segmentation::thresholds;
    image.thresholds       = {64, 192};
  }
  same_map(thresholds, "thresholds 64, 192");
  MorphologyParameters table = otsu;
  {
    ImageParameters &image = table.edit<ImageMorphology>().image;
    image.segmentation     = ImageParameters::Segmentation::colour_table;
    image.colour_table     = {{0}, {128}, {255, 255, 255}};
  }
  same_map(table, "colour table '0; 128; 255 255 255'");

  // Placement: turned counter-clockwise by 90, 180 and 270 degrees, pixel
  // (i, j) of the map (j from the bottom) goes to (n_y-1-j, i), (n_x-1-i,
  // n_y-1-j) and (j, n_x-1-i); 90 and 270 swap width and height (exact).
  for (const unsigned int degrees : {90u, 180u, 270u})
    {
      MorphologyParameters turned                   = otsu;
      turned.edit<ImageMorphology>().image.rotation = degrees;
      const Morphology   m  = Morphology::create(turned);
      const unsigned int nx = morphology.n_pixels_x(),
                         ny = morphology.n_pixels_y();
      const bool quarter    = degrees != 180;
      bool       equal
        = m.n_pixels_x() == (quarter ? ny : nx)
          && m.n_pixels_y() == (quarter ? nx : ny)
          && m.width() == (quarter ? morphology.height() : morphology.width());
      for (unsigned int j = 0; equal && j < ny; ++j)
        for (unsigned int i = 0; equal && i < nx; ++i)
          equal = morphology.pixel(i, j)
                  == (degrees == 90    ? m.pixel(ny - 1 - j, i)
                      : degrees == 180 ? m.pixel(nx - 1 - i, ny - 1 - j)
                                       : m.pixel(j, nx - 1 - i));
      check(equal,
            "Rotation = " + std::to_string(degrees)
              + ": the map turned counter-clockwise");
    }
  MorphologyParameters tiff               = otsu;
  tiff.edit<ImageMorphology>().image.file = image_path("laminate3.tif");
  same_map(tiff, "laminate3.tif");

  const std::vector<std::pair<std::string, std::vector<ElasticPhase>>> cases
    = {{"three solids",
        named_phases({{30e9, 0.2}, {80e9, 0.35}, {200e9, 0.3}})},
       {"pore layer", named_phases({{0, 0}, {30e9, 0.2}, {80e9, 0.35}})}};
  for (const auto &[label, phases] : cases)
    {
      const ApparentProperties exact = laminate_exact(phases, f, 0);
      const CellProblemResult  periodic
        = solve_cell(morphology, phases, BoundaryCondition::periodic);
      check_relative(matrix_relative_difference(periodic.properties.C, exact.C),
                     0,
                     1e-6,
                     label + ": periodic C vs exact laminate C (9 entries)",
                     1.);
      const auto &c = periodic.properties.constants;
      const auto &e = exact.constants;
      check_relative(c.E_L, e.E_L, 1e-6, label + ": E_L");
      check_relative(c.E_T, e.E_T, 1e-6, label + ": E_T");
      check_relative(c.G_LT, e.G_LT, 1e-6, label + ": G_LT");
      check_relative(c.nu_LT, e.nu_LT, 1e-6, label + ": nu_LT");
      check_relative(c.nu_TT, e.nu_TT, 1e-6, label + ": nu_TT");
    }
  return result();
}
