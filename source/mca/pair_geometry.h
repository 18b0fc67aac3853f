// The geometry of the pairs for the pair kernel (pair_kernel.cc), chosen
// once per scene: a uniform packing (one area, one rest length) or
// automata of several sizes (per-pair areas, rest lengths and face
// offsets from the Voronoi cells, doc/theory/mca.md §9). The kernel is
// instantiated on one of them; `if constexpr (Pairs::offsets)` keeps the
// uniform kernel free of the graded terms.
#ifndef tribodyn_mca_pair_geometry_h
#define tribodyn_mca_pair_geometry_h

#include <tribodyn/mca/vector_algebra.h>

namespace tribodyn
{
  namespace mca
  {
    /**
     * The geometry of the pairs of a uniform packing: one contact area S,
     * one half rest length r0 = d/2 (the pair law's policy for it; the
     * stiffness of the springs, 2G/r0, is that of the material table).
     */
    struct UniformPairs
    {
      double S, r0, inv_r0, d;
      /// Forces act on the line of centres (the dodecahedron's faces
      /// are centred on it).
      static constexpr bool offsets = false;
      static Vec3
      offset(const unsigned int)
      {
        return {{0, 0, 0}};
      }
      double
      area(const unsigned int) const
      {
        return S;
      }
      double
      inv_half_rest(const unsigned int) const
      {
        return inv_r0;
      }
      /// Distance at which an unbonded pair touches.
      double
      contact_distance(const unsigned int) const
      {
        return d;
      }
      /// Factor of the material table's relative-rotation stiffnesses
      /// (k I, k J of a pair of size d).
      static constexpr double
      moment_scale(const unsigned int)
      {
        return 1;
      }
      /// Factor of the material table's spring stiffnesses 2G / r0.
      static constexpr double
      stiffness_scale(const unsigned int)
      {
        return 1.;
      }
      static constexpr double
      inv_stiffness_scale(const unsigned int)
      {
        return 1.;
      }
    };

    /**
     * Automata of several sizes (doc/theory/mca.md §9): each pair has its
     * own area S_ij and half rest length q0_ij (its Voronoi face and
     * half the distance of the two centres at set-up), so its strains
     * are Δq / q0_ij and its springs 2G / q0_ij.
     */
    /// Factor of the material table's relative-rotation stiffnesses (k I,
    /// k J of a pair of size d, face S_d) for a pair of face @p S_p and half
    /// rest length @p q0_p: k = 2G / q0 and I = S^2 / (4 pi) (an inert pair
    /// near a change of size has S = q0 = 0).
    inline double
    graded_moment_scale(const double S_p,
                        const double q0_p,
                        const double r0,
                        const double inv_S_d)
    {
      const double s = S_p * inv_S_d;
      return q0_p > 0 ? r0 / q0_p * s * s : 0.;
    }

    struct GradedPairs
    {
      const double      *S, *q0;
      double             r0;
      const VectorArray *e;
      /// 1 / S of a pair of automata of size d.
      double inv_S_d;
      /// Forces act at the face centroid, e_ij off the line of centres:
      /// under a homogeneous stress the torques of a cell that is not
      /// centrosymmetric then vanish (Σ_f A_f x̄_f ⊗ n_f = V I).
      static constexpr bool offsets = true;
      Vec3
      offset(const unsigned int p) const
      {
        return {{e->component[0][p], e->component[1][p], e->component[2][p]}};
      }
      double
      area(const unsigned int p) const
      {
        return S[p];
      }
      double
      inv_half_rest(const unsigned int p) const
      {
        return 1. / q0[p];
      }
      double
      contact_distance(const unsigned int p) const
      {
        return 2 * q0[p];
      }
      double
      stiffness_scale(const unsigned int p) const
      {
        return r0 / q0[p];
      }
      double
      inv_stiffness_scale(const unsigned int p) const
      {
        return q0[p] / r0;
      }
      /// k I and k J scale as (2G / q0) S^2: the pair's face and halves.
      double
      moment_scale(const unsigned int p) const
      {
        return graded_moment_scale(S[p], q0[p], r0, inv_S_d);
      }
    };
  } // namespace mca
} // namespace tribodyn

#endif
