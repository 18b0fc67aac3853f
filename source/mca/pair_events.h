// The events of a pair at the end of its step (pass C of the pair kernel,
// pair_kernel.cc): plastic returns of its sides, no tension and the
// friction law's limit of an unbonded pair (its coefficient mu of the step,
// friction_coefficient(), here too); each side releases energy
// (pair_energy.h, doc/theory/mca.md §8.4), booked by the side's owner. In
// the kernel's translation unit; pass C of a plastic kernel calls it for
// every pair, inlined (its pairs have many events), that of an elastic
// kernel out of line and only for the pairs that can have events
// (unbonded, or of two materials: an elastic bulk has none, and the hot
// loop keeps its registers).
#ifndef tribodyn_mca_pair_events_h
#define tribodyn_mca_pair_events_h

#include "pair_energy.h"

#include <algorithm>
#include <cmath>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/plasticity.h>

namespace tribodyn
{
  namespace mca
  {
    template <class Law>
    inline double
    AutomatonSystem::friction_coefficient(const Law         &law,
                                          const unsigned int p) const
    {
      // a rate-dependent law's mu of this step, from pass A; a constant one
      if constexpr (Law::stateful)
        return pair_mu[p];
      else
        return law.coefficient();
    }


    template <bool plastic, class Pairs, class Law>
    [[gnu::always_inline]] inline void
    AutomatonSystem::pair_events(const unsigned int p,
                                 const Pairs       &geometry,
                                 const Law         &law,
                                 const Vec3        &t,
                                 double            &ai,
                                 double            &aj,
                                 WorkSums          &dw)
    {
      const unsigned int i = pi[p], j = pj[p];
      const double       Sp = geometry.area(p);
      // The events of the step (plastic returns, no tension, friction
      // limits): each side releases energy (doc/theory/mca.md §8.4),
      // booked in dw by the side's owner; the plastic heat of an unbonded
      // pair is that of its two sides.
      const SeriesSprings &k = springs[mat[i] * n_materials + mat[j]];
      // the compliance 1/k of side s, and c = S/2k: the energy of a side is
      // c ((sigma - m)^2 + alpha^2 |t|^2)
      const auto inv_k_of = [&](const unsigned int s) {
        return (s ? k.inv_kj : k.inv_ki) * geometry.inv_stiffness_scale(p);
      };
      const auto c_of
        = [&](const unsigned int s) { return 0.5 * Sp * inv_k_of(s); };
      const auto released = [&](const unsigned int s,
                                const double       sigma,
                                const double       sigma_new,
                                const double       alpha,
                                const double       alpha_new) {
        return pair_energy::release(Sp,
                                    inv_k_of(s),
                                    stored_side_many_body(p, s),
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
          const double dmid
            = sig_i[p] - sig_j[p]
              - 0.5 * (mc[mat[i]].D * dsm[i] - mc[mat[j]].D * dsm[j]);
          dw[many_body_work] += (owned(i) + owned(j)) * 0.25 * Sp * dmid
                                * pair_dr[2 * p] * (k.ki - k.kj) * k.inv_sum;
        }
      if constexpr (plastic)
        {
          // Radial returns of the sides: sigma - sigma_m and alpha scale by
          // M. Of the energy a side releases, the plastic work is the
          // deviatoric part, c (1 - M^2)((sigma - sigma_m)^2 + alpha^2
          // |t|^2) less the unworked second half-step; the rest, 2 c (1 -
          // M)(sigma - sigma_m)(sigma_m - m) from its many-body part m
          // differing from the automaton's mean stress, is many-body work
          // (doc/theory/mca.md §8.4).
          double pair_heat = 0;
          for (const unsigned int s : {0u, 1u})
            {
              const unsigned int a = s ? j : i;
              const double       M = plast[2 * a + 1];
              if (!(M < 1))
                continue;
              double      &sigma = s ? sig_j[p] : sig_i[p];
              double      &alpha = s ? aj : ai;
              const double sm = plast[2 * a], dev = sigma - sm;
              const double s_new = sm + M * dev, c = c_of(s),
                           m = stored_side_many_body(p, s);
              const double heat_s
                = c * (1 - M * M) * (dev * dev + alpha * alpha * dot(t, t))
                  - 0.25 * Sp * (1 - M)
                      * (dev * pair_dr[2 * p] + alpha * pair_dr[2 * p + 1]);
              pair_heat += heat_s;
              if (owned(a))
                {
                  dw[plastic_work] += heat_s;
                  dw[many_body_work] += 2 * c * (1 - M) * dev * (sm - m);
                }
              // a bond's many-body part anew at D sigma_m, its value in an
              // elastic bulk (a contact's stays: it goes with the
              // contact's pressure, when the contact loses it or opens):
              // the energy this moves between the side and kappa G^2 of its
              // automaton is many-body work too
              if (bonded[p])
                {
                  const double D = mc[mat[a]].D, m_new = D * sm;
                  Assert(mb_stored, dealii::ExcInternalError());
                  (s ? mb_j : mb_i)[p] = m_new - D * mb_mu[a];
                  if (owned(a))
                    {
                      dw[many_body_work]
                        += c * (m_new - m) * (2 * s_new - m - m_new);
                      dw[many_body_work] += pair_energy::move_weighted_side(
                        mb_state[a],
                        (s ? beta_j : beta_i)[p] * geometry.inv_half_rest(p),
                        m_new - m);
                    }
                }
              sigma = s_new;
              alpha *= M;
            }
          // Plastic heat for bond formation: only heat generated while
          // the pair is unbonded counts (seed §2.1).
          if (!heat.empty() && !bonded[p])
            heat[p] += pair_heat;
        }
      if (!bonded[p])
        {
          // no tension; the friction law's limit on each side
          const double mu = friction_coefficient(law, p);
          // (read once, before the stores to the pair's stresses)
          const double limit_factor = verification::coulomb_limit_factor;
          for (const unsigned int side : {0u, 1u})
            {
              double &sigma = side ? sig_j[p] : sig_i[p];
              if (sigma > 0)
                {
                  // the whole normal stress goes, its many-body part
                  // with it (the side as when it touched): its
                  // energy, and that of m in kappa G^2
                  const unsigned int a = side ? j : i;
                  const double       m = stored_side_many_body(p, side);
                  if (owned(a))
                    {
                      const double alpha = side ? aj : ai;
                      double       w = released(side, sigma, 0, alpha, alpha)
                                 + c_of(side) * m * m;
                      w += pair_energy::move_weighted_side(
                        mb_state[a],
                        (side ? beta_j : beta_i)[p] * geometry.inv_half_rest(p),
                        -m);
                      dw[switching_work] += w;
                    }
                  Assert(mb_stored, dealii::ExcInternalError());
                  (side ? mb_j : mb_i)[p] = -mc[mat[a]].D * mb_mu[a];
                  sigma                   = 0;
                }
            }
          const double t_norm = std::sqrt(dot(t, t));
          for (const unsigned int side : {0u, 1u})
            {
              double      &a     = side == 0 ? ai : aj;
              const double sigma = side == 0 ? sig_i[p] : sig_j[p];
              const double limit = -mu * sigma * limit_factor;
              const double tn    = std::abs(a) * t_norm;
              if (tn > limit)
                {
                  const double s = tn > 0 ? limit / tn : 0;
                  if (owned(side == 0 ? i : j))
                    {
                      dw[friction_work]
                        += released(side, sigma, sigma, a, a * s);
                      // the law's traction times the slip (tn - limit)/k
                      // (the physical balance, §8.4)
                      dw[friction_work_law]
                        += Sp * (-mu * sigma) * (tn - limit) * inv_k_of(side);
                    }
                  a *= s;
                }
            }
        }
    }
  } // namespace mca
} // namespace tribodyn

#endif
