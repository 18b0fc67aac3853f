#ifndef tribodyn_homogenization_cell_problem_h
#define tribodyn_homogenization_cell_problem_h

#include <array>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/data_out.h>
#include <memory>
#include <string>
#include <tribodyn/core/material.h>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/homogenization/effective_properties.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      struct MultigridCache; // source/homogenization/cell_multigrid.h
    }

    /// The boundary conditions of a cell problem.
    enum class BoundaryCondition
    {
      kubc,    ///< kinematic uniform: u = E x on the whole boundary
      subc,    ///< static uniform: t = Sigma n on the whole boundary
      periodic ///< u = E x + w, w periodic
    };

    /// "KUBC", "SUBC", "periodic": the names used in prm files and outputs.
    std::string
    to_string(const BoundaryCondition bc);

    /// The condition named @p name ("KUBC", "SUBC" or "periodic", as
    /// to_string() writes it; the caller's pattern has checked it).
    BoundaryCondition
    boundary_condition_named(const std::string &name);

    /// Preconditioners of the cell problems' CG.
    enum class CellPreconditioner
    {
      multigrid, ///< geometric multigrid on the pixel hierarchy, matrix-free
      amg        ///< Trilinos ML algebraic multigrid on the assembled matrix
    };

    /// Floating-point precision of the multigrid V-cycle (CG itself is
    /// always in double precision).
    enum class MultigridPrecision
    {
      single, ///< levels, smoother and transfer in float: half the traffic
      double_ ///< everything in double
    };

    /// Add the entry "Boundary conditions" (a list of KUBC, SUBC,
    /// periodic) bound to @p boundary_conditions: the 2D and the 3D cell
    /// problems declare it alike.
    void
    add_boundary_conditions_entry(
      ParameterBinding               &b,
      std::vector<BoundaryCondition> &boundary_conditions);

    /// Add the entries "Solver tolerance" and "Max iterations" of CG.
    void
    add_cg_entries(ParameterBinding &b,
                   double           &solver_tolerance,
                   unsigned int     &max_iterations);

    /// Parameters of the subsection "Cell problem".
    struct CellProblemParameters
    {
      std::vector<BoundaryCondition> boundary_conditions
        = {BoundaryCondition::kubc, BoundaryCondition::subc};
      /// Finite elements per pixel of the morphology along each axis.
      unsigned int subdivisions_per_pixel = 1;
      /// Global refinements of that mesh.
      unsigned int global_refinements = 0;
      /// Polynomial degree of the Lagrange elements.
      unsigned int fe_degree = 1;
      /// Tolerance of CG: residual relative to the norm of the unassembled
      /// element loads.
      double             solver_tolerance    = 1e-10;
      unsigned int       max_iterations      = 2000;
      CellPreconditioner preconditioner      = CellPreconditioner::multigrid;
      MultigridPrecision multigrid_precision = MultigridPrecision::single;

      /// The entries of "Cell problem", bound to the members above (their
      /// initial values are the defaults).
      ParameterBinding
      binding();

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// Volume averages of one load case.
    struct LoadCaseResult
    {
      VoigtVector  mean_stress;        ///< <sigma> (Pa), (xx, yy, xy)
      VoigtVector  mean_strain;        ///< <eps>, (xx, yy, gamma_xy)
      double       mean_stress_zz = 0; ///< <sigma_zz> (Pa), plane strain
      unsigned int cg_iterations  = 0;
    };

    /// The three load cases of one boundary condition and what follows.
    struct CellProblemResult
    {
      BoundaryCondition             boundary_condition;
      std::array<LoadCaseResult, 3> load_cases;
      ApparentProperties            properties;
    };

    /**
     * The cell problem of a 2D composite in plane strain: linear
     * elasticity with one phase per material id (isotropic or
     * transversely isotropic), three unit load
     * cases per boundary condition. Strain-driven conditions (KUBC,
     * periodic) solve for the fluctuation w in u = E x + w; the stress-driven
     * one (SUBC) solves for u with the load written as the volume term
     * int eps(v) : Sigma (equal to the boundary work of t = Sigma n).
     * CG preconditioned by geometric multigrid (matrix-free, on the mesh's
     * refinement hierarchy down to the coarsest mesh whose cells are
     * 2^L pixels wide) or by ML AMG (rigid-body modes as near-null space);
     * one preconditioner per boundary condition, reused for its three load
     * cases.
     */
    class CellProblem
    {
    public:
      CellProblem(const MPI_Comm                   comm,
                  const Morphology                &morphology,
                  const std::vector<ElasticPhase> &phases,
                  const CellProblemParameters     &parameters,
                  dealii::TimerOutput             &timer);

      /// Solve the three load cases of @p bc. When @p output_directory is
      /// not empty, write the fields of each load case there
      /// (fields_<BC>.pvd indexing fields_<BC>_<case>.vtu).
      CellProblemResult
      solve(const BoundaryCondition bc,
            const std::string      &output_directory = "");

      /// Write the material map (morphology.vtu).
      void
      write_material_map(const std::string &output_directory) const;

      dealii::types::global_dof_index
      n_dofs() const;
      /// Whether CG is preconditioned by geometric multigrid ('Preconditioner
      /// = multigrid' and a coarsest mesh of at most max_coarse_dofs DoFs).
      bool
      uses_multigrid() const;
      /// Whether the problem of @p bc is solved with multigrid: KUBC and
      /// SUBC when uses_multigrid(); periodic problems always use AMG.
      bool
      uses_multigrid(const BoundaryCondition bc) const;
      /// Levels of the multigrid hierarchy (0 with AMG).
      unsigned int
      n_multigrid_levels() const;
      /// The largest coarsest level that multigrid solves directly.
      static constexpr unsigned int max_coarse_dofs = 50000;
      dealii::types::global_cell_index
      n_cells() const;
      /// Area fraction of each material id, measured on the mesh.
      std::vector<double>
      phase_fractions() const;

    private:
      /// The mesh: the coarsest rectangle grid whose cells are 2^L times
      /// the element size, refined L + 'Global refinements' times, with
      /// periodic faces registered when @p periodic.
      void
      setup_mesh(const bool periodic);
      void
      setup_dofs();
      /// The pinned vertices of @p bc (rigid motions of SUBC, the
      /// translation of periodic): for SUBC vertices of the coarsest mesh
      /// (present on every multigrid level), for periodic the interior
      /// vertex nearest to the centre.
      std::vector<std::pair<dealii::Point<2>, std::vector<unsigned int>>>
      pinned_vertices(const BoundaryCondition bc) const;
      /// DoFs of the coarsest mesh.
      unsigned int
      n_coarse_dofs() const;
      /// Element size along x and y of the active mesh.
      std::array<double, 2>
      element_size() const;
      /// Solve the three load cases with geometric multigrid: fills the
      /// solutions and the iteration counts.
      void
      solve_with_multigrid(
        const BoundaryCondition                               bc,
        std::array<dealii::TrilinosWrappers::MPI::Vector, 3> &solutions,
        CellProblemResult                                    &result);
      /// The same with AMG on the assembled matrix.
      void
      solve_with_amg(
        const BoundaryCondition                               bc,
        std::array<dealii::TrilinosWrappers::MPI::Vector, 3> &solutions,
        CellProblemResult                                    &result);
      void
      make_constraints(const BoundaryCondition bc);
      void
      assemble(const BoundaryCondition bc);
      void
      setup_preconditioner();
      /// Volume averages of the three load cases, in one pass over the
      /// cells.
      std::array<LoadCaseResult, 3>
      postprocess(
        const BoundaryCondition bc,
        const std::array<dealii::LinearAlgebra::distributed::Vector<double>, 3>
          &solutions) const;
      void
      write_fields(const BoundaryCondition                      bc,
                   const unsigned int                           load_case,
                   const dealii::TrilinosWrappers::MPI::Vector &solution,
                   const std::string &output_directory) const;

      /// Macroscopic strain (strain-driven) or stress (SUBC) of a load case.
      static VoigtVector
      unit_load(const unsigned int load_case);

      MPI_Comm          mpi_communicator;
      const Morphology &morphology;
      /// The phases by material id (a copy: callers may pass temporaries).
      const std::vector<ElasticPhase> phases;
      const CellProblemParameters     parameters;
      dealii::TimerOutput            &timer;
      dealii::ConditionalOStream      pcout;

      /// Coarse cells along x and y, and the refinements L from the coarse
      /// mesh to the elements of 'Subdivisions per pixel'.
      std::array<unsigned int, 2> n_coarse_cells   = {{0, 0}};
      unsigned int                n_pixel_levels   = 0;
      bool                        mesh_is_periodic = false;

      dealii::parallel::distributed::Triangulation<2> triangulation;
      dealii::FESystem<2>                             fe;
      dealii::DoFHandler<2>                           dof_handler;
      dealii::IndexSet                                locally_owned_dofs;
      dealii::IndexSet                                locally_relevant_dofs;

      dealii::AffineConstraints<double>                    constraints;
      dealii::TrilinosWrappers::SparseMatrix               system_matrix;
      std::array<dealii::TrilinosWrappers::MPI::Vector, 3> system_rhs;
      /// Norm of the unassembled element loads of each load case: the
      /// scale of the CG tolerance. The assembled right-hand side cancels
      /// between elements (to round-off for a single phase), so it is no
      /// scale for the accuracy of the averages.
      std::array<double, 3>                     load_scale;
      dealii::TrilinosWrappers::PreconditionAMG preconditioner;
      /// Near-null space of the AMG; must outlive the preconditioner setup.
      std::unique_ptr<Epetra_MultiVector> rigid_body_modes;
      /// What the multigrid solvers of the boundary conditions share;
      /// reset with the DoFs.
      std::shared_ptr<internal::MultigridCache> multigrid_cache;
    };
  } // namespace homogenization
} // namespace tribodyn

#endif
