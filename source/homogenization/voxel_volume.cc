// Voxel volumes of the 3D cell problems (issue #51): the generators
// (laminate, random spheres, aligned fibres and fibres in a cone of
// orientations) and the raw files with their header.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/selection.h>
#include <tribodyn/homogenization/voxel_volume.h>

namespace tribodyn
{
  namespace homogenization
  {
    using dealii::ParameterHandler;
    namespace Patterns = dealii::Patterns;

    namespace
    {
      constexpr SelectionTable<VolumeMorphologyParameters::Generator, 5>
        generator_choices{
          {{"laminate", VolumeMorphologyParameters::Generator::laminate},
           {"spheres", VolumeMorphologyParameters::Generator::spheres},
           {"fibres", VolumeMorphologyParameters::Generator::fibres},
           {"raw file", VolumeMorphologyParameters::Generator::raw_file},
           {"image stack",
            VolumeMorphologyParameters::Generator::image_stack}}};
      constexpr SelectionTable<unsigned int, 3> axis_choices{
        {{"x", 0u}, {"y", 1u}, {"z", 2u}}};
    } // namespace


    ParameterBinding
    VolumeMorphologyParameters::binding()
    {
      ParameterBinding b("Morphology");
      b.add("Generator",
            generator,
            "Where the voxels come from: 'laminate' (layers through the "
            "whole box, normal to 'Laminate normal'), 'spheres' (random "
            "non-overlapping spheres of the heterogeneity, placed "
            "periodically), 'fibres' (the same with short cylinders along "
            "'Fibre axis', or about it within 'Fibre cone half-angle'), 'raw "
            "file' (material ids read from the raw "
            "volume that 'Raw header' describes), 'image stack' (a "
            "multi-page TIFF segmented into phases, subsection 'Image "
            "stack').",
            generator_choices);
      const char *axes[3] = {"x", "y", "z"};
      for (unsigned int d = 0; d < 3; ++d)
        b.add(std::string("Voxels in ") + axes[d],
              n_voxels[d],
              std::string("Number of voxels along ") + axes[d]
                + " (generators; a raw file or an image stack gives its "
                  "own size).",
              Patterns::Integer(2));
      b.add("Voxel size",
            voxel_size,
            "Edge of a cubic voxel of the generators (m); of an image stack "
            "the spacing of its pages (z; x and y: 'Image stack/Pixel "
            "size'); a raw file's header gives its own.",
            Patterns::Double(),
            Interval{0, 1e3, true, false});
      b.add("Volume fraction",
            volume_fraction,
            "Target volume fraction of the heterogeneity (material id 1) "
            "of the generators; in [0, 1).",
            Patterns::Double(),
            Interval{0, 1, false, true});
      b.add("Laminate normal",
            laminate_normal,
            "Laminate: the axis normal to the layers.",
            axis_choices);
      b.add("Laminate periods",
            laminate_periods,
            "Laminate: number of (matrix, heterogeneity) periods along the "
            "normal; it must divide the number of voxels along it.",
            Patterns::Integer(1));
      b.add("Radius",
            radius,
            "Spheres and fibres: radius in voxels (a voxel belongs to an "
            "inclusion when its centre lies inside).",
            Patterns::Double(),
            Interval{0.5, 1e6});
      b.add("Fibre length",
            fibre_length,
            "Fibres: length in voxels (flat-ended cylinders).",
            Patterns::Double(),
            Interval{1, 1e6});
      b.add("Fibre axis",
            fibre_axis,
            "Fibres: the axis they are aligned with (or, with 'Fibre cone "
            "half-angle' > 0, the axis of their cone of orientations).",
            axis_choices);
      b.add("Fibre cone half-angle",
            fibre_cone_angle,
            "Fibres: half-angle (degrees) of the cone about 'Fibre axis' in "
            "which the fibres' axes are drawn, uniformly over its spherical "
            "cap (the cosine of their angle to the axis uniform in [cos of "
            "the half-angle, 1], the azimuth uniform): 0 = all aligned with "
            "'Fibre axis', 90 = uniformly random orientations in 3D. Above "
            "0 the box must hold a fibre's extent plus 2 Radius + 1 voxels "
            "along every axis.",
            Patterns::Double(),
            Interval{0, 90});
      b.add("Seed",
            random_seed,
            "Spheres and fibres: seed of the random placement (same seed, "
            "same volume).",
            Patterns::Integer(0));
      b.add("Raw header",
            raw_header,
            "Raw file: the header file of the volume (lines 'size = nx ny "
            "nz', 'voxel size = h' or 'hx hy hz' in m, 'type = uint8', "
            "'file = NAME' relative to the header); the raw file holds one "
            "material id per voxel, x fastest, then y, then z.",
            Patterns::FileName());
      return b;
    }


    void
    VolumeMorphologyParameters::declare_parameters(ParameterHandler &prm)
    {
      VolumeMorphologyParameters().binding().declare(prm);
      ImageStackParameters::declare_parameters(prm);
    }


    void
    VolumeMorphologyParameters::parse_parameters(ParameterHandler &prm)
    {
      const ParameterBinding b = binding();
      b.parse(prm);
      image_stack.parse_parameters(prm, generator == Generator::image_stack);
      if (generator == Generator::raw_file)
        check_parameter(!raw_header.empty(),
                        b.path("Raw header"),
                        "give the header file of the raw volume ('Generator "
                        "= raw file' reads it).");
      if (generator == Generator::laminate)
        check_parameter(n_voxels[laminate_normal] % laminate_periods == 0,
                        b.path("Laminate periods"),
                        "it must divide the number of voxels along the "
                        "normal ("
                          + std::to_string(n_voxels[laminate_normal])
                          + "), so that every layer ends on a voxel face.");
    }


    VoxelVolume::VoxelVolume(const std::array<unsigned int, 3> &n_voxels,
                             const std::array<double, 3>       &voxel_size,
                             std::vector<std::uint8_t>          ids,
                             const std::string                 &origin)
        : n(n_voxels)
        , h(voxel_size)
        , ids(std::move(ids))
        , origin(origin)
    {
    }


    unsigned int
    VoxelVolume::n_phases() const
    {
      const unsigned int largest
        = ids.empty() ? 0 : *std::max_element(ids.begin(), ids.end());
      return std::max(2u, largest + 1);
    }


    std::vector<double>
    VoxelVolume::phase_fractions() const
    {
      std::vector<double> f(n_phases(), 0.);
      for (const std::uint8_t id : ids)
        f[id] += 1.;
      for (double &x : f)
        x /= ids.size();
      return f;
    }


    namespace
    {
      /// Layers normal to @p axis: in each of @p periods periods, the
      /// first round(f p) voxels are heterogeneity (id 1).
      VoxelVolume
      make_laminate(const VolumeMorphologyParameters &p)
      {
        const unsigned int a      = p.laminate_normal;
        const unsigned int period = p.n_voxels[a] / p.laminate_periods;
        const unsigned int thick
          = static_cast<unsigned int>(std::lround(p.volume_fraction * period));
        std::vector<std::uint8_t> ids(std::size_t(p.n_voxels[0]) * p.n_voxels[1]
                                      * p.n_voxels[2]);
        std::size_t               v = 0;
        for (unsigned int k = 0; k < p.n_voxels[2]; ++k)
          for (unsigned int j = 0; j < p.n_voxels[1]; ++j)
            for (unsigned int i = 0; i < p.n_voxels[0]; ++i, ++v)
              {
                const unsigned int index[3] = {i, j, k};
                ids[v] = (index[a] % period) < thick ? 1 : 0;
              }
        return VoxelVolume(p.n_voxels,
                           {{p.voxel_size, p.voxel_size, p.voxel_size}},
                           std::move(ids),
                           "laminate normal to " + std::string(1, "xyz"[a])
                             + ", " + std::to_string(p.laminate_periods)
                             + " period(s) of " + std::to_string(period)
                             + " voxels, " + std::to_string(thick)
                             + " of them heterogeneity");
      }


      /**
       * A unit vector uniform over the spherical cap of half-angle @p alpha
       * (radians) about the axis @p a: cos(theta) uniform in [cos(alpha),
       * 1], the azimuth phi uniform in [0, 2 pi), n = cos(theta) e_a +
       * sin(theta) (cos(phi) e_b + sin(phi) e_c) with (a, b, c) cyclic.
       */
      std::array<double, 3>
      cone_direction(std::mt19937_64   &rng,
                     const unsigned int a,
                     const double       alpha)
      {
        std::uniform_real_distribution<double> uniform(0., 1.);
        const double cos_theta = 1. - uniform(rng) * (1. - std::cos(alpha));
        const double sin_theta
          = std::sqrt(std::max(0., 1. - cos_theta * cos_theta));
        const double          phi = 2. * M_PI * uniform(rng);
        std::array<double, 3> n;
        n[a]           = cos_theta;
        n[(a + 1) % 3] = sin_theta * std::cos(phi);
        n[(a + 2) % 3] = sin_theta * std::sin(phi);
        return n;
      }


      /**
       * The squared distance of the segments x + s m and y + t n, s, t in
       * [-h, h], with unit directions m and n: the closest points of
       * Ericson (Real-Time Collision Detection, 5.1.9), s first from the
       * unconstrained minimum (the centre when the segments are
       * parallel), then t from s, then s again from the clamped t.
       */
      double
      segment_distance2(const std::array<double, 3> &x,
                        const std::array<double, 3> &m,
                        const std::array<double, 3> &y,
                        const std::array<double, 3> &n,
                        const double                 h)
      {
        std::array<double, 3> w;
        for (unsigned int k = 0; k < 3; ++k)
          w[k] = x[k] - y[k];
        double b = 0, d = 0, f = 0;
        for (unsigned int k = 0; k < 3; ++k)
          {
            b += m[k] * n[k];
            d += m[k] * w[k];
            f += n[k] * w[k];
          }
        const auto clamp = [h](const double v) { return std::clamp(v, -h, h); };
        const double denominator = 1. - b * b;
        double s = denominator > 1e-12 ? clamp((b * f - d) / denominator) : 0.;
        double t = b * s + f;
        if (t < -h || t > h)
          {
            t = clamp(t);
            s = clamp(b * t - d);
          }
        double distance2 = 0;
        for (unsigned int k = 0; k < 3; ++k)
          {
            const double g = w[k] + s * m[k] - t * n[k];
            distance2 += g * g;
          }
        return distance2;
      }


      /**
       * Random sequential addition of inclusions in the periodic box:
       * spheres of radius r, or (fibres) cylinders of radius r and length
       * l along the axis a, all in voxels. Centres are uniform; a
       * candidate is kept when its distance to every kept inclusion is at
       * least 2 r + 1 voxels (minimum image; for fibres the distance of
       * the axis segments, sqrt(p^2 + max(0, |d_a| - l)^2) with p the
       * distance across the axis and d_a along it), so that no two share a
       * voxel face; inclusions are added until their volume, 4/3 pi r^3
       * or pi r^2 l each, reaches the target fraction. A voxel is
       * heterogeneity when its centre lies inside one (minimum image):
       * an inclusion cut by a face reappears at the opposite one.
       *
       * Misaligned fibres ('Fibre cone half-angle' alpha > 0): each
       * candidate also draws its unit axis n in the cone of half-angle
       * alpha about a (cone_direction(), from a second generator seeded
       * from the seed through std::seed_seq, so that the centres are those
       * of the aligned generator), the distance of two fibres is the distance
       * of their axis segments (segment_distance2()) over the 27 periodic
       * images next to the minimum image, and a voxel is fibre when its centre
       * x has |(x - c).n| <= l/2 and |x - c|^2 - ((x - c).n)^2 <= r^2. The box
       * must hold l |n_d| + 2 r + 1 voxels along every axis d (l along a, l
       * sin(alpha) across), so that no fibre comes within 2 r + 1 of its own
       * periodic image and the 27 images hold the nearest one.
       */
      VoxelVolume
      make_inclusions(const VolumeMorphologyParameters &p)
      {
        const bool fibres
          = p.generator == VolumeMorphologyParameters::Generator::fibres;
        const auto        &n      = p.n_voxels;
        const double       r      = p.radius;
        const unsigned int a      = p.fibre_axis;
        const double       l      = fibres ? p.fibre_length : 0.;
        const double       alpha  = p.fibre_cone_angle * M_PI / 180.;
        const bool         cone   = fibres && p.fibre_cone_angle > 0;
        const double       volume = double(n[0]) * n[1] * n[2];
        const double       inclusion_volume
          = fibres ? M_PI * r * r * l : 4. / 3. * M_PI * r * r * r;
        const unsigned int n_target = static_cast<unsigned int>(
          std::lround(p.volume_fraction * volume / inclusion_volume));
        const std::string what = fibres ? "fibre" : "sphere";
        for (unsigned int d = 0; d < 3; ++d)
          check_parameter(2 * r + 1 <= n[d],
                          "Morphology/Radius",
                          "a " + what + " of radius " + format_number(r)
                            + " voxels must fit in the box (2 r + 1 <= "
                            + std::to_string(n[d]) + " voxels along "
                            + std::string(1, "xyz"[d]) + ").");
        if (fibres && !cone)
          check_parameter(l + 1 <= n[a],
                          "Morphology/Fibre length",
                          "a fibre of " + format_number(l)
                            + " voxels must be at least one voxel shorter "
                              "than the box along its axis ("
                            + std::to_string(n[a]) + " voxels along "
                            + std::string(1, "xyz"[a])
                            + "), or it would touch its periodic image.");
        if (cone)
          for (unsigned int d = 0; d < 3; ++d)
            {
              // the largest extent l |n_d| of an axis in the cone
              const double extent
                = d == a ? l : l * std::sin(std::min(alpha, M_PI / 2));
              check_parameter(
                extent + 2 * r + 1 <= n[d] + 1e-9,
                d == a ? "Morphology/Fibre length"
                       : "Morphology/Fibre cone half-angle",
                "fibres of " + format_number(l) + " voxels within "
                  + format_number(p.fibre_cone_angle) + " degrees of "
                  + std::string(1, "xyz"[a]) + " reach " + format_number(extent)
                  + " voxels along " + std::string(1, "xyz"[d])
                  + "; with the gap 2 r + 1 = " + format_number(2 * r + 1)
                  + " they need " + format_number(extent + 2 * r + 1)
                  + " of the box's " + std::to_string(n[d])
                  + ", or a fibre would come too close to its periodic "
                    "image. Lower 'Morphology/Fibre cone half-angle' or "
                    "'Morphology/Fibre length', or enlarge the box.");
            }
        std::mt19937_64 rng(p.random_seed);
        // the axes from a generator of their own, so that the centres are
        // the aligned generator's
        std::seed_seq   orientation_seed{std::uint32_t(p.random_seed),
                                       std::uint32_t(p.random_seed >> 32),
                                       51u};
        std::mt19937_64 orientation_rng(orientation_seed);
        std::uniform_real_distribution<double> uniform(0., 1.);
        std::vector<std::array<double, 3>>     centres, axes;
        // the minimum-image difference y - x
        const auto difference = [&](const std::array<double, 3> &x,
                                    const std::array<double, 3> &y) {
          std::array<double, 3> d;
          for (unsigned int k = 0; k < 3; ++k)
            {
              d[k] = y[k] - x[k];
              d[k] -= n[k] * std::round(d[k] / n[k]);
            }
          return d;
        };
        // the squared distance of two inclusions' centres (spheres) or
        // axis segments (aligned fibres)
        const auto distance2 = [&](const std::array<double, 3> &x,
                                   const std::array<double, 3> &y) {
          const auto d = difference(x, y);
          double     s = 0;
          for (unsigned int k = 0; k < 3; ++k)
            if (!fibres || k != a)
              s += d[k] * d[k];
          if (fibres)
            {
              const double g = std::max(0., std::fabs(d[a]) - l);
              s += g * g;
            }
          return s;
        };
        // the squared distance of the axis segments of two fibres of axes
        // m and v (cone), the smallest over the periodic images next to
        // the minimum image
        const auto cone_distance2 = [&](const std::array<double, 3> &x,
                                        const std::array<double, 3> &m,
                                        const std::array<double, 3> &y,
                                        const std::array<double, 3> &v) {
          const auto d        = difference(x, y);
          double     smallest = std::numeric_limits<double>::max();
          for (int i = -1; i <= 1; ++i)
            for (int j = -1; j <= 1; ++j)
              for (int k = -1; k <= 1; ++k)
                {
                  const std::array<double, 3> image{{x[0] + d[0] + i * n[0],
                                                     x[1] + d[1] + j * n[1],
                                                     x[2] + d[2] + k * n[2]}};
                  smallest = std::min(smallest,
                                      segment_distance2(x, m, image, v, l / 2));
                }
          return smallest;
        };
        const double          gap          = 2 * r + 1;
        const unsigned int    max_attempts = 1000 * std::max(n_target, 1u);
        unsigned int          attempts     = 0;
        std::array<double, 3> along{{0., 0., 0.}};
        along[a] = 1.;
        while (centres.size() < n_target && attempts < max_attempts)
          {
            ++attempts;
            std::array<double, 3> c;
            for (unsigned int d = 0; d < 3; ++d)
              c[d] = uniform(rng) * n[d];
            const std::array<double, 3> axis
              = cone ? cone_direction(orientation_rng, a, alpha) : along;
            bool free = true;
            for (unsigned int o = 0; o < centres.size(); ++o)
              if ((cone ? cone_distance2(c, axis, centres[o], axes[o])
                        : distance2(c, centres[o]))
                  < gap * gap)
                {
                  free = false;
                  break;
                }
            if (free)
              {
                centres.push_back(c);
                axes.push_back(axis);
              }
          }
        if (centres.size() < n_target)
          throw InputError(
            "Parameter 'Morphology/Volume fraction' = "
            + format_number(p.volume_fraction) + ": only "
            + std::to_string(centres.size()) + " of the "
            + std::to_string(n_target) + " non-overlapping " + what
            + "s of radius " + format_number(r)
            + " voxels it needs fit in the box after "
            + std::to_string(attempts)
            + " random placements (random sequential addition jams near a "
              "fraction of 0.38 for spheres). Lower 'Morphology/Volume "
              "fraction' or 'Morphology/Radius', or enlarge the box.");

        std::vector<std::uint8_t> ids(static_cast<std::size_t>(n[0]) * n[1]
                                        * n[2],
                                      0);
        for (unsigned int o = 0; o < centres.size(); ++o)
          {
            const auto &c = centres[o];
            const auto &m = axes[o];
            // the voxels around the inclusion, wrapped into the box
            int lower[3], upper[3];
            for (unsigned int d = 0; d < 3; ++d)
              {
                const double half = r
                                    + (cone ? 0.5 * l * std::fabs(m[d])
                                       : fibres && d == a ? 0.5 * l
                                                          : 0.);
                lower[d] = static_cast<int>(std::floor(c[d] - half)) - 1;
                upper[d] = static_cast<int>(std::ceil(c[d] + half)) + 1;
              }
            for (int k = lower[2]; k <= upper[2]; ++k)
              for (int j = lower[1]; j <= upper[1]; ++j)
                for (int i = lower[0]; i <= upper[0]; ++i)
                  {
                    const int                   idx[3] = {i, j, k};
                    const std::array<double, 3> x{{i + 0.5, j + 0.5, k + 0.5}};
                    const auto                  d = difference(c, x);
                    if (cone)
                      {
                        double s = 0, dn = 0;
                        for (unsigned int e = 0; e < 3; ++e)
                          {
                            s += d[e] * d[e];
                            dn += d[e] * m[e];
                          }
                        if (s - dn * dn > r * r || std::fabs(dn) > 0.5 * l)
                          continue;
                      }
                    else
                      {
                        double s = 0;
                        for (unsigned int e = 0; e < 3; ++e)
                          if (!fibres || e != a)
                            s += d[e] * d[e];
                        if (s > r * r || (fibres && std::fabs(d[a]) > 0.5 * l))
                          continue;
                      }
                    unsigned int wrapped[3];
                    for (unsigned int e = 0; e < 3; ++e)
                      wrapped[e] = static_cast<unsigned int>(
                        ((idx[e] % int(n[e])) + int(n[e])) % int(n[e]));
                    ids[(std::size_t(wrapped[2]) * n[1] + wrapped[1]) * n[0]
                        + wrapped[0]]
                      = 1;
                  }
          }
        const double fraction
          = std::count(ids.begin(), ids.end(), std::uint8_t(1)) / volume;
        std::ostringstream description;
        description << centres.size() << " random " << what << "s of radius "
                    << r << " voxels";
        if (fibres)
          description << " and length " << l << " voxels "
                      << (cone ? "about " : "along ") << "xyz"[a];
        if (cone)
          {
            // the mean squared cosine of the axes to the cone's axis
            double cos2 = 0;
            for (const auto &m : axes)
              cos2 += m[a] * m[a];
            description << " within a cone of half-angle " << p.fibre_cone_angle
                        << " degrees"
                        << (p.fibre_cone_angle >= 90 ? " (uniformly random "
                                                       "orientations)"
                                                     : "")
                        << ", mean cos^2 to "
                        << "xyz"[a] << " "
                        << cos2 / std::max<std::size_t>(axes.size(), 1);
          }
        description << " (seed " << p.random_seed << "), voxel volume fraction "
                    << fraction;
        return VoxelVolume(n,
                           {{p.voxel_size, p.voxel_size, p.voxel_size}},
                           std::move(ids),
                           description.str());
      }


      /// The directory part of @p path ("" or ending with '/').
      std::string
      directory_of(const std::string &path)
      {
        const auto slash = path.find_last_of('/');
        return slash == std::string::npos ? "" : path.substr(0, slash + 1);
      }
    } // namespace


    VoxelVolume
    VoxelVolume::create(const VolumeMorphologyParameters &parameters)
    {
      switch (parameters.generator)
        {
          case VolumeMorphologyParameters::Generator::laminate:
            return make_laminate(parameters);
          case VolumeMorphologyParameters::Generator::spheres:
          case VolumeMorphologyParameters::Generator::fibres:
            return make_inclusions(parameters);
          case VolumeMorphologyParameters::Generator::image_stack:
            return read_image_stack(parameters.image_stack,
                                    parameters.voxel_size);
          case VolumeMorphologyParameters::Generator::raw_file:
            break;
        }
      return read_raw(parameters.raw_header);
    }


    VoxelVolume
    VoxelVolume::read_raw(const std::string &header_file)
    {
      const std::string header = "the raw volume header '" + header_file
                                 + "' (parameter 'Morphology/Raw header')";
      const std::string where = "T" + header.substr(1);
      std::ifstream     in(header_file);
      if (!in)
        throw InputError("Cannot read " + header
                         + ": it does not exist or is not readable. Give the "
                           "path of an existing header file (relative paths "
                           "are relative to the directory tribodyn runs in).");
      std::array<unsigned int, 3> n{};
      std::array<double, 3>       h{};
      std::string                 type, file;
      bool                        has_size = false, has_h = false;
      std::string                 line;
      unsigned int                line_number = 0;
      while (std::getline(in, line))
        {
          ++line_number;
          line = line.substr(0, line.find('#'));
          if (line.find_first_not_of(" \t\r") == std::string::npos)
            continue;
          const auto equal = line.find('=');
          const auto trim  = [](std::string s) {
            const auto b = s.find_first_not_of(" \t\r");
            const auto e = s.find_last_not_of(" \t\r");
            return b == std::string::npos ? std::string()
                                           : s.substr(b, e - b + 1);
          };
          const std::string key
            = equal == std::string::npos ? "" : trim(line.substr(0, equal));
          const std::string value
            = equal == std::string::npos ? "" : trim(line.substr(equal + 1));
          const std::string at
            = where + ", line " + std::to_string(line_number) + ": ";
          std::istringstream values(value);
          if (key == "size")
            {
              long long   m[3] = {0, 0, 0};
              std::string rest;
              if (!(values >> m[0] >> m[1] >> m[2]) || (values >> rest)
                  || std::min({m[0], m[1], m[2]}) < 2
                  || std::max({m[0], m[1], m[2]}) > 100000)
                throw InputError(at + "'size = " + value
                                 + "' is not three whole numbers of voxels "
                                   "(nx ny nz), each at least 2. Write e.g. "
                                   "'size = 64 64 32'.");
              for (unsigned int d = 0; d < 3; ++d)
                n[d] = static_cast<unsigned int>(m[d]);
              has_size = true;
            }
          else if (key == "voxel size")
            {
              std::vector<double> v;
              double              x;
              while (values >> x)
                v.push_back(x);
              if (!values.eof() || (v.size() != 1 && v.size() != 3)
                  || *std::min_element(v.begin(), v.end()) <= 0)
                throw InputError(at + "'voxel size = " + value
                                 + "' is not one or three positive lengths "
                                   "(m). Write e.g. 'voxel size = 1e-5'.");
              for (unsigned int d = 0; d < 3; ++d)
                h[d] = v.size() == 1 ? v[0] : v[d];
              has_h = true;
            }
          else if (key == "type")
            type = value;
          else if (key == "file")
            file = value;
          else
            throw InputError(at + "'" + trim(line)
                             + "' is not one of the keys size, voxel size, "
                               "type, file (lines 'key = value'; '#' starts a "
                               "comment).");
        }
      for (const auto &[present, key] :
           {std::pair<bool, std::string>{has_size, "size"},
            {has_h, "voxel size"},
            {!type.empty(), "type"},
            {!file.empty(), "file"}})
        if (!present)
          throw InputError(where + " has no line '" + key
                           + " = ...'. A header gives size, voxel size, type "
                             "and file.");
      if (type != "uint8")
        throw InputError(where + ": 'type = " + type
                         + "' is not supported: tribodyn reads raw volumes of "
                           "material ids, one byte per voxel ('type = "
                           "uint8'). Segment the volume into ids 0, 1, ... "
                           "first.");
      const std::string path
        = file.front() == '/' ? file : directory_of(header_file) + file;
      std::ifstream raw(path, std::ios::binary | std::ios::ate);
      if (!raw)
        throw InputError("Cannot read the raw volume '" + path + "' named by "
                         + header
                         + ": it does not exist or is not readable. Fix the "
                           "line 'file = ...' (relative to the header's "
                           "directory).");
      const std::size_t expected = std::size_t(n[0]) * n[1] * n[2];
      const auto        bytes    = static_cast<std::size_t>(raw.tellg());
      if (bytes != expected)
        throw InputError("The raw volume '" + path + "' named by " + header
                         + " holds " + std::to_string(bytes)
                         + " bytes, but 'size = " + std::to_string(n[0]) + " "
                         + std::to_string(n[1]) + " " + std::to_string(n[2])
                         + "' with 'type = uint8' needs "
                         + std::to_string(expected)
                         + ". Fix the size in the header or the file.");
      std::vector<std::uint8_t> ids(expected);
      raw.seekg(0);
      raw.read(reinterpret_cast<char *>(ids.data()), expected);
      return VoxelVolume(n,
                         h,
                         std::move(ids),
                         "raw volume " + path + " (" + std::to_string(n[0])
                           + " x " + std::to_string(n[1]) + " x "
                           + std::to_string(n[2]) + " voxels)");
    }


    void
    VoxelVolume::write_raw(const std::string &header_file,
                           const std::string &raw_file) const
    {
      std::ofstream raw(raw_file, std::ios::binary);
      raw.write(reinterpret_cast<const char *>(ids.data()), ids.size());
      std::ofstream header(header_file);
      header.precision(17);
      header << "# " << origin << "\nsize = " << n[0] << " " << n[1] << " "
             << n[2] << "\nvoxel size = " << h[0] << " " << h[1] << " " << h[2]
             << "\ntype = uint8\nfile = "
             << raw_file.substr(raw_file.find_last_of('/') + 1) << "\n";
    }
  } // namespace homogenization
} // namespace tribodyn
