// Blocks of consecutive pairs for the passes of the pair law
// (pair_kernel.cc, bond_switching.cc): the square roots and divisions of a
// block in one branch-free loop that the compiler vectorizes.
#ifndef tribodyn_mca_pair_blocks_h
#define tribodyn_mca_pair_blocks_h

#include <cmath>
#include <tribodyn/mca/vector_algebra.h>

namespace tribodyn
{
  namespace mca
  {
    /**
     * Pair vectors, distances and their reciprocals of a block of
     * consecutive pairs. The square roots and divisions (the dearest
     * operations of a pair pass) run in one branch-free loop that the
     * compiler vectorizes; the branchy pair law then reads them.
     */
    struct NormalBlock
    {
      static constexpr unsigned int size = 64;
      alignas(64) double dn[3][size];
      alignas(64) double r[size], inv_r[size];

      /// Fill entries 0 .. nb-1 from pairs p0 .. p0+nb-1.
      template <class PairVector>
      void
      fill(const unsigned int p0,
           const unsigned int nb,
           const PairVector  &pair_vector)
      {
        for (unsigned int b = 0; b < nb; ++b)
          {
            const Vec3 v = pair_vector(p0 + b);
            for (unsigned int c = 0; c < 3; ++c)
              dn[c][b] = v[c];
          }
        for (unsigned int b = 0; b < nb; ++b)
          {
            r[b]     = std::sqrt(dn[0][b] * dn[0][b] + dn[1][b] * dn[1][b]
                             + dn[2][b] * dn[2][b]);
            inv_r[b] = 1. / r[b];
          }
      }

      Vec3
      normal(const unsigned int b) const
      {
        return {
          {dn[0][b] * inv_r[b], dn[1][b] * inv_r[b], dn[2][b] * inv_r[b]}};
      }
    };
  } // namespace mca
} // namespace tribodyn

#endif
