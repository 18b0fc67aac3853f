// The 3D cell problems on a voxel volume without a mesh (issue #51 item 5):
// trilinear elements on the voxel grid, whose nodes, cells and levels are
// found by index arithmetic instead of a deal.II triangulation, DoF handler
// and MatrixFree object per level.
#ifndef tribodyn_homogenization_voxel_grid_solver_h
#define tribodyn_homogenization_voxel_grid_solver_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>
#include <memory>
#include <string>
#include <tribodyn/homogenization/cell_problem.h>
#include <tribodyn/homogenization/voxel_volume.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      struct VoxelGridLevels;
    }

    /**
     * The KUBC, SUBC and periodic cell problems of a voxel volume on its
     * own grid. The unknowns are the three displacement components of the
     * grid's nodes ((n_x + 1)(n_y + 1)(n_z + 1) nodes; n_x n_y n_z for
     * periodic conditions, whose upper faces are the lower ones), numbered
     * x fastest, then y, then z, component innermost. The ranks own slabs of
     * node planes along z (each rank's ghosts are the planes next to its
     * slab: its neighbours'). The discretization is that of the mesh path
     * (CellProblem<3> with Q1 elements: the same element matrices, the same
     * constants to the solver tolerance); the solver is CG preconditioned by
     * a geometric multigrid V-cycle on the grids of 2^l voxels, Galerkin
     * coarse operators, Chebyshev smoothing (degree 3) around point Jacobi
     * in single precision, and a dense factorization of the coarsest grid;
     * the floating SUBC and periodic problems are solved in the complement
     * of their rigid motions (pins on the coarsest grid only), as on the
     * mesh.
     *
     * The finest grid's product goes node by node (each node's 27-node
     * stencil, one of the few hundred configurations of its eight cells'
     * phases), the coarser grids' cell by cell.
     *
     * What it keeps: per level the cells' element-matrix index (4 B per
     * cell) and the distinct element matrices; per node of the finest grid
     * its stencil's index (4 B) and the stencils; the vectors of CG
     * (double) and of the V-cycle (float). No triangulation, DoF tables or
     * index arrays per cell.
     */
    class VoxelGridSolver
    {
    public:
      /// @p stiffness: the Voigt stiffness of each material id.
      VoxelGridSolver(MPI_Comm                         comm,
                      const VoxelVolume               &volume,
                      const std::vector<VoigtMatrix6> &stiffness,
                      const CellSolverParameters      &parameters);
      ~VoxelGridSolver();

      /// Empty if the volume's grid coarsens to a small one (each axis
      /// halved while all are even, to at most a few thousand coarse
      /// DoFs), else why it does not.
      static std::string
      unsupported(const VoxelVolume &volume);

      /**
       * Whether a run of @p parameters on @p volume solves on the voxel
       * grid ('Cell problem/Grid': 'auto' takes it where it can: multigrid,
       * a grid that coarsens, no VTU fields, @p write_fields false). When
       * it takes the mesh, @p why says why the grid cannot; 'Grid = voxel
       * grid' on such a run is refused (InputError naming the entry).
       */
      static bool
      chosen(const VolumeCellProblemParameters &parameters,
             const VoxelVolume                 &volume,
             const bool                         write_fields,
             std::string                       &why);

      /// The six load cases of @p bc: averages, CG counts and times, and
      /// the fields of the first load case on @p slices.
      CellResult<3>
      solve(BoundaryCondition bc, const std::vector<SlicePlane> &slices = {});

      /// The unknowns of the non-periodic grid (the periodic one has
      /// fewer: its upper faces are the lower ones).
      dealii::types::global_dof_index
      n_dofs() const;

      /// The levels' node counts per axis, finest first, for the log.
      std::string
      describe_levels() const;

    private:
      MPI_Comm                                   comm;
      const VoxelVolume                         &volume;
      std::vector<VoigtMatrix6>                  stiffness;
      CellSolverParameters                       parameters;
      std::unique_ptr<internal::VoxelGridLevels> levels;
    };
  } // namespace homogenization
} // namespace tribodyn

#endif
