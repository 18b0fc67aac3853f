// The elastic energy of the automata at the level of their pair sides
// (doc/theory/mca.md §8.4): each side holds S ((sigma - m)^2 + |tau|^2) /
// 2k, with m its many-body part, and each automaton kappa G^2, G = sum g m
// over its weighted sides (Hooke's V lambda theta^2 / 2 in the bulk). The
// pair kernel books what changes this energy other than the springs'
// work: plastic returns, limits, opening contacts (pair_energy.h), the
// non-conservative work of the many-body law, and the jumps when weights
// change (here).

#include "pair_energy.h"

#include <cmath>
#include <tribodyn/mca/automaton_system.h>

namespace tribodyn
{
  namespace mca
  {
    double
    AutomatonSystem::pair_elastic_energy() const
    {
      double energy = 0;
      for (unsigned int p = 0; p < pi.size(); ++p)
        {
          const unsigned int i = pi[p], j = pj[p];
          if (!owned(i) && !owned(j))
            continue;
          const double t2 = dot(tau[p], tau[p]);
          // (a pair out of contact holds nothing, but for a bond broken
          // beyond the contact distance at the last step: the next step
          // releases it)
          if (!bonded[p] && !in_contact[p] && sig_i[p] == 0 && sig_j[p] == 0
              && t2 == 0)
            continue;
          for (const unsigned int s : {0u, 1u})
            if (owned(s ? j : i))
              {
                const double alpha = (s ? tau_scale_j : tau_scale_i)[p];
                energy += pair_energy::side(area_of(p),
                                            side_compliance(p, s),
                                            (s ? sig_j : sig_i)[p],
                                            side_many_body(p, s),
                                            alpha * alpha * t2);
              }
        }
      return energy + many_body_energy();
    }


    double
    AutomatonSystem::many_body_energy() const
    {
      double energy = 0;
      for (unsigned int k = 0; k < n_owned; ++k)
        energy += mb_state[k].kappa * mb_state[k].G * mb_state[k].G;
      return energy;
    }


    void
    AutomatonSystem::update_many_body_state(const unsigned int k)
    {
      // g = beta / h over the weighted sides (the many-body increment of k
      // is K sum g dq), their area, and G = sum g m
      double g_sum = 0, g_abs = 0, area = 0, G = 0;
      for_each_pair_of(k, [&](const unsigned int p, const unsigned int side) {
        const double g = side_weight(p, side);
        if (g == 0)
          return;
        g_sum += g;
        g_abs += std::abs(g);
        area += area_of(p);
        G += g * side_many_body(p, side);
      });
      const double D = mc[mat[k]].D;
      // kappa: the many-body law conserves kappa G^2 where S / g is the
      // same on every side (complete neighbourhoods, equal shares); held
      // only where the weights are mostly positive (else its work is all
      // many-body work)
      const double K = mc[mat[k]].K;
      auto        &s = mb_state[k];
      s.kappa        = D > 0 && g_sum > 0.25 * g_abs
                         ? area / (2 * K * D * g_sum * g_sum * g_sum)
                         : 0.;
      s.gamma        = g_sum;
      s.G            = G;
    }


    void
    AutomatonSystem::fold_many_body_stress()
    {
      for (unsigned int p = 0; p < pi.size(); ++p)
        {
          mb_i[p] += mc[mat[pi[p]]].D * mb_mu[pi[p]];
          mb_j[p] += mc[mat[pj[p]]].D * mb_mu[pj[p]];
        }
      std::fill(mb_mu.begin(), mb_mu.end(), 0.);
    }


    void
    AutomatonSystem::release_opening(const unsigned int p, const double dr)
    {
      // The energy of each side, and the work its stress did over the
      // step's first half (the pair force is zero at the step's end: the
      // trapezoid of velocity Verlet has only its start); a weighted side
      // leaves G and gamma of its automaton.
      const double Sp = area_of(p), t2 = dot(tau[p], tau[p]);
      for (const unsigned int side : {0u, 1u})
        {
          const unsigned int a = side ? pj[p] : pi[p];
          if (!owned(a))
            continue;
          const double sigma = side ? sig_j[p] : sig_i[p];
          const double alpha = side ? tau_scale_j[p] : tau_scale_i[p];
          const double m     = side_many_body(p, side);
          work[switching_work] += pair_energy::side(Sp,
                                                    side_compliance(p, side),
                                                    sigma,
                                                    m,
                                                    alpha * alpha * t2)
                                  + 0.25 * Sp * sigma * dr;
          const double g = side_weight(p, side);
          if (g != 0)
            {
              work[switching_work]
                += pair_energy::shift_sum(mb_state[a], -g * m);
              mb_state[a].gamma -= g;
            }
        }
    }
  } // namespace mca
} // namespace tribodyn
