// The energy of the relative-rotation moments K_ij of seed eq. (1) (their
// law: pair_moment_law.h, applied in the pair kernel, pair_kernel.cc).

#include "pair_geometry.h"

#include <cmath>
#include <tribodyn/mca/automaton_system.h>

namespace tribodyn
{
  namespace mca
  {
    double
    AutomatonSystem::pair_moment_energy() const
    {
      // |K . n|^2 / 2 k_twist + |K x n|^2 / 2 k_bend of the interacting
      // pairs, each counted once (by the owner of i, as in energies())
      double energy = 0;
      for (unsigned int p = 0; p < pi.size(); ++p)
        if (owned(pi[p]) && (bonded[p] || in_contact[p]))
          {
            double       r;
            const Vec3   n  = unit_normal(p, r);
            const Vec3   K  = pair_moment[p];
            const double Kn = dot(K, n);
            const auto  &ks
              = rotation_springs[mat[pi[p]] * n_materials + mat[pj[p]]];
            // (automata of several sizes: the pair's own stiffnesses, as
            // the kernel's GradedPairs::moment_scale)
            const double f = graded ? graded_moment_scale(pair_area[p],
                                                          pair_half_rest[p],
                                                          r0,
                                                          1. / S)
                                    : 1.;
            if (f > 0) // (an inert pair carries no moment)
              energy += 0.5 * Kn * Kn / (f * ks.twist)
                        + 0.5 * (dot(K, K) - Kn * Kn) / (f * ks.bend);
          }
      return energy;
    }
  } // namespace mca
} // namespace tribodyn
