// The energy of a pair's sides and what its events release (doc/theory/
// mca.md §8.4): the formulas the pair kernel (pair_kernel.cc) and the
// energy sums (pair_energy.cc) share.
#ifndef tribodyn_mca_pair_energy_h
#define tribodyn_mca_pair_energy_h

#include <tribodyn/mca/automaton_system.h>

namespace tribodyn
{
  namespace mca
  {
    namespace pair_energy
    {
      /// Energy S ((sigma - m)^2 + alpha^2 |t|^2) / 2k of a pair side of
      /// area @p S and spring compliance @p inv_k = 1/k: normal stress @p
      /// sigma with many-body part @p m, shear stress alpha t (@p a2t2 =
      /// alpha^2 |t|^2).
      inline double
      side(const double S,
           const double inv_k,
           const double sigma,
           const double m,
           const double a2t2)
      {
        const double e = sigma - m;
        return 0.5 * S * inv_k * (e * e + a2t2);
      }

      /**
       * Work released by a side whose normal stress @p sigma becomes
       * @p sigma_new and whose shear factor @p alpha becomes @p alpha_new
       * at the end of a step (Coulomb limit, no tension): the drop of its
       * energy (spring compliance @p inv_k = 1/k, many-body part @p m
       * unchanged, |t|^2 = @p t2), minus the work the removed stress did
       * not do over the step's second half (velocity Verlet: the pair force
       * works at the mean of its values at the two ends of the step; the
       * side carries half of it over the pair's normal increment @p dr and
       * tangential one, t . du = @p tdu).
       */
      inline double
      release(const double S,
              const double inv_k,
              const double m,
              const double sigma,
              const double sigma_new,
              const double alpha,
              const double alpha_new,
              const double t2,
              const double dr,
              const double tdu)
      {
        const double e = sigma - m, e_new = sigma_new - m;
        return 0.5 * S * inv_k
                 * (e * e - e_new * e_new
                    + (alpha * alpha - alpha_new * alpha_new) * t2)
               - 0.25 * S
                   * ((sigma - sigma_new) * dr + (alpha - alpha_new) * tdu);
      }

      /// Move G of an automaton's many-body state @p state by @p dG;
      /// returns the drop of its energy kappa G^2.
      inline double
      shift_sum(ManyBodyState &state, const double dG)
      {
        const double G = state.G, G_new = G + dG;
        state.G = G_new;
        return state.kappa * (G * G - G_new * G_new);
      }

      /// The many-body part m of a side of weight @p g (g = beta / h) of
      /// an automaton with many-body state @p state moves by @p dm: G moves
      /// by g dm; returns the drop of kappa G^2. A weighted side's m that
      /// moves on its own ends the automaton's uniform shape (lambda = 0:
      /// the pair kernel marks it general at its end). Nothing for an
      /// unweighted side.
      inline double
      move_weighted_side(ManyBodyState &state, const double g, const double dm)
      {
        if (g == 0)
          return 0;
        state.lambda = 0;
        return shift_sum(state, g * dm);
      }

      /// Energy lost when the series springs of a pair (area @p S,
      /// @p inv_sum = 1 / (k_i + k_j)) set its two sides' shear stresses
      /// alpha_i t, alpha_j t equal again (|t|^2 = @p t2): S t2 (alpha_i -
      /// alpha_j)^2 / 2 (k_i + k_j).
      inline double
      shear_mixing(const double S,
                   const double inv_sum,
                   const double alpha_i,
                   const double alpha_j,
                   const double t2)
      {
        const double da = alpha_i - alpha_j;
        return 0.5 * S * t2 * da * da * inv_sum;
      }
    } // namespace pair_energy


    inline double
    AutomatonSystem::side_many_body(const unsigned int p,
                                    const unsigned int s) const
    {
      if (mb_stored)
        return stored_side_many_body(p, s);
      const unsigned int a = s ? pj[p] : pi[p];
      return mc[mat[a]].D * mb_mu[a] + mb_offset[a];
    }


    inline double
    AutomatonSystem::side_sigma(const unsigned int p,
                                const unsigned int s) const
    {
      if (mb_stored)
        return (s ? sig_j : sig_i)[p];
      return sig_e[p] + side_many_body(p, s);
    }


    inline double
    AutomatonSystem::stored_side_many_body(const unsigned int p,
                                           const unsigned int s) const
    {
      Assert(mb_stored, dealii::ExcInternalError());
      const unsigned int a = s ? pj[p] : pi[p];
      return mc[mat[a]].D * mb_mu[a] + (s ? mb_j : mb_i)[p];
    }


    inline double
    AutomatonSystem::side_compliance(const unsigned int p,
                                     const unsigned int s) const
    {
      const SeriesSprings &k = springs[mat[pi[p]] * n_materials + mat[pj[p]]];
      return (s ? k.inv_kj : k.inv_ki) * (graded ? pair_half_rest[p] / r0 : 1.);
    }


    inline double
    AutomatonSystem::side_weight(const unsigned int p,
                                 const unsigned int s) const
    {
      return (s ? beta_j : beta_i)[p] / (graded ? pair_half_rest[p] : r0);
    }
  } // namespace mca
} // namespace tribodyn

#endif
