// Morphology generators and the grid-file reader:
// - random vertical heterogeneities: the achieved fraction is within one
//   heterogeneity's area of the target, heterogeneities neither overlap nor
//   touch (every heterogeneity pixel column segment has the generator's
//   width exactly), heights lie in the requested range, and the same seed
//   gives the same morphology;
// - a grid file written and read back gives the same pixels, and its
//   connected heterogeneities are counted (the generator's, and 4 in a
//   hand-drawn grid with an L and a corner-touching pair);
// - a laminate has exactly the requested layer fraction.

#include "../test_utilities.h"

#include <cstdio>
#include <fstream>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/morphology_sources/laminate.h>
#include <tribodyn/core/morphology_sources/random_vertical.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace tribodyn;
  using namespace tribodyn_test;

  MorphologyParameters p; // the seed's defaults: 280 x 80 pixels of 0.1 mm
  const Morphology     m = Morphology::create(p);
  const double         max_area_fraction
    = 1 * 36. / (280. * 80.); // one 1 x 36 pixel heterogeneity
  check(std::abs(m.heterogeneity_fraction() - 0.1) <= max_area_fraction,
        "random fraction " + std::to_string(m.heterogeneity_fraction())
          + " is within one heterogeneity of 0.1");

  // Horizontal runs of heterogeneity pixels have width exactly 1 pixel
  // (0.1 mm), vertical runs have heights in [12, 36] pixels: this fails if
  // two heterogeneities touch or overlap.
  bool widths_ok = true, heights_ok = true;
  for (unsigned int j = 0; j < m.n_pixels_y(); ++j)
    for (unsigned int i = 0; i < m.n_pixels_x(); ++i)
      if (m.pixel(i, j) == material_id::heterogeneity)
        {
          const bool left  = i > 0 && m.pixel(i - 1, j) != 0;
          const bool right = i + 1 < m.n_pixels_x() && m.pixel(i + 1, j) != 0;
          widths_ok        = widths_ok && !left && !right;
        }
  for (unsigned int i = 0; i < m.n_pixels_x(); ++i)
    {
      unsigned int run = 0;
      for (unsigned int j = 0; j <= m.n_pixels_y(); ++j)
        {
          if (j < m.n_pixels_y() && m.pixel(i, j) != 0)
            ++run;
          else
            {
              if (run > 0 && (run < 12 || run > 36))
                heights_ok = false;
              run = 0;
            }
        }
    }
  check(widths_ok, "heterogeneities are 1 pixel wide and never touch sideways");
  check(heights_ok, "heterogeneity heights lie in [1.2, 3.6] mm");

  const Morphology again = Morphology::create(p);
  bool             same  = true;
  for (unsigned int j = 0; j < m.n_pixels_y(); ++j)
    for (unsigned int i = 0; i < m.n_pixels_x(); ++i)
      same = same && m.pixel(i, j) == again.pixel(i, j);
  check(same, "the same seed gives the same morphology");

  MorphologyParameters other = p;
  other.random_seed          = 2;
  const Morphology m2        = Morphology::create(other);
  bool             differ    = false;
  for (unsigned int j = 0; j < m.n_pixels_y(); ++j)
    for (unsigned int i = 0; i < m.n_pixels_x(); ++i)
      differ = differ || m.pixel(i, j) != m2.pixel(i, j);
  check(differ, "another seed gives another morphology");

  const std::string file = "morphology_roundtrip.txt";
  m.write_grid_file(file);
  const Morphology read
    = Morphology::read_grid_file(file, m.width(), m.height());
  bool equal = read.n_pixels_x() == m.n_pixels_x()
               && read.n_pixels_y() == m.n_pixels_y();
  for (unsigned int j = 0; equal && j < m.n_pixels_y(); ++j)
    for (unsigned int i = 0; i < m.n_pixels_x(); ++i)
      equal = equal && m.pixel(i, j) == read.pixel(i, j);
  check(equal, "grid file written and read back gives the same pixels");
  // The generator's heterogeneities never touch, so the connected groups
  // of the file are the generator's placements.
  check(read.n_heterogeneities() == m.n_heterogeneities()
          && m.n_heterogeneities() > 0,
        "grid file: " + std::to_string(read.n_heterogeneities())
          + " connected heterogeneities, generator placed "
          + std::to_string(m.n_heterogeneities()));
  std::remove(file.c_str());

  // A hand-drawn grid: an L of 4 pixels, a pair touching at a corner only
  // (two heterogeneities), and a lone pixel: 4.
  {
    const std::string hand = "morphology_hand.txt";
    {
      std::ofstream out(hand);
      out << "1 0 0 0 1\n1 0 0 1 0\n1 1 0 0 0\n0 0 0 0 1\n";
    }
    const Morphology h = Morphology::read_grid_file(hand, 5e-4, 4e-4);
    check(h.n_heterogeneities() == 4,
          "hand-drawn grid: " + std::to_string(h.n_heterogeneities())
            + " connected heterogeneities, expected 4");
    std::remove(hand.c_str());
  }

  MorphologyParameters l;
  l.use<LaminateMorphology>().n_periods = 4;
  l.n_pixels_x                          = 40;
  l.n_pixels_y                          = 10;
  l.volume_fraction = 0.2; // 2 of the 10 pixels of each period
  check_relative(Morphology::create(l).heterogeneity_fraction(),
                 0.2,
                 1e-14,
                 "laminate fraction");
  return result();
}
