// The kinematics of a pair over one step, as the pair laws of both
// kernels compute them (pass A of pair_kernel.cc, the elastic bulk's of
// pair_kernel_bulk.cc; doc/theory/mca.md §2): its distances and normals at
// the step's ends, the stored shear stress turned into the new tangent
// plane, and the slip of the contact points. Each is written once here,
// and inlined the kernels compute what the formulas written out in their
// loops did, bit for bit, the bulk's loop still vectorized. (Plain
// `inline`: forced inlining made GCC version the bulk kernel's gather
// loop otherwise, with half its prefetches.)
#ifndef tribodyn_mca_pair_kinematics_h
#define tribodyn_mca_pair_kinematics_h

#include <algorithm>
#include <cmath>
#include <tribodyn/mca/vector_algebra.h>

namespace tribodyn
{
  namespace mca
  {
    /// A pair's distances over the step: r now and ro at its start, their
    /// reciprocals, the reciprocal length of the sum of the two unit
    /// normals (its mid-step normal is (n + n_old) inv_nm), and dr = r -
    /// ro.
    struct PairStepGeometry
    {
      double r, ro, inv_r, inv_ro, inv_nm, dr;
    };

    /// The step's geometry of a pair of vector (@p xn, @p yn, @p zn) now,
    /// which moved by @p du over the step (its vector then: the
    /// difference).
    inline PairStepGeometry
    pair_step_geometry(const double xn,
                       const double yn,
                       const double zn,
                       const double dux,
                       const double duy,
                       const double duz)
    {
      const double     xo = xn - dux, yo = yn - duy, zo = zn - duz;
      PairStepGeometry g;
      g.r      = std::sqrt(xn * xn + yn * yn + zn * zn);
      g.ro     = std::sqrt(xo * xo + yo * yo + zo * zo);
      g.inv_r  = 1. / g.r;
      g.inv_ro = 1. / g.ro;
      // mid-step normal n + n_old, normalized by inv_nm
      const double mx = xn * g.inv_r + xo * g.inv_ro,
                   my = yn * g.inv_r + yo * g.inv_ro,
                   mz = zn * g.inv_r + zo * g.inv_ro;
      g.inv_nm        = 1. / std::sqrt(mx * mx + my * my + mz * mz);
      // r - ro without cancellation: (dnew - dold).(dnew + dold) / (r + ro)
      g.dr = ((xn - xo) * (xn + xo) + (yn - yo) * (yn + yo)
              + (zn - zo) * (zn + zo))
             / (g.r + g.ro);
      return g;
    }


    /// The stored shear stress (@p tx, @p ty, @p tz) turned into the
    /// tangent plane of the pair's new normal (vector (@p xn, @p yn, @p zn)
    /// of reciprocal length @p inv_r), keeping its magnitude (both sides
    /// of the pair are multiples of it); a stress (nearly) along the new
    /// normal is dropped.
    inline Vec3
    turned_shear(const double tx,
                 const double ty,
                 const double tz,
                 const double xn,
                 const double yn,
                 const double zn,
                 const double inv_r)
    {
      const double t2 = tx * tx + ty * ty + tz * tz;
      const double tn = (tx * xn + ty * yn + tz * zn) * inv_r;
      const double px = tx - tn * xn * inv_r, py = ty - tn * yn * inv_r,
                   pz = tz - tn * zn * inv_r;
      const double p2 = px * px + py * py + pz * pz;
      const double s
        = p2 > 1e-12 * t2 ? std::sqrt(t2 / std::max(p2, 1e-300)) : 0.;
      return {{px * s, py * s, pz * s}};
    }


    /**
     * The relative tangential displacement of a pair's contact points over
     * the step, in @p du: on entry dt (v_j - v_i), the relative
     * displacement of the centres. With rotations (@p rot), less the turn
     * dt (q_i w_i + q_j w_j) x nm of the arms @p qi, @p qj (angular
     * velocities @p wi, @p wj: entry @p b of a block's arrays); where the
     * contact point is off the line of centres (Pairs::offsets: the face
     * centroid of a graded packing, at offset e), plus the turn dt (w_j - w_i)
     * x e, whose normal part is added to the change of distance @p dr too. Then
     * projected onto the tangent plane of the mid-step normal @p nm.
     */
    template <bool rot, class Pairs, unsigned int block>
    inline void
    contact_point_slip(Vec3        &du,
                       double      &dr,
                       const Vec3  &nm,
                       const double qi,
                       const double qj,
                       const double (&wi)[3][block],
                       const double (&wj)[3][block],
                       const unsigned int b,
                       const double       dt,
                       const Pairs       &geometry,
                       const unsigned int p)
    {
      if constexpr (rot)
        {
          Vec3 th;
          for (unsigned int c = 0; c < 3; ++c)
            th[c] = dt * (qi * wi[c][b] + qj * wj[c][b]);
          const Vec3 rc = cross(th, nm);
          for (unsigned int c = 0; c < 3; ++c)
            du[c] -= rc[c];
          if constexpr (Pairs::offsets)
            {
              const Vec3 e = geometry.offset(p);
              Vec3       dw;
              for (unsigned int c = 0; c < 3; ++c)
                dw[c] = dt * (wj[c][b] - wi[c][b]);
              const Vec3 re = cross(dw, e);
              for (unsigned int c = 0; c < 3; ++c)
                du[c] += re[c];
              dr += dot(re, nm);
            }
        }
      const double dun = dot(du, nm);
      for (unsigned int c = 0; c < 3; ++c)
        du[c] -= dun * nm[c];
    }
  } // namespace mca
} // namespace tribodyn

#endif
