#ifndef tribodyn_mca_plasticity_h
#define tribodyn_mca_plasticity_h

#include <algorithm>
#include <tribodyn/mca/parameters.h>
#include <tribodyn/mca/vector_algebra.h>

namespace tribodyn
{
  namespace mca
  {
    /**
     * Faults to inject, for verification only: 1 in every run of tribodyn.
     * The test program tests/mca/faulted_run.cc sets one to show that the
     * physical energy balance (SystemEnergies::physical_balance_residual())
     * catches a stress update that does not dissipate what its law says,
     * which the booked balance cannot see (doc/theory/mca.md §8.4).
     */
    namespace verification
    {
      /// A factor on the radial return's M (read once per returning
      /// automaton).
      inline double radial_return_factor = 1;
      /// A factor on the Coulomb limit mu |sigma| of an unbonded side
      /// (read once per slipping side).
      inline double coulomb_limit_factor = 1;
    } // namespace verification

    /**
     * Plastic strain increment of the Wilkins radial return from the trial
     * equivalent stress @p q_trial for piecewise linear hardening (linear,
     * or bilinear with a second modulus from Second hardening onset):
     * q_trial - 3 G de = sigma_y(eps_p + de).
     */
    inline double
    plastic_increment(const MaterialParameters &m,
                      const double              G,
                      const double              eps_p,
                      const double              q_trial)
    {
      double s0 = m.yield_stress, e0 = 0, H = m.hardening_modulus;
      if (m.hardening == Hardening::bilinear
          && eps_p >= m.second_hardening_onset)
        {
          s0 = m.yield_stress_at(m.second_hardening_onset);
          e0 = m.second_hardening_onset;
          H  = m.second_hardening_modulus;
        }
      double de = (q_trial - s0 - H * (eps_p - e0)) / (3 * G + H);
      if (m.hardening == Hardening::bilinear && eps_p < m.second_hardening_onset
          && eps_p + de > m.second_hardening_onset)
        {
          s0 = m.yield_stress_at(m.second_hardening_onset);
          e0 = m.second_hardening_onset;
          H  = m.second_hardening_modulus;
          de = (q_trial - s0 - H * (eps_p - e0)) / (3 * G + H);
        }
      return std::max(de, 0.);
    }


    /**
     * The share of a continuum's deviatoric energy V s:s/4G that the sides
     * of an automaton hold, tr(B s^2) / tr(s^2), for its deviatoric stress
     * @p s and the inverse @p inverse_fabric of its fabric B = sum_j (q S /
     * V) n n (doc/theory/mca.md §3, §8.4): a side of area S and arm q holds
     * S q |s n|^2 / 4G, and the sum over the sides is V tr(B s^2) / 4G. 1
     * in a complete neighbourhood (B = I); below 1 at faces. Where the
     * fabric is ill conditioned the stored inverse is I and so is B here.
     */
    inline double
    sides_energy_share(const Sym3 &inverse_fabric, const Sym3 &s)
    {
      // B from its inverse (symmetric 3 x 3, by cofactors)
      const double a = inverse_fabric[0], b = inverse_fabric[1],
                   c = inverse_fabric[2], yz = inverse_fabric[3],
                   xz = inverse_fabric[4], xy = inverse_fabric[5];
      const double c00 = b * c - yz * yz, c11 = a * c - xz * xz,
                   c22 = a * b - xy * xy, c12 = xy * xz - a * yz,
                   c02 = xy * yz - b * xz, c01 = xz * yz - c * xy;
      const double det = a * c00 + xy * c01 + xz * c02;
      // s^2 (symmetric): the products of the rows of s
      const double sxx = s[0] * s[0] + s[5] * s[5] + s[4] * s[4],
                   syy = s[5] * s[5] + s[1] * s[1] + s[3] * s[3],
                   szz = s[4] * s[4] + s[3] * s[3] + s[2] * s[2],
                   syz = s[5] * s[4] + s[1] * s[3] + s[3] * s[2],
                   sxz = s[0] * s[4] + s[5] * s[3] + s[4] * s[2],
                   sxy = s[0] * s[5] + s[5] * s[1] + s[4] * s[3];
      const double tr  = sxx + syy + szz;
      if (!(tr > 0) || det == 0)
        return 1;
      return (c00 * sxx + c11 * syy + c22 * szz
              + 2 * (c12 * syz + c02 * sxz + c01 * sxy))
             / (det * tr);
    }
  } // namespace mca
} // namespace tribodyn

#endif
