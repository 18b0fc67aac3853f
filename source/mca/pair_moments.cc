// The energy of the relative-rotation moments K_ij of seed eq. (1) (their
// law: the chosen one of include/tribodyn/mca/moment_laws.h, applied in the
// pair kernel, pair_kernel.cc).

#include "pair_geometry.h"

#include <cmath>
#include <tribodyn/mca/automaton_system.h>
#include <type_traits>

namespace tribodyn
{
  namespace mca
  {
    std::pair<double, double>
    AutomatonSystem::rotation_stiffnesses(const unsigned int mi,
                                          const unsigned int mj) const
    {
      std::pair<double, double> k{0., 0.};
      moment_laws.with_selected(
        [&](const auto &law) { k = law.stiffnesses(mi * n_materials + mj); });
      return k;
    }


    double
    AutomatonSystem::moment_scale_of(const unsigned int p) const
    {
      return graded ? graded_moment_scale(pair_area[p],
                                          pair_half_rest[p],
                                          r0,
                                          1. / S)
                    : 1.;
    }


    double
    AutomatonSystem::pair_moment_energy() const
    {
      // |K . n|^2 / 2 k_twist + |K x n|^2 / 2 k_bend of the pairs, each
      // counted once (by the owner of i, as in energies()); a pair out of
      // contact holds no moment (but for a bond broken beyond the contact
      // distance at the last step: the next step releases it)
      double energy = 0;
      moment_laws.with_selected([&](const auto &law) {
        if constexpr (std::decay_t<decltype(law)>::active)
          for (unsigned int p = 0; p < pi.size(); ++p)
            if (owned(pi[p]))
              {
                double     r;
                const Vec3 n = unit_normal(p, r);
                // (automata of several sizes: the pair's own stiffnesses)
                const double f = moment_scale_of(p);
                if (f > 0) // (an inert pair carries no moment)
                  energy += law.energy(p,
                                       mat[pi[p]] * n_materials + mat[pj[p]],
                                       n,
                                       f);
              }
      });
      return energy;
    }
  } // namespace mca
} // namespace tribodyn
