// The law of the relative-rotation moment K_ij of a pair (seed eq. (1),
// M_ij = q_ij n_ij x F_ij + K_ij), which the seed names but does not
// specify: an incremental elastic moment of the relative rotation, updated
// like the pair's shear stress (doc/theory/mca.md §3, "Relative rotation").
// Inline, for the pair kernel (pair_kernel.cc): pass A updates the trial
// moment from the step's kinematics, pass C limits it for unbonded
// contacts with their final normal stress and adds the torques. Only when
// Interaction/Relative rotation stiffness > 0 (and rotations are on).
#ifndef tribodyn_mca_pair_moment_law_h
#define tribodyn_mca_pair_moment_law_h

#include <cmath>
#include <tribodyn/mca/vector_algebra.h>

namespace tribodyn
{
  namespace mca
  {
    namespace pair_moment_law
    {
      /// @p m carried from the pair axis @p n_old to @p n (the smallest
      /// rotation taking one to the other, Rodrigues; @p c = n_old . n),
      /// then spun about @p n by the angle 2 atan(@p half_phi): the moment
      /// follows the pair as a rigid frame. Both rotations are exactly
      /// orthogonal (the spin in Cayley's form, without trigonometric
      /// calls: 2 atan(phi / 2) = phi - phi^3 / 12, phi = O(1e-3)).
      inline Vec3
      rotate_with_pair(const Vec3  &m,
                       const Vec3  &n_old,
                       const Vec3  &n,
                       const double c,
                       const double half_phi)
      {
        const Vec3   ax  = cross(n_old, n); // sin(angle) times the axis
        const Vec3   axm = cross(ax, m);
        const double s   = dot(ax, m) / (1 + c);
        Vec3         r;
        for (unsigned int e = 0; e < 3; ++e)
          r[e] = c * m[e] + axm[e] + s * ax[e];
        const double inv = 1. / (1 + half_phi * half_phi);
        const double cp  = (1 - half_phi * half_phi) * inv,
                     sp  = 2 * half_phi * inv;
        const Vec3   nxr = cross(n, r);
        const double rn  = dot(n, r) * (1 - cp);
        for (unsigned int e = 0; e < 3; ++e)
          r[e] = cp * r[e] + sp * nxr[e] + rn * n[e];
        return r;
      }

      /// Trial moment of a step: the stored moment @p K_old follows the
      /// pair's axis (@p n_old -> @p n) and the mean spin (w_i + w_j)/2 . n_m
      /// dt of its automata about the mid-step axis @p nm (objective
      /// update), plus the elastic increment of the relative rotation of the
      /// step, twisting (along the axis, stiffness @p k_twist) and bending
      /// (across it, @p k_bend); the moment on i turns i with j (restoring).
      inline Vec3
      trial(const Vec3  &K_old,
            const Vec3  &n_old,
            const Vec3  &n,
            const Vec3  &nm,
            const Vec3  &wi,
            const Vec3  &wj,
            const double step_dt,
            const double k_twist,
            const double k_bend)
      {
        const double half_phi = 0.25 * step_dt * (dot(wi, nm) + dot(wj, nm));
        Vec3 K = rotate_with_pair(K_old, n_old, n, dot(n_old, n), half_phi);
        Vec3 dth;
        for (unsigned int c = 0; c < 3; ++c)
          dth[c] = step_dt * (wj[c] - wi[c]);
        const double twist = dot(dth, nm);
        for (unsigned int c = 0; c < 3; ++c)
          K[c] += k_twist * twist * nm[c] + k_bend * (dth[c] - twist * nm[c]);
        return K;
      }

      /// An unbonded contact transmits a moment only through its
      /// compressive normal force @p p_n (>= 0): the bending moment of a
      /// no-tension face keeps the resultant inside the kern of the circle
      /// of radius @p a (eccentricity a/4), the twisting moment is at most
      /// that of Coulomb slip over the whole face, (2/3) mu p_n a. Limits
      /// @p K (axis @p n) and returns the work of the slip (friction work).
      inline double
      limit_unbonded(Vec3        &K,
                     const Vec3  &n,
                     const double p_n,
                     const double mu,
                     const double a,
                     const double k_twist,
                     const double k_bend)
      {
        const double Kn = dot(K, n);
        Vec3         Kt = K;
        for (unsigned int c = 0; c < 3; ++c)
          Kt[c] -= Kn * n[c];
        const double Kt_norm = std::sqrt(dot(Kt, Kt));
        const double limit_t = 2. / 3. * mu * p_n * a;
        const double limit_b = 0.25 * p_n * a;
        double       kn = Kn, scale_b = 1, work = 0;
        if (std::abs(Kn) > limit_t)
          {
            work += limit_t * (std::abs(Kn) - limit_t) / k_twist;
            kn = Kn > 0 ? limit_t : -limit_t;
          }
        if (Kt_norm > limit_b)
          {
            work += limit_b * (Kt_norm - limit_b) / k_bend;
            scale_b = limit_b / Kt_norm;
          }
        for (unsigned int c = 0; c < 3; ++c)
          K[c] = kn * n[c] + scale_b * Kt[c];
        return work;
      }
    } // namespace pair_moment_law
  }   // namespace mca
} // namespace tribodyn

#endif
