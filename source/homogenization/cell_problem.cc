// The cell problems of 2D morphologies and 3D voxel volumes (declared in
// cell_problem.h): their parameters, the mesh and the DoFs, the
// constraints of each boundary condition and the solve of one condition.
// The assembly and the averages are in cell_assembly.cc, the solvers in
// cell_solvers.cc, the field output in cell_output.cc.
#include "cell_multigrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/numerics/vector_tools.h>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/selection.h>
#include <tribodyn/homogenization/cell_problem.h>

namespace tribodyn
{
  namespace homogenization
  {
    using namespace dealii;

    namespace
    {
      constexpr SelectionTable<CellPreconditioner, 2> preconditioner_choices{
        {{"multigrid", CellPreconditioner::multigrid},
         {"AMG", CellPreconditioner::amg}}};
      constexpr SelectionTable<VolumeGrid, 3> grid_choices{
        {{"auto", VolumeGrid::automatic},
         {"mesh", VolumeGrid::mesh},
         {"voxel grid", VolumeGrid::voxel_grid}}};
      constexpr SelectionTable<MultigridPrecision, 2> precision_choices{
        {{"single", MultigridPrecision::single},
         {"double", MultigridPrecision::double_}}};
    } // namespace

    std::string
    to_string(const BoundaryCondition bc)
    {
      switch (bc)
        {
          case BoundaryCondition::kubc:
            return "KUBC";
          case BoundaryCondition::subc:
            return "SUBC";
          case BoundaryCondition::periodic:
            return "periodic";
        }
      return "unknown";
    }


    BoundaryCondition
    boundary_condition_named(const std::string &name)
    {
      return name == "KUBC"   ? BoundaryCondition::kubc
             : name == "SUBC" ? BoundaryCondition::subc
                              : BoundaryCondition::periodic;
    }


    void
    add_boundary_conditions_entry(
      ParameterBinding               &b,
      std::vector<BoundaryCondition> &boundary_conditions)
    {
      std::string conditions;
      for (const BoundaryCondition bc : boundary_conditions)
        conditions += (conditions.empty() ? "" : ", ") + to_string(bc);
      b.add(
        "Boundary conditions",
        conditions,
        "Boundary conditions of the cell problems, a comma-separated list: "
        "'KUBC' (u = E x on the boundary: apparent stiffness, an upper "
        "bound), 'SUBC' (t = Sigma n on the boundary: apparent compliance, a "
        "lower bound), 'periodic' (periodic fluctuation; exact for a "
        "periodic morphology).",
        Patterns::MultipleSelection("KUBC|SUBC|periodic"),
        [&boundary_conditions,
         where = b.path("Boundary conditions")](const std::string &text) {
          boundary_conditions.clear();
          for (const auto &name : Utilities::split_string_list(text))
            {
              const BoundaryCondition bc = boundary_condition_named(name);
              if (std::find(boundary_conditions.begin(),
                            boundary_conditions.end(),
                            bc)
                  == boundary_conditions.end())
                boundary_conditions.push_back(bc);
            }
          check_parameter(!boundary_conditions.empty(),
                          where,
                          "give at least one of KUBC, SUBC, periodic.");
        });
    }


    void
    add_cg_entries(ParameterBinding &b,
                   double           &solver_tolerance,
                   unsigned int     &max_iterations)
    {
      b.add("Solver tolerance",
            solver_tolerance,
            "CG stops when the residual is below this fraction of the "
            "right-hand side's norm; in (0, 1).",
            Patterns::Double(),
            Interval{0, 1, true, true});
      b.add("Max iterations",
            max_iterations,
            "Maximum number of CG iterations per load case.",
            Patterns::Integer(1));
    }


    ParameterBinding
    CellProblemParameters::binding()
    {
      ParameterBinding b("Cell problem");
      add_boundary_conditions_entry(b, boundary_conditions);
      b.add("Subdivisions per pixel",
            subdivisions_per_pixel,
            "Elements per morphology pixel along each axis (coarse mesh).",
            Patterns::Integer(1));
      b.add("Global refinements",
            global_refinements,
            "Number of global refinements of the coarse mesh; each one halves "
            "the element size.",
            Patterns::Integer(0, 12));
      b.add("Finite element degree",
            fe_degree,
            "Polynomial degree of the Lagrange elements.",
            Patterns::Integer(1, 4));
      add_cg_entries(b, solver_tolerance, max_iterations);
      b.add("Preconditioner",
            preconditioner,
            "Preconditioner of CG: 'multigrid' (geometric multigrid on the "
            "pixel hierarchy: matrix-free operator, Chebyshev smoothing, the "
            "coarsest mesh solved directly; its iteration counts do not grow "
            "as the mesh is refined) or 'AMG' (Trilinos ML on the assembled "
            "matrix). Multigrid coarsens while the number of elements along "
            "both axes is even; when the coarsest mesh keeps more than "
            "50000 DoFs (pixel counts with few factors of 2), AMG is used "
            "instead and the screen says so; so is it for periodic "
            "conditions with elements of degree 2 to 4.",
            preconditioner_choices);
      b.add("Multigrid precision",
            multigrid_precision,
            "Floating-point precision of the multigrid V-cycle (levels, "
            "smoother, transfer; the coarsest level is factorized in double "
            "and CG always runs in double, so the result is as accurate "
            "either way): 'single' halves the memory traffic of the "
            "preconditioner (CG 1.2 times faster on the 1.1e6-DoF bench); "
            "'double' keeps the "
            "iteration counts of SUBC constant as the mesh is refined also at "
            "tolerances below 1e-11, where single precision adds a few "
            "(doc/theory/homogenization.md, 'Cell problems').",
            precision_choices);
      return b;
    }


    void
    CellProblemParameters::declare_parameters(ParameterHandler &prm)
    {
      CellProblemParameters().binding().declare(prm);
    }


    void
    CellProblemParameters::parse_parameters(ParameterHandler &prm)
    {
      binding().parse(prm);
    }


    ParameterBinding
    VolumeCellProblemParameters::binding()
    {
      ParameterBinding b("Cell problem");
      add_boundary_conditions_entry(b, boundary_conditions);
      add_cg_entries(b, solver_tolerance, max_iterations);
      b.add("Preconditioner",
            preconditioner,
            "Preconditioner of CG: 'multigrid' (geometric multigrid on the "
            "voxel hierarchy, matrix-free, one 24 x 24 element matrix per "
            "distinct cell stiffness, the periodicity carried through its "
            "levels; its iteration counts do not grow with the volume; 2-3 "
            "times faster than AMG in a third to a tenth of its memory, "
            "doc/performance.md) or 'AMG' (Trilinos ML on the assembled "
            "matrix, the six rigid-body modes as near-null space). Volumes "
            "whose coarsest mesh (the voxel counts halved while all three "
            "are even) keeps more than 50000 DoFs use AMG.",
            preconditioner_choices);
      b.add("Multigrid precision",
            multigrid_precision,
            "Floating-point precision of the multigrid V-cycle (levels, "
            "smoother, transfer; the coarsest level is factorized in double "
            "and CG always runs in double): 'single' halves the memory "
            "traffic and the memory of the levels, 'double' as in 2D.",
            precision_choices);
      b.add("Grid",
            grid,
            "How the cell problems are discretized (trilinear elements on "
            "the voxels either way, the same constants to the solver "
            "tolerance): 'voxel grid' finds the nodes, cells and coarse "
            "levels by index arithmetic, the ranks owning slabs of node "
            "planes along z (no triangulation, DoF tables or per-cell "
            "indices: a third to a fifth of the mesh's memory, and faster; "
            "multigrid only, the voxel counts halved while all three are "
            "even must reach a grid of at most 3000 unknowns, and it writes "
            "no VTU fields); 'mesh' a deal.II triangulation (any voxel "
            "counts, AMG, 'Output/Write fields'); 'auto' the voxel grid "
            "where it can, else the mesh (the screen says which).",
            grid_choices);
      return b;
    }


    void
    VolumeCellProblemParameters::declare_parameters(ParameterHandler &prm)
    {
      VolumeCellProblemParameters().binding().declare(prm);
    }


    void
    VolumeCellProblemParameters::parse_parameters(ParameterHandler &prm)
    {
      binding().parse(prm);
    }


    // @sect3{The mesh and the DoFs}
    //
    // The elements are the pixels (or voxels) of the geometry, subdivided
    // in 2D by 'Subdivisions per pixel'. p4est keeps one tree per coarse
    // cell, and multigrid needs a hierarchy of levels: the coarse mesh is
    // the element grid halved while all its counts are even (a 128^3
    // volume is one tree), refined back L times, and in 2D 'Global
    // refinements' times more.

    template <int dim>
    CellProblem<dim>::CellProblem(const MPI_Comm              comm,
                                  const Geometry             &geometry,
                                  const std::vector<Phase>   &phases,
                                  const CellSolverParameters &parameters,
                                  TimerOutput                &timer)
        : mpi_communicator(comm)
        , geometry(geometry)
        , phases(phases)
        , parameters(parameters)
        , timer(timer)
        , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
        , triangulation(comm,
                        Triangulation<dim>::none,
                        parallel::distributed::Triangulation<
                          dim>::construct_multigrid_hierarchy)
        , fe(FE_Q<dim>(parameters.fe_degree), dim)
        , dof_handler(triangulation)
    {
      setup_mesh(parameters.boundary_conditions.front()
                 == BoundaryCondition::periodic);
      setup_dofs();
      if (parameters.preconditioner == CellPreconditioner::multigrid
          && !uses_multigrid())
        {
          pcout << "Note: the coarsest mesh of the multigrid hierarchy would "
                << "have ";
          for (unsigned int d = 0; d < dim; ++d)
            pcout << (d > 0 ? " x " : "") << n_coarse_cells[d];
          pcout << " elements (" << n_coarse_dofs() << " DoFs > "
                << max_coarse_dofs << "): the element counts along "
                << (dim == 2 ? "x and y" : "x, y and z")
                << " have too few common factors of 2. Using AMG instead; "
                << (dim == 2 ? "pixel counts divisible by a power of 2 (or "
                               "'Subdivisions per pixel' = 2, 4, ...)"
                             : "voxel counts divisible by a power of 2")
                << " allow multigrid." << std::endl;
        }
    }


    template <int dim>
    void
    CellProblem<dim>::setup_mesh(const bool periodic)
    {
      TimerOutput::Scope scope(timer, "mesh and dofs");
      triangulation.clear();
      for (unsigned int d = 0; d < dim; ++d)
        n_coarse_cells[d] = Traits::n_elements(geometry, parameters, d);
      n_element_levels = 0;
      while (std::all_of(n_coarse_cells.begin(),
                         n_coarse_cells.end(),
                         [](const unsigned int n) { return n % 2 == 0; }))
        {
          for (unsigned int &n : n_coarse_cells)
            n /= 2;
          ++n_element_levels;
        }
      Point<dim>                upper;
      std::vector<unsigned int> repetitions(dim);
      for (unsigned int d = 0; d < dim; ++d)
        {
          upper[d]       = Traits::extent(geometry, d);
          repetitions[d] = n_coarse_cells[d];
        }
      GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                repetitions,
                                                Point<dim>(),
                                                upper,
                                                /*colorize = */ true);
      // Periodic constraints on a distributed mesh need the ghost layer to
      // reach across the periodic faces. Registered only for the periodic
      // problem: multigrid would take the periodicity of the triangulation
      // into the constraints of every level.
      mesh_is_periodic = periodic;
      if (periodic)
        {
          std::vector<GridTools::PeriodicFacePair<
            typename parallel::distributed::Triangulation<dim>::cell_iterator>>
            pairs;
          for (unsigned int d = 0; d < dim; ++d)
            GridTools::collect_periodic_faces(
              triangulation, 2 * d, 2 * d + 1, d, pairs);
          triangulation.add_periodicity(pairs);
        }
      triangulation.refine_global(n_element_levels
                                  + parameters.global_refinements);
      // Each element lies in one pixel (voxel): its material is that of its
      // centre.
      for (const auto &cell : triangulation.active_cell_iterators())
        if (!cell->is_artificial())
          cell->set_material_id(Traits::material_at(geometry, cell->center()));
    }


    template <int dim>
    std::array<double, dim>
    CellProblem<dim>::element_size() const
    {
      const unsigned int refinements
        = n_element_levels + parameters.global_refinements;
      std::array<double, dim> h;
      for (unsigned int d = 0; d < dim; ++d)
        h[d] = Traits::extent(geometry, d) / (n_coarse_cells[d] << refinements);
      return h;
    }


    template <int dim>
    double
    CellProblem<dim>::measure() const
    {
      double m = Traits::extent(geometry, 0);
      for (unsigned int d = 1; d < dim; ++d)
        m *= Traits::extent(geometry, d);
      return m;
    }


    template <int dim>
    void
    CellProblem<dim>::setup_dofs()
    {
      TimerOutput::Scope scope(timer, "mesh and dofs");
      multigrid_cache.reset(); // its objects refer to the old DoFs
      dof_handler.distribute_dofs(fe);
      // Level DoFs only where multigrid will run on this mesh (not when
      // AMG takes over).
      if (uses_multigrid())
        dof_handler.distribute_mg_dofs();
      locally_owned_dofs = dof_handler.locally_owned_dofs();
      DoFTools::extract_locally_relevant_dofs(dof_handler,
                                              locally_relevant_dofs);
    }


    template <int dim>
    unsigned int
    CellProblem<dim>::n_coarse_dofs() const
    {
      unsigned int n = dim;
      for (unsigned int d = 0; d < dim; ++d)
        n *= n_coarse_cells[d] * parameters.fe_degree + 1;
      return n;
    }


    template <int dim>
    bool
    CellProblem<dim>::uses_multigrid() const
    {
      return parameters.preconditioner == CellPreconditioner::multigrid
             && n_coarse_dofs() <= max_coarse_dofs;
    }


    template <int dim>
    bool
    CellProblem<dim>::uses_multigrid(const BoundaryCondition bc) const
    {
      // Multilinear elements carry the periodicity through the levels
      // (cell_multigrid_periodic.h: the periodic images' DoFs replaced by their
      // masters' in the cell tables, a transfer that expands and folds
      // them); other degrees take deal.II 9.4's matrix-free transfer,
      // which does not (CG took 759 iterations where KUBC took 8 in 2D):
      // AMG for them.
      return uses_multigrid()
             && (bc != BoundaryCondition::periodic
                 || parameters.fe_degree == 1);
    }


    template <int dim>
    unsigned int
    CellProblem<dim>::n_multigrid_levels() const
    {
      return uses_multigrid() ? triangulation.n_global_levels() : 0;
    }


    template <int dim>
    types::global_dof_index
    CellProblem<dim>::n_dofs() const
    {
      return dof_handler.n_dofs();
    }


    template <int dim>
    types::global_cell_index
    CellProblem<dim>::n_cells() const
    {
      return triangulation.n_global_active_cells();
    }


    template <int dim>
    std::vector<double>
    CellProblem<dim>::phase_fractions() const
    {
      std::vector<double> fraction(phases.size(), 0.);
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          fraction[cell->material_id()] += cell->measure();
      Utilities::MPI::sum(fraction, mpi_communicator, fraction);
      const double total = measure();
      for (double &f : fraction)
        f /= total;
      return fraction;
    }


    template <int dim>
    typename CellProblem<dim>::Voigt
    CellProblem<dim>::unit_load(const unsigned int load_case)
    {
      Voigt load;
      load[load_case] = 1.;
      return load;
    }


    // @sect3{The constraints of the boundary conditions}

    namespace
    {
      /// Constrain component(s) @p components of the vertex at @p point to
      /// zero, on every rank that sees that vertex.
      template <int dim>
      void
      pin_vertex(const DoFHandler<dim>           &dof_handler,
                 const Point<dim>                &point,
                 const std::vector<unsigned int> &components,
                 const double                     tolerance,
                 const IndexSet                  &locally_relevant_dofs,
                 AffineConstraints<double>       &constraints)
      {
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
            for (const unsigned int v : cell->vertex_indices())
              if (cell->vertex(v).distance(point) < tolerance)
                for (const unsigned int c : components)
                  {
                    const types::global_dof_index dof
                      = cell->vertex_dof_index(v, c);
                    if (locally_relevant_dofs.is_element(dof)
                        && !constraints.is_constrained(dof))
                      constraints.add_line(dof);
                  }
      }
    } // namespace


    template <int dim>
    std::vector<std::pair<Point<dim>, std::vector<unsigned int>>>
    CellProblem<dim>::pinned_vertices(const BoundaryCondition bc) const
    {
      std::vector<std::pair<Point<dim>, std::vector<unsigned int>>> pins;
      switch (bc)
        {
          case BoundaryCondition::periodic:
            {
              // Periodic w is defined up to a translation: pin the interior
              // vertex nearest to the centre (of the active mesh; the
              // multigrid's coarsest level pins a vertex of its own:
              // solve_with_multigrid()).
              const auto         h = element_size();
              const unsigned int refinements
                = n_element_levels + parameters.global_refinements;
              Point<dim>                centre;
              std::vector<unsigned int> all(dim);
              for (unsigned int d = 0; d < dim; ++d)
                {
                  centre[d] = ((n_coarse_cells[d] << refinements) / 2) * h[d];
                  all[d]    = d;
                }
              pins.push_back({centre, all});
              break;
            }
          case BoundaryCondition::subc:
            {
              // Pure traction problem: remove the rigid motions by fixing
              // the corner at the origin, the components but x of the
              // corner along x, and in 3D the z component of the corner
              // along y (vertices of the coarsest mesh, on every multigrid
              // level). The load is self-equilibrated, so these supports
              // carry no force.
              std::vector<unsigned int> components(dim);
              for (unsigned int d = 0; d < dim; ++d)
                components[d] = d;
              pins.push_back({Point<dim>(), components});
              for (unsigned int axis = 0; axis + 1 < dim; ++axis)
                {
                  Point<dim> corner;
                  corner[axis] = Traits::extent(geometry, axis);
                  components.erase(components.begin());
                  pins.push_back({corner, components});
                }
              break;
            }
          case BoundaryCondition::kubc:
            break;
        }
      return pins;
    }


    template <int dim>
    void
    CellProblem<dim>::make_constraints(const BoundaryCondition bc)
    {
      constraints.clear();
      constraints.reinit(locally_relevant_dofs);
      const auto   h         = element_size();
      const double tolerance = 1e-3 * *std::min_element(h.begin(), h.end());

      if (bc == BoundaryCondition::kubc)
        // Fluctuation w = 0 on the whole boundary.
        for (types::boundary_id id = 0; id < 2 * dim; ++id)
          VectorTools::interpolate_boundary_values(
            dof_handler, id, Functions::ZeroFunction<dim>(dim), constraints);
      if (bc == BoundaryCondition::periodic)
        for (unsigned int d = 0; d < dim; ++d)
          DoFTools::make_periodicity_constraints(
            dof_handler, 2 * d, 2 * d + 1, d, constraints);
      for (const auto &[point, components] : pinned_vertices(bc))
        pin_vertex(dof_handler,
                   point,
                   components,
                   tolerance,
                   locally_relevant_dofs,
                   constraints);
      constraints.close();
    }


    // @sect3{The solve of one boundary condition}
    //
    // The mesh with or without periodic faces, the constraints, CG with one
    // of the two preconditioners (cell_solvers.cc), then the averages
    // (cell_assembly.cc) and the apparent properties.

    template <int dim>
    CellResult<dim>
    CellProblem<dim>::solve(const BoundaryCondition        bc,
                            const LoadCaseObserver        &observer,
                            const std::vector<SlicePlane> &slices)
    {
      const auto start = std::chrono::steady_clock::now();
      // The periodic problem needs the periodic faces registered in the
      // mesh, the others must not see them (multigrid would carry the
      // periodicity into their levels).
      if ((bc == BoundaryCondition::periodic) != mesh_is_periodic)
        {
          setup_mesh(bc == BoundaryCondition::periodic);
          setup_dofs();
        }
      make_constraints(bc);
      if constexpr (tabulated_elements)
        tabulate_elements(bc);

      CellResult<dim> result;
      result.boundary_condition = bc;
      result.multigrid          = uses_multigrid(bc);
      // Each load case's averages (and fields, for the outputs that ask)
      // as soon as it is solved: one solution and one field alive at a
      // time.
      LinearAlgebra::distributed::Vector<double> field(locally_owned_dofs,
                                                       locally_relevant_dofs,
                                                       mpi_communicator);
      const auto solved = [&](const unsigned int                   load_case,
                              const TrilinosWrappers::MPI::Vector &solution) {
        TimerOutput::Scope scope(timer, "averages and fields");
        // both hold the locally owned DoFs in the same order
        field.zero_out_ghost_values();
        const double *values = solution.trilinos_vector()[0];
        for (unsigned int k = 0; k < field.locally_owned_size(); ++k)
          field.local_element(k) = values[k];
        constraints.distribute(field);
        field.update_ghost_values();
        const auto       &solved_case = result.load_cases[load_case];
        CellLoadCase<dim> averaged    = postprocess(bc, load_case, field);
        averaged.cg_iterations        = solved_case.cg_iterations;
        averaged.cg_time              = solved_case.cg_time;
        result.load_cases[load_case]  = averaged;
        const bool sliced             = load_case == 0 && !slices.empty();
        if (!observer && !sliced)
          return;
        const auto cell_values = cell_fields(bc, load_case, field);
        if (observer)
          observer({bc, load_case, field, cell_values});
        if (sliced)
          for (const SlicePlane &plane : slices)
            result.slices.push_back(slice(plane, cell_values));
      };
      if (result.multigrid)
        solve_with_multigrid(bc, result, solved);
      else
        solve_with_amg(bc, result, solved);

      result.properties = apparent_properties(bc, result);
      result.wall_time  = std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start)
                           .count();
      return result;
    }


    // @sect3{The apparent properties}
    //
    // The averages of the strain-driven load cases are the columns of the
    // apparent stiffness C, those of SUBC the columns of the apparent
    // compliance S. In plane strain the averaged sigma_zz gives the row c_z
    // as well: under SUBC <sigma_zz> = zz . Sigma and <eps> = S Sigma, so
    // <sigma_zz> = (C^T zz) . <eps>.

    template <>
    ApparentProperties
    CellProblem<2>::apparent_properties(const BoundaryCondition bc,
                                        const CellResult<2>    &result)
    {
      VoigtMatrix M;
      VoigtVector zz;
      for (unsigned int j = 0; j < 3; ++j)
        {
          const LoadCaseResult &r = result.load_cases[j];
          for (unsigned int i = 0; i < 3; ++i)
            M[i][j] = (bc == BoundaryCondition::subc ? r.mean_strain[i]
                                                     : r.mean_stress[i]);
          zz[j] = r.mean_stress_zz;
        }
      if (bc == BoundaryCondition::subc)
        {
          const VoigtMatrix C = invert(M);
          return properties_from_stiffness(C, transpose(C) * zz);
        }
      return properties_from_stiffness(M, zz);
    }


    template <>
    VolumeProperties
    CellProblem<3>::apparent_properties(const BoundaryCondition bc,
                                        const CellResult<3>    &result)
    {
      const bool   strain_driven = bc != BoundaryCondition::subc;
      VoigtMatrix6 M;
      for (unsigned int j = 0; j < 6; ++j)
        for (unsigned int i = 0; i < 6; ++i)
          M[i][j] = strain_driven ? result.load_cases[j].mean_stress[i]
                                  : result.load_cases[j].mean_strain[i];
      return strain_driven ? volume_properties_from_stiffness(M)
                           : volume_properties_from_compliance(M);
    }


    template class CellProblem<2>;
    template class CellProblem<3>;
  } // namespace homogenization
} // namespace tribodyn
