#include <algorithm>
#include <cmath>
#include <random>
#include <tribodyn/core/errors.h>
#include <tribodyn/mca/inclusions.h>
#include <tribodyn/mca/packing.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      /// Rough surface f(x, y) in [-1, 1]: a few random-phase cosines whose
      /// wave vectors are periodic over the domain when possible.
      struct RoughSurface
      {
        std::vector<std::array<double, 4>> waves; // kx, ky, phase, weight

        RoughSurface(const GeometryParameters &g)
        {
          std::mt19937                           rng(g.roughness_seed);
          std::uniform_real_distribution<double> uni(0, 1);
          const double Lx  = g.domain_upper[0] - g.domain_lower[0];
          const double Ly  = g.domain_upper[1] - g.domain_lower[1];
          const double k   = 2 * M_PI / g.roughness_wavelength;
          double       sum = 0;
          for (unsigned int s = 0; s < 6; ++s)
            {
              const double angle = M_PI * uni(rng);
              double       kx = k * std::cos(angle), ky = k * std::sin(angle);
              if (g.periodic[0])
                kx = 2 * M_PI / Lx * std::round(kx * Lx / (2 * M_PI));
              if (g.periodic[1])
                ky = 2 * M_PI / Ly * std::round(ky * Ly / (2 * M_PI));
              const double weight = 0.5 + uni(rng);
              waves.push_back({{kx, ky, 2 * M_PI * uni(rng), weight}});
              sum += weight;
            }
          for (auto &w : waves)
            w[3] /= sum;
        }

        double
        operator()(const double x, const double y) const
        {
          double f = 0;
          for (const auto &w : waves)
            f += w[3] * std::cos(w[0] * x + w[1] * y + w[2]);
          return f;
        }
      };
    } // namespace


    namespace
    {
      /// Region membership with the periodic images of the region.
      bool
      region_contains(const Region             &r,
                      const GeometryParameters &g,
                      const Point3             &p)
      {
        if (r.contains(p))
          return true;
        if (r.shape == Region::Shape::box)
          return false; // boxes are given in the box's own frame
        for (int sz = -1; sz <= 1; ++sz)
          for (int sy = -1; sy <= 1; ++sy)
            for (int sx = -1; sx <= 1; ++sx)
              {
                const int s[3] = {sx, sy, sz};
                bool      ok   = sx != 0 || sy != 0 || sz != 0;
                Point3    q    = p;
                for (unsigned int c = 0; c < 3 && ok; ++c)
                  {
                    if (s[c] != 0 && !g.periodic[c])
                      ok = false;
                    q[c] += s[c] * (g.domain_upper[c] - g.domain_lower[c]);
                  }
                if (ok && r.contains(q))
                  return true;
              }
        return false;
      }
    } // namespace


    namespace
    {
      /// Call @p f(x, y) on a grid of the box's xy extent: the surface is a
      /// sum of six cosines, and a grid of 1/64 of the shortest wavelength
      /// resolves its extremes to ~0.1 % of the amplitude.
      template <class F>
      void
      for_each_surface_grid_point(const GeometryParameters &g, const F &f)
      {
        const double Lx = g.domain_upper[0] - g.domain_lower[0];
        const double Ly = g.domain_upper[1] - g.domain_lower[1];
        const double h  = g.roughness_wavelength / 64;
        const auto   nx = static_cast<unsigned int>(std::ceil(Lx / h));
        const auto   ny = static_cast<unsigned int>(std::ceil(Ly / h));
        for (unsigned int i = 0; i <= nx; ++i)
          for (unsigned int j = 0; j <= ny; ++j)
            f(g.domain_lower[0] + i * Lx / nx, g.domain_lower[1] + j * Ly / ny);
      }
    } // namespace


    double
    rough_surface_rise(const GeometryParameters &g, const double shift_y)
    {
      if (!g.rough_interface || g.roughness_amplitude == 0)
        return 0;
      const RoughSurface surface(g);
      double             rise = -1;
      for_each_surface_grid_point(g, [&](const double x, const double y) {
        rise = std::max(rise, surface(x, y) - surface(x, y - shift_y));
      });
      return g.roughness_amplitude * rise;
    }


    std::pair<double, double>
    rough_surface_range(const GeometryParameters &g)
    {
      const RoughSurface surface(g);
      double             lowest = 1, highest = -1;
      for_each_surface_grid_point(g, [&](const double x, const double y) {
        const double f = surface(x, y);
        lowest         = std::min(lowest, f);
        highest        = std::max(highest, f);
      });
      return {g.interface_height + g.roughness_amplitude * lowest,
              g.interface_height + g.roughness_amplitude * highest};
    }


    void
    pack_box(const GeometryParameters                           &g,
             const Point3                                       &lower,
             const Point3                                       &upper,
             const std::function<void(const PackedAutomaton &)> &add,
             const bool                                          continued)
    {
      const double        d     = g.automaton_size;
      const double        a     = d * std::sqrt(2.);
      const auto         &basis = g.fcc_basis;
      std::array<long, 3> n;
      for (unsigned int c = 0; c < 3; ++c)
        n[c] = static_cast<long>(
          std::floor((g.domain_upper[c] - g.domain_lower[c]) / a + 1e-9));
      if (4.0 * (n[0] + 1) * (n[1] + 1) * (n[2] + 1) >= 4294967295.)
        throw InputError(
          "The FCC lattice of the box has more than 2^32 sites (automaton "
          "ids are 32-bit in this deal.II build): use a larger "
          "Geometry/Automaton size or a smaller box.");
      const RoughSurface surface(g);
      // Sites whose final position may lie in [lower, upper]: the upper
      // body of a rough interface is shifted up by the interface gap.
      const double        margin = 1e-9 * a;
      std::array<long, 3> lo, hi;
      for (unsigned int c = 0; c < 3; ++c)
        {
          double blo = lower[c] - margin, bhi = upper[c] + margin;
          if (c == 2 && g.rough_interface)
            blo -= std::max(0., g.interface_gap);
          const double o = g.domain_lower[c] + a / 4;
          lo[c]          = static_cast<long>(std::floor((blo - o) / a)) - 1;
          hi[c]          = static_cast<long>(std::ceil((bhi - o) / a));
          // the lattice of the box (continued: beyond it, but in a
          // periodic direction the caller gives boxes of the period only)
          if (!continued || g.periodic[c])
            {
              lo[c] = std::max(0L, lo[c]);
              hi[c] = std::min(n[c], hi[c]);
            }
        }
      // Body 1 of a rough interface may be shifted along y (periodic): its
      // sites that land in [lower, upper] come from anywhere in y, so the
      // whole y range is enumerated (the box test below keeps those that
      // land in [lower, upper]).
      const double shift_y = g.rough_interface ? g.interface_shift_y : 0.;
      const double Ly      = g.domain_upper[1] - g.domain_lower[1];
      auto         wrap_y  = [&](double y) {
        if (shift_y == 0)
          return y;
        y += shift_y;
        y -= Ly * std::floor((y - g.domain_lower[1]) / Ly);
        return y;
      };
      if (shift_y != 0)
        {
          lo[1] = 0;
          hi[1] = n[1];
        }
      const InclusionLayout      *inclusions = g.inclusion_layout.get();
      const std::array<double, 2> z_bodies   = g.bodies_z_range();
      for (long k = lo[2]; k <= hi[2]; ++k)
        for (long j = lo[1]; j <= hi[1]; ++j)
          for (long i = lo[0]; i <= hi[0]; ++i)
            for (unsigned int bi = 0; bi < 4; ++bi)
              {
                const auto &b = basis[bi];
                Point3      p;
                const long  ijk[3] = {i, j, k};
                bool        inside = true, in_lattice = true;
                for (unsigned int c = 0; c < 3; ++c)
                  {
                    p[c] = g.domain_lower[c] + a / 4 + a * (ijk[c] + b[c]);
                    if (p[c] >= g.domain_upper[c]
                        && (!continued || g.periodic[c]))
                      inside = false;
                    if (ijk[c] < 0 || ijk[c] > n[c])
                      in_lattice = false;
                  }
                if (!inside)
                  continue;
                // (the continued lattice goes on outside the bodies)
                int body = g.body_containing(p);
                if (body < 0 && !continued)
                  continue;
                body = std::max(body, 0);
                // Graded packing: in a band of level L only the sites of the
                // lattice of size 2^L d are kept, those whose half-lattice
                // indices h = 2 (i, j, k) + 2 b are multiples of 2^L with
                // an even sum over 2^L.
                // (continued: beyond the bodies in z, the band at their
                // top or bottom goes on)
                const unsigned int level = g.size_level(
                  continued ? Point3(p[0],
                                     p[1],
                                     std::clamp(p[2], z_bodies[0], z_bodies[1]))
                            : p);
                if (level > 0)
                  {
                    const long step = 1L << level;
                    long       sum  = 0;
                    bool       on   = true;
                    for (unsigned int c = 0; c < 3; ++c)
                      {
                        const long h = 2 * ijk[c] + (b[c] > 0 ? 1 : 0);
                        on           = on && h % step == 0;
                        sum += h;
                      }
                    if (!on || (sum / step) % 2 != 0)
                      continue;
                  }
                PackedAutomaton automaton;
                automaton.level = static_cast<unsigned char>(level);
                automaton.transitional
                  = !g.size_bands.empty() && g.near_size_change(p);
                automaton.id
                  = in_lattice ? static_cast<std::uint32_t>(
                      ((k * (n[1] + 1) + j) * (n[0] + 1) + i) * 4 + bi)
                               : outside_lattice;
                automaton.position = p;
                automaton.material = g.bodies[body].material;
                automaton.body     = std::min(body, 255);
                if (g.rough_interface)
                  {
                    const double h
                      = g.interface_height
                        + g.roughness_amplitude * surface(p[0], p[1]);
                    automaton.body = p[2] < h ? 0 : 1;
                    if (automaton.body == 1)
                      {
                        automaton.position[2] += g.interface_gap;
                        automaton.position[1] = wrap_y(p[1]);
                      }
                  }
                bool in_box = true;
                for (unsigned int c = 0; c < 3; ++c)
                  if (automaton.position[c] < lower[c] - margin
                      || automaton.position[c] > upper[c] + margin)
                    in_box = false;
                if (!in_box)
                  continue;
                if (continued)
                  {
                    add(automaton);
                    continue;
                  }
                bool removed = false;
                for (const Region &r : g.regions)
                  if (region_contains(r, g, p))
                    {
                      if (r.material < 0)
                        removed = true;
                      else
                        {
                          removed            = false;
                          automaton.material = r.material;
                        }
                    }
                if (inclusions && inclusions->in_part(p, automaton.body))
                  {
                    automaton.part  = 1;
                    const int shape = inclusions->shape_at(p, automaton.body);
                    if (shape == 1)
                      removed = true;
                    else if (shape == 0)
                      {
                        automaton.material = inclusions->material;
                        automaton.part     = 2;
                      }
                  }
                if (!removed)
                  add(automaton);
              }
    }


    std::vector<PackedAutomaton>
    pack_automata(const GeometryParameters &g, const unsigned int n_materials)
    {
      (void)n_materials;
      std::vector<PackedAutomaton> packed;
      Point3                       upper = g.domain_upper;
      if (g.rough_interface)
        upper[2] += std::max(0., g.interface_gap);
      pack_box(g, g.domain_lower, upper, [&](const PackedAutomaton &a) {
        packed.push_back(a);
      });
      std::sort(packed.begin(),
                packed.end(),
                [](const PackedAutomaton &a, const PackedAutomaton &b) {
                  return a.id < b.id;
                });
      if (packed.empty())
        throw InputError(
          "The packing is empty: no FCC site of spacing Geometry/Automaton "
          "size lies inside a body of Geometry/Bodies (or every one was "
          "removed by a void region). Check the boxes and the automaton "
          "size.");
      return packed;
    }
  } // namespace mca
} // namespace tribodyn
