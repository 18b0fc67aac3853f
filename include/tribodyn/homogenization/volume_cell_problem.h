#ifndef tribodyn_homogenization_volume_cell_problem_h
#define tribodyn_homogenization_volume_cell_problem_h

#include <Epetra_MultiVector.h>
#include <array>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <memory>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/homogenization/cell_problem.h>
#include <tribodyn/homogenization/volume_properties.h>
#include <tribodyn/homogenization/voxel_volume.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    /// Parameters of the subsection "Cell problem" of the 3D problem.
    struct VolumeCellProblemParameters
    {
      std::vector<BoundaryCondition> boundary_conditions
        = {BoundaryCondition::kubc, BoundaryCondition::subc};
      double             solver_tolerance = 1e-10;
      unsigned int       max_iterations   = 2000;
      CellPreconditioner preconditioner   = CellPreconditioner::amg;

      /// The entries of "Cell problem", bound to the members above.
      ParameterBinding
      binding();

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// Volume averages of one 3D load case.
    struct VolumeLoadCaseResult
    {
      VoigtVector6 mean_stress; ///< <sigma> (Pa), Voigt order
      VoigtVector6 mean_strain; ///< <eps>, engineering shears
      unsigned int cg_iterations = 0;
    };

    /// The six load cases of one boundary condition and what follows.
    struct VolumeCellProblemResult
    {
      BoundaryCondition                   boundary_condition;
      std::array<VolumeLoadCaseResult, 6> load_cases;
      VolumeProperties                    properties;
      /// Wall time of the setup (assembly and AMG, or multigrid) and the
      /// six solves (s).
      double wall_time = 0;
      /// Whether CG was preconditioned by geometric multigrid (else AMG).
      bool multigrid = false;
    };

    /**
     * The cell problems of a voxel volume: 3D linear elasticity, one
     * trilinear (Q1) hexahedron per voxel with the voxel's phase, six unit
     * load cases per boundary condition. As in 2D, the strain-driven
     * conditions (KUBC, periodic) solve for the fluctuation w in u = E x +
     * w, SUBC for u with the load int eps(v) : Sigma and the six rigid
     * motions removed by pinning three corners. Every cell is the same
     * box, so the element matrix and loads are computed once per phase.
     * Solver: CG preconditioned by ML's smoothed-aggregation AMG on the
     * assembled matrix with the six rigid-body modes as near-null space
     * (default), or, for KUBC and SUBC with 'Cell problem/Preconditioner =
     * multigrid', by geometric multigrid on the voxel hierarchy
     * (matrix-free, volume_multigrid.h; a first version, slower than AMG
     * on the volumes measured: doc/theory/homogenization.md).
     */
    class VolumeCellProblem
    {
    public:
      VolumeCellProblem(const MPI_Comm                     comm,
                        const VoxelVolume                 &volume,
                        const std::vector<VoigtMatrix6>   &stiffness,
                        const VolumeCellProblemParameters &parameters,
                        dealii::TimerOutput               &timer);

      /// Solve the six load cases of @p bc.
      VolumeCellProblemResult
      solve(const BoundaryCondition bc);

      dealii::types::global_dof_index
      n_dofs() const;
      dealii::types::global_cell_index
      n_cells() const;
      /// Volume fraction of each material id, measured on the mesh.
      std::vector<double>
      phase_fractions() const;
      /// Whether the problem of @p bc is solved with geometric multigrid.
      bool
      uses_multigrid(const BoundaryCondition bc) const;

    private:
      /// The coarsest box mesh whose cells are 2^L voxels wide along every
      /// axis, refined L times (one element per voxel); periodic faces
      /// registered when @p periodic.
      void
      setup_mesh(const bool periodic);
      void
      setup_dofs();
      void
      make_constraints(const BoundaryCondition bc);
      void
      assemble(const BoundaryCondition bc);
      void
      setup_preconditioner();
      /// DoFs of the coarsest mesh.
      unsigned int
      n_coarse_dofs() const;
      /// The pinned vertices of @p bc and their components.
      std::vector<std::pair<dealii::Point<3>, std::vector<unsigned int>>>
      pinned_vertices(const BoundaryCondition bc) const;
      /// Solve the six load cases with geometric multigrid (@p solutions
      /// get the locally owned values, @p result the iteration counts).
      void
      solve_with_multigrid(
        const BoundaryCondition                               bc,
        std::array<dealii::TrilinosWrappers::MPI::Vector, 6> &solutions,
        VolumeCellProblemResult                              &result);
      /// The same with AMG on the assembled matrix.
      void
      solve_with_amg(
        const BoundaryCondition                               bc,
        std::array<dealii::TrilinosWrappers::MPI::Vector, 6> &solutions,
        VolumeCellProblemResult                              &result);
      /// The element matrix, the element loads of the six unit loads (per
      /// phase) and the integrals of the strain of each shape function.
      void
      compute_element_data(const BoundaryCondition bc);

      MPI_Comm                          mpi_communicator;
      const VoxelVolume                &volume;
      const std::vector<VoigtMatrix6>   stiffness;
      const VolumeCellProblemParameters parameters;
      dealii::TimerOutput              &timer;
      dealii::ConditionalOStream        pcout;

      std::array<unsigned int, 3> n_coarse_cells   = {{0, 0, 0}};
      unsigned int                n_voxel_levels   = 0;
      bool                        mesh_is_periodic = false;

      dealii::parallel::distributed::Triangulation<3> triangulation;
      dealii::FESystem<3>                             fe;
      dealii::DoFHandler<3>                           dof_handler;
      dealii::IndexSet                                locally_owned_dofs;
      dealii::IndexSet                                locally_relevant_dofs;
      dealii::AffineConstraints<double>               constraints;
      dealii::TrilinosWrappers::SparseMatrix          system_matrix;
      std::array<dealii::TrilinosWrappers::MPI::Vector, 6> system_rhs;
      std::array<double, 6>                                load_scale;
      dealii::TrilinosWrappers::PreconditionAMG            preconditioner;
      std::unique_ptr<Epetra_MultiVector>                  rigid_body_modes;

      /// Per phase: the 24 x 24 element matrix and the six element loads.
      std::vector<dealii::FullMatrix<double>>            element_matrix;
      std::vector<std::array<dealii::Vector<double>, 6>> element_load;
      /// Integral over the element of the Voigt strain of each shape
      /// function: 6 x 24 (the same for every element).
      dealii::FullMatrix<double> strain_integral;
    };
  } // namespace homogenization
} // namespace tribodyn

#endif
