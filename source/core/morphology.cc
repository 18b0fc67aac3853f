#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/selection.h>

namespace tribodyn
{
  namespace
  {
    using Generator = MorphologyParameters::Generator;
    constexpr SelectionTable<Generator, 5> generator_choices{
      {{"homogeneous", Generator::homogeneous},
       {"random vertical", Generator::random_vertical},
       {"laminate", Generator::laminate},
       {"grid file", Generator::grid_file},
       {"image", Generator::image}}};
    using LaminateNormal = MorphologyParameters::LaminateNormal;
    constexpr SelectionTable<LaminateNormal, 2> laminate_normal_choices{
      {{"x", LaminateNormal::x}, {"y", LaminateNormal::y}}};
  } // namespace


  ParameterBinding
  MorphologyParameters::binding()
  {
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    ParameterBinding b("Morphology");
    // The reference spells the defaults of Height and of the
    // heterogeneities' sizes 0.008, 0.0001, ..., where exact_number()
    // would write 8e-3, 1e-4: they are written by format_number() from the
    // members and read as ParameterHandler::get_double() reads.
    const auto number = [](double &value) {
      return [&value](const std::string &text) {
        value = dealii::Utilities::string_to_double(text);
      };
    };
    b.add("Generator",
          generator,
          "How the material map is made: 'homogeneous' (matrix only), "
          "'random vertical' (random non-overlapping vertical heterogeneities, "
          "seed 001 Fig. 1), 'laminate' (layers through the whole rectangle), "
          "'grid file' (plain-text grid of material ids, see 'Grid file'), "
          "'image' (a segmented PNG or TIFF micrograph, any number of phases, "
          "see the subsection 'Image').",
          generator_choices);
    b.add("Width",
          width,
          "Size of the rectangle along x (the sliding direction), in m.",
          Double());
    b.add("Height",
          format_number(height),
          "Size of the rectangle along y, in m.",
          Double(),
          number(height));
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
    b.add("Seed",
          random_seed,
          "Seed of the random number generator: each seed gives one random "
          "morphology (the seed 001 study used six: seeds 1 to 6).",
          Integer(0));
    b.add("Laminate normal",
          laminate_normal,
          "Stacking direction of a laminate: 'x' gives vertical layers, 'y' "
          "horizontal ones.",
          laminate_normal_choices);
    b.add("Laminate periods",
          n_laminate_periods,
          "Number of (matrix, heterogeneity) layer pairs of a laminate.",
          Integer(1));
    b.add("Grid file",
          grid_file,
          "Plain-text grid of material ids (0 matrix, 1 heterogeneity; or 0 "
          "to N-1 for the N materials of 'Materials/Names'), one row of pixels "
          "per line, top row first; '#' starts a comment line. The grid is "
          "stretched over Width x Height.");
    return b;
  }


  void
  MorphologyParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    MorphologyParameters().binding().declare(prm);
    ImageParameters::declare_parameters(prm);
  }


  void
  MorphologyParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    const double           inf = std::numeric_limits<double>::max();
    const ParameterBinding b   = binding();
    b.parse(prm);
    if (generator == Generator::image)
      image.parse_parameters(prm);

    // Width and Height stay checked here, not by ranges of the binding:
    // their checks come after the image's (as the refusals always have).
    check_parameter_range(b.path("Width"), width, 0, inf, true, true);
    check_parameter_range(b.path("Height"), height, 0, inf, true, true);
    if (generator == Generator::random_vertical
        || generator == Generator::laminate)
      check_parameter_range(b.path("Volume fraction"),
                            volume_fraction,
                            0,
                            1,
                            true,
                            true,
                            "It is the area fraction of heterogeneities; use "
                            "'Generator = homogeneous' for a single phase.");
    if (generator == Generator::random_vertical)
      {
        check_parameter_range(b.path("Heterogeneity width"),
                              inclusion_width,
                              0,
                              width,
                              true,
                              false);
        check_parameter_range(b.path("Heterogeneity min height"),
                              inclusion_min_height,
                              0,
                              height,
                              true,
                              false);
        check_parameter_range(b.path("Heterogeneity max height"),
                              inclusion_max_height,
                              inclusion_min_height,
                              height,
                              false,
                              false,
                              "It must be at least the min height and at most "
                              "the rectangle's height.");
      }
    if (generator == Generator::grid_file)
      {
        check_parameter(!grid_file.empty(),
                        b.path("Grid file"),
                        "'Generator = grid file' needs the path of the grid "
                        "file.");
        // The pixels are the file's: record them (parameters.prm then
        // says what the run used, not the generator's defaults).
        const Morphology grid = Morphology::read_grid_file(grid_file, 1., 1.);
        n_pixels_x            = grid.n_pixels_x();
        n_pixels_y            = grid.n_pixels_y();
        prm.enter_subsection("Morphology");
        prm.set("Pixels in x", static_cast<long int>(n_pixels_x));
        prm.set("Pixels in y", static_cast<long int>(n_pixels_y));
        prm.leave_subsection();
      }
    if (generator == Generator::image)
      {
        // Read and segment the image now, so that a bad file is refused
        // before any output, and record its size as for a grid file.
        const SegmentedImage segmented = segment_image(image);
        n_pixels_x                     = segmented.n_x;
        n_pixels_y                     = segmented.n_y;
        width                          = segmented.n_x * segmented.pixel_width;
        height                         = segmented.n_y * segmented.pixel_height;
        prm.enter_subsection("Morphology");
        prm.set("Pixels in x", static_cast<long int>(n_pixels_x));
        prm.set("Pixels in y", static_cast<long int>(n_pixels_y));
        prm.set("Width", width);
        prm.set("Height", height);
        prm.leave_subsection();
      }
  }


  bool
  MorphologyParameters::is_map() const
  {
    return generator == Generator::image || generator == Generator::grid_file;
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


  Morphology
  Morphology::create(const MorphologyParameters &p)
  {
    using Generator = MorphologyParameters::Generator;
    if (p.generator == Generator::grid_file)
      return read_grid_file(p.grid_file, p.width, p.height);
    if (p.generator == Generator::image)
      {
        const SegmentedImage s = segment_image(p.image);
        Morphology           m(s.n_x * s.pixel_width,
                     s.n_y * s.pixel_height,
                     s.n_x,
                     s.n_y,
                     s.ids,
                     s.description);
        m.n_placed = m.count_connected_heterogeneities();
        return m;
      }

    const unsigned int        nx = p.n_pixels_x, ny = p.n_pixels_y;
    std::vector<unsigned int> ids(static_cast<std::size_t>(nx) * ny,
                                  material_id::matrix);
    Morphology                m(p.width, p.height, nx, ny, ids);

    if (p.generator == Generator::homogeneous)
      {
        m.origin = "homogeneous matrix";
        return m;
      }

    if (p.generator == Generator::laminate)
      {
        const bool along_x
          = p.laminate_normal == MorphologyParameters::LaminateNormal::x;
        const unsigned int n = along_x ? nx : ny;
        check_parameter(n % p.n_laminate_periods == 0,
                        "Morphology/Laminate periods",
                        "the number of pixels along the stacking direction ("
                          + std::to_string(n)
                          + ") must be a multiple of the number of periods ("
                          + std::to_string(p.n_laminate_periods) + ").");
        const unsigned int period = n / p.n_laminate_periods;
        const unsigned int layer
          = static_cast<unsigned int>(std::lround(p.volume_fraction * period));
        check_parameter(layer >= 1 && layer < period,
                        "Morphology/Volume fraction",
                        "a laminate period of " + std::to_string(period)
                          + " pixels cannot hold a heterogeneity layer of "
                            "fraction "
                          + format_number(p.volume_fraction)
                          + "; use more pixels or fewer periods.");
        for (unsigned int j = 0; j < ny; ++j)
          for (unsigned int i = 0; i < nx; ++i)
            {
              const unsigned int k = along_x ? i : j;
              // The heterogeneity layer sits in the middle of each period.
              const unsigned int offset = (period - layer) / 2;
              if (k % period >= offset && k % period < offset + layer)
                m.ids[j * nx + i] = material_id::heterogeneity;
            }
        m.n_placed = p.n_laminate_periods;
        m.origin
          = std::string("laminate, layers normal to ") + (along_x ? "x" : "y");
        return m;
      }

    // Random non-overlapping vertical heterogeneities. Each one is a
    // rectangle of w pixels by a random number of pixels in
    // [h_min, h_max]; a candidate is rejected if it touches or overlaps one
    // already placed (a one-pixel gap keeps them distinct). Placement stops
    // when the area is closest to the target.
    const double       hx = p.width / nx, hy = p.height / ny;
    const unsigned int w
      = pixels_exact(p.inclusion_width, hx, "Morphology/Heterogeneity width");
    const unsigned int h_min = static_cast<unsigned int>(
      std::ceil(p.inclusion_min_height / hy - 1e-9));
    const unsigned int h_max = static_cast<unsigned int>(
      std::floor(p.inclusion_max_height / hy + 1e-9));
    check_parameter(h_min >= 1 && h_min <= h_max && h_max <= ny,
                    "Morphology/Heterogeneity min height",
                    "the height range [" + format_number(p.inclusion_min_height)
                      + ", " + format_number(p.inclusion_max_height)
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
            m.ids[j * nx + i] = material_id::heterogeneity;
        // Mark the placed rectangle grown by one pixel as unavailable.
        for (unsigned int j = (y0 > 0 ? y0 - 1 : 0);
             j < std::min(ny, y0 + h + 1);
             ++j)
          for (unsigned int i = (x0 > 0 ? x0 - 1 : 0);
               i < std::min(nx, x0 + w + 1);
               ++i)
            occupied_or_near[j * nx + i] = true;
        area += w * h;
        ++m.n_placed;
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
    m.origin = "random vertical heterogeneities, seed "
               + std::to_string(p.random_seed);
    return m;
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
