// The 3D cell problems on the voxel grid (issue #51 item 5): the same Q1
// discretization as CellProblem<3>, with the nodes, cells, levels and
// ranks' slabs found by index arithmetic (the grids: voxel_grid.h; the
// finest grid's node stencils and their kernels: voxel_grid_stencils.h;
// here the cell operators, the levels, the multigrid and the solve). See
// voxel_grid_solver.h and
// doc/theory/homogenization.md ("3D voxel volumes", Solver, "The voxel grid").

#include "cell_multigrid_galerkin.h"
#include "voxel_grid.h"
#include "voxel_grid_stencils.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <deal.II/base/aligned_vector.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <map>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/homogenization/voxel_grid_solver.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      /**
       * The elasticity operator of one grid: the cells' element matrices
       * (one per distinct index), applied cell by cell; KUBC's boundary
       * nodes as identity rows (read as zero by the cells). What
       * PreconditionChebyshev and SolverCG need of a matrix.
       */
      template <typename Number>
      struct GridOperator : public dealii::Subscriptor
      {
        const VoxelGrid                                 *grid        = nullptr;
        const std::vector<std::uint32_t>                *cell_matrix = nullptr;
        std::vector<std::array<Number, n_dofs * n_dofs>> matrices;
        bool                                             dirichlet = false;
        std::vector<std::size_t>                         constrained_owned;
        std::shared_ptr<dealii::DiagonalMatrix<GridVector<Number>>>
          inverse_diagonal;
        /// If set (the finest grid), vmult() applies these node by node
        /// instead of the cells' element matrices.
        std::shared_ptr<const NodeStencils> stencils;
        /// Their coefficients in Number, NodeStencils::n_coefficients per
        /// configuration (the table itself in double, a copy in float);
        /// a row of zeros for the rows outside the box.
        const Number                 *coefficients = nullptr;
        dealii::AlignedVector<Number> coefficients_copy;
        std::vector<Number>           zero_row;

        void
        initialize(const VoxelGrid                  &g,
                   const std::vector<std::uint32_t> &cells,
                   const bool                        kubc)
        {
          grid        = &g;
          cell_matrix = &cells;
          dirichlet   = kubc;
          constrained_owned.clear();
          if (dirichlet)
            for (unsigned int k = g.kb; k < g.ke; ++k)
              for (unsigned int j = 0; j < g.nn[1]; ++j)
                for (unsigned int i = 0; i < g.nn[0]; ++i)
                  if (g.on_boundary(i, j, k))
                    constrained_owned.push_back(g.local(i, j, k));
        }

        void
        initialize_dof_vector(GridVector<Number> &v) const
        {
          v.reinit(grid->partitioner);
        }
        global_dof_index
        m() const
        {
          return grid->size();
        }
        /// (PreconditionChebyshev's fallback when it has no diagonal: it
        /// always gets inverse_diagonal)
        Number
        el(const global_dof_index, const global_dof_index) const
        {
          AssertThrow(false, dealii::ExcNotImplemented());
          return 0;
        }

        /// Apply @p f(the vector-local indices of the cell's vertices, its
        /// element matrix, its constraint mask (constraint_mask()), its
        /// indices (i, j, k)) to every owned cell.
        template <class F>
        void
        for_each_cell(const F &f) const
        {
          const VoxelGrid &g    = *grid;
          std::size_t      cell = 0;
          for (unsigned int k = g.kb; k < g.cells_end(); ++k)
            for (unsigned int j = 0; j < g.n[1]; ++j)
              for (unsigned int i = 0; i < g.n[0]; ++i, ++cell)
                {
                  f(g.vertices(i, j, k),
                    (*cell_matrix)[cell],
                    constraint_mask(i, j, k),
                    {{i, j, k}});
                }
        }

        /// The element matrices @p K (FEEvaluation's component-major DoF
        /// order 8 c + v), stored in the node-major order 3 v + c of the
        /// vectors: a cell's two vertices along x are six consecutive
        /// Numbers of one node row.
        void
        set_matrices(const std::vector<Element::ElementMatrix<double>> &K)
        {
          matrices.resize(K.size());
          for (unsigned int m = 0; m < K.size(); ++m)
            for (unsigned int a = 0; a < n_dofs; ++a)
              for (unsigned int b = 0; b < n_dofs; ++b)
                matrices[m][n_dofs * node_major(a) + node_major(b)]
                  = Number(K[m][n_dofs * a + b]);
        }
        /// The node-major index of the component-major DoF @p i = 8 c + v.
        static constexpr unsigned int
        node_major(const unsigned int i)
        {
          return 3 * (i % n_vertices) + i / n_vertices;
        }

        /// Apply @p node_stencils (of this grid) in vmult().
        void
        use_stencils(const std::shared_ptr<const NodeStencils> &node_stencils)
        {
          stencils = node_stencils;
          if constexpr (std::is_same_v<Number, double>)
            coefficients = stencils->table[0].data();
          else
            {
              const auto &table = stencils->table;
              coefficients_copy.resize(table.size()
                                       * NodeStencils::n_coefficients);
              for (std::size_t c = 0; c < table.size(); ++c)
                for (unsigned int i = 0; i < NodeStencils::n_coefficients; ++i)
                  coefficients_copy[c * NodeStencils::n_coefficients + i]
                    = Number(table[c][i]);
              coefficients = coefficients_copy.data();
            }
          zero_row.assign(3 * grid->nn[0] + 8, Number(0));
        }

        /**
         * dst = A src. The cells go row by row (x fastest); a cell's eight
         * vertices are two consecutive nodes in each of four node rows, so
         * its 24 values are four copies of six consecutive Numbers. Up to
         * four consecutive cells of the same element matrix are multiplied
         * together (multiply_element_matrices(): each column of the matrix
         * loaded once for all), as they are in a phase's bulk; the cells of
         * KUBC's boundary and the periodic wrap take the general path, one
         * at a time.
         */
        void
        vmult(GridVector<Number> &dst, const GridVector<Number> &src) const
        {
          if (stencils)
            {
              vmult_by_nodes(dst, src);
              return;
            }
          const bool had_ghosts = src.has_ghost_elements();
          if (!had_ghosts)
            src.update_ghost_values();
          dst = Number(0);
          dst.zero_out_ghost_values();
          const Number    *in   = src.begin();
          Number          *out  = dst.begin();
          const VoxelGrid &g    = *grid;
          const auto      &ids  = *cell_matrix;
          std::size_t      cell = 0;
          for (unsigned int k = g.kb; k < g.cells_end(); ++k)
            for (unsigned int j = 0; j < g.n[1]; ++j, cell += g.n[0])
              {
                const unsigned int j1 = g.next(j, 1), k1 = g.next(k, 2);
                const std::size_t  row[4] = {g.local(0, j, k),
                                             g.local(0, j1, k),
                                             g.local(0, j, k1),
                                             g.local(0, j1, k1)};
                // the cells of the general path: KUBC's boundary rows and
                // end cells, the periodic wrap
                const bool boundary_row
                  = dirichlet
                    && (j == 0 || k == 0 || j + 1 == g.n[1] || k + 1 == g.n[2]);
                const unsigned int first = boundary_row ? g.n[0]
                                           : dirichlet  ? 1
                                                        : 0;
                const unsigned int last
                  = boundary_row
                      ? g.n[0]
                      : (dirichlet || g.periodic ? g.n[0] - 1 : g.n[0]);
                for (unsigned int i = 0; i < std::min(first, g.n[0]); ++i)
                  general_cell(in, out, i, j, k, ids[cell + i]);
                for (unsigned int i = first; i < last;)
                  {
                    const std::uint32_t m     = ids[cell + i];
                    unsigned int        count = 1;
                    while (count < 4 && i + count < last
                           && ids[cell + i + count] == m)
                      ++count;
                    const Number *K = matrices[m].data();
                    switch (count)
                      {
                        case 4:
                          row_cells<4>(K, in, out, row, i);
                          break;
                        case 3:
                          row_cells<3>(K, in, out, row, i);
                          break;
                        case 2:
                          row_cells<2>(K, in, out, row, i);
                          break;
                        default:
                          row_cells<1>(K, in, out, row, i);
                      }
                    i += count;
                  }
                for (unsigned int i = std::max(last, first); i < g.n[0]; ++i)
                  general_cell(in, out, i, j, k, ids[cell + i]);
              }
          dst.compress(dealii::VectorOperation::add);
          for (const std::size_t k : constrained_owned)
            for (unsigned int c = 0; c < 3; ++c)
              out[k + c] = in[k + c];
          if (!had_ghosts)
            src.zero_out_ghost_values();
        }

        /**
         * dst = A src by the node stencils: each owned node's three values
         * from the nine rows of nodes around it (the ghost planes next to
         * the slab; wrapped on the periodic grid; zeros outside the box);
         * the nodes at the ends of a row read their segments from a copy
         * (wrapped or zero), the others straight from the rows.
         */
        void
        vmult_by_nodes(GridVector<Number>       &dst,
                       const GridVector<Number> &src) const
        {
          const bool had_ghosts = src.has_ghost_elements();
          if (!had_ghosts)
            src.update_ghost_values();
          const VoxelGrid     &g      = *grid;
          const Number        *in     = src.begin();
          Number              *out    = dst.begin();
          const std::uint32_t *config = stencils->config.data();
          const unsigned int   nx     = g.nn[0];
          auto                 row    = [&](const int j, const int k) {
            if (g.periodic)
              return in
                     + g.local(0,
                               (j + int(g.nn[1])) % int(g.nn[1]),
                               (k + int(g.nn[2])) % int(g.nn[2]));
            if (j < 0 || k < 0 || j >= int(g.nn[1]) || k >= int(g.nn[2]))
              return zero_row.data();
            return in + g.local(0, j, k);
          };
          std::size_t node = 0;
          for (unsigned int k = g.kb; k < g.ke; ++k)
            for (unsigned int j = 0; j < g.nn[1]; ++j)
              {
                const Number *rows[9];
                for (unsigned int rp = 0; rp < 9; ++rp)
                  rows[rp]
                    = row(int(j) + int(rp % 3) - 1, int(k) + int(rp / 3) - 1);
                Number              *o   = out + g.local(0, j, k);
                const std::uint32_t *c_j = config + node;
                node += nx;
                // the interior nodes two at a time, the others one by one
                unsigned int i   = 0;
                auto         one = [&](const unsigned int i) {
                  const std::uint32_t c = c_j[i];
                  if (c == NodeStencils::identity)
                    {
                      for (unsigned int a = 0; a < 3; ++a)
                        o[3 * i + a] = rows[4][3 * i + a];
                      return;
                    }
                  const Number *S
                    = coefficients
                      + std::size_t(c) * NodeStencils::n_coefficients;
                  const Number *x[9];
                  Number        ends[9][9];
                  if (i > 0 && i + 1 < nx)
                    for (unsigned int rp = 0; rp < 9; ++rp)
                      x[rp] = rows[rp] + 3 * (i - 1);
                  else
                    for (unsigned int rp = 0; rp < 9; ++rp)
                      {
                        // the row's first or last node: its neighbours
                        // along x wrapped (periodic) or zero
                        for (unsigned int s = 0; s < 3; ++s)
                          {
                            const int  n      = int(i) + int(s) - 1;
                            const bool inside = n >= 0 && n < int(nx);
                            const int  m      = (n + int(nx)) % int(nx);
                            for (unsigned int a = 0; a < 3; ++a)
                              ends[rp][3 * s + a] = inside || g.periodic
                                                              ? rows[rp][3 * m + a]
                                                              : Number(0);
                          }
                        x[rp] = ends[rp];
                      }
                  apply_stencil(S, x, o + 3 * i);
                };
                one(i++);
                for (; i + 2 < nx; i += 2)
                  {
                    const std::uint32_t c0 = c_j[i], c1 = c_j[i + 1];
                    if (c0 == NodeStencils::identity
                        || c1 == NodeStencils::identity)
                      {
                        one(i);
                        one(i + 1);
                        continue;
                      }
                    const Number *x[9];
                    for (unsigned int rp = 0; rp < 9; ++rp)
                      x[rp] = rows[rp] + 3 * (i - 1);
                    const Number *S0
                      = coefficients
                        + std::size_t(c0) * NodeStencils::n_coefficients,
                      *S1 = coefficients
                            + std::size_t(c1) * NodeStencils::n_coefficients;
                    if (c0 == c1)
                      apply_stencils<true>(S0, S0, x, o + 3 * i);
                    else
                      apply_stencils<false>(S0, S1, x, o + 3 * i);
                  }
                for (; i < nx; ++i)
                  one(i);
              }
          dst.zero_out_ghost_values();
          if (!had_ghosts)
            src.zero_out_ghost_values();
        }

        /// @p count consecutive cells from (i, row) of the element matrix
        /// @p K, their nodes within the rows @p row.
        template <unsigned int count>
        static void
        row_cells(const Number      *K,
                  const Number      *in,
                  Number            *out,
                  const std::size_t *row,
                  const unsigned int i)
        {
          Number x[count][n_dofs], y[count][n_dofs];
          for (unsigned int t = 0; t < count; ++t)
            for (unsigned int r = 0; r < 4; ++r)
              std::memcpy(&x[t][6 * r],
                          in + row[r] + 3 * (i + t),
                          6 * sizeof(Number));
          if constexpr (count == 1)
            multiply_element_matrix<Number, n_dofs>(K, x[0], y[0]);
          else
            multiply_element_matrices<Number, n_dofs, count>(K, x, y);
          // node i + s of a row gets its left cell's (s - 1) right vertex
          // and its right cell's (s) left vertex: each node added once
          for (unsigned int r = 0; r < 4; ++r)
            {
              Number node[3 * (count + 1)];
              for (unsigned int c = 0; c < 3; ++c)
                {
                  node[c]             = y[0][6 * r + c];
                  node[3 * count + c] = y[count - 1][6 * r + 3 + c];
                }
              for (unsigned int t = 1; t < count; ++t)
                for (unsigned int c = 0; c < 3; ++c)
                  node[3 * t + c] = y[t][6 * r + c] + y[t - 1][6 * r + 3 + c];
              Number *o = out + row[r] + 3 * i;
              for (unsigned int a = 0; a < 3 * (count + 1); ++a)
                o[a] += node[a];
            }
        }

        /// One cell by its vertices' indices, with KUBC's constraints.
        void
        general_cell(const Number       *in,
                     Number             *out,
                     const unsigned int  i,
                     const unsigned int  j,
                     const unsigned int  k,
                     const std::uint32_t m) const
        {
          const auto          v    = grid->vertices(i, j, k);
          const std::uint32_t mask = constraint_mask(i, j, k);
          Number              x[n_dofs], y[n_dofs];
          for (unsigned int q = 0; q < n_vertices; ++q)
            for (unsigned int c = 0; c < 3; ++c)
              x[3 * q + c] = ((mask >> (3 * q)) & 1u) ? 0 : in[v[q] + c];
          multiply_element_matrix<Number, n_dofs>(matrices[m].data(), x, y);
          for (unsigned int q = 0; q < n_vertices; ++q)
            if (!((mask >> (3 * q)) & 1u))
              for (unsigned int c = 0; c < 3; ++c)
                out[v[q] + c] += y[3 * q + c];
        }

        /// KUBC: bit 3 v + c set for the components of the cell's vertices
        /// v on the boundary.
        std::uint32_t
        constraint_mask(const unsigned int i,
                        const unsigned int j,
                        const unsigned int k) const
        {
          const VoxelGrid &g    = *grid;
          std::uint32_t    mask = 0;
          if (dirichlet
              && (i == 0 || j == 0 || k == 0 || i + 1 == g.n[0]
                  || j + 1 == g.n[1] || k + 1 == g.n[2]))
            for (unsigned int q = 0; q < n_vertices; ++q)
              if (g.on_boundary(i + (q & 1),
                                j + ((q >> 1) & 1),
                                k + ((q >> 2) & 1)))
                mask |= 7u << (3 * q);
          return mask;
        }


        void
        compute_inverse_diagonal()
        {
          inverse_diagonal
            = std::make_shared<dealii::DiagonalMatrix<GridVector<Number>>>();
          auto &d = inverse_diagonal->get_vector();
          initialize_dof_vector(d);
          Number *out = d.begin();
          if (stencils)
            {
              // the node's own block (rp = 4, dx = 0, b = a)
              for (std::size_t n = 0; n < stencils->config.size(); ++n)
                for (unsigned int a = 0; a < 3; ++a)
                  {
                    const std::uint32_t c = stencils->config[n];
                    out[3 * n + a]
                      = c == NodeStencils::identity
                          ? Number(1)
                          : Number(1)
                              / Number(
                                stencils
                                  ->table[c][NodeStencils::index(4, a, 3 + a)]);
                  }
              return;
            }
          for_each_cell([&](const std::array<std::size_t, n_vertices> &v,
                            const std::uint32_t                        m,
                            const std::uint32_t                        mask,
                            const std::array<unsigned int, 3> &) {
            for (unsigned int q = 0; q < n_vertices; ++q)
              for (unsigned int c = 0; c < 3; ++c)
                {
                  const unsigned int i = 3 * q + c;
                  if (!((mask >> i) & 1u))
                    out[v[q] + c] += matrices[m][(n_dofs + 1) * i];
                }
          });
          d.compress(dealii::VectorOperation::add);
          for (const std::size_t k : constrained_owned)
            for (unsigned int c = 0; c < 3; ++c)
              d.local_element(k + c) = 1;
          for (unsigned int i = 0; i < d.locally_owned_size(); ++i)
            d.local_element(i) = Number(1) / d.local_element(i);
        }
      };


      /**
       * The grids of one kind (periodic or not) and their element
       * matrices: the voxels' phases on the finest, the Galerkin products
       * on the coarser ones (cell_multigrid_galerkin.h: the same matrices
       * as the mesh's hierarchy).
       */
      struct VoxelGridLevels
      {
        bool                                    periodic = false;
        std::vector<VoxelGrid>                  grids;
        std::vector<std::vector<std::uint32_t>> cell_matrix;
        /// Per grid the distinct element matrices (double); on the finest
        /// one the phases' (its cells' matrix index is their phase).
        std::vector<std::vector<Element::ElementMatrix<double>>> matrices;
        /// The coarsest grid's assembled matrix (all ranks, unconstrained).
        dealii::FullMatrix<double> coarse_matrix;

        /// The grids (not periodic) and their element matrices.
        VoxelGridLevels(const MPI_Comm                   comm,
                        const VoxelVolume               &volume,
                        const std::vector<VoigtMatrix6> &stiffness)
            : comm(comm)
            , volume(volume)
        {
          make_grids(false);
          const unsigned int levels = grids.size();

          // The element matrices of the owned cells of every grid.
          const StiffnessOverBox<3> stiffness_of_box =
            [&](const dealii::Point<3> &lower, const dealii::Point<3> &upper) {
              std::array<unsigned int, 3> index;
              for (unsigned int d = 0; d < 3; ++d)
                index[d] = static_cast<unsigned int>(0.5 * (lower[d] + upper[d])
                                                     / volume.voxel_size(d));
              return stiffness[volume.voxel(index[0], index[1], index[2])];
            };
          GalerkinElementMatrices<3> galerkin(stiffness_of_box,
                                              {{volume.voxel_size(0),
                                                volume.voxel_size(1),
                                                volume.voxel_size(2)}});
          cell_matrix.resize(levels);
          matrices.resize(levels);
          for (const VoigtMatrix6 &C : stiffness)
            matrices[0].push_back(
              Element::element_matrix(entries(C),
                                      {{volume.voxel_size(0),
                                        volume.voxel_size(1),
                                        volume.voxel_size(2)}}));
          for (unsigned int l = 0; l < levels; ++l)
            {
              const VoxelGrid                      &g = grids[l];
              std::map<unsigned int, std::uint32_t> index_of;
              auto                                 &cells = cell_matrix[l];
              cells.reserve(
                std::size_t(g.cells_end() - std::min(g.kb, g.cells_end()))
                * g.n[0] * g.n[1]);
              for (unsigned int k = g.kb; k < g.cells_end(); ++k)
                for (unsigned int j = 0; j < g.n[1]; ++j)
                  for (unsigned int i = 0; i < g.n[0]; ++i)
                    {
                      if (l == 0)
                        {
                          cells.push_back(volume.voxel(i, j, k));
                          continue;
                        }
                      const dealii::Point<3> lower(i * g.h[0],
                                                   j * g.h[1],
                                                   k * g.h[2]);
                      const dealii::Point<3> upper((i + 1) * g.h[0],
                                                   (j + 1) * g.h[1],
                                                   (k + 1) * g.h[2]);
                      const unsigned int     id = galerkin.id(lower, upper, l);
                      const auto [it, inserted]
                        = index_of.emplace(id, matrices[l].size());
                      if (inserted)
                        matrices[l].push_back(galerkin.matrix(l, id));
                      cells.push_back(it->second);
                    }
            }

          assemble_coarse_matrix();
        }

        /// The finest grid's node stencils (KUBC's or the others'), or
        /// none if the volume has so many configurations that they would
        /// take more memory than a few bytes per node.
        std::shared_ptr<const NodeStencils>
        fine_stencils(const bool kubc) const
        {
          const VoxelGrid  &g = grids[0];
          const std::size_t owned_nodes
            = std::size_t(g.ke - g.kb) * g.nn[0] * g.nn[1];
          auto stencils = std::make_shared<NodeStencils>(
            g,
            matrices[0],
            [&](const unsigned int i,
                const unsigned int j,
                const unsigned int k) {
              return std::uint32_t(volume.voxel(i, j, k));
            },
            kubc,
            std::max<std::size_t>(1024, owned_nodes / 256));
          if (stencils->empty())
            return nullptr;
          return stencils;
        }

        /// Switch the grids to periodic or not: their nodes, slabs and the
        /// coarsest matrix change, the cells and their matrices do not (the
        /// owned cell planes are the same).
        void
        set_periodic(const bool p)
        {
          if (p == periodic)
            return;
          make_grids(p);
          assemble_coarse_matrix();
        }

      private:
        /// The grids of 2^l voxels while they coarsen (n_grids()). The
        /// ranks' slabs: balanced cell planes on the finest grid, each
        /// coarser grid's boundaries the finer ones halved (rounded up),
        /// so that a rank's fine planes read the coarse planes of its slab
        /// and the two next to it.
        void
        make_grids(const bool p)
        {
          periodic = p;
          grids.clear();
          std::array<unsigned int, 3> n;
          std::array<double, 3>       h;
          for (unsigned int d = 0; d < 3; ++d)
            {
              n[d] = volume.n_voxels(d);
              h[d] = volume.voxel_size(d);
            }
          const unsigned int levels = n_grids(n);
          AssertThrow(levels > 0, dealii::ExcInternalError());
          const unsigned int R = dealii::Utilities::MPI::n_mpi_processes(comm);
          const unsigned int r = dealii::Utilities::MPI::this_mpi_process(comm);
          const unsigned int planes = periodic ? n[2] : n[2] + 1;
          unsigned int       kb     = std::size_t(r) * n[2] / R;
          unsigned int ke = r + 1 == R ? planes : std::size_t(r + 1) * n[2] / R;
          for (unsigned int l = 0; l < levels; ++l)
            {
              grids.emplace_back(n, h, periodic, kb, ke, comm);
              for (unsigned int d = 0; d < 3; ++d)
                {
                  n[d] /= 2;
                  h[d] *= 2;
                }
              kb = (kb + 1) / 2;
              ke = (ke + 1) / 2;
            }
        }

        /// The coarsest grid's matrix: each rank adds its cells', the sum
        /// over the ranks on every rank.
        void
        assemble_coarse_matrix()
        {
          const VoxelGrid &c = grids.back();
          coarse_matrix.reinit(c.size(), c.size());
          std::size_t cell = 0;
          for (unsigned int k = c.kb; k < c.cells_end(); ++k)
            for (unsigned int j = 0; j < c.n[1]; ++j)
              for (unsigned int i = 0; i < c.n[0]; ++i, ++cell)
                {
                  const auto &K = matrices.back()[cell_matrix.back()[cell]];
                  global_dof_index dof[n_dofs];
                  for (unsigned int q = 0; q < n_vertices; ++q)
                    {
                      const unsigned int x = (q & 1) ? c.next(i, 0) : i;
                      const unsigned int y = ((q >> 1) & 1) ? c.next(j, 1) : j;
                      const unsigned int z = ((q >> 2) & 1) ? c.next(k, 2) : k;
                      const global_dof_index node
                        = (global_dof_index(z) * c.nn[1] + y) * c.nn[0] + x;
                      for (unsigned int d = 0; d < 3; ++d)
                        dof[n_vertices * d + q] = 3 * node + d;
                    }
                  for (unsigned int a = 0; a < n_dofs; ++a)
                    for (unsigned int b = 0; b < n_dofs; ++b)
                      coarse_matrix(dof[a], dof[b]) += K[n_dofs * a + b];
                }
          dealii::Utilities::MPI::sum(
            dealii::ArrayView<const double>(&coarse_matrix(0, 0),
                                            coarse_matrix.n_elements()),
            comm,
            dealii::ArrayView<double>(&coarse_matrix(0, 0),
                                      coarse_matrix.n_elements()));
        }

        MPI_Comm           comm;
        const VoxelVolume &volume;
      };


      /**
       * CG with the V-cycle on the grids for one boundary condition, in
       * @p LevelNumber (float: the mixed-precision default).
       */
      template <typename LevelNumber>
      class GridMultigrid
      {
        using LevelVector = GridVector<LevelNumber>;
        using Smoother
          = dealii::PreconditionChebyshev<GridOperator<LevelNumber>,
                                          LevelVector,
                                          dealii::DiagonalMatrix<LevelVector>>;

      public:
        GridMultigrid(const VoxelGridLevels  &levels,
                      const BoundaryCondition bc,
                      const MPI_Comm          comm)
            : levels(levels)
            , comm(comm)
            , kubc(bc == BoundaryCondition::kubc)
            , n_rigid(bc == BoundaryCondition::subc
                        ? 6
                        : (bc == BoundaryCondition::periodic ? 3 : 0))
        {
          const unsigned int n_levels = levels.grids.size();
          fine.initialize(levels.grids[0], levels.cell_matrix[0], kubc);
          fine.set_matrices(levels.matrices[0]);
          const auto stencils = levels.fine_stencils(kubc);
          if (stencils)
            fine.use_stencils(stencils);
          operators.resize(n_levels);
          smoothers.resize(n_levels);
          r.resize(n_levels);
          b.resize(n_levels);
          x.resize(n_levels);
          for (unsigned int l = 0; l < n_levels; ++l)
            {
              auto &op = operators[l];
              op.initialize(levels.grids[l], levels.cell_matrix[l], kubc);
              op.set_matrices(levels.matrices[l]);
              if (l == 0 && stencils)
                op.use_stencils(stencils);
              op.initialize_dof_vector(r[l]);
              op.initialize_dof_vector(b[l]);
              op.initialize_dof_vector(x[l]);
              if (l + 1 == n_levels)
                break;
              op.compute_inverse_diagonal();
              typename Smoother::AdditionalData data;
              data.smoothing_range     = 15.;
              data.degree              = 3;
              data.eig_cg_n_iterations = 10;
              data.preconditioner      = op.inverse_diagonal;
              smoothers[l].initialize(op, data);
            }
          set_up_coarse_solve();
          if (n_rigid > 0)
            set_up_rigid_motions();
        }

        /// The load of @p load on the fine grid; the norm of the element
        /// loads (the tolerance's scale).
        double
        assemble_rhs(GridVector<double>              &rhs,
                     const dealii::Tensor<1, 6>      &load,
                     const bool                       strain_driven,
                     const std::vector<VoigtMatrix6> &stiffness) const
        {
          fine.initialize_dof_vector(rhs);
          std::vector<std::array<double, n_dofs>> loads;
          const auto                             &g = levels.grids[0];
          for (unsigned int m = 0; m < levels.matrices[0].size(); ++m)
            loads.push_back(Element::element_load(levels.matrices[0][m],
                                                  entries(stiffness[m]),
                                                  load,
                                                  strain_driven,
                                                  g.h));
          double  scale = 0;
          double *out   = rhs.begin();
          fine.for_each_cell([&](const std::array<std::size_t, n_vertices> &v,
                                 const std::uint32_t                        m,
                                 const std::uint32_t mask,
                                 const std::array<unsigned int, 3> &) {
            for (unsigned int q = 0; q < n_vertices; ++q)
              for (unsigned int c = 0; c < 3; ++c)
                {
                  const double f = loads[m][n_vertices * c + q];
                  scale += f * f;
                  if (!((mask >> (3 * q + c)) & 1u))
                    out[v[q] + c] += f;
                }
          });
          rhs.compress(dealii::VectorOperation::add);
          if (n_rigid > 0)
            project(rhs);
          return std::sqrt(dealii::Utilities::MPI::sum(scale, comm));
        }

        void
        solve(dealii::SolverControl    &control,
              GridVector<double>       &solution,
              const GridVector<double> &rhs) const
        {
          fine.initialize_dof_vector(solution);
          dealii::SolverCG<GridVector<double>> cg(control);
          cg.solve(fine, solution, rhs, *this);
          if (n_rigid > 0)
            project(solution);
        }

        /// CG's preconditioner: one V-cycle (between two projections on
        /// the complement of the rigid motions, for the floating problems).
        void
        vmult(GridVector<double> &dst, const GridVector<double> &src) const
        {
          b[0].copy_locally_owned_data_from(src);
          if (n_rigid > 0)
            project(b[0]);
          vcycle(0);
          dst.copy_locally_owned_data_from(x[0]);
          if (n_rigid > 0)
            project(dst);
        }

        const GridOperator<double> &
        fine_operator() const
        {
          return fine;
        }

      private:
        /// x[l] from b[l].
        void
        vcycle(const unsigned int l) const
        {
          if (l + 1 == levels.grids.size())
            {
              coarse_solve(x[l], b[l]);
              return;
            }
          smoothers[l].vmult(x[l], b[l]);
          operators[l].vmult(r[l], x[l]);
          r[l].sadd(LevelNumber(-1), LevelNumber(1), b[l]);
          restrict_residual(l);
          vcycle(l + 1);
          prolongate_add(l);
          smoothers[l].step(x[l], b[l]);
        }

        /// The trilinear weights of a fine node index @p I's coarse nodes
        /// along one axis: I / 2 (weight 1) if I is even, else (I - 1) / 2
        /// and (I + 1) / 2 (weights 1/2; the second wrapped on the periodic
        /// grid).
        static unsigned int
        parents(const unsigned int I,
                const VoxelGrid   &coarse,
                const unsigned int d,
                unsigned int       index[2],
                LevelNumber        weight[2])
        {
          if (I % 2 == 0)
            {
              index[0]  = I / 2;
              weight[0] = 1;
              return 1;
            }
          index[0]  = I / 2;
          index[1]  = coarse.next(I / 2, d);
          weight[0] = weight[1] = LevelNumber(0.5);
          return 2;
        }

        /// Apply @p f(fine local index, coarse local index, weight) to
        /// every owned fine node and its coarse parents.
        template <class F>
        void
        for_each_parent(const unsigned int l, const F &f) const
        {
          const VoxelGrid &g = levels.grids[l], &c = levels.grids[l + 1];
          for (unsigned int K = g.kb; K < g.ke; ++K)
            {
              unsigned int       kz[2], jy[2], ix[2];
              LevelNumber        wz[2], wy[2], wx[2];
              const unsigned int nz = parents(K, c, 2, kz, wz);
              for (unsigned int J = 0; J < g.nn[1]; ++J)
                {
                  const unsigned int ny = parents(J, c, 1, jy, wy);
                  for (unsigned int I = 0; I < g.nn[0]; ++I)
                    {
                      const unsigned int nx   = parents(I, c, 0, ix, wx);
                      const std::size_t  fine = g.local(I, J, K);
                      for (unsigned int a = 0; a < nz; ++a)
                        for (unsigned int e = 0; e < ny; ++e)
                          for (unsigned int s = 0; s < nx; ++s)
                            f(fine,
                              c.local(ix[s], jy[e], kz[a]),
                              wz[a] * wy[e] * wx[s]);
                    }
                }
            }
        }

        /// b[l + 1] = P^T r[l] (KUBC: zero on the boundary).
        void
        restrict_residual(const unsigned int l) const
        {
          LevelVector &coarse = b[l + 1];
          coarse              = LevelNumber(0);
          coarse.zero_out_ghost_values();
          LevelNumber       *out = coarse.begin();
          const LevelNumber *in  = r[l].begin();
          for_each_parent(l,
                          [&](const std::size_t fine,
                              const std::size_t parent,
                              const LevelNumber w) {
                            for (unsigned int c = 0; c < 3; ++c)
                              out[parent + c] += w * in[fine + c];
                          });
          coarse.compress(dealii::VectorOperation::add);
          for (const std::size_t k : operators[l + 1].constrained_owned)
            for (unsigned int c = 0; c < 3; ++c)
              out[k + c] = 0;
        }

        /// x[l] += P x[l + 1].
        void
        prolongate_add(const unsigned int l) const
        {
          const LevelVector &coarse = x[l + 1];
          coarse.update_ghost_values();
          const LevelNumber *in  = coarse.begin();
          LevelNumber       *out = x[l].begin();
          for_each_parent(l,
                          [&](const std::size_t fine,
                              const std::size_t parent,
                              const LevelNumber w) {
                            for (unsigned int c = 0; c < 3; ++c)
                              out[fine + c] += w * in[parent + c];
                          });
          coarse.zero_out_ghost_values();
        }

        /// The coarsest grid's matrix with its constraints (KUBC: the
        /// boundary; SUBC: pins of the rigid motions; periodic: the
        /// translations at node 0) as identity rows, factorized.
        void
        set_up_coarse_solve()
        {
          const VoxelGrid &c = levels.grids.back();
          coarse_fixed.clear();
          auto dof = [&](unsigned int i,
                         unsigned int j,
                         unsigned int k,
                         unsigned int d) {
            return 3 * ((global_dof_index(k) * c.nn[1] + j) * c.nn[0] + i) + d;
          };
          if (kubc)
            {
              for (unsigned int k = 0; k < c.nn[2]; ++k)
                for (unsigned int j = 0; j < c.nn[1]; ++j)
                  for (unsigned int i = 0; i < c.nn[0]; ++i)
                    if (c.on_boundary(i, j, k))
                      for (unsigned int d = 0; d < 3; ++d)
                        coarse_fixed.push_back(dof(i, j, k, d));
            }
          else
            {
              // node 0 fixed; SUBC also the node on the x axis in y and z
              // and the node on the y axis in z (the rotations)
              for (unsigned int d = 0; d < 3; ++d)
                coarse_fixed.push_back(dof(0, 0, 0, d));
              if (n_rigid == 6)
                {
                  coarse_fixed.push_back(dof(c.n[0], 0, 0, 1));
                  coarse_fixed.push_back(dof(c.n[0], 0, 0, 2));
                  coarse_fixed.push_back(dof(0, c.n[1], 0, 2));
                }
            }
          dealii::FullMatrix<double> A(levels.coarse_matrix);
          for (const global_dof_index f : coarse_fixed)
            for (unsigned int k = 0; k < A.m(); ++k)
              {
                A(f, k) = 0;
                A(k, f) = 0;
              }
          for (const global_dof_index f : coarse_fixed)
            A(f, f) = 1;
          coarse_lu.reinit(A.m());
          coarse_lu = A;
          coarse_lu.compute_lu_factorization();
        }

        void
        coarse_solve(LevelVector &dst, const LevelVector &src) const
        {
          const VoxelGrid       &c     = levels.grids.back();
          const global_dof_index first = c.plane_dofs() * c.kb;
          dealii::Vector<double> full(c.size());
          for (unsigned int k = 0; k < src.locally_owned_size(); ++k)
            full[first + k] = src.local_element(k);
          dealii::Utilities::MPI::sum(full, comm, full);
          for (const global_dof_index f : coarse_fixed)
            full[f] = 0;
          coarse_lu.solve(full);
          for (unsigned int k = 0; k < dst.locally_owned_size(); ++k)
            dst.local_element(k) = LevelNumber(full[first + k]);
        }

        /// The rigid motions (SUBC: translations and rotations about the
        /// box's centre; periodic: translations) and their Gram matrix over
        /// the fine grid's nodes.
        void
        set_up_rigid_motions()
        {
          const VoxelGrid &g = levels.grids[0];
          for (unsigned int d = 0; d < 3; ++d)
            centre[d] = 0.5 * g.n[d] * g.h[d];
          dealii::FullMatrix<double> gram(n_rigid, n_rigid);
          for_each_owned_node([&](const std::size_t, const double *y) {
            double m[6][3];
            rigid_motions(y, m);
            for (unsigned int a = 0; a < n_rigid; ++a)
              for (unsigned int b = 0; b < n_rigid; ++b)
                gram(a, b)
                  += m[a][0] * m[b][0] + m[a][1] * m[b][1] + m[a][2] * m[b][2];
          });
          dealii::Utilities::MPI::sum(
            dealii::ArrayView<const double>(&gram(0, 0), gram.n_elements()),
            comm,
            dealii::ArrayView<double>(&gram(0, 0), gram.n_elements()));
          gram_inverse.reinit(n_rigid, n_rigid);
          gram_inverse.invert(gram);
        }

        /// @p f(local index of component 0, position relative to the
        /// centre) for each owned node of the fine grid.
        template <class F>
        void
        for_each_owned_node(const F &f) const
        {
          const VoxelGrid &g = levels.grids[0];
          for (unsigned int k = g.kb; k < g.ke; ++k)
            for (unsigned int j = 0; j < g.nn[1]; ++j)
              for (unsigned int i = 0; i < g.nn[0]; ++i)
                {
                  const double y[3] = {i * g.h[0] - centre[0],
                                       j * g.h[1] - centre[1],
                                       k * g.h[2] - centre[2]};
                  f(g.local(i, j, k), y);
                }
        }

        /// The rigid motions' values m[k][c] at the position @p y (relative
        /// to the centre): translations e_k, k < 3, and rotations about
        /// axis k - 3, e_axis x y.
        void
        rigid_motions(const double *y, double m[6][3]) const
        {
          for (unsigned int k = 0; k < n_rigid; ++k)
            for (unsigned int c = 0; c < 3; ++c)
              m[k][c] = k == c ? 1. : 0.;
          for (unsigned int k = 3; k < n_rigid; ++k)
            {
              const unsigned int axis = k - 3, a = (axis + 1) % 3,
                                 b = (axis + 2) % 3;
              m[k][a]              = -y[b];
              m[k][b]              = y[a];
            }
        }

        /// v -= R G^-1 R^T v: the l2 projection on the complement of the
        /// rigid motions. R^T v from the sums of v_c and of v_c y_d over
        /// the owned nodes (y the position relative to the centre: the
        /// rotation about axis e, components a = e + 1 and b = e + 2,
        /// gives sum y_a v_b - y_b v_a), the motion to subtract as
        /// t + W y: one pass each, with the coordinates by the rows.
        template <typename Number>
        void
        project(GridVector<Number> &v) const
        {
          const VoxelGrid &g        = levels.grids[0];
          Number          *values   = v.begin();
          double           sums[12] = {}; // S_c, then M_cd = sum v_c y_d
          for (unsigned int k = g.kb; k < g.ke; ++k)
            for (unsigned int j = 0; j < g.nn[1]; ++j)
              {
                const Number *row  = values + g.local(0, j, k);
                double        s[3] = {}, m[3] = {};
                for (unsigned int i = 0; i < g.nn[0]; ++i)
                  {
                    const double y0 = i * g.h[0] - centre[0];
                    for (unsigned int c = 0; c < 3; ++c)
                      {
                        s[c] += row[3 * i + c];
                        m[c] += row[3 * i + c] * y0;
                      }
                  }
                const double y1 = j * g.h[1] - centre[1],
                             y2 = k * g.h[2] - centre[2];
                for (unsigned int c = 0; c < 3; ++c)
                  {
                    sums[c] += s[c];
                    sums[3 + 3 * c] += m[c];
                    sums[4 + 3 * c] += s[c] * y1;
                    sums[5 + 3 * c] += s[c] * y2;
                  }
              }
          dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(sums, 12),
                                      comm,
                                      dealii::ArrayView<double>(sums, 12));
          const auto M = [&](const unsigned int c, const unsigned int d) {
            return sums[3 + 3 * c + d];
          };
          double rt[6] = {sums[0], sums[1], sums[2]};
          for (unsigned int axis = 0; axis + 3 < n_rigid; ++axis)
            {
              const unsigned int a = (axis + 1) % 3, b = (axis + 2) % 3;
              rt[3 + axis] = M(b, a) - M(a, b);
            }
          double alpha[6] = {};
          for (unsigned int p = 0; p < n_rigid; ++p)
            for (unsigned int q = 0; q < n_rigid; ++q)
              alpha[p] += gram_inverse(p, q) * rt[q];
          double W[3][3] = {};
          for (unsigned int axis = 0; axis + 3 < n_rigid; ++axis)
            {
              const unsigned int a = (axis + 1) % 3, b = (axis + 2) % 3;
              W[a][b] -= alpha[3 + axis];
              W[b][a] += alpha[3 + axis];
            }
          for (unsigned int k = g.kb; k < g.ke; ++k)
            for (unsigned int j = 0; j < g.nn[1]; ++j)
              {
                Number      *row = values + g.local(0, j, k);
                const double y1  = j * g.h[1] - centre[1],
                             y2  = k * g.h[2] - centre[2];
                double t[3];
                for (unsigned int c = 0; c < 3; ++c)
                  t[c] = alpha[c] + W[c][1] * y1 + W[c][2] * y2;
                for (unsigned int i = 0; i < g.nn[0]; ++i)
                  {
                    const double y0 = i * g.h[0] - centre[0];
                    for (unsigned int c = 0; c < 3; ++c)
                      row[3 * i + c] -= Number(t[c] + W[c][0] * y0);
                  }
              }
        }

        const VoxelGridLevels                 &levels;
        const MPI_Comm                         comm;
        const bool                             kubc;
        const unsigned int                     n_rigid;
        GridOperator<double>                   fine;
        std::vector<GridOperator<LevelNumber>> operators;
        std::vector<Smoother>                  smoothers;
        mutable std::vector<LevelVector>       r, b, x;
        std::vector<global_dof_index>          coarse_fixed;
        dealii::LAPACKFullMatrix<double>       coarse_lu;
        double                                 centre[3] = {};
        dealii::FullMatrix<double>             gram_inverse;
      };


      /**
       * The averages of one load case from the solution @p u (the
       * fluctuation for KUBC and periodic, the displacement for SUBC): the
       * mean over the voxels of the strain (the cell average of the Q1
       * strain: differences of face means) and of the stress C strain;
       * and the voxels' fields on the @p slices (CellProblem's names and
       * order: stresses, von Mises, strains, material id), summed over the
       * ranks.
       */
      template <class Operator>
      CellLoadCase<3>
      grid_averages(const Operator                  &fine,
                    const VoxelGridLevels           &levels,
                    const std::vector<VoigtMatrix6> &stiffness,
                    const VoxelVolume               &volume,
                    const GridVector<double>        &u,
                    const dealii::Tensor<1, 6>      &load,
                    const bool                       strain_driven,
                    std::vector<FieldSlice>         &slices,
                    const MPI_Comm                   comm)
      {
        const VoxelGrid &g = levels.grids[0];
        for (FieldSlice &s : slices)
          {
            s.names = CellProblem<3>::cell_field_names();
            for (unsigned int d = 0, a = 0; d < 3; ++d)
              if (d != s.plane.axis)
                {
                  s.axes[a] = d;
                  s.n[a]    = g.n[d];
                  ++a;
                }
            s.values.assign(s.names.size(),
                            std::vector<double>(std::size_t(s.n[0]) * s.n[1]));
          }
        u.update_ghost_values();
        const double *in       = u.begin();
        double        sums[12] = {};
        fine.for_each_cell([&](const std::array<std::size_t, n_vertices> &v,
                               const std::uint32_t                        m,
                               const std::uint32_t,
                               const std::array<unsigned int, 3> &cell) {
          double G[3][3] = {};
          for (unsigned int q = 0; q < n_vertices; ++q)
            for (unsigned int c = 0; c < 3; ++c)
              for (unsigned int d = 0; d < 3; ++d)
                G[c][d]
                  += ((q >> d) & 1 ? 0.25 : -0.25) * in[v[q] + c] / g.h[d];
          dealii::Tensor<1, 6> e;
          e[0] = G[0][0];
          e[1] = G[1][1];
          e[2] = G[2][2];
          e[3] = G[1][2] + G[2][1];
          e[4] = G[0][2] + G[2][0];
          e[5] = G[0][1] + G[1][0];
          if (strain_driven)
            e += load;
          const dealii::Tensor<1, 6> s = stiffness[m] * e;
          for (unsigned int i = 0; i < 6; ++i)
            {
              sums[i] += s[i];
              sums[6 + i] += e[i];
            }
          for (FieldSlice &slice : slices)
            if (cell[slice.plane.axis] == slice.plane.index)
              {
                const std::size_t at
                  = cell[slice.axes[0]]
                    + std::size_t(slice.n[0]) * cell[slice.axes[1]];
                const double normal[3] = {s[0], s[1], s[2]};
                const double shear[3]  = {s[3], s[4], s[5]};
                unsigned int f         = 0;
                for (unsigned int a = 0; a < 6; ++a)
                  slice.values[f++][at] = s[a];
                slice.values[f++][at] = von_mises_stress(normal, shear);
                for (unsigned int a = 0; a < 6; ++a)
                  slice.values[f++][at] = e[a];
                slice.values[f][at] = volume.voxel(cell[0], cell[1], cell[2]);
              }
        });
        u.zero_out_ghost_values();
        dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(sums, 12),
                                    comm,
                                    dealii::ArrayView<double>(sums, 12));
        // each voxel is owned by one rank, zero on the others
        for (FieldSlice &slice : slices)
          for (auto &values : slice.values)
            dealii::Utilities::MPI::sum(values, comm, values);
        const double    n_cells = double(g.n[0]) * g.n[1] * g.n[2];
        CellLoadCase<3> result;
        for (unsigned int i = 0; i < 6; ++i)
          {
            result.mean_stress[i] = sums[i] / n_cells;
            result.mean_strain[i] = sums[6 + i] / n_cells;
          }
        return result;
      }
    } // namespace internal


    VoxelGridSolver::VoxelGridSolver(MPI_Comm                         comm,
                                     const VoxelVolume               &volume,
                                     const std::vector<VoigtMatrix6> &stiffness,
                                     const CellSolverParameters &parameters)
        : comm(comm)
        , volume(volume)
        , stiffness(stiffness)
        , parameters(parameters)
    {
      const std::string why = unsupported(volume);
      AssertThrow(why.empty(), dealii::ExcMessage(why));
    }


    VoxelGridSolver::~VoxelGridSolver() = default;


    std::string
    VoxelGridSolver::unsupported(const VoxelVolume &volume)
    {
      std::array<unsigned int, 3> n;
      for (unsigned int d = 0; d < 3; ++d)
        n[d] = volume.n_voxels(d);
      if (internal::n_grids(n) > 0)
        return "";
      std::ostringstream s;
      s << "the voxel grid " << n[0] << " x " << n[1] << " x " << n[2]
        << " does not coarsen to at most " << internal::max_coarse_dofs
        << " unknowns by halving every axis while all are even";
      return s.str();
    }


    bool
    VoxelGridSolver::chosen(const VolumeCellProblemParameters &parameters,
                            const VoxelVolume                 &volume,
                            const bool                         write_fields,
                            std::string                       &why)
    {
      why = parameters.preconditioner != CellPreconditioner::multigrid
              ? "it has no AMG ('Cell problem/Preconditioner = AMG')"
            : write_fields
              ? "it writes no VTU fields ('Output/Write fields = true')"
              : unsupported(volume);
      if (parameters.grid == VolumeGrid::voxel_grid)
        check_parameter(why.empty(),
                        "Cell problem/Grid",
                        "'voxel grid' cannot solve this run: " + why
                          + ". Set it to 'mesh' or 'auto'.");
      return parameters.grid != VolumeGrid::mesh && why.empty();
    }


    dealii::types::global_dof_index
    VoxelGridSolver::n_dofs() const
    {
      return 3 * dealii::types::global_dof_index(volume.n_voxels(0) + 1)
             * (volume.n_voxels(1) + 1) * (volume.n_voxels(2) + 1);
    }


    std::string
    VoxelGridSolver::describe_levels() const
    {
      std::array<unsigned int, 3> n;
      for (unsigned int d = 0; d < 3; ++d)
        n[d] = volume.n_voxels(d);
      std::ostringstream s;
      const unsigned int levels = internal::n_grids(n);
      for (unsigned int l = 0; l < levels; ++l)
        {
          s << (l > 0 ? ", " : "") << n[0] << " x " << n[1] << " x " << n[2];
          for (auto &m : n)
            m /= 2;
        }
      return s.str();
    }


    CellResult<3>
    VoxelGridSolver::solve(const BoundaryCondition        bc,
                           const std::vector<SlicePlane> &slices)
    {
      const auto start    = std::chrono::steady_clock::now();
      const bool periodic = bc == BoundaryCondition::periodic;
      if (!levels)
        levels = std::make_unique<internal::VoxelGridLevels>(comm,
                                                             volume,
                                                             stiffness);
      levels->set_periodic(periodic);
      CellResult<3> result;
      result.boundary_condition = bc;
      result.multigrid          = true;
      const bool strain_driven  = bc != BoundaryCondition::subc;

      auto solve_all = [&](const auto &multigrid) {
        internal::GridVector<double> rhs, solution;
        for (unsigned int load_case = 0; load_case < 6; ++load_case)
          {
            dealii::Tensor<1, 6> load;
            load[load_case] = 1;
            const double scale
              = multigrid.assemble_rhs(rhs, load, strain_driven, stiffness);
            dealii::SolverControl control(parameters.max_iterations,
                                          parameters.solver_tolerance * scale);
            const auto            cg_start = std::chrono::steady_clock::now();
            multigrid.solve(control, solution, rhs);
            std::vector<FieldSlice> sliced;
            if (load_case == 0)
              for (const SlicePlane &plane : slices)
                sliced.push_back({plane, {}, {}, {}, {}});
            CellLoadCase<3> averaged
              = internal::grid_averages(multigrid.fine_operator(),
                                        *levels,
                                        stiffness,
                                        volume,
                                        solution,
                                        load,
                                        strain_driven,
                                        sliced,
                                        comm);
            for (FieldSlice &s : sliced)
              result.slices.push_back(std::move(s));
            averaged.cg_iterations = control.last_step();
            averaged.cg_time       = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - cg_start)
                                 .count();
            result.load_cases[load_case] = averaged;
          }
      };
      if (parameters.multigrid_precision == MultigridPrecision::single)
        solve_all(internal::GridMultigrid<float>(*levels, bc, comm));
      else
        solve_all(internal::GridMultigrid<double>(*levels, bc, comm));

      VoigtMatrix6 M;
      for (unsigned int j = 0; j < 6; ++j)
        for (unsigned int i = 0; i < 6; ++i)
          M[i][j] = strain_driven ? result.load_cases[j].mean_stress[i]
                                  : result.load_cases[j].mean_strain[i];
      result.properties = strain_driven ? volume_properties_from_stiffness(M)
                                        : volume_properties_from_compliance(M);
      result.wall_time  = std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start)
                           .count();
      return result;
    }
  } // namespace homogenization
} // namespace tribodyn
