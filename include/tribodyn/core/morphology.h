#ifndef tribodyn_core_morphology_h
#define tribodyn_core_morphology_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <tribodyn/core/material.h>
#include <tribodyn/core/parameter_binding.h>
#include <vector>

namespace tribodyn
{
  /// Material ids used by morphologies and meshes.
  namespace material_id
  {
    constexpr unsigned int matrix        = 0;
    constexpr unsigned int heterogeneity = 1;
  } // namespace material_id

  class MorphologySource;

  /**
   * Parameters of the subsection "Morphology": a rectangle of width (along
   * x, the sliding direction) by height (along y), described on a grid of
   * pixels, each pixel holding a material id. The map is made by a source
   * (`Generator`: core/morphology_source.h), which owns its own entries;
   * the entries here are common to the sources.
   */
  struct MorphologyParameters
  {
    /// Size of the rectangle along x and y (m).
    double width  = 28e-3;
    double height = 8e-3;
    /// Number of pixels along x and y (generators; a file sets its own).
    unsigned int n_pixels_x = 280;
    unsigned int n_pixels_y = 80;
    /// Target area fraction of heterogeneities (random, laminate).
    double volume_fraction = 0.1;
    /// Seed of a random generator.
    unsigned int random_seed = 1;

    /// The chosen source with its parameters (`Generator`; by default
    /// 'random vertical'). Copies of the parameters share it; use() and
    /// edit() replace it.
    std::shared_ptr<const MorphologySource> source;

    MorphologyParameters();

    /// The common entries of "Morphology", bound to the members above
    /// (their initial values are the defaults), and `Generator`, which
    /// makes the chosen source in @p chosen.
    ParameterBinding
    binding(std::unique_ptr<MorphologySource> &chosen);

    /// Declare the common entries and every registered source's.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Read the common entries, then the chosen source's (its checks and
    /// what it records).
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Whether the map is read from a file (an image or a grid file),
    /// rather than generated: it may hold any number of phases.
    bool
    is_map() const;

    /// Make the source a new @p Source with its defaults (its header
    /// included by the caller), and return it to set its parameters:
    /// `p.use<LaminateMorphology>().n_periods = 2;`.
    template <typename Source>
    Source &
    use()
    {
      const std::shared_ptr<Source> s = std::make_shared<Source>();
      source                          = s;
      return *s;
    }

    /// Make the source a copy of the current one, which must be a
    /// @p Source (std::logic_error otherwise), and return it to change its
    /// parameters (copies of these parameters keep the old one).
    template <typename Source>
    Source &
    edit()
    {
      const auto *current = dynamic_cast<const Source *>(source.get());
      if (current == nullptr)
        throw std::logic_error(
          "MorphologyParameters::edit(): the source is of another type");
      const std::shared_ptr<Source> s = std::make_shared<Source>(*current);
      source                          = s;
      return *s;
    }

    /// Refuse a `Volume fraction` outside (0, 1) (the generators that
    /// place heterogeneities by it); @p b gives the path.
    void
    check_volume_fraction(const ParameterBinding &b) const;
  };

  /**
   * A two-phase morphology on a rectangle: a grid of n_x by n_y pixels, each
   * of material_id::matrix or material_id::heterogeneity. Pixel (i, j) covers
   * [i h_x, (i+1) h_x] x [j h_y, (j+1) h_y] with j counted from the bottom.
   * Shared by the homogenization cell problem and the meso pin of the
   * contact solver (same parameters and seed give the same morphology).
   */
  class Morphology
  {
  public:
    Morphology(const double                     width,
               const double                     height,
               const unsigned int               n_x,
               const unsigned int               n_y,
               const std::vector<unsigned int> &ids);

    /// The same with the description's @p origin (e.g. "image a.png").
    Morphology(const double                     width,
               const double                     height,
               const unsigned int               n_x,
               const unsigned int               n_y,
               const std::vector<unsigned int> &ids,
               const std::string               &origin);

    /// n_heterogeneities() of a map read from a file: its connected groups
    /// of heterogeneity pixels.
    static constexpr unsigned int connected_groups
      = static_cast<unsigned int>(-1);

    /// The same with the number of heterogeneities its generator placed
    /// (n_heterogeneities()), or connected_groups.
    Morphology(const double                     width,
               const double                     height,
               const unsigned int               n_x,
               const unsigned int               n_y,
               const std::vector<unsigned int> &ids,
               const std::string               &origin,
               const unsigned int               n_heterogeneities);

    /// Build the morphology the parameters describe (their source's).
    static Morphology
    create(const MorphologyParameters &parameters);

    /// Read a plain-text grid: one row of ids per line, top row first;
    /// blank lines and lines starting with '#' are ignored.
    static Morphology
    read_grid_file(const std::string &file_name,
                   const double       width,
                   const double       height);

    unsigned int
    n_pixels_x() const;
    unsigned int
    n_pixels_y() const;
    double
    width() const;
    double
    height() const;
    double
    pixel_width() const;
    double
    pixel_height() const;

    /// Material id of pixel (i, j), j counted from the bottom.
    unsigned int
    pixel(const unsigned int i, const unsigned int j) const;

    /// Material id at a point of the rectangle (points on pixel edges go to
    /// the pixel above/right, clamped at the far edges).
    unsigned int
    material_at(const dealii::Point<2> &p) const;

    /// Area fraction of heterogeneity pixels.
    double
    heterogeneity_fraction() const;

    /// Number of phases: the largest material id plus one (at least 2:
    /// matrix and heterogeneity, even when a map holds only matrix).
    unsigned int
    n_phases() const;

    /// Area fraction of the pixels of each material id 0 .. n_phases()-1.
    std::vector<double>
    phase_fractions() const;

    /// Number of distinct heterogeneities: as placed by the generator, or
    /// for a grid file the connected groups of heterogeneity pixels (pixels
    /// sharing an edge).
    unsigned int
    n_heterogeneities() const;

    /// Connected groups of heterogeneity pixels (sharing an edge).
    unsigned int
    count_connected_heterogeneities() const;

    /**
     * The pixels a pin keeps when the phases flagged in @p void_phase (by
     * material id; ids past its end are solid) are cut out of it: the solid
     * pixels connected to the top row through shared edges. A solid
     * fragment that no chain of solid pixels ties to the loaded top face
     * would be a loose body in the pin; it is cut too.
     */
    std::vector<bool>
    held_from_top(const std::vector<bool> &void_phase) const;

    /// One-line description for the screen and summary.json.
    std::string
    description() const;

    /// Write the grid in the format read_grid_file() reads.
    void
    write_grid_file(const std::string &file_name) const;

    /**
     * The window of @p window_nx by @p window_ny pixels whose lower-left
     * pixel is (@p i0, @p j0), as a morphology of its own with the same
     * pixel size (the windows of an RVE-size study). Heterogeneities cut by
     * the window's edges are kept cut; n_heterogeneities() of the window
     * counts its connected heterogeneity pixels. The window must lie in the
     * rectangle (std::logic_error otherwise: callers check user input).
     */
    Morphology
    window(const unsigned int i0,
           const unsigned int j0,
           const unsigned int window_nx,
           const unsigned int window_ny) const;

  private:
    /// Mark (in @p seen) every pixel that @p accept takes and that is
    /// connected through shared edges to a pixel of @p stack (already
    /// marked).
    void
    flood_fill(std::vector<bool>                      &seen,
               std::vector<std::size_t>                stack,
               const std::function<bool(std::size_t)> &accept) const;

    double                    rectangle_width;
    double                    rectangle_height;
    unsigned int              n_x;
    unsigned int              n_y;
    std::vector<unsigned int> ids; // row-major from the bottom: ids[j n_x + i]
    unsigned int              n_placed = 0;
    std::string               origin;
  };

  /**
   * Fill @p triangulation (empty on entry) with a structured mesh of the
   * morphology's rectangle: @p subdivisions_per_pixel by the same number of
   * quadrilaterals per pixel, so that phase boundaries lie on element
   * edges, and set each cell's material id from the morphology. Boundary
   * ids: 0 left (x = 0), 1 right, 2 bottom (y = 0), 3 top. Global
   * refinement afterwards keeps the ids (children inherit them).
   */
  void
  create_morphology_mesh(const Morphology         &morphology,
                         const unsigned int        subdivisions_per_pixel,
                         dealii::Triangulation<2> &triangulation);

  /**
   * The same mesh with only the pixels flagged in @p kept (one flag per
   * pixel, row-major from the bottom, as Morphology::held_from_top() gives
   * them): the others are voids. Boundary ids as above on the rectangle's
   * sides; the faces of the voids get boundary id 4.
   */
  void
  create_morphology_mesh(const Morphology         &morphology,
                         const unsigned int        subdivisions_per_pixel,
                         const std::vector<bool>  &kept,
                         dealii::Triangulation<2> &triangulation);
} // namespace tribodyn

#endif
