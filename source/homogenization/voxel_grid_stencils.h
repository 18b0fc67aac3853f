// The finest voxel grid's operator node by node (issue #51 item 5;
// voxel_grid_solver.cc): the stencils of the nodes' configurations and
// the kernels that apply them (AVX2 in float and double, a generic one
// otherwise). Internal to voxel_grid_solver.cc.
#ifndef tribodyn_homogenization_voxel_grid_stencils_h
#define tribodyn_homogenization_voxel_grid_stencils_h

#include "voxel_grid.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <deal.II/base/aligned_vector.h>
#ifdef __AVX2__
#  include <immintrin.h>
#endif
#include <map>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      /**
       * The finest grid's operator node by node: each owned node's three
       * rows of the assembled matrix, a 27-node stencil of 3 x 3 blocks,
       * depend only on its eight cells' phases (and, for KUBC, on which
       * of its neighbours are on the boundary: their columns are zero). A
       * volume of a few phases has a few hundred such configurations; each
       * node keeps the index of its own. Applying the stencil reads the
       * nine rows of nodes around the node, three consecutive nodes (nine
       * Numbers) of each, and writes the node's three values once: no
       * element products, no scatter, no ghost contributions to send back
       * (doc/theory/homogenization.md, "3D voxel volumes", Solver, "The
       * voxel grid").
       */
      struct NodeStencils
      {
        /// The configuration of KUBC's boundary nodes: identity rows.
        static constexpr std::uint32_t identity = ~std::uint32_t(0);
        /// The phase of a cell outside a non-periodic box, in the keys.
        static constexpr std::uint32_t absent = ~std::uint32_t(0);
        /// Per configuration and row of nodes (dy, dz) (rp = (dy + 1) +
        /// 3 (dz + 1)), 32 coefficients: for each output component a the
        /// first eight of the segment s = 3 (dx + 1) + b (the input
        /// component b of the node dx = -1, 0, 1), then the ninth (s = 8)
        /// of the three components and zeros (index(); 32: vectors of
        /// eight aligned).
        static constexpr unsigned int row_stride     = 32;
        static constexpr unsigned int n_coefficients = 9 * row_stride;
        static constexpr unsigned int
        index(const unsigned int rp, const unsigned int a, const unsigned int s)
        {
          return row_stride * rp + (s < 8 ? 8 * a + s : 24 + a);
        }

        /// Per owned node (x fastest, then y, then z) its configuration.
        std::vector<std::uint32_t>                                config;
        dealii::AlignedVector<std::array<double, n_coefficients>> table;
        static_assert(sizeof(std::array<double, n_coefficients>)
                        == n_coefficients * sizeof(double),
                      "the table is read as one array");

        /// The stencils of the owned nodes of @p g, whose cell (i, j, k)
        /// has the element matrix @p K[phase(i, j, k)]; none (empty()) if
        /// the volume has more than @p max_configurations of them.
        template <class Phase>
        NodeStencils(const VoxelGrid                                   &g,
                     const std::vector<Element::ElementMatrix<double>> &K,
                     const Phase                                       &phase,
                     const bool                                         kubc,
                     const std::size_t max_configurations)
        {
          // the key: the phases of the eight cells around the node (x
          // fastest; absent outside a non-periodic box) and the mask of
          // its constrained neighbours (KUBC)
          using Key = std::array<std::uint32_t, 9>;
          std::map<Key, std::uint32_t> index_of;
          Key                          last{};
          std::uint32_t                last_index = identity;
          auto wrap = [&](const int i, const unsigned int d) -> int {
            if (g.periodic)
              return (i + int(g.n[d])) % int(g.n[d]);
            return (i < 0 || i >= int(g.n[d])) ? -1 : i;
          };
          config.reserve(std::size_t(g.ke - g.kb) * g.nn[0] * g.nn[1]);
          for (unsigned int k = g.kb; k < g.ke; ++k)
            for (unsigned int j = 0; j < g.nn[1]; ++j)
              for (unsigned int i = 0; i < g.nn[0]; ++i)
                {
                  if (kubc && g.on_boundary(i, j, k))
                    {
                      config.push_back(identity);
                      continue;
                    }
                  Key key{};
                  for (unsigned int c = 0; c < 8; ++c)
                    {
                      const int x = wrap(int(i) - 1 + (c & 1), 0),
                                y = wrap(int(j) - 1 + ((c >> 1) & 1), 1),
                                z = wrap(int(k) - 1 + ((c >> 2) & 1), 2);
                      key[c]
                        = (x < 0 || y < 0 || z < 0) ? absent : phase(x, y, z);
                    }
                  if (kubc)
                    for (unsigned int nb = 0; nb < 27; ++nb)
                      if (g.on_boundary(i + nb % 3 - 1,
                                        j + (nb / 3) % 3 - 1,
                                        k + nb / 9 - 1))
                        key[8] |= 1u << nb;
                  if (key != last || last_index == identity)
                    {
                      const auto [it, inserted]
                        = index_of.emplace(key, table.size());
                      if (inserted)
                        {
                          if (table.size() == max_configurations)
                            {
                              config.clear();
                              table.clear();
                              return;
                            }
                          table.push_back(stencil(key, K));
                        }
                      last       = key;
                      last_index = it->second;
                    }
                  config.push_back(last_index);
                }
        }

        bool
        empty() const
        {
          return table.empty();
        }

      private:
        /// The stencil of the cells' phases and constrained neighbours
        /// @p key: each cell c adds the rows of the node's vertex in it (v,
        /// opposite to c) against its vertices w, the neighbours
        /// dx = (c & 1) - 1 + (w & 1), ...
        static std::array<double, n_coefficients>
        stencil(const std::array<std::uint32_t, 9>                &key,
                const std::vector<Element::ElementMatrix<double>> &K)
        {
          std::array<double, n_coefficients> S{};
          for (unsigned int c = 0; c < 8; ++c)
            {
              if (key[c] == absent)
                continue;
              const auto        &Kc = K[key[c]];
              const unsigned int v  = 7 - c;
              for (unsigned int w = 0; w < 8; ++w)
                {
                  const unsigned int dx = (c & 1) + (w & 1),
                                     dy = ((c >> 1) & 1) + ((w >> 1) & 1),
                                     dz = ((c >> 2) & 1) + ((w >> 2) & 1);
                  if ((key[8] >> (dx + 3 * dy + 9 * dz)) & 1u)
                    continue;
                  const unsigned int rp = dy + 3 * dz;
                  for (unsigned int a = 0; a < 3; ++a)
                    for (unsigned int b = 0; b < 3; ++b)
                      S[index(rp, a, 3 * dx + b)]
                        += Kc[n_dofs * (n_vertices * a + v) + n_vertices * b
                              + w];
                }
            }
          return S;
        }
      };


      /**
       * y (3 values) = the stencil @p S applied to the nine segments @p x
       * (each three consecutive nodes' nine values; NodeStencils'
       * layout): per segment, the first eight values in one vector times
       * each output component's coefficients, the ninth alone; two
       * partial sums, so that the chains of dependent multiply-adds are
       * short. Any precision (double: CG's operator).
       */
      template <typename Number>
      inline void
      apply_stencil(const Number *S, const Number *const *x, Number *y)
      {
        typedef Number Segment __attribute__((vector_size(8 * sizeof(Number))));
        Segment        sum[2][3] = {};
        Number         last[3]   = {};
#pragma GCC unroll 9
        for (unsigned int rp = 0; rp < 9; ++rp)
          {
            Segment values;
            std::memcpy(&values, x[rp], sizeof(Segment));
            const Number ninth = x[rp][8];
#pragma GCC unroll 3
            for (unsigned int a = 0; a < 3; ++a)
              {
                Segment coefficients;
                std::memcpy(&coefficients,
                            S + NodeStencils::row_stride * rp + 8 * a,
                            sizeof(Segment));
                sum[rp & 1][a] += coefficients * values;
                last[a] += S[NodeStencils::row_stride * rp + 24 + a] * ninth;
              }
          }
        for (unsigned int a = 0; a < 3; ++a)
          {
            const Segment s = sum[0][a] + sum[1][a];
            Number        r = last[a];
            for (unsigned int l = 0; l < 8; ++l)
              r += s[l];
            y[a] = r;
          }
      }


      /**
       * The same in single precision (the V-cycle's) with AVX2: the ninth
       * values times the three components' coefficients at once, and the
       * eight-wide sums of the three components reduced together
       * (horizontal adds). (The compiler's own vectorization of the
       * generic version spent more on shuffles than on the products.)
       */
      inline void
      apply_stencil(const float *S, const float *const *x, float *y)
      {
#ifdef __AVX2__
        __m256 sum[2][3];
        __m128 last[2];
        for (unsigned int p = 0; p < 2; ++p)
          {
            for (unsigned int a = 0; a < 3; ++a)
              sum[p][a] = _mm256_setzero_ps();
            last[p] = _mm_setzero_ps();
          }
#  pragma GCC unroll 9
        for (unsigned int rp = 0; rp < 9; ++rp)
          {
            const __m256 values = _mm256_loadu_ps(x[rp]);
            const __m128 ninth  = _mm_broadcast_ss(x[rp] + 8);
            const float *s      = S + NodeStencils::row_stride * rp;
#  pragma GCC unroll 3
            for (unsigned int a = 0; a < 3; ++a)
              sum[rp & 1][a] = _mm256_fmadd_ps(_mm256_loadu_ps(s + 8 * a),
                                               values,
                                               sum[rp & 1][a]);
            last[rp & 1]
              = _mm_fmadd_ps(_mm_loadu_ps(s + 24), ninth, last[rp & 1]);
          }
        const __m256 s0 = _mm256_add_ps(sum[0][0], sum[1][0]),
                     s1 = _mm256_add_ps(sum[0][1], sum[1][1]),
                     s2 = _mm256_add_ps(sum[0][2], sum[1][2]);
        // [s0, s1, s2, s2] in each half, then the halves added
        const __m256 h
          = _mm256_hadd_ps(_mm256_hadd_ps(s0, s1), _mm256_hadd_ps(s2, s2));
        const __m128 r = _mm_add_ps(_mm_add_ps(_mm256_castps256_ps128(h),
                                               _mm256_extractf128_ps(h, 1)),
                                    _mm_add_ps(last[0], last[1]));
        _mm_storel_pi(reinterpret_cast<__m64 *>(y), r);
        y[2] = _mm_cvtss_f32(_mm_movehl_ps(r, r));
#else
        apply_stencil<float>(S, x, y);
#endif
      }

      /**
       * Two neighbouring nodes along x at once (their stencils @p S0 and
       * @p S1, the same one if @p same; the second node's segments three
       * numbers after the first's): the six sums reduced together into
       * the six consecutive outputs @p y.
       */
      template <bool same, typename Number>
      inline void
      apply_stencils(const Number        *S0,
                     const Number        *S1,
                     const Number *const *x,
                     Number              *y)
      {
        const Number *x1[9];
        for (unsigned int rp = 0; rp < 9; ++rp)
          x1[rp] = x[rp] + 3;
        apply_stencil(S0, x, y);
        apply_stencil(S1, x1, y + 3);
      }

#ifdef __AVX2__
      /// In single precision with AVX2: if the two nodes have the same
      /// stencil (as in a phase's bulk), each coefficient is loaded once
      /// for both (the loads, not the multiply-adds, bound the single
      /// node's product); the first node's ninth value is taken from the
      /// second node's vector.
      template <bool same>
      inline void
      apply_stencils(const float        *S0,
                     const float        *S1,
                     const float *const *x,
                     float              *y)
      {
        __m256 sum[2][3];
        __m128 last[2];
        for (unsigned int n = 0; n < 2; ++n)
          {
            for (unsigned int a = 0; a < 3; ++a)
              sum[n][a] = _mm256_setzero_ps();
            last[n] = _mm_setzero_ps();
          }
        const __m256i lane5 = _mm256_set1_epi32(5);
#  pragma GCC unroll 9
        for (unsigned int rp = 0; rp < 9; ++rp)
          {
            const __m256 values[2]
              = {_mm256_loadu_ps(x[rp]), _mm256_loadu_ps(x[rp] + 3)};
            const __m128 ninth[2]
              = {_mm256_castps256_ps128(
                   _mm256_permutevar8x32_ps(values[1], lane5)),
                 _mm_broadcast_ss(x[rp] + 11)};
            const float *s[2] = {S0 + NodeStencils::row_stride * rp,
                                 S1 + NodeStencils::row_stride * rp};
#  pragma GCC unroll 3
            for (unsigned int a = 0; a < 3; ++a)
              {
                const __m256 c0 = _mm256_load_ps(s[0] + 8 * a);
                const __m256 c1 = same ? c0 : _mm256_load_ps(s[1] + 8 * a);
                sum[0][a]       = _mm256_fmadd_ps(c0, values[0], sum[0][a]);
                sum[1][a]       = _mm256_fmadd_ps(c1, values[1], sum[1][a]);
              }
            const __m128 t0 = _mm_load_ps(s[0] + 24);
            const __m128 t1 = same ? t0 : _mm_load_ps(s[1] + 24);
            last[0]         = _mm_fmadd_ps(t0, ninth[0], last[0]);
            last[1]         = _mm_fmadd_ps(t1, ninth[1], last[1]);
          }
        // [y0, y1, y2, y3] and [y4, y5, y4, y5] in each half, the halves
        // added; the ninth values' sums [l0 l1 l2 0] of the two nodes
        // moved to the same places
        const __m256 h0 = _mm256_hadd_ps(_mm256_hadd_ps(sum[0][0], sum[0][1]),
                                         _mm256_hadd_ps(sum[0][2], sum[1][0])),
                     h1 = _mm256_hadd_ps(_mm256_hadd_ps(sum[1][1], sum[1][2]),
                                         _mm256_hadd_ps(sum[1][1], sum[1][2]));
        const __m128 l0 = _mm_insert_ps(last[0], last[1], 0x30),
                     l1 = _mm_shuffle_ps(last[1], last[1], 0x09);
        const __m128 r0 = _mm_add_ps(_mm_add_ps(_mm256_castps256_ps128(h0),
                                                _mm256_extractf128_ps(h0, 1)),
                                     l0),
                     r1 = _mm_add_ps(_mm_add_ps(_mm256_castps256_ps128(h1),
                                                _mm256_extractf128_ps(h1, 1)),
                                     l1);
        _mm_storeu_ps(y, r0);
        _mm_storel_pi(reinterpret_cast<__m64 *>(y + 4), r1);
      }
#endif

      /// The same in double precision (CG's operator) with AVX2: a segment
      /// is two vectors of four and the ninth value.
      inline void
      apply_stencil(const double *S, const double *const *x, double *y)
      {
#ifdef __AVX2__
        __m256d sum[3][2], last = _mm256_setzero_pd();
        for (unsigned int a = 0; a < 3; ++a)
          sum[a][0] = sum[a][1] = _mm256_setzero_pd();
#  pragma GCC unroll 9
        for (unsigned int rp = 0; rp < 9; ++rp)
          {
            const __m256d low   = _mm256_loadu_pd(x[rp]);
            const __m256d high  = _mm256_loadu_pd(x[rp] + 4);
            const __m256d ninth = _mm256_broadcast_sd(x[rp] + 8);
            const double *s     = S + NodeStencils::row_stride * rp;
#  pragma GCC unroll 3
            for (unsigned int a = 0; a < 3; ++a)
              {
                sum[a][0]
                  = _mm256_fmadd_pd(_mm256_loadu_pd(s + 8 * a), low, sum[a][0]);
                sum[a][1] = _mm256_fmadd_pd(_mm256_loadu_pd(s + 8 * a + 4),
                                            high,
                                            sum[a][1]);
              }
            last = _mm256_fmadd_pd(_mm256_loadu_pd(s + 24), ninth, last);
          }
        const __m256d s0 = _mm256_add_pd(sum[0][0], sum[0][1]),
                      s1 = _mm256_add_pd(sum[1][0], sum[1][1]),
                      s2 = _mm256_add_pd(sum[2][0], sum[2][1]);
        // [s0, s1 | s0, s1] and [s2, s2 | s2, s2] (pairs summed), halves
        // added
        const __m256d h01 = _mm256_hadd_pd(s0, s1),
                      h22 = _mm256_hadd_pd(s2, s2);
        const __m128d r01 = _mm_add_pd(_mm256_castpd256_pd128(h01),
                                       _mm256_extractf128_pd(h01, 1)),
                      r22 = _mm_add_pd(_mm256_castpd256_pd128(h22),
                                       _mm256_extractf128_pd(h22, 1));
        _mm_storeu_pd(y, _mm_add_pd(r01, _mm256_castpd256_pd128(last)));
        y[2]
          = _mm_cvtsd_f64(r22) + _mm_cvtsd_f64(_mm256_extractf128_pd(last, 1));
#else
        apply_stencil<double>(S, x, y);
#endif
      }
    } // namespace internal
  }   // namespace homogenization
} // namespace tribodyn

#endif
