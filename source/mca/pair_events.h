// The events of a pair at the end of its step (pass C of the pair kernel,
// pair_kernel.cc): plastic returns of its sides, no tension and the
// friction law's limit of an unbonded pair; each side releases energy
// (pair_energy.h, doc/theory/mca.md §8.4), booked by the side's owner. In
// the kernel's translation unit, inlined into its pass C.
#ifndef tribodyn_mca_pair_events_h
#define tribodyn_mca_pair_events_h

#include "pair_energy.h"

#include <algorithm>
#include <cmath>
#include <tribodyn/mca/automaton_system.h>

namespace tribodyn
{
  namespace mca
  {
    template <bool plastic, class Pairs, class Law>
    [[gnu::always_inline]] inline void
    AutomatonSystem::pair_events(const unsigned int p,
                                 const Pairs       &geometry,
                                 const Law         &law,
                                 const Vec3        &t,
                                 double            &ai,
                                 double            &aj,
                                 double            &mb_work)
    {
      const unsigned int i = pi[p], j = pj[p];
      const double       Sp = geometry.area(p);
      // The events of the step (plastic returns, no tension,
      // friction limits): each side releases energy
      // (pair_energy::release, doc/theory/mca.md §8.4), booked by
      // the side's owner; the plastic heat of an unbonded pair is
      // that of its two sides.
      // (the sides' spring stiffnesses: read where an event needs
      // them)
      const auto k_of = [&](const unsigned int s) {
        const SeriesSprings &k = springs[mat[i] * n_materials + mat[j]];
        return (s ? k.kj : k.ki) * geometry.stiffness_scale(p);
      };
      // many-body part of side s, and its release of one event
      auto m_of = [&](const unsigned int s) {
        return s ? mc[mat[j]].D * mb_mu[j] + mb_j[p]
                 : mc[mat[i]].D * mb_mu[i] + mb_i[p];
      };
      auto released = [&](const unsigned int s,
                          const double       sigma,
                          const double       sigma_new,
                          const double       alpha,
                          const double       alpha_new) {
        return pair_energy::release(Sp,
                                    k_of(s),
                                    m_of(s),
                                    sigma,
                                    sigma_new,
                                    alpha,
                                    alpha_new,
                                    dot(t, t),
                                    pair_dr[2 * p],
                                    pair_dr[2 * p + 1]);
      };
      // pairs of two materials: the many-body work of the sides'
      // difference (sigma_i - sigma_j)(dq_j - dq_i) / 2 at mid-step
      if (mat[i] != mat[j] && (owned(i) || owned(j)))
        {
          const double ki = k_of(0), kj = k_of(1);
          const double dmid
            = sig_i[p] - sig_j[p]
              - 0.5 * (mc[mat[i]].D * dsm[2 * i] - mc[mat[j]].D * dsm[2 * j]);
          mb_work += (owned(i) + owned(j)) * 0.25 * Sp * dmid * pair_dr[2 * p]
                     * (ki - kj) / (ki + kj);
        }
      if constexpr (plastic)
        {
          const double Mi = plast[2 * i + 1], Mj = plast[2 * j + 1];
          // (the plastic work of a side: the deviatoric energy its
          // return releases; the rest of the release, from its
          // many-body part m differing from the automaton's mean
          // stress, is many-body work: doc/theory/mca.md §8.4)
          double pair_heat = 0;
          auto   plastic_return =
            [&](const unsigned int s, double &sigma, double &alpha) {
              const double sm  = plast[2 * (s ? j : i)],
                           M   = plast[2 * (s ? j : i) + 1];
              const double dev = sigma - sm, s_new = sm + M * dev;
              const double w = released(s, sigma, s_new, alpha, alpha * M);
              const double heat_s
                = w - (1 - M) * Sp * (sm - m_of(s)) * dev / k_of(s);
              pair_heat += heat_s;
              const unsigned int a = s ? j : i;
              if (owned(a))
                {
                  work[plastic_work] += heat_s;
                  mb_work += w - heat_s;
                }
              // a bond's many-body part anew at D sigma_m, its value in
              // an elastic bulk (a contact's stays: it goes with the
              // contact's pressure, when the contact loses it or
              // opens): the energy this moves between the side and
              // kappa G^2 of its automaton is many-body work too
              if (bonded[p])
                {
                  const double m_old = m_of(s), m_new = mc[mat[a]].D * sm;
                  (s ? mb_j : mb_i)[p] = m_new - mc[mat[a]].D * mb_mu[a];
                  if (owned(a))
                    {
                      const double e_old = s_new - m_old, e_new = s_new - m_new;
                      mb_work
                        += Sp * (e_old * e_old - e_new * e_new) / (2 * k_of(s));
                      const double beta = (s ? beta_j : beta_i)[p];
                      if (beta != 0)
                        {
                          mb_work += pair_energy::shift_sum(
                            mb_state[a],
                            beta * geometry.inv_half_rest(p) * (m_new - m_old));
                        }
                    }
                }
              sigma = s_new;
              alpha *= M;
            };
          if (Mi < 1)
            plastic_return(0, sig_i[p], ai);
          if (Mj < 1)
            plastic_return(1, sig_j[p], aj);
          // Plastic heat for bond formation: only heat generated while
          // the pair is unbonded counts (seed §2.1).
          if (!heat.empty() && !bonded[p])
            heat[p] += pair_heat;
        }
      if (!bonded[p])
        {
          // no tension; the friction law's limit on each side
          const double mu = friction_coefficient(law, p);
          for (const unsigned int side : {0u, 1u})
            {
              double &sigma = side ? sig_j[p] : sig_i[p];
              if (sigma > 0)
                {
                  // the whole normal stress goes, its many-body part
                  // with it (the side as when it touched): its
                  // energy, and that of m in kappa G^2
                  const unsigned int a = side ? j : i;
                  const double       m = m_of(side);
                  if (owned(a))
                    {
                      const double alpha = side ? aj : ai;
                      double       w = released(side, sigma, 0, alpha, alpha)
                                 + Sp * m * m / (2 * k_of(side));
                      const double beta = (side ? beta_j : beta_i)[p];
                      if (beta != 0)
                        {
                          w += pair_energy::shift_sum(
                            mb_state[a], -beta * geometry.inv_half_rest(p) * m);
                        }
                      work[switching_work] += w;
                    }
                  (side ? mb_j : mb_i)[p] = -mc[mat[a]].D * mb_mu[a];
                  sigma                   = 0;
                }
            }
          const double t_norm = std::sqrt(dot(t, t));
          for (const unsigned int side : {0u, 1u})
            {
              double      &a     = side == 0 ? ai : aj;
              const double sigma = side == 0 ? sig_i[p] : sig_j[p];
              const double limit = -mu * sigma;
              const double tn    = std::abs(a) * t_norm;
              if (tn > limit)
                {
                  const double s = tn > 0 ? limit / tn : 0;
                  if (owned(side == 0 ? i : j))
                    work[friction_work]
                      += released(side, sigma, sigma, a, a * s);
                  a *= s;
                }
            }
        }
    }
  } // namespace mca
} // namespace tribodyn

#endif
