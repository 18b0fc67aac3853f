#ifndef tribodyn_homogenization_cell_problem_h
#define tribodyn_homogenization_cell_problem_h

#include <Epetra_MultiVector.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <functional>
#include <memory>
#include <string>
#include <tribodyn/core/material.h>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/homogenization/effective_properties.h>
#include <tribodyn/homogenization/volume_properties.h>
#include <tribodyn/homogenization/voxel_volume.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      struct MultigridCache; // source/homogenization/cell_multigrid.h

      /// Integrals over one element of the strain, the stress (Voigt
      /// vectors of @p n_voigt entries) and, in plane strain, sigma_zz of a
      /// load case.
      template <unsigned int n_voigt>
      struct ElementIntegrals
      {
        dealii::Tensor<1, n_voigt> strain;
        dealii::Tensor<1, n_voigt> stress;
        double                     stress_zz = 0;
        double                     measure   = 0;
      };
    } // namespace internal

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

    /// How a 3D volume's cell problems are discretized (`Cell problem/Grid`;
    /// the same Q1 elements either way).
    enum class VolumeGrid
    {
      automatic, ///< the voxel grid where it can, else the mesh
      mesh,      ///< a deal.II triangulation of the voxels (CellProblem<3>)
      voxel_grid ///< the voxel grid by index arithmetic (VoxelGridSolver)
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

    /// What the cell problems of both dimensions are solved with: the
    /// entries of the subsection "Cell problem" (the 3D problem declares a
    /// subset, VolumeCellProblemParameters).
    struct CellSolverParameters
    {
      std::vector<BoundaryCondition> boundary_conditions
        = {BoundaryCondition::kubc, BoundaryCondition::subc};
      /// Finite elements per pixel of the morphology along each axis (2D).
      unsigned int subdivisions_per_pixel = 1;
      /// Global refinements of that mesh (2D).
      unsigned int global_refinements = 0;
      /// Polynomial degree of the Lagrange elements (2D; 1 in 3D).
      unsigned int fe_degree = 1;
      /// Tolerance of CG: residual relative to the norm of the unassembled
      /// element loads.
      double             solver_tolerance    = 1e-10;
      unsigned int       max_iterations      = 2000;
      CellPreconditioner preconditioner      = CellPreconditioner::multigrid;
      MultigridPrecision multigrid_precision = MultigridPrecision::single;
    };

    /// Parameters of the subsection "Cell problem" of the 2D problem.
    struct CellProblemParameters : CellSolverParameters
    {
      /// The entries of "Cell problem", bound to the members above (their
      /// initial values are the defaults).
      ParameterBinding
      binding();

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// Parameters of the subsection "Cell problem" of the 3D problem: one
    /// trilinear element per voxel, so no subdivisions, refinements or
    /// degree.
    struct VolumeCellProblemParameters : CellSolverParameters
    {
      /// Cell problem/Grid.
      VolumeGrid grid = VolumeGrid::automatic;

      /// The entries of "Cell problem", bound to the members above.
      ParameterBinding
      binding();

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /**
     * What distinguishes the cell problems of the two dimensions, and only
     * that: the geometry (a 2D morphology of pixels, a 3D volume of
     * voxels), how a phase gives its Voigt stiffness, and the apparent
     * properties that the averages make. Voigt vectors have
     * n_voigt = dim (dim + 1) / 2 entries: (xx, yy, xy) in 2D, (xx, yy, zz,
     * yz, xz, xy) in 3D, strains with engineering shears.
     */
    template <int dim>
    struct CellTraits;

    template <>
    struct CellTraits<2>
    {
      static constexpr unsigned int n_voigt = 3;
      using Geometry                        = Morphology;
      /// A phase in plane strain: its in-plane stiffness C and the row c_z
      /// of sigma_zz.
      using Phase      = ElasticPhase;
      using Properties = ApparentProperties;

      static const VoigtMatrix &
      stiffness(const Phase &phase)
      {
        return phase.C;
      }
      static double
      extent(const Geometry &morphology, const unsigned int axis)
      {
        return axis == 0 ? morphology.width() : morphology.height();
      }
      /// Elements along @p axis before the global refinements.
      static unsigned int
      n_elements(const Geometry             &morphology,
                 const CellSolverParameters &parameters,
                 const unsigned int          axis)
      {
        return (axis == 0 ? morphology.n_pixels_x() : morphology.n_pixels_y())
               * parameters.subdivisions_per_pixel;
      }
      static unsigned int
      material_at(const Geometry &morphology, const dealii::Point<2> &p)
      {
        return morphology.material_at(p);
      }
    };

    template <>
    struct CellTraits<3>
    {
      static constexpr unsigned int n_voigt = 6;
      using Geometry                        = VoxelVolume;
      /// A phase: its 6 x 6 Voigt stiffness.
      using Phase      = VoigtMatrix6;
      using Properties = VolumeProperties;

      static const VoigtMatrix6 &
      stiffness(const Phase &phase)
      {
        return phase;
      }
      static double
      extent(const Geometry &volume, const unsigned int axis)
      {
        return volume.length(axis);
      }
      static unsigned int
      n_elements(const Geometry &volume,
                 const CellSolverParameters &,
                 const unsigned int axis)
      {
        return volume.n_voxels(axis);
      }
      /// The material of the voxel that holds @p p (clamped at the far
      /// faces).
      static unsigned int
      material_at(const Geometry &volume, const dealii::Point<3> &p)
      {
        unsigned int index[3];
        for (unsigned int d = 0; d < 3; ++d)
          index[d]
            = std::min(volume.n_voxels(d) - 1,
                       static_cast<unsigned int>(p[d] / volume.voxel_size(d)));
        return volume.voxel(index[0], index[1], index[2]);
      }
    };

    /// Volume averages of one load case.
    template <int dim>
    struct CellLoadCase
    {
      /// <sigma> (Pa), Voigt order
      dealii::Tensor<1, CellTraits<dim>::n_voigt> mean_stress;
      /// <eps>, engineering shears
      dealii::Tensor<1, CellTraits<dim>::n_voigt> mean_strain;
      /// <sigma_zz> (Pa) of plane strain (2D only)
      double       mean_stress_zz = 0;
      unsigned int cg_iterations  = 0;
      /// Wall time of its CG solve (s; the preconditioner's setup and the
      /// right-hand side not included).
      double cg_time = 0;
    };

    /// A plane of elements: the axis it is normal to and the index of its
    /// layer of elements along that axis (3D: a slice of the voxels).
    struct SlicePlane
    {
      unsigned int axis  = 2;
      unsigned int index = 0;
    };

    /// The cell fields of one load case (those of the VTU output, the
    /// averages over each element) on a plane of elements.
    struct FieldSlice
    {
      SlicePlane plane;
      /// The two axes along the plane, in increasing order, and the
      /// number of elements along each.
      std::array<unsigned int, 2> axes = {{0, 1}};
      std::array<unsigned int, 2> n    = {{0, 0}};
      /// The fields' names (as in the VTU: stress_xx, ..., von_mises,
      /// strain_xx, ..., material_id).
      std::vector<std::string> names;
      /// values[f][a + n[0] b]: field f of the element at index a along
      /// axes[0] and b along axes[1].
      std::vector<std::vector<double>> values;
    };

    /// The von Mises stress of the normal stresses @p normal (xx, yy, zz)
    /// and the shears @p shear (yz, xz, xy).
    inline double
    von_mises_stress(const double normal[3], const double shear[3])
    {
      return std::sqrt(0.5
                         * ((normal[0] - normal[1]) * (normal[0] - normal[1])
                            + (normal[1] - normal[2]) * (normal[1] - normal[2])
                            + (normal[2] - normal[0]) * (normal[2] - normal[0]))
                       + 3
                           * (shear[0] * shear[0] + shear[1] * shear[1]
                              + shear[2] * shear[2]));
    }

    /// The load cases of one boundary condition (one per Voigt component)
    /// and what follows from them.
    template <int dim>
    struct CellResult
    {
      BoundaryCondition boundary_condition;
      std::array<CellLoadCase<dim>, CellTraits<dim>::n_voigt> load_cases;
      typename CellTraits<dim>::Properties                    properties;
      /// Wall time of the setup (assembly and AMG, or multigrid) and the
      /// solves (s).
      double wall_time = 0;
      /// Whether CG was preconditioned by geometric multigrid (else AMG).
      bool multigrid = false;
      /// The cell fields of the first load case on the planes solve() was
      /// asked for.
      std::vector<FieldSlice> slices;

      /// The CG iterations and the CG wall time (s) of the load cases,
      /// summed.
      unsigned int
      cg_iterations() const
      {
        unsigned int n = 0;
        for (const auto &lc : load_cases)
          n += lc.cg_iterations;
        return n;
      }
      double
      cg_time() const
      {
        double t = 0;
        for (const auto &lc : load_cases)
          t += lc.cg_time;
        return t;
      }
    };

    using LoadCaseResult = CellLoadCase<2>;
    /// A load case as solve() hands it to its observer: the solution of
    /// load case @p load_case of boundary condition @p bc (the fluctuation
    /// w, or the displacement under SUBC, with its ghosts) and its cell
    /// fields (CellProblem::cell_field_names(), one value per active cell).
    template <int dim>
    struct LoadCaseFields
    {
      BoundaryCondition                                         bc;
      unsigned int                                              load_case;
      const dealii::LinearAlgebra::distributed::Vector<double> &field;
      const std::vector<dealii::Vector<float>>                 &values;
    };

    using CellProblemResult       = CellResult<2>;
    using VolumeLoadCaseResult    = CellLoadCase<3>;
    using VolumeCellProblemResult = CellResult<3>;

    /**
     * The cell problem of a composite: linear elasticity with one phase
     * per material id, one unit load case per Voigt component and
     * boundary condition; in 2D in plane strain on the pixels of a
     * morphology (elements of any degree, optionally subdivided and
     * refined), in 3D on the voxels of a volume (one trilinear hexahedron
     * per voxel). Strain-driven conditions (KUBC, periodic) solve for the
     * fluctuation w in u = E x + w; the stress-driven one (SUBC) solves
     * for u with the load written as the volume term int eps(v) : Sigma
     * (equal to the boundary work of t = Sigma n).
     *
     * The implementation is split along what it does:
     * - cell_problem.cc: the mesh (the coarsest box grid whose cells are
     *   2^L elements wide, refined L times), the DoFs, the constraints of
     *   each boundary condition, and solve(), which ties the rest together;
     * - cell_assembly.cc: the element integrals, the assembled matrix and
     *   right-hand sides of the AMG path, and the volume averages;
     * - cell_solvers.cc: CG with ML AMG (rigid-body modes as near-null
     *   space) or with the matrix-free geometric multigrid of
     *   cell_multigrid.h, one preconditioner per boundary condition,
     *   reused for its load cases;
     * - cell_output.cc: the cell fields of a load case, written as VTU
     *   or cut along planes, and the material map.
     */
    template <int dim>
    class CellProblem
    {
    public:
      /// stress_xx, ... (the Voigt components; in 2D then stress_zz),
      /// von_mises, strain_xx, ... (engineering shears strain_gamma_xy,
      /// ...), material_id.
      static std::vector<std::string>
      cell_field_names();
      using Traits                          = CellTraits<dim>;
      static constexpr unsigned int n_voigt = Traits::n_voigt;
      using Voigt                           = dealii::Tensor<1, n_voigt>;
      using VoigtMatrixType                 = dealii::Tensor<2, n_voigt>;
      using Geometry                        = typename Traits::Geometry;
      using Phase                           = typename Traits::Phase;
      /// What becomes of a load case's solution (its locally owned values,
      /// constraints not yet distributed) as soon as it is solved: one
      /// solution alive at a time.
      using LoadCaseSolved
        = std::function<void(const unsigned int,
                             const dealii::TrilinosWrappers::MPI::Vector &)>;

      CellProblem(const MPI_Comm              comm,
                  const Geometry             &geometry,
                  const std::vector<Phase>   &phases,
                  const CellSolverParameters &parameters,
                  dealii::TimerOutput        &timer);

      /// What solve() calls with each load case's solution and cell fields
      /// (the fields are computed only when one is given).
      using LoadCaseObserver = std::function<void(const LoadCaseFields<dim> &)>;

      /// Solve the load cases of @p bc; hand each load case's solution and
      /// cell fields to @p observer (the outputs: e.g. the "fields"
      /// postprocessor writes them with write_fields()). The cell fields
      /// of the first load case on each of @p slices go to
      /// CellResult::slices.
      CellResult<dim>
      solve(const BoundaryCondition        bc,
            const LoadCaseObserver        &observer = {},
            const std::vector<SlicePlane> &slices   = {});

      /// Write the displacement u = E x + w (or u, SUBC) of load case
      /// @p fields.load_case and its cell fields as VTU in
      /// @p output_directory, and the .pvd index of the load cases up to
      /// it (fields_<BC>.pvd indexing, in 2D, fields_<BC>_<case>.vtu, one
      /// file through MPI I/O; in 3D fields_<BC>_<k>.pvtu, k = 0 to 5,
      /// each of one piece per rank, fields_<BC>_<k>.<rank>.vtu).
      void
      write_fields(const LoadCaseFields<dim> &fields,
                   const std::string         &output_directory) const;

      /// Write the material map (morphology.vtu; 2D).
      void
      write_material_map(const std::string &output_directory) const;

      dealii::types::global_dof_index
      n_dofs() const;
      /// Whether CG is preconditioned by geometric multigrid ('Preconditioner
      /// = multigrid' and a coarsest mesh of at most max_coarse_dofs DoFs).
      bool
      uses_multigrid() const;
      /// Whether the problem of @p bc is solved with multigrid: when
      /// uses_multigrid(), but for periodic problems of elements of degree
      /// 2 to 4 (AMG).
      bool
      uses_multigrid(const BoundaryCondition bc) const;
      /// Levels of the multigrid hierarchy (0 with AMG).
      unsigned int
      n_multigrid_levels() const;
      /// The largest coarsest level that multigrid solves directly.
      static constexpr unsigned int max_coarse_dofs = 50000;
      dealii::types::global_cell_index
      n_cells() const;
      /// Area (2D) or volume (3D) fraction of each material id, measured on
      /// the mesh.
      std::vector<double>
      phase_fractions() const;

    private:
      /// The mesh: the coarsest box grid whose cells are 2^L times the
      /// element size, refined L + 'Global refinements' times, with
      /// periodic faces registered when @p periodic.
      void
      setup_mesh(const bool periodic);
      void
      setup_dofs();
      /// The pinned vertices of @p bc (rigid motions of SUBC, the
      /// translation of periodic): for SUBC vertices of the coarsest mesh
      /// (present on every multigrid level), for periodic the interior
      /// vertex nearest to the centre.
      std::vector<std::pair<dealii::Point<dim>, std::vector<unsigned int>>>
      pinned_vertices(const BoundaryCondition bc) const;
      /// DoFs of the coarsest mesh.
      unsigned int
      n_coarse_dofs() const;
      /// Element size along each axis of the active mesh.
      std::array<double, dim>
      element_size() const;
      /// The size of the box: the product of its extents.
      double
      measure() const;
      /// Solve the load cases with geometric multigrid, one after the
      /// other: the CG time and iterations of each in @p result, then
      /// @p solved with its solution.
      void
      solve_with_multigrid(const BoundaryCondition bc,
                           CellResult<dim>        &result,
                           const LoadCaseSolved   &solved);
      /// The same with AMG on the assembled matrix.
      void
      solve_with_amg(const BoundaryCondition bc,
                     CellResult<dim>        &result,
                     const LoadCaseSolved   &solved);
      void
      make_constraints(const BoundaryCondition bc);
      /// Whether the element integrals are tabulated once per phase
      /// (element_tables) rather than evaluated on every cell; see
      /// cell_assembly.cc.
      static constexpr bool tabulated_elements = dim == 3;
      /// The element matrix and the element loads per phase, and the
      /// strain integrals of the shape functions, when tabulated.
      void
      tabulate_elements(const BoundaryCondition bc);
      void
      assemble(const BoundaryCondition bc);
      void
      setup_preconditioner();
      using ElementIntegrals = internal::ElementIntegrals<n_voigt>;
      /// Call @p f(cell, k, integrals) for every locally owned cell and
      /// every @p fields[k], the solution of load case @p load_cases[k]
      /// of @p bc (its ghosts and constrained values set), with the
      /// integrals over the cell of eps = E + eps(w) (E = 0 for SUBC),
      /// sigma = C eps and sigma_zz: one pass over the cells for all
      /// fields. Defined in cell_integrals.h.
      template <typename F>
      void
      for_each_element_integral(
        const BoundaryCondition          bc,
        const std::vector<unsigned int> &load_cases,
        const std::vector<
          const dealii::LinearAlgebra::distributed::Vector<double> *> &fields,
        const F                                                       &f) const;
      /// Volume averages of load case @p load_case of @p bc from its
      /// solution @p field (its ghosts and constrained values set).
      CellLoadCase<dim>
      postprocess(
        const BoundaryCondition                                   bc,
        const unsigned int                                        load_case,
        const dealii::LinearAlgebra::distributed::Vector<double> &field) const;
      /// The averages over each element of the stress, von Mises stress
      /// and strain of load case @p load_case of @p bc, and the material
      /// id: one vector per field, indexed by active cell (the locally
      /// owned ones set), named by cell_field_names().
      std::vector<dealii::Vector<float>>
      cell_fields(
        const BoundaryCondition                                   bc,
        const unsigned int                                        load_case,
        const dealii::LinearAlgebra::distributed::Vector<double> &field) const;
      /// The cell fields @p values on @p plane, summed over the ranks.
      FieldSlice
      slice(const SlicePlane                         &plane,
            const std::vector<dealii::Vector<float>> &values) const;
      /// The apparent properties of the averages of @p result.
      static typename Traits::Properties
      apparent_properties(const BoundaryCondition bc,
                          const CellResult<dim>  &result);

      /// Macroscopic strain (strain-driven) or stress (SUBC) of a load case.
      static Voigt
      unit_load(const unsigned int load_case);

      MPI_Comm        mpi_communicator;
      const Geometry &geometry;
      /// The phases by material id (a copy: callers may pass temporaries).
      const std::vector<Phase>   phases;
      const CellSolverParameters parameters;
      dealii::TimerOutput       &timer;
      dealii::ConditionalOStream pcout;

      /// Coarse cells along each axis, and the refinements L from the
      /// coarse mesh to the elements (pixels or voxels, subdivided).
      std::array<unsigned int, dim> n_coarse_cells   = {};
      unsigned int                  n_element_levels = 0;
      bool                          mesh_is_periodic = false;

      dealii::parallel::distributed::Triangulation<dim> triangulation;
      dealii::FESystem<dim>                             fe;
      dealii::DoFHandler<dim>                           dof_handler;
      dealii::IndexSet                                  locally_owned_dofs;
      dealii::IndexSet                                  locally_relevant_dofs;

      dealii::AffineConstraints<double>                          constraints;
      dealii::TrilinosWrappers::SparseMatrix                     system_matrix;
      std::array<dealii::TrilinosWrappers::MPI::Vector, n_voigt> system_rhs;
      /// Norm of the unassembled element loads of each load case: the
      /// scale of the CG tolerance. The assembled right-hand side cancels
      /// between elements (to round-off for a single phase), so it is no
      /// scale for the accuracy of the averages.
      std::array<double, n_voigt>               load_scale;
      dealii::TrilinosWrappers::PreconditionAMG preconditioner;
      /// Near-null space of the AMG; must outlive the preconditioner setup.
      std::unique_ptr<Epetra_MultiVector> rigid_body_modes;
      /// What the multigrid solvers of the boundary conditions share;
      /// reset with the DoFs.
      std::shared_ptr<internal::MultigridCache> multigrid_cache;

      /// Tabulated elements: per phase the element matrix and the element
      /// loads of the unit loads; the integral over the element of the
      /// Voigt strain of each shape function (n_voigt x dofs per cell).
      std::vector<dealii::FullMatrix<double>>                  element_matrix;
      std::vector<std::array<dealii::Vector<double>, n_voigt>> element_load;
      dealii::FullMatrix<double>                               strain_integral;
    };
  } // namespace homogenization
} // namespace tribodyn

#endif
