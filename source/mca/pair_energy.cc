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
          if (!bonded[p] && !in_contact[p] && side_sigma(p, 0) == 0
              && side_sigma(p, 1) == 0 && t2 == 0)
            continue;
          for (const unsigned int s : {0u, 1u})
            if (owned(s ? j : i))
              {
                const double alpha = shear_factor(p, s);
                energy += pair_energy::side(area_of(p),
                                            side_compliance(p, s),
                                            side_sigma(p, s),
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
      // is K sum g dq), their area, and G = sum g m; whether S / g and m
      // are the same on all of them (to 1e-12)
      double       g_sum = 0, g_abs = 0, area = 0, G = 0;
      double       ratio_0 = 0, m_0 = 0;
      unsigned int n_weighted = 0;
      bool         uniform    = true;
      for_each_pair_of(k, [&](const unsigned int p, const unsigned int side) {
        const double g = side_weight(p, side);
        if (g == 0)
          return;
        const double m = side_many_body(p, side), ratio = area_of(p) / g;
        if (n_weighted++ == 0)
          {
            ratio_0 = ratio;
            m_0     = m;
          }
        else if (std::abs(ratio - ratio_0) > 1e-12 * std::abs(ratio_0)
                 || std::abs(m - m_0) > 1e-12 * std::abs(m_0))
          uniform = false;
        g_sum += g;
        g_abs += std::abs(g);
        area += area_of(p);
        G += g * m;
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
      // Uniform: S = lambda g and m = D mu + c on every weighted side. A
      // step then moves kappa G^2 = lambda (D mu + c)^2 / 2 K D by exactly
      // the work of these sides, sum S dq (D mu + D dmu / 2 + c) with dmu
      // = K sum g dq: their many-body work is zero, and the kernel skips
      // their sums (doc/theory/mca.md §8.4).
      uniform     = uniform && n_weighted > 0 && s.kappa > 0;
      mb_shape[k] = uniform ? ManyBodyShape::uniform : ManyBodyShape::general;
      s.lambda    = uniform ? area / g_sum : 0.;
    }


    void
    AutomatonSystem::many_body_step(const unsigned int k_begin,
                                    const unsigned int k_end,
                                    const bool         last,
                                    double            &work_mb)
    {
      // Pair kernel, after pass A (dsm: the volumetric strain increments;
      // the mean-stress increments K dsm from here on). The many-body work
      // of D mu at mid-step (mu and half of this step's increment) over
      // the summed sides, minus the change of kappa G^2 (G moves by D dsm
      // gamma) but where the automaton is uniform (the change is the work
      // of its weighted sides, not summed); then mu of the automaton.
      for (unsigned int k = k_begin; k < k_end; ++k)
        {
          dsm[k] *= mc[mat[k]].K;
          const double D  = mc[mat[k]].D;
          const double dm = D * dsm[k];
          auto        &st = mb_state[k];
          double       sq = side_dq[k];
          if (mb_shape[k] == ManyBodyShape::opened)
            {
              // a weighted side opened in pass A (release_opening()): the
              // sums of the others, skipped, from dsm (S = lambda g on
              // each; their common m is G / gamma), and the automaton on
              // the sums from now on
              const double s_w = st.lambda * dsm[k] / mc[mat[k]].K;
              sq += s_w;
              if (st.gamma != 0)
                work_mb += (st.G / st.gamma - D * mb_mu[k]) * s_w;
              mb_shape[k] = ManyBodyShape::general;
              st.lambda   = 0;
            }
          work_mb += (D * mb_mu[k] + 0.5 * dm) * sq;
          if (mb_shape[k] == ManyBodyShape::uniform)
            st.G += dm * st.gamma;
          else
            work_mb += pair_energy::shift_sum(st, dm * st.gamma);
          mb_mu[k] += dsm[k];
        }
      // the ghosts' from their owners' increments, once every owned one
      // is done (the pair kernel's last chunk)
      if (last)
        {
          if (partition.neighbours().active())
            partition.neighbours().update(dsm.data(), 1);
          for (unsigned int k = n_owned; k < n_local; ++k)
            mb_mu[k] += dsm[k];
        }
      // Where the pairs store their sides' common part only (no event can
      // occur, PairArrays::sig_e), pass C reads each side's many-body part
      // m = D mu + c of its automaton instead of adding D dsm to it: dsm
      // holds m from here on, the ghosts' too.
      const auto to_many_body_part
        = [this](const unsigned int begin, const unsigned int end) {
            for (unsigned int k = begin; k < end; ++k)
              dsm[k] = mc[mat[k]].D * mb_mu[k] + mb_offset[k];
          };
      if (!mb_stored)
        {
          to_many_body_part(k_begin, k_end);
          if (last)
            to_many_body_part(n_owned, n_local);
        }
    }


    void
    AutomatonSystem::sync_many_body_shapes()
    {
      // Between steps an automaton is uniform exactly where lambda != 0:
      // update_many_body_state() and many_body_step() set the two
      // together, and an event that ends the shape zeroes lambda (the
      // kernel's end calls this); no automaton is left opened.
      mb_shape.resize(mb_state.size());
      for (unsigned int k = 0; k < mb_state.size(); ++k)
        mb_shape[k] = mb_state[k].lambda != 0 ? ManyBodyShape::uniform
                                              : ManyBodyShape::general;
    }


    void
    AutomatonSystem::fold_many_body_stress()
    {
      if (mb_stored)
        for (unsigned int p = 0; p < pi.size(); ++p)
          {
            mb_i[p] += mc[mat[pi[p]]].D * mb_mu[pi[p]];
            mb_j[p] += mc[mat[pj[p]]].D * mb_mu[pj[p]];
          }
      else
        // (the same sums as the sides', once per automaton)
        for (unsigned int k = 0; k < mb_mu.size(); ++k)
          mb_offset[k] += mc[mat[k]].D * mb_mu[k];
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
          const double alpha = shear_factor(p, side);
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
              // (in pass A: its other sides have been or will be
              // skipped, the kernel sums them after the pass)
              if (mb_shape[a] == ManyBodyShape::uniform)
                mb_shape[a] = ManyBodyShape::opened;
            }
        }
    }
  } // namespace mca
} // namespace tribodyn
