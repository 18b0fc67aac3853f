#ifndef tribodyn_mca_plasticity_h
#define tribodyn_mca_plasticity_h

#include <algorithm>
#include <tribodyn/mca/parameters.h>

namespace tribodyn
{
  namespace mca
  {
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
  } // namespace mca
} // namespace tribodyn

#endif
