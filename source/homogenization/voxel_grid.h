// The voxel grids of the 3D cell problems without a mesh (issue #51 item 5;
// voxel_grid_solver.cc): how many grids a volume coarsens to, and one grid
// of the hierarchy on a rank, its nodes and cells found by index
// arithmetic. Internal to voxel_grid_solver.cc.
#ifndef tribodyn_homogenization_voxel_grid_h
#define tribodyn_homogenization_voxel_grid_h

#include "cell_multigrid_operator.h"

#include <array>
#include <cstdint>
#include <deal.II/base/types.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <tribodyn/homogenization/volume_properties.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      using dealii::types::global_dof_index;
      template <typename Number>
      using GridVector = dealii::LinearAlgebra::distributed::Vector<Number>;
      using Element    = ElasticityOperator<3, 1, double>;
      constexpr unsigned int n_vertices = 8;
      constexpr unsigned int n_dofs     = 24;

      /// The coarsest grid's unknowns at most (its dense factorization).
      constexpr global_dof_index max_coarse_dofs = 3000;

      /// The number of grids: every axis halved while all are even and at
      /// least 4 and the grid has more than 1000 unknowns (the last grid
      /// is the coarsest); 0 if the coarsest has more than
      /// max_coarse_dofs.
      inline unsigned int
      n_grids(std::array<unsigned int, 3> n)
      {
        unsigned int levels = 1;
        auto         nodes  = [&]() {
          return global_dof_index(n[0] + 1) * (n[1] + 1) * (n[2] + 1);
        };
        while (3 * nodes() > 1000 && n[0] % 2 == 0 && n[1] % 2 == 0
               && n[2] % 2 == 0 && n[0] >= 4 && n[1] >= 4 && n[2] >= 4)
          {
            for (auto &m : n)
              m /= 2;
            ++levels;
          }
        return 3 * nodes() <= max_coarse_dofs ? levels : 0;
      }

      /// The upper triangle of @p C, as the element matrices take it.
      inline Element::StiffnessEntries
      entries(const VoigtMatrix6 &C)
      {
        Element::StiffnessEntries e;
        for (unsigned int i = 0; i < 6; ++i)
          for (unsigned int j = i; j < 6; ++j)
            e[Element::entry(i, j)] = C[i][j];
        return e;
      }


      /**
       * One grid of the hierarchy on this rank: its cells and nodes, the
       * rank's slab of node planes [kb, ke) and the vector-local index of
       * each node plane it reads (its own and the ghost planes kb - 1 and
       * ke).
       */
      struct VoxelGrid
      {
        std::array<unsigned int, 3> n;  // cells per axis
        std::array<unsigned int, 3> nn; // nodes per axis
        std::array<double, 3>       h;  // cell size
        bool                        periodic = false;
        unsigned int                kb = 0, ke = 0;
        std::shared_ptr<const dealii::Utilities::MPI::Partitioner> partitioner;
        std::vector<std::int64_t>                                  plane_offset;

        /// The grid of @p cells cells per axis, node planes [kb, ke) on this
        /// rank.
        VoxelGrid(const std::array<unsigned int, 3> &cells,
                  const std::array<double, 3>       &size,
                  const bool                         periodic,
                  const unsigned int                 kb,
                  const unsigned int                 ke,
                  const MPI_Comm                     comm)
            : n(cells)
            , h(size)
            , periodic(periodic)
            , kb(kb)
            , ke(ke)
        {
          for (unsigned int d = 0; d < 3; ++d)
            nn[d] = periodic ? n[d] : n[d] + 1;
          const global_dof_index plane = plane_dofs();
          dealii::IndexSet       owned(plane * nn[2]), ghosts(plane * nn[2]);
          owned.add_range(plane * kb, plane * ke);
          std::vector<unsigned int> ghost_planes;
          for (const int p : {int(kb) - 1, int(ke)})
            {
              const int q = periodic ? (p + int(nn[2])) % int(nn[2]) : p;
              if (q >= 0 && q < int(nn[2])
                  && !(unsigned(q) >= kb && unsigned(q) < ke))
                {
                  ghosts.add_range(plane * q, plane * (q + 1));
                  ghost_planes.push_back(q);
                }
            }
          partitioner
            = std::make_shared<dealii::Utilities::MPI::Partitioner>(owned,
                                                                    ghosts,
                                                                    comm);
          plane_offset.assign(nn[2], -1);
          for (unsigned int p = kb; p < ke; ++p)
            plane_offset[p] = std::int64_t(plane) * (p - kb);
          for (const unsigned int q : ghost_planes)
            plane_offset[q] = partitioner->global_to_local(plane * q);
        }

        global_dof_index
        plane_dofs() const
        {
          return 3 * global_dof_index(nn[0]) * nn[1];
        }
        global_dof_index
        size() const
        {
          return plane_dofs() * nn[2];
        }
        /// The node index i + 1 along axis @p d (0 past the periodic end).
        unsigned int
        next(const unsigned int i, const unsigned int d) const
        {
          return i + 1 == nn[d] ? 0 : i + 1;
        }
        /// The owned cell planes: [kb, cells_end()).
        unsigned int
        cells_end() const
        {
          return std::min(ke, n[2]);
        }
        /// Vector-local index of component 0 of node (i, j, k).
        std::size_t
        local(const unsigned int i,
              const unsigned int j,
              const unsigned int k) const
        {
          return plane_offset[k] + 3 * (std::size_t(j) * nn[0] + i);
        }
        /// Whether the node is on the boundary (KUBC's constraints).
        bool
        on_boundary(const unsigned int i,
                    const unsigned int j,
                    const unsigned int k) const
        {
          return !periodic
                 && (i == 0 || j == 0 || k == 0 || i == n[0] || j == n[1]
                     || k == n[2]);
        }
        /// The vector-local indices of a cell's vertices (lexicographic, x
        /// fastest: ElasticityOperator's vertex order).
        std::array<std::size_t, n_vertices>
        vertices(const unsigned int i,
                 const unsigned int j,
                 const unsigned int k) const
        {
          const unsigned int i1 = next(i, 0), j1 = next(j, 1), k1 = next(k, 2);
          return {{local(i, j, k),
                   local(i1, j, k),
                   local(i, j1, k),
                   local(i1, j1, k),
                   local(i, j, k1),
                   local(i1, j, k1),
                   local(i, j1, k1),
                   local(i1, j1, k1)}};
        }
      };
    } // namespace internal
  }   // namespace homogenization
} // namespace tribodyn

#endif
