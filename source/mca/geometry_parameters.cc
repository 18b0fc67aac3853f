// Parameters of the scene: box, bodies, regions, rough interface.

#include "parameter_tools.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/patterns.h>
#include <iomanip>
#include <limits>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/selection.h>
#include <tribodyn/mca/packing.h>
#include <tribodyn/mca/parameters.h>
#include <unistd.h>

namespace tribodyn
{
  namespace mca
  {
    using dealii::ParameterHandler;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;

    namespace
    {
      /// Geometry/Size bands/Size at free faces: fine (true) or band.
      const SelectionTable<bool, 2> free_face_table{
        {{"fine", true}, {"band", false}}};
    } // namespace
    namespace Patterns = dealii::Patterns;

    using namespace parameter_tools;

    namespace
    {
      /// Number of FCC cells of side @p a in the box [@p lower, @p upper]
      /// (not rounded: a size check).
      double
      box_fcc_cells(const Point3 &lower, const Point3 &upper, const double a)
      {
        double n = 1;
        for (unsigned int d = 0; d < 3; ++d)
          n *= (upper[d] - lower[d]) / a;
        return n;
      }

      /// Whether @p f(plane, reach) holds for a height where the size
      /// changes across a band's face (the levels just below and above the
      /// plane differ; the bands are half-open: z_lower belongs to the
      /// band), @p reach being 3 times its larger size 2^L d: the automata
      /// within it of the plane are near the change of size
      /// (GeometryParameters::near_size_change()).
      template <class F>
      bool
      any_size_change(const GeometryParameters &g, const F &f)
      {
        const double eps = 1e-9 * g.automaton_size;
        for (const GeometryParameters::SizeBand &band : g.size_bands)
          for (const double plane : {band.z_lower, band.z_upper})
            {
              const unsigned int below = g.size_level(plane - eps);
              const unsigned int above = g.size_level(plane + eps);
              if (below != above
                  && f(plane,
                       3. * (1u << std::max(below, above)) * g.automaton_size))
                return true;
            }
        return false;
      }
    } // namespace

    // ------------------------------------------------------------------
    bool
    Region::contains(const Point3 &p) const
    {
      switch (shape)
        {
          case Shape::box:
            for (unsigned int d = 0; d < 3; ++d)
              if (p[d] < std::min(a[d], b[d]) || p[d] > std::max(a[d], b[d]))
                return false;
            return true;
          case Shape::sphere:
            return p.distance_square(a) <= radius * radius;
          case Shape::cylinder:
            {
              const dealii::Tensor<1, 3> axis = b - a;
              const double               L2   = axis.norm_square();
              const double               s    = (p - a) * axis / L2;
              if (s < 0 || s > 1)
                return false;
              const dealii::Tensor<1, 3> off = (p - a) - s * axis;
              return off.norm_square() <= radius * radius;
            }
        }
      return false;
    }


    namespace
    {
      /// A point as the Geometry entries write it ("x, y, z").
      std::string
      point_text(const Point3 &p)
      {
        return format_number(p[0]) + ", " + format_number(p[1]) + ", "
               + format_number(p[2]);
      }
    } // namespace


    ParameterBinding
    GeometryParameters::binding()
    {
      ParameterBinding b("Geometry");
      b.add("Automaton size",
            automaton_size,
            "Automaton size d (m): the distance between neighbours of the FCC "
            "packing; contact area S = d^2/(2 sqrt 2), volume V = d^3/sqrt 2.",
            Double(),
            Interval{0, inf, true, true});
      // a corner of the box: its entry reads "x, y, z" into the member
      const auto add_corner = [&b](const std::string &name,
                                   Point3            &corner,
                                   const std::string &documentation) {
        b.add(name,
              point_text(corner),
              documentation,
              Patterns::Anything(),
              [&corner, p = b.path(name)](const std::string &text) {
                corner = parse_point(text, p);
              });
      };
      add_corner("Domain lower",
                 domain_lower,
                 "Lower corner of the simulation box (m). In periodic "
                 "directions the box is the period and its length must hold a "
                 "whole number of FCC cells (a = d sqrt 2).");
      add_corner("Domain upper",
                 domain_upper,
                 "Upper corner of the simulation box (m). In non-periodic "
                 "directions automata must stay inside it (leave room for the "
                 "motion).");
      for (unsigned int d = 0; d < 3; ++d)
        b.add(std::string("Periodic ") + "xyz"[d],
              periodic[d],
              std::string("Periodic boundary in ") + "xyz"[d] + ".");
      b.add("Bodies",
            bodies_text,
            "Boxes filled with automata on one FCC lattice (origin at 'Domain "
            "lower' + a/4 in every direction), separated by ';': 'x0 y0 z0 x1 "
            "y1 z1 MATERIAL'. Automata of different bodies are not bonded at "
            "the start.");
      b.add("Size bands",
            size_bands_text,
            "Graded packing, separated by ';': 'z0 z1 k' packs the sites with "
            "z0 <= z < z1 with automata of size 2^k d (k = 1 or 2) on the FCC "
            "lattice of that size, whose sites are also sites of the finer "
            "lattices; elsewhere the size is d. Bands must not overlap, and "
            "the size changes by a factor 2 at a time (d, 2d, 4d) where "
            "bodies are on both sides (a band may end at a body's top or "
            "bottom face with any size). Automata "
            "near a change of size take their volumes and contact areas from "
            "their Voronoi cells (doc/theory/mca.md section 9); with a rough "
            "interface every change of size keeps (3 2^L + 1) d clear of its "
            "surface (2^L d the larger size), or the run is refused. Or "
            "'interface N M', the layout of a friction scene: d within N cells "
            "(a = d sqrt 2) of the rough interface's mean height and in the "
            "4 cells at the bodies' bottom and top (the loading layers), 2d "
            "in the next M cells from the interface (M >= 4; 'interface N' "
            "is M = 4) and in 4-cell transitions next to the loading layers, "
            "4d elsewhere (the log prints the bands). 'interface N M O' "
            "makes the 4 outer cells of 2^O d: O = 1 (2d), O = 2 (4d to the "
            "faces, no transitions); the loading layers are then counted in "
            "layers of those automata (Friction loading/Loading layer "
            "thickness). "
            "Plan a graded scene with tribodyn --partition-report N "
            "FILE.prm.");
      b.add("Size at free faces",
            fine_free_faces,
            "Graded packing at the free lateral faces of the bodies (faces in "
            "x or y that are not periodic). fine: the FCC cells of size 2d "
            "whose sites lie closer than a = d sqrt(2) to such a face, and "
            "those of size 4d closer than 4a, are packed one size finer (a "
            "skin of d, then of 2d, 1-2 layers thick), so a band has the "
            "fine lattice's free surface (a free surface of coarse automata "
            "is softer: its missing bonds reach twice as deep; "
            "doc/theory/mca.md section 9); band: the band's size reaches the "
            "face.",
            free_face_table);
      b.add("Regions",
            regions_text,
            "Regions applied in order after the packing, separated by ';': "
            "'box x0 y0 z0 x1 y1 z1 M', 'sphere cx cy cz r M', 'cylinder ax "
            "ay az bx by bz r M' (axis from a to b, any direction), where M "
            "is a material name (sets the material) or 'void' (removes the "
            "automata).");
      return b;
    }


    ParameterBinding
    GeometryParameters::rough_interface_binding()
    {
      ParameterBinding b("Geometry/Rough interface");
      b.add("Enabled",
            rough_interface,
            "Split the packing into body 0 below and body 1 above a rough "
            "surface z = Height + Amplitude * f(x, y), f a sum of "
            "random-phase cosines with the given wavelength (periodic over "
            "the box when the wavelength divides it).");
      b.add("Height", interface_height, "Mean height (m).");
      b.add("Amplitude",
            roughness_amplitude,
            "Roughness amplitude (m), >= 0.",
            Double(),
            Interval{0, inf, false, true});
      // (its lower end, 2d with the interface on, is checked in
      // parse_parameters())
      b.add("Wavelength",
            roughness_wavelength,
            "Roughness wavelength (m), > 0.");
      b.add("Seed", roughness_seed, "Seed of the random phases.", Integer(0));
      b.add("Gap",
            interface_gap,
            "Initial gap: body 1 is shifted up by it (m).",
            Double(),
            Interval{0, inf, false, true});
      return b;
    }


    void
    GeometryParameters::declare_parameters(ParameterHandler &prm)
    {
      GeometryParameters g;
      g.binding().declare(prm);
      g.rough_interface_binding().declare(prm);
      InclusionPackingParameters().binding().declare(prm);
    }


    void
    GeometryParameters::parse_parameters(
      ParameterHandler               &prm,
      const std::vector<std::string> &material_names)
    {
      const ParameterBinding b     = binding();
      const ParameterBinding rough = rough_interface_binding();
      b.parse(prm);
      rough.parse(prm);
      // (the fuzzer found a wavelength 1000 x below the automaton size
      // hanging the set-up: a surface finer than the lattice cannot be
      // represented)
      check_parameter_range(rough.path("Wavelength"),
                            roughness_wavelength,
                            rough_interface ? 2 * automaton_size : 0.,
                            inf,
                            !rough_interface,
                            true);
      {
        const double a = automaton_size * std::sqrt(2.);
        for (unsigned int d = 0; d < 3; ++d)
          {
            const double      L = domain_upper[d] - domain_lower[d];
            const std::string name
              = std::string("Geometry/Domain lower and Domain upper (")
                + "xyz"[d] + ")";
            check_parameter(L > 0,
                            name,
                            "the domain must have a positive length in "
                            "every direction.");
            if (periodic[d])
              {
                const double cells = L / a;
                check_parameter(
                  std::abs(cells - std::round(cells)) < 1e-6 * cells
                    && std::round(cells) >= 2,
                  name,
                  "in a periodic direction the length must be a whole "
                  "number (>= 2) of FCC cells a = d sqrt(2) = "
                    + format_number(a) + " m ('" + b.path("Automaton size")
                    + "' d = " + format_number(automaton_size)
                    + " m); the nearest is "
                    + format_number(std::max(2., std::round(cells)) * a)
                    + " m.");
              }
          }

        // The background mesh has cells of about the automaton size: a box
        // of more than 1e10 FCC cells (~4e10 automata) is a unit mistake.
        const double n_fcc_cells = box_fcc_cells(domain_lower, domain_upper, a);
        check_parameter(n_fcc_cells <= 1e10,
                        "Geometry/Domain lower and Domain upper",
                        "the box holds " + format_number(n_fcc_cells)
                          + " FCC cells of a = d sqrt(2) = " + format_number(a)
                          + " m (limit 1e10): shrink the box or enlarge '"
                          + b.path("Automaton size") + "'.");
        bodies.clear();
        for (const std::string &entry : split(bodies_text, ';'))
          {
            const std::string p = b.path("Bodies");
            const auto        t = tokens(entry);
            if (t.size() != 7)
              throw InputError("Parameter '" + p + "': the entry '" + entry
                               + "' must read 'x0 y0 z0 x1 y1 z1 MATERIAL'.");
            Body body;
            body.lower    = read_point(t, 0, p, entry);
            body.upper    = read_point(t, 3, p, entry);
            body.material = material_index(material_names, t[6], p);
            bodies.push_back(body);
          }
        check_parameter(!bodies.empty(),
                        b.path("Bodies"),
                        "give at least one body.");

        size_bands.clear();
        for (const std::string &entry :
             split(bands_around_interface(size_bands_text), ';'))
          {
            const auto        t = tokens(entry);
            const std::string p = b.path("Size bands");
            if (t.size() != 3)
              throw InputError("Parameter '" + p + "': the entry '" + entry
                               + "' must read 'z0 z1 k' (heights in m, k = "
                                 "1 or 2: automata of size 2^k d).");
            SizeBand band;
            band.z_lower   = to_double(t[0], p, entry);
            band.z_upper   = to_double(t[1], p, entry);
            const double k = to_double(t[2], p, entry);
            check_parameter(band.z_lower < band.z_upper,
                            p,
                            "the entry '" + entry + "' must have z0 < z1.");
            check_parameter(k == 1 || k == 2,
                            p,
                            "the entry '" + entry + "' has level " + t[2]
                              + "; give k = 1 (size 2d) or 2 (size 4d).");
            band.level = static_cast<unsigned int>(k);
            for (const SizeBand &other : size_bands)
              check_parameter(band.z_upper <= other.z_lower
                                || other.z_upper <= band.z_lower,
                              p,
                              "the band '" + entry
                                + "' overlaps an earlier one: give each "
                                  "height one size.");
            size_bands.push_back(band);
          }
        // Sizes change by one level at a time: across a jump d -> 4d the
        // Voronoi cells of the small automata reach far between the large
        // ones (doc/theory/mca.md §9). A band's side where no body is (at
        // a body's bottom or top face, or the box's) has no automata on
        // one side and changes nothing.
        auto in_a_body = [&](const double z) {
          for (const Body &b : bodies)
            if (b.lower[2] <= z && z < b.upper[2])
              return true;
          return false;
        };
        for (const SizeBand &band : size_bands)
          for (const double plane : {band.z_lower, band.z_upper})
            {
              const double eps = 1e-9 * automaton_size;
              if (!in_a_body(plane - eps) || !in_a_body(plane + eps))
                continue;
              const int below = size_level(plane - eps);
              const int above = size_level(plane + eps);
              check_parameter(std::abs(below - above) <= 1,
                              b.path("Size bands"),
                              "at z = " + format_number(plane)
                                + " m the size jumps from "
                                + std::to_string(1 << below) + "d to "
                                + std::to_string(1 << above)
                                + "d; grade it through a band of 2d "
                                  "between them (sizes may change by a "
                                  "factor 2 only).");
            }
        check_size_changes_clear_of_interface();
        // A periodic direction must hold whole cells of the coarsest
        // lattice, or its sites do not match across the period.
        unsigned int top = 0;
        for (const SizeBand &band : size_bands)
          top = std::max(top, band.level);
        for (unsigned int e = 0; e < 3 && top > 0; ++e)
          if (periodic[e])
            {
              const double coarse
                = (1u << top) * automaton_size * std::sqrt(2.);
              const double cells = (domain_upper[e] - domain_lower[e]) / coarse;
              check_parameter(
                std::abs(cells - std::round(cells)) < 1e-6 * cells
                  && std::round(cells) >= 1,
                b.path("Size bands"),
                std::string("with automata of ") + std::to_string(1u << top)
                  + "d the periodic length in " + "xyz"[e]
                  + " must be a whole number of their FCC cells, "
                  + std::to_string(1u << top)
                  + " d sqrt(2) = " + format_number(coarse)
                  + " m (Geometry/Domain lower and "
                    "Domain upper), or the coarse sites do not match across "
                    "the period; the nearest is "
                  + format_number(std::max(1., std::round(cells)) * coarse)
                  + " m.");
            }

        regions.clear();
        for (const std::string &entry : split(regions_text, ';'))
          {
            const auto        t = tokens(entry);
            Region            r;
            const std::string p = b.path("Regions");
            std::size_t       n = 0;
            if (!t.empty() && t[0] == "box")
              {
                r.shape = Region::Shape::box;
                n       = 8;
              }
            else if (!t.empty() && t[0] == "sphere")
              {
                r.shape = Region::Shape::sphere;
                n       = 6;
              }
            else if (!t.empty() && t[0] == "cylinder")
              {
                r.shape = Region::Shape::cylinder;
                n       = 9;
              }
            else
              throw InputError("Parameter '" + p + "': the entry '" + entry
                               + "' must start with box, sphere or cylinder.");
            if (t.size() != n)
              throw InputError(
                "Parameter '" + p + "': the entry '" + entry + "' has "
                + std::to_string(t.size()) + " fields; expected "
                + std::to_string(n)
                + " ('box x0 y0 z0 x1 y1 z1 M', 'sphere cx cy cz r M' or "
                  "'cylinder ax ay az bx by bz r M').");
            r.a = read_point(t, 1, p, entry);
            if (r.shape == Region::Shape::sphere)
              r.radius = to_double(t[4], p, entry);
            else
              r.b = read_point(t, 4, p, entry);
            if (r.shape == Region::Shape::cylinder)
              {
                r.radius = to_double(t[7], p, entry);
                check_parameter((r.b - r.a).norm() > 0,
                                p,
                                "the cylinder '" + entry
                                  + "' has a zero-length axis.");
              }
            if (r.shape != Region::Shape::box)
              check_parameter(r.radius > 0,
                              p,
                              "the radius in '" + entry
                                + "' must be positive.");
            r.material = t.back() == "void"
                           ? -1
                           : static_cast<int>(
                             material_index(material_names, t.back(), p));
            regions.push_back(r);
          }
      }
      inclusions.parse_parameters(prm, material_names);
      generate_inclusion_layout();
    }


    void
    GeometryParameters::check_memory_per_rank(const unsigned int n_ranks) const
    {
      // Found by the parameter fuzzer: a box that, filled, needs more memory
      // per rank than the whole machine has would only thrash in the set-up
      // (about 1 KB per automaton, 4 automata per FCC cell). Checked when a
      // run starts (not at parsing: tribodyn --partition-report reports
      // scenes of any size for any number of ranks).
      const double a           = automaton_size * std::sqrt(2.);
      const double n_fcc_cells = box_fcc_cells(domain_lower, domain_upper, a);
      const double per_rank    = n_fcc_cells * 4 * 1000. / n_ranks;
      const double installed
        = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
      check_parameter(installed <= 0 || per_rank <= installed,
                      "Geometry/Domain lower and Domain upper",
                      "the box holds " + format_number(n_fcc_cells)
                        + " FCC cells of a = d sqrt(2) = " + format_number(a)
                        + " m; filled, that is about "
                        + format_number(per_rank / 1e9) + " GB per rank on "
                        + format_number(n_ranks)
                        + " rank(s), more than this machine's "
                        + format_number(installed / 1e9)
                        + " GB: shrink the box, enlarge "
                          "'Geometry/Automaton size', or run on more ranks "
                          "(nodes; tribodyn --partition-report N FILE.prm "
                          "gives the memory per rank on N ranks).");
    }

    unsigned int
    GeometryParameters::size_level(const double z) const
    {
      for (const SizeBand &band : size_bands)
        if (z >= band.z_lower && z < band.z_upper)
          return band.level;
      return 0;
    }


    double
    GeometryParameters::largest_pair_distance() const
    {
      unsigned int top = 0;
      for (const SizeBand &band : size_bands)
        top = std::max(top, band.level);
      return top == 0 ? automaton_size
                      : transition_face_factor() * (1u << top) * automaton_size;
    }


    namespace
    {
      /// Distance of @p q inside the free lateral faces of @p body (its
      /// faces in x and y that are not periodic).
      double
      lateral_depth(const Point3              &q,
                    const Body                &body,
                    const std::array<bool, 3> &periodic)
      {
        double depth = std::numeric_limits<double>::max();
        for (unsigned int c = 0; c < 2; ++c)
          if (!periodic[c])
            depth
              = std::min({depth, q[c] - body.lower[c], body.upper[c] - q[c]});
        return depth;
      }
    } // namespace


    int
    GeometryParameters::body_containing(const Point3 &p) const
    {
      for (unsigned int m = 0; m < bodies.size(); ++m)
        {
          bool inside = true;
          for (unsigned int c = 0; c < 3; ++c)
            inside = inside && p[c] >= bodies[m].lower[c]
                     && p[c] < bodies[m].upper[c];
          if (inside)
            return static_cast<int>(m);
        }
      return -1;
    }


    void
    GeometryParameters::check_size_changes_clear_of_interface() const
    {
      // The automata within 3 times the larger size of a change of size
      // (near_size_change()) take their contact areas from the Voronoi
      // cells of the set-up; a pair of them found later is inert (no face,
      // no force: AutomatonSystem::new_pair_area()). Where they can meet
      // the other body of a rough interface, contacts would be lost
      // silently (and the set-up's cells would reach across a narrow gap:
      // the Voronoi check's internal error). They must stay below the
      // lowest point of the surface (above its highest) by one more
      // automaton d, the contact distance of two fine ones.
      if (!rough_interface || size_bands.empty())
        return;
      const auto [lowest, highest] = rough_surface_range(*this);
      any_size_change(*this, [&](const double plane, const double near) {
        const double reach = near + automaton_size;
        if (plane + reach <= lowest || plane - reach >= highest)
          return false;
        throw InputError(
          "Parameter 'Geometry/Size bands': the change of size at z = "
          + format_number(plane) + " m is within " + format_number(reach)
          + " m of the rough interface, whose surface spans z = "
          + format_number(lowest) + " to " + format_number(highest)
          + " m. The automata within 3 times the larger size of a "
            "change of size take their contact areas from the set-up "
            "and a contact they make later is inert (doc/theory/mca.md "
            "section 9), so they must stay one automaton d clear of the "
            "other body: keep every change of size below z = "
          + format_number(lowest - reach) + " m or above "
          + format_number(highest + reach)
          + " m (with 'interface N M': a larger N).");
      });
    }


    std::string
    GeometryParameters::bands_around_interface(const std::string &text) const
    {
      const auto t = tokens(text);
      if (t.empty() || t[0] != "interface")
        return text;
      const std::string p = "Geometry/Size bands";
      check_parameter(t.size() >= 2 && t.size() <= 4,
                      p,
                      "'" + text
                        + "' must read 'interface N', 'interface N M' or "
                          "'interface N M O' (N cells of fine automata on "
                          "each side of the rough interface, then M of 2d; "
                          "O the size level of the outer cells that hold the "
                          "loading layers) or list the bands as 'z0 z1 k; "
                          "...'.");
      // a whole number in [lowest, highest] read from @p word, or a
      // refusal saying what @p what (N, M or O) is
      const auto whole = [&](const std::string &word,
                             const double       lowest,
                             const double       highest,
                             const std::string &what) {
        const double n = to_double(word, p, text);
        check_parameter(n >= lowest && n <= highest && n == std::round(n),
                        p,
                        "in '" + text + "' " + what);
        return std::lround(n);
      };
      const long N = whole(t[1],
                           1,
                           1e6,
                           "N, the cells of fine automata on each side of the "
                           "interface, must be a whole number >= 1 (cells of "
                           "a = d sqrt 2).");
      const long M = t.size() >= 3
                       ? whole(t[2],
                               4,
                               1e6,
                               "M, the cells of 2d next to the fine band, "
                               "must be a whole number >= 4 (cells of a = d "
                               "sqrt 2).")
                       : 4;
      const long O = t.size() == 4
                       ? whole(t[3],
                               0,
                               2,
                               "O, the size level of the outer cells (the "
                               "loading layers), must be 0 (d), 1 (2d) or 2 "
                               "(4d).")
                       : 0;
      check_parameter(rough_interface,
                      p,
                      "'" + text
                        + "' grades the bodies around the rough interface: "
                          "enable Geometry/Rough interface, or give the "
                          "bands as 'z0 z1 k; ...'.");
      // Heights in cells of the fine lattice from the bodies' bottom, as
      // the graded friction scenes were laid out by hand: the outer 4
      // cells (loading layers) of size 2^O d, 4-cell transitions of 2d
      // next to them if they are fine, M cells of 2d next to the fine
      // band, 4d between.
      const double a      = automaton_size * std::sqrt(2.);
      double       bottom = domain_upper[2], top = domain_lower[2];
      for (const Body &b : bodies)
        {
          bottom = std::min(bottom, b.lower[2]);
          top    = std::max(top, b.upper[2]);
        }
      const long cells  = std::lround(std::floor((top - bottom) / a + 1e-6));
      const long centre = std::lround((interface_height - bottom) / a);
      const long outer  = O == 0 ? 8 : 4; // the outer cells and transitions
      const long below  = centre - N - M - outer - 4; // left for 4d
      const long above  = cells - centre - N - M - outer - 4;
      check_parameter(
        below > 0 && above > 0,
        p,
        "'" + text + "': the bodies are " + std::to_string(centre)
          + " cells (a = d sqrt 2) below and " + std::to_string(cells - centre)
          + " above the rough interface; the layout needs more than N + M + "
          + std::to_string(outer + 4)
          + " on each side (N fine, M of 2d, some 4d and the outer cells). "
            "Lower N or M, make the bodies taller or give the bands as 'z0 "
            "z1 k; ...'.");
      // Bands {z0, z1, level} in cells; the fine ones are the gaps. The 4d
      // of the bases starts `coarse` cells from each face, after 4 cells of
      // 2d unless it reaches the face.
      const long                       coarse = O == 0 ? 8 : (O == 1 ? 4 : 0);
      std::vector<std::array<long, 3>> bands;
      if (O < 2)
        bands.push_back({{coarse - 4, coarse, 1}});
      bands.push_back({{coarse, centre - N - M, 2}});
      bands.push_back({{centre - N - M, centre - N, 1}});
      bands.push_back({{centre + N, centre + N + M, 1}});
      bands.push_back({{centre + N + M, cells - coarse, 2}});
      if (O < 2)
        bands.push_back({{cells - coarse, cells - coarse + 4, 1}});
      std::ostringstream out;
      out << std::setprecision(17);
      for (const auto &band : bands)
        out << (out.tellp() > 0 ? "; " : "") << bottom + band[0] * a << ' '
            << (band[1] == cells ? top : bottom + band[1] * a) << ' '
            << band[2];
      return out.str();
    }


    std::array<double, 2>
    GeometryParameters::bodies_z_range() const
    {
      const double          a     = automaton_size * std::sqrt(2.);
      std::array<double, 2> range = {{domain_upper[2], domain_lower[2]}};
      for (const Body &b : bodies)
        {
          range[0] = std::min(range[0], b.lower[2]);
          range[1] = std::max(range[1], b.upper[2] - 1e-9 * a);
        }
      return range;
    }


    unsigned int
    GeometryParameters::size_level(const Point3 &p) const
    {
      const unsigned int band = size_level(p[2]);
      if (band == 0 || !has_skins())
        return band;
      const int m = body_containing(p);
      if (m < 0)
        return 0;
      const Body  &body  = bodies[m];
      const double a     = automaton_size * std::sqrt(2.);
      const double depth = lateral_depth(p, body, periodic);
      // The FCC cells of the lattice of 2^L d (rhombic dodecahedra
      // |x_i| + |x_j| <= A/2 about their sites, A = 2^L a) are kept if their
      // sites lie in the band and skin_depth(L) inside the body. A site of
      // the next finer lattice is the site, a face centre or an axis vertex
      // of these cells; as at a plane between bands (there the finer sites
      // start at the vertices of the coarse cells), it is coarse (dropped
      // unless a coarse site) inside a kept cell or on a face of one, and
      // fine at a vertex that at least half of its six cells leave to the
      // skin (a vertex with fewer would be a lone fine site among coarse
      // ones).
      for (unsigned int level = band; level > 0; --level)
        {
          const double A = (1u << level) * a, T = skin_depth(level);
          if (depth >= T + A / 2)
            return level;
          if (depth < T - A / 2)
            continue;
          std::array<long, 3> n0;
          for (unsigned int c = 0; c < 3; ++c)
            n0[c] = static_cast<long>(
              std::floor((p[c] - domain_lower[c] - a / 4) / A));
          const double tol     = 1e-9 * A;
          const auto   z_range = bodies_z_range();
          unsigned int n_cells = 0, n_skin = 0;
          bool         inside_kept = false;
          for (long i = -1; i <= 1; ++i)
            for (long j = -1; j <= 1; ++j)
              for (long k = -1; k <= 1; ++k)
                for (const auto &b : fcc_basis)
                  {
                    const long n[3] = {n0[0] + i, n0[1] + j, n0[2] + k};
                    Point3     site;
                    double     x[3];
                    for (unsigned int c = 0; c < 3; ++c)
                      {
                        site[c] = domain_lower[c] + a / 4 + A * (n[c] + b[c]);
                        x[c]    = std::abs(p[c] - site[c]);
                      }
                    const double sums[3]
                      = {x[0] + x[1], x[0] + x[2], x[1] + x[2]};
                    unsigned int on_faces = 0;
                    bool         holds    = true;
                    for (const double sum : sums)
                      {
                        holds = holds && sum <= A / 2 + tol;
                        on_faces += sum > A / 2 - tol;
                      }
                    if (!holds)
                      continue;
                    // (beyond the bodies in z the bands at their top and
                    // bottom go on, as the continued lattice does)
                    const bool kept
                      = size_level(std::clamp(site[2], z_range[0], z_range[1]))
                          >= level
                        && lateral_depth(site, body, periodic) >= T;
                    ++n_cells;
                    n_skin += !kept;
                    // inside, or on a face (one of the three sums at A/2)
                    inside_kept = inside_kept || (kept && on_faces <= 1);
                  }
          if (inside_kept || 2 * n_skin <= n_cells)
            return level;
        }
      return 0;
    }


    bool
    GeometryParameters::near_size_change(const Point3 &p) const
    {
      const double z = p[2];
      // the inner faces of the skins at free lateral faces, where the
      // bands near p are coarser than the skin
      const int m = has_skins() ? body_containing(p) : -1;
      if (m >= 0)
        {
          const double depth = lateral_depth(p, bodies[m], periodic);
          for (unsigned int level = 1; level <= 2; ++level)
            {
              // (the faces between kept and skin cells lie within A/2 of
              // the skin depth)
              const double width
                = (3. + std::sqrt(0.5)) * (1u << level) * automaton_size;
              if (std::abs(depth - skin_depth(level)) >= width)
                continue;
              for (const SizeBand &band : size_bands)
                if (band.level >= level && band.z_lower < z + width
                    && z - width < band.z_upper)
                  return true;
            }
        }
      return any_size_change(*this, [z](const double plane, const double near) {
        return std::abs(z - plane) < near;
      });
    }
  } // namespace mca
} // namespace tribodyn
