// Blocks of consecutive pairs for the passes of the pair law
// (pair_kernel.cc, bond_switching.cc): the square roots and divisions of a
// block in one branch-free loop that the compiler vectorizes.
#ifndef tribodyn_mca_pair_blocks_h
#define tribodyn_mca_pair_blocks_h

#include <cmath>
#include <cstddef>
#include <tribodyn/mca/vector_algebra.h>
#include <unistd.h>
#include <vector>

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

      /// Fill entries 0 .. nb-1 of pairs p0 .. p0+nb-1: from the distances
      /// and normals that pass A kept (PairArrays::step_normals, written by
      /// keep_normal(); dn then holds the normal itself and inv_r 1, so
      /// that normal() gives it unchanged), or anew where it kept none
      /// (@p kept empty).
      template <class PairVector>
      void
      fill(const unsigned int         p0,
           const unsigned int         nb,
           const std::vector<double> &kept,
           const unsigned int         n_pairs,
           const PairVector          &pair_vector)
      {
        if (kept.empty())
          {
            fill(p0, nb, pair_vector);
            return;
          }
        const double *k = kept.data() + p0;
        for (unsigned int b = 0; b < nb; ++b)
          {
            r[b]     = k[b];
            inv_r[b] = 1;
            for (unsigned int c = 0; c < 3; ++c)
              dn[c][b] = k[(c + 1) * std::size_t(n_pairs) + b];
          }
      }

      /// Keep distance @p r and unit normal @p n of pair @p p in @p kept
      /// (4 blocks of @p n_pairs: r, n_x, n_y, n_z), for fill().
      static void
      keep_normal(std::vector<double> &kept,
                  const unsigned int   n_pairs,
                  const unsigned int   p,
                  const double         r,
                  const Vec3          &n)
      {
        kept[p] = r;
        for (unsigned int c = 0; c < 3; ++c)
          kept[(c + 1) * std::size_t(n_pairs) + p] = n[c];
      }

      Vec3
      normal(const unsigned int b) const
      {
        return {
          {dn[0][b] * inv_r[b], dn[1][b] * inv_r[b], dn[2][b] * inv_r[b]}};
      }
    };


    /**
     * Ask for the j-side data of the pair `distance` pairs ahead (two
     * blocks): the pairs run in the order of their automata i, so the
     * processor streams the i side and the pair arrays by itself, but it
     * cannot foresee the neighbours j. Requested a block early, their
     * cache lines arrive while the block in between computes. A hint only:
     * no result changes. `n_ahead` is the pair count, or 0 where the
     * automata's data stay in the core's caches anyway (prefetch_pairs()).
     */
    template <class... Arrays>
    inline void
    prefetch_ahead(const unsigned int *pj,
                   const unsigned int  p,
                   const unsigned int  n_ahead,
                   const Arrays &...arrays)
    {
      constexpr unsigned int distance = 2 * NormalBlock::size;
      if (p + distance < n_ahead)
        {
          const unsigned int j = pj[p + distance];
          (__builtin_prefetch(&arrays[j]), ...);
        }
    }


    /**
     * Ask for the lines of per-pair arrays (doubles) four blocks ahead,
     * once per line (8 pairs): pass A streams some fifteen arrays at
     * once, more than the processor's own stream prefetcher keeps up with
     * (passes B and C gained nothing measurable from it). `write`: arrays
     * the pass writes (their lines asked for to be written). A hint only;
     * `n_ahead` as in prefetch_ahead().
     */
    template <int write, class... Arrays>
    inline void
    prefetch_streams(const unsigned int p,
                     const unsigned int n_ahead,
                     const Arrays &...arrays)
    {
      constexpr unsigned int distance = 4 * NormalBlock::size;
      if (p % 8 == 0 && p + distance < n_ahead)
        (__builtin_prefetch(arrays.data() + p + distance, write), ...);
    }


    /**
     * The `n_ahead` of prefetch_ahead(): the pair count where the positions,
     * velocities and spins of the local automata (72 bytes each) exceed a
     * core's level-2 cache (as the system reports it; 1 MiB if it does
     * not), 0 below: there the neighbours' data stay cached and requests
     * would only cost (doc/performance.md, "Prefetching the neighbours").
     */
    inline long
    level2_cache_bytes()
    {
      static const long level2 = [] {
        const long bytes = sysconf(_SC_LEVEL2_CACHE_SIZE);
        return bytes > 0 ? bytes : 1L << 20;
      }();
      return level2;
    }

    inline unsigned int
    prefetch_pairs(const unsigned int n_pairs, const unsigned int n_local)
    {
      return static_cast<long>(n_local) * 72 > level2_cache_bytes() ? n_pairs
                                                                    : 0;
    }

    /**
     * Does pass A keep the pairs' distances and normals for the later
     * passes of a plastic or bond kernel (PairArrays::step_normals)? Where
     * they (32 bytes a pair) fill at most a quarter of a core's level-2
     * cache: reading them back is then cheaper than computing them anew
     * (two_body_friction.prm, 4 480 pairs: 4 % faster), but beyond, the
     * extra memory traffic costs more than the square roots (friction_steel
     * with 69 504 pairs 2 % slower, the plastic 10^5 block 6 %;
     * doc/performance.md).
     */
    inline bool
    keep_pair_normals(const unsigned int n_pairs)
    {
      return static_cast<long>(n_pairs) * 32 <= level2_cache_bytes() / 4;
    }
  } // namespace mca
} // namespace tribodyn

#endif
