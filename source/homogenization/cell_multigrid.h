// Geometric multigrid for the cell problems (issue #19 item 4, #51): a
// matrix-free elasticity operator on the pixel (voxel) hierarchy,
// Chebyshev smoothing and a direct solve on the coarsest mesh, as the
// preconditioner of CG. Private to the homogenization sources.
#ifndef tribodyn_source_homogenization_cell_multigrid_h
#define tribodyn_source_homogenization_cell_multigrid_h

#include <deal.II/base/point.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_vector.h>
#include <functional>
#include <memory>
#include <tribodyn/homogenization/cell_problem.h>
#include <utility>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      /// The constraints of a boundary condition, on every level: zero
      /// fluctuation on the whole boundary (KUBC), pinned components of
      /// single vertices (SUBC: vertices of the coarsest mesh, so on every
      /// level; periodic: one vertex of the active mesh), and periodicity
      /// (the triangulation's periodic faces: on every level the DoFs of a
      /// vertex on an upper face equal those of its image on the lower
      /// faces x_d = 0, as DoFTools::make_periodicity_constraints() makes
      /// them on the active mesh).
      template <int dim>
      struct LevelConstraintDescription
      {
        bool zero_boundary = false;
        bool periodic      = false;
        /// The pinned vertices and their components.
        std::vector<std::pair<dealii::Point<dim>, std::vector<unsigned int>>>
          pins;
        /// The pins of the coarsest level where they are not @p pins (the
        /// periodic problem's pin need not be a vertex of the coarsest
        /// mesh): empty = @p pins.
        std::vector<std::pair<dealii::Point<dim>, std::vector<unsigned int>>>
          coarse_pins;
        /// Distance below which a vertex is the pinned point.
        double tolerance = 0;
      };

      /// Voigt stiffness averaged over a box of the cell (lower and upper
      /// corners): the coefficient of a cell on any level of the
      /// hierarchy.
      template <int dim>
      using StiffnessOverBox
        = std::function<dealii::Tensor<2, CellTraits<dim>::n_voigt>(
          const dealii::Point<dim> &,
          const dealii::Point<dim> &)>;

      /**
       * CG preconditioned by a geometric multigrid V-cycle, for one set of
       * constraints (one boundary condition) and any number of load cases.
       * The operator is applied matrix-free (deal.II's MatrixFree with one
       * constant stiffness per cell); the levels are those of the mesh's
       * refinement hierarchy: multilinear elements with Galerkin coarse
       * operators (cell_multigrid_galerkin.h), other degrees with the
       * coefficient of a coarse cell the arithmetic mean of the fine cells
       * it covers; pins (SUBC) on the coarsest level only, the finer ones
       * and CG solving the floating problem with the rigid motions
       * projected out (multilinear elements); Chebyshev smoothing
       * (degree 3) around point Jacobi; the coarsest level solved directly
       * (Amesos KLU). Multilinear elements take a fast path: one element
       * matrix (8 x 8 in 2D, 24 x 24 in 3D) per distinct stiffness,
       * applied cell by cell.
       */
      template <int dim>
      class CellMultigridSolver
      {
      public:
        virtual ~CellMultigridSolver() = default;

        /// Right-hand side of a unit load: -int eps(v) : C E for the
        /// macroscopic strain E (@p strain_driven) or int eps(v) : Sigma
        /// for the macroscopic stress Sigma. Returns the norm of the
        /// unassembled element loads (the scale of the CG tolerance).
        virtual double
        assemble_rhs(const dealii::Tensor<1, CellTraits<dim>::n_voigt> &load,
                     const bool strain_driven)
          = 0;

        /// Solve for the last assembled right-hand side; @p solution gets
        /// the locally owned values (constraints not yet distributed).
        /// Throws SolverControl::NoConvergence.
        virtual void
        solve(dealii::SolverControl                 &control,
              dealii::TrilinosWrappers::MPI::Vector &solution)
          = 0;
      };

      /// What the boundary conditions of one mesh can share: the matrix-free
      /// objects of the bilinear fast path (active mesh and levels), which
      /// hold no constraints (the operator applies them). Opaque; reset it
      /// when the mesh or its DoFs change.
      struct MultigridCache
      {
        virtual ~MultigridCache() = default;
      };

      /// The solver for elements of degree @p fe_degree (1 to 4 in 2D, 1 in
      /// 3D) on @p dof_handler (multigrid DoFs distributed), with the
      /// active level's @p constraints and the description of the same
      /// constraints on the levels; the V-cycle in single precision when
      /// @p single_precision (CG in double either way). @p cache is filled
      /// by the first call and reused by the next ones on the same DoFs.
      template <int dim>
      std::unique_ptr<CellMultigridSolver<dim>>
      make_cell_multigrid_solver(
        const unsigned int                       fe_degree,
        const bool                               single_precision,
        std::shared_ptr<MultigridCache>         &cache,
        const dealii::DoFHandler<dim>           &dof_handler,
        const dealii::AffineConstraints<double> &constraints,
        const LevelConstraintDescription<dim>   &level_constraints,
        const StiffnessOverBox<dim>             &stiffness,
        dealii::TimerOutput                     &timer);
    } // namespace internal
  }   // namespace homogenization
} // namespace tribodyn

#endif
