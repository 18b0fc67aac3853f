// Random sequential addition of spheres or short fibres in a periodic box
// of voxels: the placement shared by the volume sources 'spheres' and
// 'fibres'.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/volume_sources/random_inclusions.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
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


    } // namespace


    // The placement and the voxels: see the header.
    VoxelVolume
    make_random_inclusions(const VolumeMorphologyParameters &p,
                           const InclusionShape             &shape)
    {
      const bool         fibres = shape.fibres;
      const auto        &n      = p.n_voxels;
      const double       r      = p.radius;
      const unsigned int a      = shape.axis;
      const double       l      = fibres ? shape.length : 0.;
      const double       alpha  = shape.cone_angle * M_PI / 180.;
      const bool         cone   = fibres && shape.cone_angle > 0;
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
                + format_number(shape.cone_angle) + " degrees of "
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
      const auto difference
        = [&](const std::array<double, 3> &x, const std::array<double, 3> &y) {
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
      const auto distance2
        = [&](const std::array<double, 3> &x, const std::array<double, 3> &y) {
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
      // Bins at least as wide as the largest distance of two centres that
      // can conflict (the gap, plus a fibre's length): a conflict is
      // between neighbouring bins (periodic), so a placement tests the
      // few inclusions there instead of all (the placement was quadratic
      // in their number: 8 s for the 3 709 spheres of a 128^3 volume).
      const double                       reach = gap + (fibres ? l : 0.);
      std::array<unsigned int, 3>        n_bins;
      std::array<double, 3>              bin_size;
      std::vector<std::vector<unsigned>> bins;
      std::vector<unsigned int>          near;
      for (unsigned int d = 0; d < 3; ++d)
        {
          n_bins[d]   = std::max(1u, static_cast<unsigned int>(n[d] / reach));
          bin_size[d] = double(n[d]) / n_bins[d];
        }
      bins.resize(std::size_t(n_bins[0]) * n_bins[1] * n_bins[2]);
      // the bins b - 1, b, b + 1 along one axis (periodic), each once
      struct Neighbours
      {
        unsigned int bin[3];
        unsigned int n;
      };
      const auto neighbour_bins = [](const unsigned int b,
                                     const unsigned int n_bins) {
        return n_bins <= 3
                 ? Neighbours{{0, 1, 2}, n_bins}
                 : Neighbours{{(b + n_bins - 1) % n_bins, b, (b + 1) % n_bins},
                              3};
      };
      while (centres.size() < n_target && attempts < max_attempts)
        {
          ++attempts;
          std::array<double, 3> c;
          for (unsigned int d = 0; d < 3; ++d)
            c[d] = uniform(rng) * n[d];
          const std::array<double, 3> axis
            = cone ? cone_direction(orientation_rng, a, alpha) : along;
          // the inclusions placed in the bins next to c's (the only ones
          // that can be closer than the gap), in the order of their
          // placement: the same decisions as a test against all of them
          const auto bin_of
            = [&](const std::array<double, 3> &x, const unsigned int d) {
                return std::min(n_bins[d] - 1,
                                static_cast<unsigned int>(x[d] / bin_size[d]));
              };
          near.clear();
          unsigned int b[3];
          for (unsigned int d = 0; d < 3; ++d)
            b[d] = bin_of(c, d);
          Neighbours around[3];
          for (unsigned int d = 0; d < 3; ++d)
            around[d] = neighbour_bins(b[d], n_bins[d]);
          for (unsigned int z = 0; z < around[2].n; ++z)
            for (unsigned int y = 0; y < around[1].n; ++y)
              for (unsigned int x = 0; x < around[0].n; ++x)
                for (const unsigned int o :
                     bins[(std::size_t(around[2].bin[z]) * n_bins[1]
                           + around[1].bin[y])
                            * n_bins[0]
                          + around[0].bin[x]])
                  near.push_back(o);
          std::sort(near.begin(), near.end());
          bool free = true;
          for (const unsigned int o : near)
            if ((cone ? cone_distance2(c, axis, centres[o], axes[o])
                      : distance2(c, centres[o]))
                < gap * gap)
              {
                free = false;
                break;
              }
          if (free)
            {
              bins[(std::size_t(b[2]) * n_bins[1] + b[1]) * n_bins[0] + b[0]]
                .push_back(centres.size());
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
          + " voxels it needs fit in the box after " + std::to_string(attempts)
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
      description << centres.size() << " random " << what << "s of radius " << r
                  << " voxels";
      if (fibres)
        description << " and length " << l << " voxels "
                    << (cone ? "about " : "along ") << "xyz"[a];
      if (cone)
        {
          // the mean squared cosine of the axes to the cone's axis
          double cos2 = 0;
          for (const auto &m : axes)
            cos2 += m[a] * m[a];
          description << " within a cone of half-angle " << shape.cone_angle
                      << " degrees"
                      << (shape.cone_angle >= 90 ? " (uniformly random "
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
  } // namespace homogenization
} // namespace tribodyn
