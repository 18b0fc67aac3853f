// The morphology source 'grid file': a plain-text grid of material ids.
#include <tribodyn/core/errors.h>
#include <tribodyn/core/morphology_sources/grid_file.h>

namespace tribodyn
{
  void
  GridFileMorphology::bind(ParameterBinding &b)
  {
    b.add("Grid file",
          file,
          "Plain-text grid of material ids (0 matrix, 1 heterogeneity; or 0 "
          "to N-1 for the N materials of 'Materials/Names'), one row of pixels "
          "per line, top row first; '#' starts a comment line. The grid is "
          "stretched over Width x Height.");
  }


  void
  GridFileMorphology::parse(dealii::ParameterHandler &prm,
                            const ParameterBinding   &b,
                            MorphologyParameters     &common)
  {
    check_parameter(!file.empty(),
                    b.path("Grid file"),
                    "'Generator = grid file' needs the path of the grid "
                    "file.");
    // The pixels are the file's: record them (parameters.prm then says
    // what the run used, not the generator's defaults).
    const Morphology grid = Morphology::read_grid_file(file, 1., 1.);
    common.n_pixels_x     = grid.n_pixels_x();
    common.n_pixels_y     = grid.n_pixels_y();
    prm.enter_subsection("Morphology");
    prm.set("Pixels in x", static_cast<long int>(common.n_pixels_x));
    prm.set("Pixels in y", static_cast<long int>(common.n_pixels_y));
    prm.leave_subsection();
  }


  Morphology
  GridFileMorphology::create(const MorphologyParameters &p) const
  {
    return Morphology::read_grid_file(file, p.width, p.height);
  }


  bool
  GridFileMorphology::is_map() const
  {
    return true;
  }


  static const bool grid_file_morphology_registered = MorphologySources::add(
    {"grid file", 4, "plain-text grid of material ids, see 'Grid file'", [] {
       return std::make_unique<GridFileMorphology>();
     }});
} // namespace tribodyn
