#include <cmath>
#include <random>
#include <tribodyn/core/errors.h>
#include <tribodyn/mca/automaton_system.h>

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


    std::vector<PackedAutomaton>
    pack_automata(const GeometryParameters &g, const unsigned int n_materials)
    {
      const double                               d = g.automaton_size;
      const double                               a = d * std::sqrt(2.);
      const std::array<std::array<double, 3>, 4> basis
        = {{{{0, 0, 0}}, {{0.5, 0.5, 0}}, {{0.5, 0, 0.5}}, {{0, 0.5, 0.5}}}};
      std::array<long, 3> n;
      for (unsigned int c = 0; c < 3; ++c)
        n[c] = static_cast<long>(
          std::floor((g.domain_upper[c] - g.domain_lower[c]) / a + 1e-9));
      const RoughSurface surface(g);

      std::vector<PackedAutomaton> packed;
      for (long k = 0; k < n[2] + 1; ++k)
        for (long j = 0; j < n[1] + 1; ++j)
          for (long i = 0; i < n[0] + 1; ++i)
            for (const auto &b : basis)
              {
                Point3     p;
                const long ijk[3] = {i, j, k};
                bool       inside = true;
                for (unsigned int c = 0; c < 3; ++c)
                  {
                    p[c] = g.domain_lower[c] + a / 4 + a * (ijk[c] + b[c]);
                    if (p[c] >= g.domain_upper[c])
                      inside = false;
                  }
                if (!inside)
                  continue;
                int body = -1;
                for (unsigned int m = 0; m < g.bodies.size(); ++m)
                  {
                    bool in = true;
                    for (unsigned int c = 0; c < 3; ++c)
                      if (p[c] < g.bodies[m].lower[c]
                          || p[c] >= g.bodies[m].upper[c])
                        in = false;
                    if (in)
                      {
                        body = m;
                        break;
                      }
                  }
                if (body < 0)
                  continue;
                PackedAutomaton automaton;
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
                      automaton.position[2] += g.interface_gap;
                  }
                bool removed = false;
                for (const Region &r : g.regions)
                  if (r.contains(p))
                    {
                      if (r.material < 0)
                        removed = true;
                      else
                        {
                          removed            = false;
                          automaton.material = r.material;
                        }
                    }
                if (!removed)
                  packed.push_back(automaton);
              }
      (void)n_materials;
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
