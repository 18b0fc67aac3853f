// The stress contributions of a pair's sides to the stress tensors of its
// automata (seed eq. 4), for the passes of the pair kernel
// (pair_kernel.cc): the plastic trial stress of pass B and the final
// stress of pass C that the bond criteria read. In a header of the
// kernel's translation unit so that the passes inline it.
#ifndef tribodyn_mca_pair_stress_h
#define tribodyn_mca_pair_stress_h

#include <tribodyn/mca/automaton_system.h>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    inline void
    AutomatonSystem::add_pair_stress(const unsigned int   p,
                                     const Vec3          &n,
                                     const double         r,
                                     std::vector<Mat3>   &target,
                                     const bool           skip_elastic,
                                     const unsigned char *only) const
    {
      // Seed eq. (4): T^i += (q_ij S / V_i) n_ij (x) F_ij / S, for each
      // owned side of the pair (q_ji = r_ij - q_ij); sigma^i = sym(B^-1 T).
      // (plastic and bond kernels only, which store the shear factors)
      Assert(shear_factors && mb_stored, dealii::ExcInternalError());
      if (owned(pi[p]) && !(skip_elastic && elastic(pi[p]))
          && (only == nullptr || only[pi[p]]))
        {
          Vec3 t;
          for (unsigned int c = 0; c < 3; ++c)
            t[c] = sig_i[p] * n[c] + tau_scale_i[p] * tau.component[c][p];
          add_outer(target[pi[p]],
                    moment_arm(p, r, 0) * area_of(p)
                      / automaton_volume(*this, pi[p]),
                    n,
                    t);
        }
      if (owned(pj[p]) && !(skip_elastic && elastic(pj[p]))
          && (only == nullptr || only[pj[p]]))
        {
          Vec3 t;
          for (unsigned int c = 0; c < 3; ++c)
            t[c] = sig_j[p] * n[c] + tau_scale_j[p] * tau.component[c][p];
          add_outer(target[pj[p]],
                    moment_arm(p, r, 1) * area_of(p)
                      / automaton_volume(*this, pj[p]),
                    n,
                    t);
        }
    }
  } // namespace mca
} // namespace tribodyn

#endif
