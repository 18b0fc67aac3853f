// The moment of the relative rotation of the two automata of a pair, K_ij of
// seed eq. (1) (M_ij = q_ij n_ij x F_ij + K_ij), which the seed names but
// does not specify: an incremental elastic moment of the relative rotation,
// updated like the pair's shear stress (doc/theory/mca.md §3, "Relative
// rotation"). Evaluated after the pair forces of a step (pass C of the
// kernel) and before its bond switching, only when
// Interaction/Relative rotation stiffness > 0 (and rotations are on).

#include <cmath>
#include <tribodyn/mca/automaton_system.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      Vec3
      normalized(const Vec3 &a)
      {
        const double inv = 1. / std::sqrt(dot(a, a));
        return {{a[0] * inv, a[1] * inv, a[2] * inv}};
      }

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
    } // namespace


    void
    AutomatonSystem::relative_rotation_moments(const double step_dt)
    {
      const unsigned int n_pairs = pi.size();
      const double       mu      = prm.interaction.friction_coefficient;
      // radius of the circular contact face of area S
      const double a = std::sqrt(S / M_PI);
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          if (!bonded[p] && !in_contact[p])
            {
              // separated: no moment (like the pair's stresses)
              pair_moment.set(p, {{0, 0, 0}});
              continue;
            }
          const unsigned int i = pi[p], j = pj[p];
          // the pair axis before and after the step (the drift moved each
          // automaton by dt v), and at mid-step
          const Vec3 dnew = pair_vector(p);
          Vec3       dold;
          for (unsigned int c = 0; c < 3; ++c)
            dold[c] = dnew[c] - step_dt * (v[j][c] - v[i][c]);
          const Vec3   n = normalized(dnew), n_old = normalized(dold);
          const double cos_n = dot(n_old, n);
          // |n + n_old| = sqrt(2 + 2 cos_n)
          const double inv_m = 1. / std::sqrt(2 + 2 * cos_n);
          const Vec3   nm{{(n[0] + n_old[0]) * inv_m,
                           (n[1] + n_old[1]) * inv_m,
                           (n[2] + n_old[2]) * inv_m}};
          // objective update: the stored moment follows the pair's axis
          // and the mean spin (w_i + w_j)/2 . n_m dt of its automata about
          // that axis
          const double half_phi
            = 0.25 * step_dt * (dot(w[i], nm) + dot(w[j], nm));
          Vec3 K = rotate_with_pair(pair_moment[p], n_old, n, cos_n, half_phi);
          // elastic increment from the relative rotation of the step,
          // twisting (along the axis) and bending (across it); the moment
          // on i turns i with j (restoring)
          const RotationSprings &ks
            = rotation_springs[mat[i] * n_materials + mat[j]];
          Vec3 dth;
          for (unsigned int c = 0; c < 3; ++c)
            dth[c] = step_dt * (w[j][c] - w[i][c]);
          const double twist = dot(dth, nm);
          for (unsigned int c = 0; c < 3; ++c)
            K[c]
              += ks.twist * twist * nm[c] + ks.bend * (dth[c] - twist * nm[c]);
          if (!bonded[p])
            {
              // An unbonded contact transmits a moment only through its
              // compressive normal stress: the bending moment of a
              // no-tension face keeps the resultant inside the kern of the
              // circle (eccentricity a/4), the twisting moment is at most
              // that of Coulomb slip over the whole face, (2/3) mu
              // |sigma| S a. The slip work is friction work (side i's
              // owner counts it: one moment per pair).
              const double p_n = -0.5 * (sig_i[p] + sig_j[p]) * S; // >= 0
              const double Kn  = dot(K, n);
              Vec3         Kt  = K;
              for (unsigned int c = 0; c < 3; ++c)
                Kt[c] -= Kn * n[c];
              const double Kt_norm = std::sqrt(dot(Kt, Kt));
              const double limit_t = 2. / 3. * mu * p_n * a;
              const double limit_b = 0.25 * p_n * a;
              double       kn = Kn, scale_b = 1;
              if (std::abs(Kn) > limit_t)
                {
                  if (owned(i))
                    friction_work
                      += limit_t * (std::abs(Kn) - limit_t) / ks.twist;
                  kn = Kn > 0 ? limit_t : -limit_t;
                }
              if (Kt_norm > limit_b)
                {
                  if (owned(i))
                    friction_work += limit_b * (Kt_norm - limit_b) / ks.bend;
                  scale_b = limit_b / Kt_norm;
                }
              for (unsigned int c = 0; c < 3; ++c)
                K[c] = kn * n[c] + scale_b * Kt[c];
            }
          pair_moment.set(p, K);
          if (owned(i))
            for (unsigned int c = 0; c < 3; ++c)
              torque[i][c] += K[c];
          if (owned(j))
            for (unsigned int c = 0; c < 3; ++c)
              torque[j][c] -= K[c];
        }
    }


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
            energy += 0.5 * Kn * Kn / ks.twist
                      + 0.5 * (dot(K, K) - Kn * Kn) / ks.bend;
          }
      return energy;
    }
  } // namespace mca
} // namespace tribodyn
