#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/morphology_source.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/parameter_binding.h>

namespace tribodyn
{
  // The engines' questions to a source (MorphologySource): a generator's
  // answers.
  bool
  MorphologySource::is_map() const
  {
    return false;
  }


  std::string
  MorphologySource::phases_set_by() const
  {
    return "";
  }


  MorphologyParameters::MorphologyParameters()
      : source(MorphologySources::create("random vertical"))
  {
  }


  ParameterBinding
  MorphologyParameters::binding(std::unique_ptr<MorphologySource> &chosen)
  {
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    ParameterBinding b("Morphology");
    MorphologySources::add_generator_entry(
      b, "random vertical", "How the material map is made: ", chosen);
    b.add("Width",
          width,
          "Size of the rectangle along x (the sliding direction), in m.",
          Double());
    // The reference spells the default of Height 0.008, where
    // exact_number() would write 8e-3: it is written by format_number()
    // from the member and read as ParameterHandler::get_double() reads.
    b.add("Height",
          format_number(height),
          "Size of the rectangle along y, in m.",
          Double(),
          [this](const std::string &text) {
            height = dealii::Utilities::string_to_double(text);
          });
    b.add("Pixels in x",
          n_pixels_x,
          "Number of pixels of the material map along x (generators only; a "
          "grid file sets its own).",
          Integer(1));
    b.add("Pixels in y",
          n_pixels_y,
          "Number of pixels of the material map along y.",
          Integer(1));
    b.add("Volume fraction",
          volume_fraction,
          "Target area fraction of heterogeneities, in (0, 1) ('random "
          "vertical' and 'laminate').",
          Double());
    b.add("Seed",
          random_seed,
          "Seed of the random number generator: each seed gives one random "
          "morphology (the seed 001 study used six: seeds 1 to 6).",
          Integer(0));
    return b;
  }


  void
  MorphologyParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    std::unique_ptr<MorphologySource> unused;
    MorphologyParameters().binding(unused).declare(prm);
    MorphologySources::declare_sources(prm);
  }


  void
  MorphologyParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    const double                      inf = std::numeric_limits<double>::max();
    std::unique_ptr<MorphologySource> chosen;
    const ParameterBinding            b = binding(chosen);
    b.parse(prm);
    check_parameter_range(b.path("Width"), width, 0, inf, true, true);
    check_parameter_range(b.path("Height"), height, 0, inf, true, true);
    source = MorphologySources::parse_chosen(std::move(chosen), prm, b, *this);
  }


  bool
  MorphologyParameters::is_map() const
  {
    return source->is_map();
  }


  void
  MorphologyParameters::check_volume_fraction(const ParameterBinding &b) const
  {
    check_parameter_range(b.path("Volume fraction"),
                          volume_fraction,
                          0,
                          1,
                          true,
                          true,
                          "It is the area fraction of heterogeneities; use "
                          "'Generator = homogeneous' for a single phase.");
  }


  Morphology::Morphology(const double                     width,
                         const double                     height,
                         const unsigned int               n_x,
                         const unsigned int               n_y,
                         const std::vector<unsigned int> &ids)
      : rectangle_width(width)
      , rectangle_height(height)
      , n_x(n_x)
      , n_y(n_y)
      , ids(ids)
      , origin("given")
  {
    if (ids.size() != static_cast<std::size_t>(n_x) * n_y)
      throw std::logic_error("Morphology: ids do not match the grid size");
  }


  Morphology::Morphology(const double                     width,
                         const double                     height,
                         const unsigned int               n_x,
                         const unsigned int               n_y,
                         const std::vector<unsigned int> &ids,
                         const std::string               &origin)
      : Morphology(width, height, n_x, n_y, ids)
  {
    this->origin = origin;
  }


  Morphology::Morphology(const double                     width,
                         const double                     height,
                         const unsigned int               n_x,
                         const unsigned int               n_y,
                         const std::vector<unsigned int> &ids,
                         const std::string               &origin,
                         const unsigned int               n_heterogeneities)
      : Morphology(width, height, n_x, n_y, ids, origin)
  {
    n_placed = n_heterogeneities == connected_groups
                 ? count_connected_heterogeneities()
                 : n_heterogeneities;
  }


  Morphology
  Morphology::create(const MorphologyParameters &p)
  {
    return p.source->create(p);
  }


  void
  Morphology::flood_fill(std::vector<bool>                      &seen,
                         std::vector<std::size_t>                stack,
                         const std::function<bool(std::size_t)> &accept) const
  {
    // 4-connectivity: two pixels touching at a corner only are not
    // connected (two fibres, or a pin's two grains held by one node).
    while (!stack.empty())
      {
        const std::size_t  k = stack.back();
        const unsigned int i = k % n_x, j = k / n_x;
        stack.pop_back();
        const auto visit = [&](const std::size_t q) {
          if (!seen[q] && accept(q))
            {
              seen[q] = true;
              stack.push_back(q);
            }
        };
        if (i > 0)
          visit(k - 1);
        if (i + 1 < n_x)
          visit(k + 1);
        if (j > 0)
          visit(k - n_x);
        if (j + 1 < n_y)
          visit(k + n_x);
      }
  }


  unsigned int
  Morphology::count_connected_heterogeneities() const
  {
    const auto heterogeneity = [&](const std::size_t q) {
      return ids[q] == material_id::heterogeneity;
    };
    std::vector<bool> seen(ids.size(), false);
    unsigned int      count = 0;
    for (std::size_t start = 0; start < ids.size(); ++start)
      if (!seen[start] && heterogeneity(start))
        {
          ++count;
          seen[start] = true;
          flood_fill(seen, {start}, heterogeneity);
        }
    return count;
  }


  std::vector<bool>
  Morphology::held_from_top(const std::vector<bool> &void_phase) const
  {
    const auto solid = [&](const std::size_t q) {
      return ids[q] >= void_phase.size() || !void_phase[ids[q]];
    };
    std::vector<bool>        held(ids.size(), false);
    std::vector<std::size_t> top;
    for (unsigned int i = 0; i < n_x; ++i)
      {
        const std::size_t q = static_cast<std::size_t>(n_y - 1) * n_x + i;
        if (solid(q))
          {
            held[q] = true;
            top.push_back(q);
          }
      }
    flood_fill(held, top, solid);
    return held;
  }


  Morphology
  Morphology::window(const unsigned int i0,
                     const unsigned int j0,
                     const unsigned int window_nx,
                     const unsigned int window_ny) const
  {
    if (window_nx == 0 || window_ny == 0 || i0 + window_nx > n_x
        || j0 + window_ny > n_y)
      throw std::logic_error("Morphology::window: the window leaves the map");
    std::vector<unsigned int> w(static_cast<std::size_t>(window_nx)
                                * window_ny);
    for (unsigned int j = 0; j < window_ny; ++j)
      for (unsigned int i = 0; i < window_nx; ++i)
        w[static_cast<std::size_t>(j) * window_nx + i]
          = ids[static_cast<std::size_t>(j0 + j) * n_x + i0 + i];
    Morphology m(window_nx * pixel_width(),
                 window_ny * pixel_height(),
                 window_nx,
                 window_ny,
                 w,
                 "window of " + std::to_string(window_nx) + " x "
                   + std::to_string(window_ny) + " pixels at ("
                   + std::to_string(i0) + ", " + std::to_string(j0) + ") of "
                   + origin);
    m.n_placed = m.count_connected_heterogeneities();
    return m;
  }


  unsigned int
  Morphology::n_pixels_x() const
  {
    return n_x;
  }

  unsigned int
  Morphology::n_pixels_y() const
  {
    return n_y;
  }

  double
  Morphology::width() const
  {
    return rectangle_width;
  }

  double
  Morphology::height() const
  {
    return rectangle_height;
  }

  double
  Morphology::pixel_width() const
  {
    return rectangle_width / n_x;
  }

  double
  Morphology::pixel_height() const
  {
    return rectangle_height / n_y;
  }

  unsigned int
  Morphology::pixel(const unsigned int i, const unsigned int j) const
  {
    return ids[static_cast<std::size_t>(j) * n_x + i];
  }


  unsigned int
  Morphology::material_at(const dealii::Point<2> &p) const
  {
    const auto clamp = [](const double v, const unsigned int n) {
      const long k = static_cast<long>(std::floor(v));
      return static_cast<unsigned int>(
        std::min<long>(std::max<long>(k, 0), static_cast<long>(n) - 1));
    };
    return pixel(clamp(p[0] / pixel_width(), n_x),
                 clamp(p[1] / pixel_height(), n_y));
  }


  double
  Morphology::heterogeneity_fraction() const
  {
    std::size_t count = 0;
    for (const unsigned int id : ids)
      count += (id == material_id::heterogeneity);
    return static_cast<double>(count) / ids.size();
  }


  unsigned int
  Morphology::n_phases() const
  {
    return std::max(2u, *std::max_element(ids.begin(), ids.end()) + 1);
  }


  std::vector<double>
  Morphology::phase_fractions() const
  {
    std::vector<double> fractions(n_phases(), 0.);
    for (const unsigned int id : ids)
      fractions[id] += 1;
    for (double &f : fractions)
      f /= ids.size();
    return fractions;
  }


  unsigned int
  Morphology::n_heterogeneities() const
  {
    return n_placed;
  }


  std::string
  Morphology::description() const
  {
    std::ostringstream s;
    s << origin << "; " << n_x << " x " << n_y << " pixels over "
      << rectangle_width * 1e3 << " mm x " << rectangle_height * 1e3 << " mm";
    if (origin.rfind("image", 0) == 0 || n_phases() > 2)
      {
        // Any number of phases: the fraction of each.
        const std::vector<double> f = phase_fractions();
        s << "; phase fractions";
        for (unsigned int k = 0; k < f.size(); ++k)
          s << (k == 0 ? " " : ", ") << f[k];
        return s.str();
      }
    s << "; heterogeneity fraction " << heterogeneity_fraction();
    if (n_placed > 0)
      s << " (" << n_placed << " heterogeneities)";
    return s.str();
  }


  void
  create_morphology_mesh(const Morphology         &morphology,
                         const unsigned int        subdivisions_per_pixel,
                         dealii::Triangulation<2> &triangulation)
  {
    const std::vector<unsigned int> repetitions
      = {morphology.n_pixels_x() * subdivisions_per_pixel,
         morphology.n_pixels_y() * subdivisions_per_pixel};
    dealii::GridGenerator::subdivided_hyper_rectangle(
      triangulation,
      repetitions,
      dealii::Point<2>(0, 0),
      dealii::Point<2>(morphology.width(), morphology.height()),
      /*colorize = */ true);
    // Every coarse cell (including artificial ones of a distributed
    // triangulation) gets its id, so that all ranks agree.
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      cell->set_material_id(morphology.material_at(cell->center()));
  }


  void
  create_morphology_mesh(const Morphology         &morphology,
                         const unsigned int        subdivisions_per_pixel,
                         const std::vector<bool>  &kept,
                         dealii::Triangulation<2> &triangulation)
  {
    const unsigned int s  = subdivisions_per_pixel;
    const unsigned int nx = morphology.n_pixels_x() * s,
                       ny = morphology.n_pixels_y() * s;
    const double dx = morphology.width() / nx, dy = morphology.height() / ny;
    AssertThrow(kept.size()
                  == static_cast<std::size_t>(morphology.n_pixels_x())
                       * morphology.n_pixels_y(),
                dealii::ExcInternalError());

    // The vertices of the full grid, the cells of the kept pixels (in
    // deal.II's vertex order); vertices of voids only are dropped after.
    std::vector<dealii::Point<2>> vertices;
    vertices.reserve(static_cast<std::size_t>(nx + 1) * (ny + 1));
    for (unsigned int j = 0; j <= ny; ++j)
      for (unsigned int i = 0; i <= nx; ++i)
        vertices.emplace_back(i * dx, j * dy);
    std::vector<dealii::CellData<2>> cells;
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        {
          const std::size_t pixel
            = static_cast<std::size_t>(j / s) * morphology.n_pixels_x() + i / s;
          if (!kept[pixel])
            continue;
          dealii::CellData<2> cell;
          const unsigned int  v = j * (nx + 1) + i;
          cell.vertices         = {v, v + 1, v + nx + 1, v + nx + 2};
          cell.material_id      = morphology.pixel(i / s, j / s);
          cells.push_back(cell);
        }
    AssertThrow(!cells.empty(), dealii::ExcInternalError());
    dealii::SubCellData no_subcells;
    dealii::GridTools::delete_unused_vertices(vertices, cells, no_subcells);
    triangulation.create_triangulation(vertices, cells, no_subcells);

    // Boundary ids by position: the rectangle's sides, else a void's face.
    const double tolerance = 1e-6 * std::min(dx, dy);
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const dealii::Point<2> c  = cell->face(f)->center();
            const unsigned int     id = c[0] < tolerance ? 0
                                        : c[0] > morphology.width() - tolerance ? 1
                                        : c[1] < tolerance ? 2
                                        : c[1] > morphology.height() - tolerance
                                          ? 3
                                          : 4;
            cell->face(f)->set_boundary_id(id);
          }
  }
} // namespace tribodyn
