#include "cell_integrals.h"
#include "cell_multigrid.h"

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
    using internal::AffineDisplacement;
    using internal::CellIntegrals;
    using internal::for_each_owned_cell_integral;

    namespace
    {
      constexpr SelectionTable<CellPreconditioner, 2> preconditioner_choices{
        {{"multigrid", CellPreconditioner::multigrid},
         {"AMG", CellPreconditioner::amg}}};
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
            "instead and the screen says so.",
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


    CellProblem::CellProblem(const MPI_Comm                   comm,
                             const Morphology                &morphology,
                             const std::vector<ElasticPhase> &phases,
                             const CellProblemParameters     &parameters,
                             TimerOutput                     &timer)
        : mpi_communicator(comm)
        , morphology(morphology)
        , phases(phases)
        , parameters(parameters)
        , timer(timer)
        , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
        , triangulation(comm,
                        Triangulation<2>::none,
                        parallel::distributed::Triangulation<
                          2>::construct_multigrid_hierarchy)
        , fe(FE_Q<2>(parameters.fe_degree), 2)
        , dof_handler(triangulation)
    {
      setup_mesh(parameters.boundary_conditions.front()
                 == BoundaryCondition::periodic);
      setup_dofs();
      if (parameters.preconditioner == CellPreconditioner::multigrid
          && !uses_multigrid())
        pcout << "Note: the coarsest mesh of the multigrid hierarchy would "
              << "have " << n_coarse_cells[0] << " x " << n_coarse_cells[1]
              << " elements (" << n_coarse_dofs() << " DoFs > "
              << max_coarse_dofs << "): the element counts along x and y "
              << "have too few common factors of 2. Using AMG instead; "
              << "pixel counts divisible by a power of 2 (or 'Subdivisions "
              << "per pixel' = 2, 4, ...) allow multigrid." << std::endl;
    }


    void
    CellProblem::setup_mesh(const bool periodic)
    {
      TimerOutput::Scope scope(timer, "mesh and dofs");
      triangulation.clear();
      // The elements of 'Subdivisions per pixel' are the pixel grid
      // refined; the coarse mesh halves it while both counts are even, so
      // that multigrid finds a hierarchy of L levels down to it.
      n_coarse_cells
        = {{morphology.n_pixels_x() * parameters.subdivisions_per_pixel,
            morphology.n_pixels_y() * parameters.subdivisions_per_pixel}};
      n_pixel_levels = 0;
      while (n_coarse_cells[0] % 2 == 0 && n_coarse_cells[1] % 2 == 0)
        {
          n_coarse_cells[0] /= 2;
          n_coarse_cells[1] /= 2;
          ++n_pixel_levels;
        }
      GridGenerator::subdivided_hyper_rectangle(
        triangulation,
        {n_coarse_cells[0], n_coarse_cells[1]},
        Point<2>(0, 0),
        Point<2>(morphology.width(), morphology.height()),
        /*colorize = */ true);
      // Periodic constraints on a distributed mesh need the ghost layer to
      // reach across the periodic faces. Registered only for the periodic
      // problem: multigrid takes the periodicity of the triangulation into
      // the constraints of every level.
      mesh_is_periodic = periodic;
      if (periodic)
        {
          std::vector<GridTools::PeriodicFacePair<
            parallel::distributed::Triangulation<2>::cell_iterator>>
            pairs;
          GridTools::collect_periodic_faces(triangulation, 0, 1, 0, pairs);
          GridTools::collect_periodic_faces(triangulation, 2, 3, 1, pairs);
          triangulation.add_periodicity(pairs);
        }
      triangulation.refine_global(n_pixel_levels
                                  + parameters.global_refinements);
      // Each element lies in one pixel: its material is that of its centre.
      for (const auto &cell : triangulation.active_cell_iterators())
        if (!cell->is_artificial())
          cell->set_material_id(morphology.material_at(cell->center()));
    }


    std::array<double, 2>
    CellProblem::element_size() const
    {
      const unsigned int refinements
        = n_pixel_levels + parameters.global_refinements;
      return {{morphology.width() / (n_coarse_cells[0] << refinements),
               morphology.height() / (n_coarse_cells[1] << refinements)}};
    }


    void
    CellProblem::setup_dofs()
    {
      TimerOutput::Scope scope(timer, "mesh and dofs");
      multigrid_cache.reset(); // its objects refer to the old DoFs
      dof_handler.distribute_dofs(fe);
      // Level DoFs only where multigrid will run on this mesh (not for the
      // periodic problem's mesh, nor when AMG takes over).
      if (uses_multigrid() && !mesh_is_periodic)
        dof_handler.distribute_mg_dofs();
      locally_owned_dofs = dof_handler.locally_owned_dofs();
      DoFTools::extract_locally_relevant_dofs(dof_handler,
                                              locally_relevant_dofs);
    }


    unsigned int
    CellProblem::n_coarse_dofs() const
    {
      return 2 * (n_coarse_cells[0] * parameters.fe_degree + 1)
             * (n_coarse_cells[1] * parameters.fe_degree + 1);
    }


    bool
    CellProblem::uses_multigrid() const
    {
      return parameters.preconditioner == CellPreconditioner::multigrid
             && n_coarse_dofs() <= max_coarse_dofs;
    }


    bool
    CellProblem::uses_multigrid(const BoundaryCondition bc) const
    {
      // deal.II 9.4's matrix-free level transfer does not carry the
      // periodicity constraints between levels (CG took 759 iterations
      // where KUBC took 8): periodic problems keep AMG.
      return uses_multigrid() && bc != BoundaryCondition::periodic;
    }


    unsigned int
    CellProblem::n_multigrid_levels() const
    {
      return uses_multigrid() ? triangulation.n_global_levels() : 0;
    }


    types::global_dof_index
    CellProblem::n_dofs() const
    {
      return dof_handler.n_dofs();
    }


    types::global_cell_index
    CellProblem::n_cells() const
    {
      return triangulation.n_global_active_cells();
    }


    std::vector<double>
    CellProblem::phase_fractions() const
    {
      std::vector<double> area(phases.size(), 0.);
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          area[cell->material_id()] += cell->measure();
      Utilities::MPI::sum(area, mpi_communicator, area);
      const double total = morphology.width() * morphology.height();
      for (double &a : area)
        a /= total;
      return area;
    }


    VoigtVector
    CellProblem::unit_load(const unsigned int load_case)
    {
      VoigtVector load;
      load[load_case] = 1.;
      return load;
    }


    namespace
    {
      /// Constrain component(s) @p components of the vertex at @p point to
      /// zero, on every rank that sees that vertex.
      void
      pin_vertex(const DoFHandler<2>             &dof_handler,
                 const Point<2>                  &point,
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


    std::vector<std::pair<Point<2>, std::vector<unsigned int>>>
    CellProblem::pinned_vertices(const BoundaryCondition bc) const
    {
      switch (bc)
        {
          case BoundaryCondition::periodic:
            {
              // Periodic w is defined up to a translation: pin the interior
              // vertex nearest to the centre. (Periodic problems are solved
              // with AMG: the vertex need not exist on coarser levels.)
              const auto         h = element_size();
              const unsigned int refinements
                = n_pixel_levels + parameters.global_refinements;
              return {
                {Point<2>(((n_coarse_cells[0] << refinements) / 2) * h[0],
                          ((n_coarse_cells[1] << refinements) / 2) * h[1]),
                 {0, 1}}};
            }
          case BoundaryCondition::subc:
            // Pure traction problem: remove the rigid motions by fixing the
            // bottom-left corner and the vertical displacement of the
            // bottom-right one. The load is self-equilibrated, so these
            // supports carry no force.
            return {{Point<2>(0, 0), {0, 1}},
                    {Point<2>(morphology.width(), 0), {1}}};
          case BoundaryCondition::kubc:
            break;
        }
      return {};
    }


    void
    CellProblem::make_constraints(const BoundaryCondition bc)
    {
      constraints.clear();
      constraints.reinit(locally_relevant_dofs);
      const auto   h         = element_size();
      const double tolerance = 1e-3 * std::min(h[0], h[1]);

      if (bc == BoundaryCondition::kubc)
        // Fluctuation w = 0 on the whole boundary.
        for (const types::boundary_id id : {0, 1, 2, 3})
          VectorTools::interpolate_boundary_values(
            dof_handler, id, Functions::ZeroFunction<2>(2), constraints);
      if (bc == BoundaryCondition::periodic)
        {
          DoFTools::make_periodicity_constraints(
            dof_handler, 0, 1, 0, constraints);
          DoFTools::make_periodicity_constraints(
            dof_handler, 2, 3, 1, constraints);
        }
      for (const auto &[point, components] : pinned_vertices(bc))
        pin_vertex(dof_handler,
                   point,
                   components,
                   tolerance,
                   locally_relevant_dofs,
                   constraints);
      constraints.close();
    }


    namespace
    {
      /// Run @p solve (a CG solve with @p control), turning Trilinos's and
      /// deal.II's failures into errors that say what to change.
      template <typename F>
      void
      run_cg(const BoundaryCondition bc,
             const unsigned int      load_case,
             const double            rhs_norm,
             const F                &solve)
      {
        try
          {
            solve();
          }
        catch (const SolverControl::NoConvergence &e)
          {
            throw RunError("The " + to_string(bc) + " cell problem, load case "
                           + std::to_string(load_case)
                           + ", did not converge: CG reached "
                           + std::to_string(e.last_step)
                           + " iterations with a relative residual of "
                           + format_number(e.last_residual / rhs_norm)
                           + ". Raise 'Cell problem/Max iterations' or 'Cell "
                             "problem/Solver tolerance'.");
          }
        catch (const ExceptionBase &e)
          {
            // AztecOO breakdown or loss of precision.
            std::ostringstream info;
            e.print_info(info);
            throw RunError("The " + to_string(bc) + " cell problem, load case "
                           + std::to_string(load_case)
                           + ", failed in CG: " + info.str()
                           + " This happens when 'Cell problem/Solver "
                             "tolerance' is below what double precision "
                             "can reach; raise it (1e-10 is ample).");
          }
      }
    } // namespace


    void
    CellProblem::solve_with_multigrid(
      const BoundaryCondition                       bc,
      std::array<TrilinosWrappers::MPI::Vector, 3> &solutions,
      CellProblemResult                            &result)
    {
      internal::LevelConstraintDescription levels;
      levels.zero_boundary = bc == BoundaryCondition::kubc;
      for (const auto &[point, components] : pinned_vertices(bc))
        levels.pins.push_back({point, components});
      const auto h     = element_size();
      levels.tolerance = 1e-3 * std::min(h[0], h[1]);

      // The coefficient of a cell on any level: the mean plane-strain
      // stiffness of the elements (each in one pixel) it covers.
      std::vector<VoigtMatrix> stiffness_of_phase;
      for (const auto &phase : phases)
        stiffness_of_phase.push_back(phase.C);
      const auto stiffness = [&](const Point<2> &lower, const Point<2> &upper) {
        const int   i0 = static_cast<int>(std::lround(lower[0] / h[0]));
        const int   i1 = static_cast<int>(std::lround(upper[0] / h[0]));
        const int   j0 = static_cast<int>(std::lround(lower[1] / h[1]));
        const int   j1 = static_cast<int>(std::lround(upper[1] / h[1]));
        VoigtMatrix sum;
        for (int j = j0; j < j1; ++j)
          for (int i = i0; i < i1; ++i)
            sum += stiffness_of_phase[morphology.material_at(
              Point<2>((i + 0.5) * h[0], (j + 0.5) * h[1]))];
        return VoigtMatrix(sum / double((i1 - i0) * (j1 - j0)));
      };

      const auto solver
        = internal::make_cell_multigrid_solver(parameters.fe_degree,
                                               parameters.multigrid_precision
                                                 == MultigridPrecision::single,
                                               multigrid_cache,
                                               dof_handler,
                                               constraints,
                                               levels,
                                               stiffness,
                                               timer);
      for (unsigned int load_case = 0; load_case < 3; ++load_case)
        {
          TimerOutput::Scope scope(timer, "CG solve");
          const double       rhs_norm
            = solver->assemble_rhs(unit_load(load_case),
                                   bc != BoundaryCondition::subc);
          SolverControl control(parameters.max_iterations,
                                parameters.solver_tolerance * rhs_norm,
                                /*log_history = */ false,
                                /*log_result = */ false);
          run_cg(bc, load_case, rhs_norm, [&]() {
            solver->solve(control, solutions[load_case]);
          });
          result.load_cases[load_case].cg_iterations = control.last_step();
        }
    }


    void
    CellProblem::solve_with_amg(
      const BoundaryCondition                       bc,
      std::array<TrilinosWrappers::MPI::Vector, 3> &solutions,
      CellProblemResult                            &result)
    {
      assemble(bc);
      setup_preconditioner();
      for (unsigned int load_case = 0; load_case < 3; ++load_case)
        {
          TimerOutput::Scope         scope(timer, "CG solve");
          const double               rhs_norm = load_scale[load_case];
          SolverControl              control(parameters.max_iterations,
                                parameters.solver_tolerance * rhs_norm,
                                /*log_history = */ false,
                                /*log_result = */ false);
          TrilinosWrappers::SolverCG cg(control);
          run_cg(bc, load_case, rhs_norm, [&]() {
            cg.solve(system_matrix,
                     solutions[load_case],
                     system_rhs[load_case],
                     preconditioner);
          });
          result.load_cases[load_case].cg_iterations = control.last_step();
        }
    }


    CellProblemResult
    CellProblem::solve(const BoundaryCondition bc,
                       const std::string      &output_directory)
    {
      // The periodic problem needs the periodic faces registered in the
      // mesh, the others must not see them (multigrid would carry the
      // periodicity into their levels).
      if ((bc == BoundaryCondition::periodic) != mesh_is_periodic)
        {
          setup_mesh(bc == BoundaryCondition::periodic);
          setup_dofs();
        }
      make_constraints(bc);

      CellProblemResult result;
      result.boundary_condition = bc;
      std::array<TrilinosWrappers::MPI::Vector, 3> solutions;
      for (auto &solution : solutions)
        solution.reinit(locally_owned_dofs, mpi_communicator);
      if (uses_multigrid(bc))
        solve_with_multigrid(bc, solutions, result);
      else
        solve_with_amg(bc, solutions, result);

      {
        TimerOutput::Scope scope(timer, "averages and fields");
        // the fields with their ghosts, as deal.II vectors (local access)
        std::array<LinearAlgebra::distributed::Vector<double>, 3> fields;
        for (unsigned int load_case = 0; load_case < 3; ++load_case)
          {
            auto &field = fields[load_case];
            field.reinit(locally_owned_dofs,
                         locally_relevant_dofs,
                         mpi_communicator);
            // both hold the locally owned DoFs in the same order
            const double *values = solutions[load_case].trilinos_vector()[0];
            for (unsigned int k = 0; k < field.locally_owned_size(); ++k)
              field.local_element(k) = values[k];
            constraints.distribute(field);
            field.update_ghost_values();
          }
        const auto averages = postprocess(bc, fields);
        for (unsigned int load_case = 0; load_case < 3; ++load_case)
          {
            const unsigned int iterations
              = result.load_cases[load_case].cg_iterations;
            result.load_cases[load_case]               = averages[load_case];
            result.load_cases[load_case].cg_iterations = iterations;
            if (!output_directory.empty())
              {
                constraints.distribute(solutions[load_case]);
                TrilinosWrappers::MPI::Vector ghosted(locally_owned_dofs,
                                                      locally_relevant_dofs,
                                                      mpi_communicator);
                ghosted = solutions[load_case];
                write_fields(bc, load_case, ghosted, output_directory);
              }
          }
      }

      // Apparent properties: columns of C (strain-driven) or of S (SUBC).
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
          // <sigma_zz> = zz . Sigma and <eps> = S Sigma, so
          // <sigma_zz> = (C^T zz) . <eps>.
          const VoigtMatrix C = invert(M);
          result.properties   = properties_from_stiffness(C, transpose(C) * zz);
        }
      else
        result.properties = properties_from_stiffness(M, zz);
      return result;
    }


    std::array<LoadCaseResult, 3>
    CellProblem::postprocess(
      const BoundaryCondition bc,
      const std::array<LinearAlgebra::distributed::Vector<double>, 3>
        &solutions) const
    {
      const bool               strain_driven = bc != BoundaryCondition::subc;
      std::vector<VoigtVector> macro_strains;
      std::vector<const LinearAlgebra::distributed::Vector<double> *> fields;
      for (unsigned int load_case = 0; load_case < 3; ++load_case)
        {
          macro_strains.push_back(strain_driven ? unit_load(load_case)
                                                : VoigtVector());
          fields.push_back(&solutions[load_case]);
        }

      // Sums per load case: stress (3), strain (3), sigma_zz (1).
      std::vector<double> sums(21, 0.);
      for_each_owned_cell_integral(dof_handler,
                                   fe,
                                   parameters.fe_degree,
                                   phases,
                                   fields,
                                   macro_strains,
                                   [&](const auto &,
                                       const unsigned int   load_case,
                                       const CellIntegrals &integrals) {
                                     double *s = &sums[7 * load_case];
                                     for (unsigned int i = 0; i < 3; ++i)
                                       {
                                         s[i] += integrals.stress[i];
                                         s[3 + i] += integrals.strain[i];
                                       }
                                     s[6] += integrals.stress_zz;
                                   });
      Utilities::MPI::sum(sums, mpi_communicator, sums);
      const double area = morphology.width() * morphology.height();
      std::array<LoadCaseResult, 3> r;
      for (unsigned int load_case = 0; load_case < 3; ++load_case)
        {
          const double *s = &sums[7 * load_case];
          for (unsigned int i = 0; i < 3; ++i)
            {
              r[load_case].mean_stress[i] = s[i] / area;
              r[load_case].mean_strain[i] = s[3 + i] / area;
            }
          r[load_case].mean_stress_zz = s[6] / area;
        }
      return r;
    }


  } // namespace homogenization
} // namespace tribodyn
