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
    AutomatonSystem::add_side_stress(Mat3              &target,
                                     const unsigned int p,
                                     const unsigned int side,
                                     const unsigned int a,
                                     const double       sigma,
                                     const double       alpha,
                                     const double       r,
                                     const Vec3        &n) const
    {
      // Seed eq. (4): T^a += (q S / V_a) n (x) F / S, F / S the side's
      // traction sigma n + alpha tau (q_ji = r_ij - q_ij).
      Vec3 t;
      for (unsigned int c = 0; c < 3; ++c)
        t[c] = sigma * n[c] + alpha * tau.component[c][p];
      add_outer(target,
                moment_arm(p, r, side) * area_of(p)
                  / automaton_volume(*this, a),
                n,
                t);
    }


    inline void
    AutomatonSystem::add_pair_stress(const unsigned int   p,
                                     const Vec3          &n,
                                     const double         r,
                                     std::vector<Mat3>   &target,
                                     const bool           skip_elastic,
                                     const unsigned char *only) const
    {
      // Each owned side of the pair (add_side_stress()); sigma^i =
      // sym(B^-1 T) (fabric_corrected()).
      // (plastic and bond kernels only, which store the shear factors)
      Assert(shear_factors && mb_stored, dealii::ExcInternalError());
      const unsigned int i = pi[p], j = pj[p];
      if (owned(i) && !(skip_elastic && elastic(i))
          && (only == nullptr || only[i]))
        add_side_stress(target[i], p, 0, i, sig_i[p], tau_scale_i[p], r, n);
      if (owned(j) && !(skip_elastic && elastic(j))
          && (only == nullptr || only[j]))
        add_side_stress(target[j], p, 1, j, sig_j[p], tau_scale_j[p], r, n);
    }
  } // namespace mca
} // namespace tribodyn

#endif
