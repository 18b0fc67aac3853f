// Bond switching of the automata (seed 000 Sec. 2.1; doc/theory/mca.md
// Sec. 5): bonded pairs break at the bond breaking stress, unbonded
// contacts in compression at the yield stress bond once their plastic heat
// reaches a fraction of the bond energy. Called at the end of the pair
// kernel of bond scenes (pair_kernel.cc); acts from the next step.

#include "pair_blocks.h"

#include <algorithm>
#include <tribodyn/mca/automaton_system.h>

namespace tribodyn
{
  namespace mca
  {
    template <bool plastic>
    void
    AutomatonSystem::bond_switching()
    {
      // Bond switching (takes effect at the next step), from the automata's
      // stress tensors (eq. 4) exchanged with the neighbours.
      // member buffer: no allocation per step
      std::vector<double> &ex = bond_buffer;
      ex.assign(static_cast<std::size_t>(n_local) * 7, 0.);
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          ex[7 * k + 6] = plastic_scene ? sigma_y[k] : mc[mat[k]].yield0;
          // an automaton of an elastic region with only elastic partners
          // takes part in no bond check: its stress is not needed
          bool needed = !elastic(k);
          if (!needed)
            for_each_pair_of(
              k, [&](const unsigned int p, const unsigned int side) {
                needed = needed || !elastic(side ? pi[p] : pj[p]);
              });
          if (!needed)
            continue;
          const Sym3 s = fabric_corrected(k, trial[k]);
          for (unsigned int c = 0; c < 6; ++c)
            ex[7 * k + c] = s[c];
        }
      if (neighbours.active())
        neighbours.update(ex.data(), 7);
      const double heat_fraction = prm.interaction.bond_formation_heat_fraction;
      const unsigned int n_pairs = pi.size();
      NormalBlock        nblock;
      auto               pair_vector_of
        = [this](const unsigned int p) { return pair_vector(p); };
      for (unsigned int p0 = 0; p0 < n_pairs; p0 += NormalBlock::size)
        {
          const unsigned int nb = std::min(NormalBlock::size, n_pairs - p0);
          nblock.fill(p0, nb, pair_vector_of);
          for (unsigned int b = 0; b < nb; ++b)
            {
              const unsigned int p = p0 + b, i = pi[p], j = pj[p];
              if (elastic(i) && elastic(j))
                continue; // no bond switching inside elastic regions
              const double r  = nblock.r[b];
              const Vec3   n  = nblock.normal(b);
              const double sn = 0.5 * (sig_i[p] + sig_j[p]);
              const double am = 0.5 * (tau_scale_i[p] + tau_scale_j[p]);
              if (bonded[p] && prm.interaction.bond_breaking)
                {
                  Sym3 s;
                  for (unsigned int c = 0; c < 6; ++c)
                    s[c] = 0.5 * (ex[7 * i + c] + ex[7 * j + c]);
                  // replace the normal and shear parts by the pair's own
                  const double sxx = s[0], syy = s[1], szz = s[2], syz = s[3],
                               sxz = s[4], sxy = s[5];
                  Vec3         sn_vec{{sxx * n[0] + sxy * n[1] + sxz * n[2],
                                       sxy * n[0] + syy * n[1] + syz * n[2],
                                       sxz * n[0] + syz * n[1] + szz * n[2]}};
                  const double snn = dot(sn_vec, n);
                  Vec3         corr;
                  for (unsigned int c = 0; c < 3; ++c)
                    corr[c]
                      = am * tau.component[c][p] - (sn_vec[c] - snn * n[c]);
                  add_sym(s, sn - snn, n, n);
                  add_sym(s, 1, n, corr);
                  add_sym(s, 1, corr, n);
                  const double limit
                    = std::min(mc[mat[i]].sigma_b, mc[mat[j]].sigma_b);
                  if (von_mises_squared(s) >= limit * limit)
                    {
                      bonded[p]     = 0;
                      in_contact[p] = r < (graded ? 2 * pair_half_rest[p] : d);
                      // a new contact for the friction law
                      friction_laws.with_selected(
                        [p](auto &law) { law.start_contact(p); });
                      if (!heat.empty())
                        heat[p] = 0;
                      changed[i] = changed[j] = 1;
                      any_changed             = true;
                    }
                }
              else if (!bonded[p] && in_contact[p]
                       && prm.interaction.bond_formation)
                {
                  const double sy = std::min(ex[7 * i + 6], ex[7 * j + 6]);
                  const double Eb
                    = std::min(mc[mat[i]].w_b, mc[mat[j]].w_b) * area_of(p) * r;
                  const double h = heat.empty() ? 0. : heat[p];
                  if (sn <= -sy && h >= heat_fraction * Eb)
                    {
                      bonded[p] = 1;
                      if (!heat.empty())
                        heat[p] = 0;
                      changed[i] = changed[j] = 1;
                      any_changed             = true;
                    }
                }
            }
        }
    }


    template void
    AutomatonSystem::bond_switching<true>();
    template void
    AutomatonSystem::bond_switching<false>();
  } // namespace mca
} // namespace tribodyn
