// The elastic moment K_ij of the relative rotation of a pair (seed eq.
// (1), M_ij = q_ij n_ij x F_ij + K_ij), which the seed names but does not
// specify: an incremental elastic moment of the relative rotation, updated
// like the pair's shear stress (doc/theory/mca.md §3, "Relative
// rotation"). On when Interaction/Relative rotation stiffness > 0 (it
// needs Rotations). A policy of the pair kernel (pair_law.h): pass A
// updates the trial moment from the step's kinematics (trial()), pass C
// limits it for unbonded contacts with their final normal stress
// (limit_unbonded()) and adds the torques; the moment of each pair is this
// law's pair state (field "moment", odd under i <-> j).
#ifndef tribodyn_mca_moment_laws_elastic_h
#define tribodyn_mca_moment_laws_elastic_h

#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/law_selection.h>
#include <tribodyn/mca/pair_fields.h>
#include <tribodyn/mca/series_springs.h>
#include <tribodyn/mca/vector_algebra.h>
#include <utility>
#include <vector>

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


    class ElasticMoment
    {
    public:
      static constexpr const char *name            = "elastic";
      static constexpr bool        active          = true;
      static constexpr bool        needs_rotations = true;

      struct Parameters : BoundLawParameters<Parameters>
      {
        /// Factor lambda of the stiffnesses of K_ij: twisting lambda k J,
        /// bending lambda k I of the pair's contact face. 0: no K_ij.
        double stiffness = 0;

        ParameterBinding
        binding()
        {
          ParameterBinding e("", "Interaction");
          // Above pi d^2 / S = 2 sqrt(2) pi the moments' springs make the
          // rotation of an automaton whose neighbours turn the other way
          // stiffer than its shear springs make a rotation with them (the
          // stiffest rotational mode without K_ij), and the step limit of
          // Time/Courant factor no longer covers them (doc/theory/mca.md
          // §3).
          e.add(
            "Relative rotation stiffness",
            stiffness,
            "Factor of the stiffnesses of the moment K_ij of the relative "
            "rotation of the two automata of a pair (seed eq. 1): an "
            "incremental elastic moment, twisting stiffness factor * k * J "
            "and bending stiffness factor * k * I, with k the pair's series "
            "stiffness per unit area and I = S^2/(4 pi), J = 2 I the second "
            "moments of a circular contact face of area S "
            "(doc/theory/mca.md). Unbonded pairs in contact carry it up to "
            "the no-tension (bending) and Coulomb (twisting) limits. 0: no "
            "K_ij (as before); 1: the parallel-bond value. Needs Rotations; "
            "in [0, 2 sqrt(2) pi = 8.89] (above, the explicit step limit "
            "would not cover the springs).",
            dealii::Patterns::Double(),
            Interval{0,
                     2 * std::sqrt(2.) * M_PI,
                     false,
                     false,
                     "Above 2 sqrt(2) pi the relative-rotation springs are "
                     "stiffer than the shear springs' rotational stiffness "
                     "and the explicit time step would not cover them; 1 "
                     "is the parallel-bond value."});
          return e;
        }

        bool
        chosen() const
        {
          return stiffness > 0;
        }
      };

      explicit ElasticMoment(const Parameters &p)
          : lambda(p.stiffness)
      {
      }

      /// The twisting and bending springs of each pair of materials from
      /// their normal @p springs (the table of the pair kernel) and the
      /// contact area @p S of a pair of size d: the contact face as a
      /// circle, I = S^2 / (4 pi) about a diameter, J = 2 I polar; the
      /// stiffness per unit area of the two halves in series, k = k_i k_j
      /// / (k_i + k_j), is that of the normal and shear springs.
      void
      set_up(const std::vector<SeriesSprings> &springs, const double S)
      {
        rotation_springs.clear();
        for (const auto &k : springs)
          {
            const double k_area = k.ki * k.kj * k.inv_sum;
            const double I      = S * S / (4 * M_PI);
            rotation_springs.push_back(
              {lambda * k_area * 2 * I, lambda * k_area * I});
          }
      }

      void
      register_pair_fields(PairFieldTable              &table,
                           const std::function<bool()> &in_use)
      {
        // the moment on i (-K_ij on j): odd under i <-> j
        table.add({"moment",
                   Relabel::odd,
                   0,
                   {&K.component[0], &K.component[1], &K.component[2]},
                   nullptr,
                   in_use,
                   {}});
      }

      /// Pair @p p separated: it carries no moment.
      void
      separate(const unsigned int p)
      {
        K.set(p, {{0, 0, 0}});
      }

      /// Pass A, a block of @p nb consecutive pairs from @p p0: their
      /// trial moments (pair_moment_law::trial()) into @p K_trial, from the
      /// block's axes @p n_old, @p n, mid-step axes @p nm and spins @p wi,
      /// @p wj; @p pair_type (mat_i * n_materials + mat_j) and the
      /// stiffness factor @p f of its size per pair. One loop without
      /// branches over the block, which the compiler vectorizes (the two
      /// divisions of the rotations were a tenth of a friction scene's
      /// step, pair by pair); the kernel stores the moments of the pairs
      /// that stay in contact (store_trial()).
      template <unsigned int block>
      void
      trial_block(const unsigned int  p0,
                  const unsigned int  nb,
                  const unsigned int *pair_type,
                  const double       *f,
                  const double (&n_old)[3][block],
                  const double (&n)[3][block],
                  const double (&nm)[3][block],
                  const double (&wi)[3][block],
                  const double (&wj)[3][block],
                  const double step_dt,
                  double (&K_trial)[3][block]) const
      {
        alignas(64) double k_twist[block], k_bend[block];
        for (unsigned int b = 0; b < nb; ++b)
          {
            const RotationSprings &ks = rotation_springs[pair_type[b]];
            k_twist[b]                = f[b] * ks.twist;
            k_bend[b]                 = f[b] * ks.bend;
          }
        const double *K0 = K.component[0].data() + p0,
                     *K1 = K.component[1].data() + p0,
                     *K2 = K.component[2].data() + p0;
        // (the pairs are independent: without the hint the compiler's
        // run-time checks of overlapping arrays exceed its limit and the
        // loop stays scalar)
#pragma GCC ivdep
        for (unsigned int b = 0; b < nb; ++b)
          {
            const Vec3 m = pair_moment_law::trial(
              {{K0[b], K1[b], K2[b]}},
              {{n_old[0][b], n_old[1][b], n_old[2][b]}},
              {{n[0][b], n[1][b], n[2][b]}},
              {{nm[0][b], nm[1][b], nm[2][b]}},
              {{wi[0][b], wi[1][b], wi[2][b]}},
              {{wj[0][b], wj[1][b], wj[2][b]}},
              step_dt,
              k_twist[b],
              k_bend[b]);
            for (unsigned int c = 0; c < 3; ++c)
              K_trial[c][b] = m[c];
          }
      }

      /// Pass A: pair @p p (block position @p b) keeps its trial moment.
      template <unsigned int block>
      void
      store_trial(const unsigned int p,
                  const unsigned int b,
                  const double (&K_trial)[3][block])
      {
        K.set(p, {{K_trial[0][b], K_trial[1][b], K_trial[2][b]}});
      }

      /// The moment K_ij on i of pair @p p.
      Vec3
      moment(const unsigned int p) const
      {
        return K[p];
      }

      /// Pass C, an unbonded contact: its moment limited by its
      /// compressive normal force @p p_n with friction coefficient @p mu
      /// over a face of radius @p a (pair_moment_law::limit_unbonded()),
      /// stored and returned in @p moment_out; returns the work of the
      /// slip (friction work).
      double
      limit_unbonded(const unsigned int p,
                     const unsigned int pair_type,
                     const Vec3        &n,
                     const double       p_n,
                     const double       mu,
                     const double       a,
                     const double       f,
                     Vec3              &moment_out)
      {
        const RotationSprings &ks   = rotation_springs[pair_type];
        Vec3                   m    = K[p];
        const double           work = pair_moment_law::limit_unbonded(
          m, n, p_n, mu, a, f * ks.twist, f * ks.bend);
        K.set(p, m);
        moment_out = m;
        return work;
      }

      /// Elastic energy |K . n|^2 / 2 k_twist + |K x n|^2 / 2 k_bend of
      /// pair @p p (axis @p n, stiffness factor @p f > 0).
      double
      energy(const unsigned int p,
             const unsigned int pair_type,
             const Vec3        &n,
             const double       f) const
      {
        const Vec3   m  = K[p];
        const double Kn = dot(m, n);
        const auto  &ks = rotation_springs[pair_type];
        return 0.5 * Kn * Kn / (f * ks.twist)
               + 0.5 * (dot(m, m) - Kn * Kn) / (f * ks.bend);
      }

      /// Twisting and bending stiffnesses (N m / rad) of a pair of
      /// materials @p pair_type of size d.
      std::pair<double, double>
      stiffnesses(const unsigned int pair_type) const
      {
        const auto &k = rotation_springs[pair_type];
        return {k.twist, k.bend};
      }

    private:
      struct RotationSprings
      {
        double twist, bend;
      };
      double                       lambda;
      std::vector<RotationSprings> rotation_springs;
      /// Relative-rotation moment K_ij on i of each pair.
      VectorArray K;
    };
  } // namespace mca
} // namespace tribodyn

#endif
