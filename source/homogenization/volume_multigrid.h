// Geometric multigrid for the cell problems of voxel volumes (issue #51):
// a matrix-free 3D elasticity operator (deal.II's FEEvaluation, one
// constant 6x6 stiffness per cell) on the voxel hierarchy, Chebyshev
// smoothing, a direct solve on the coarsest mesh, as the preconditioner of
// CG. Private to the homogenization sources.
#ifndef tribodyn_source_homogenization_volume_multigrid_h
#define tribodyn_source_homogenization_volume_multigrid_h

#include <deal.II/base/point.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_vector.h>
#include <functional>
#include <memory>
#include <tribodyn/homogenization/volume_properties.h>
#include <utility>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      /// The constraints of a boundary condition on every level: zero
      /// fluctuation on the six faces (KUBC) and pinned components of
      /// vertices (SUBC; vertices of the coarsest mesh, on every level).
      struct VolumeLevelConstraints
      {
        bool zero_boundary = false;
        std::vector<std::pair<dealii::Point<3>, std::vector<unsigned int>>>
          pins;
        /// Distance below which a vertex is the pinned point.
        double tolerance = 0;
      };

      /// The 3D stiffness averaged over a box (lower and upper corners):
      /// the coefficient of a cell on any level of the hierarchy.
      using StiffnessOverBox3D
        = std::function<VoigtMatrix6(const dealii::Point<3> &lower,
                                     const dealii::Point<3> &upper)>;

      /**
       * CG preconditioned by a geometric multigrid V-cycle on the levels
       * of the mesh's refinement hierarchy (one set of constraints, any
       * number of load cases). Operator matrix-free in double precision
       * for CG; the V-cycle in single precision (level operators, Chebyshev
       * smoothing of degree 3 around point Jacobi, transfer), the coarsest
       * level factorized in double (Amesos KLU). The coefficient of a
       * coarse cell is the arithmetic mean of the stiffness of the voxels
       * it covers, as in 2D (cell_multigrid.h).
       */
      class VolumeMultigridSolver
      {
      public:
        virtual ~VolumeMultigridSolver() = default;

        /// Right-hand side of a unit load: -int eps(v) : C E (@p
        /// strain_driven) or int eps(v) : Sigma. Returns the norm of the
        /// unassembled element loads (the scale of the CG tolerance).
        virtual double
        assemble_rhs(const VoigtVector6 &load, const bool strain_driven)
          = 0;

        /// Solve for the last assembled right-hand side; @p solution gets
        /// the locally owned values. Throws SolverControl::NoConvergence.
        virtual void
        solve(dealii::SolverControl                 &control,
              dealii::TrilinosWrappers::MPI::Vector &solution)
          = 0;
      };

      /// The solver on @p dof_handler (multigrid DoFs distributed) with
      /// the active mesh's @p constraints and their description on the
      /// levels.
      std::unique_ptr<VolumeMultigridSolver>
      make_volume_multigrid_solver(
        const dealii::DoFHandler<3>             &dof_handler,
        const dealii::AffineConstraints<double> &constraints,
        const VolumeLevelConstraints            &level_constraints,
        const StiffnessOverBox3D                &stiffness,
        dealii::TimerOutput                     &timer);
    } // namespace internal
  }   // namespace homogenization
} // namespace tribodyn

#endif
