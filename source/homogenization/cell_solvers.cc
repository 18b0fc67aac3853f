// The solvers of the cell problems (declared in cell_problem.h): CG
// preconditioned by ML's smoothed-aggregation AMG on the assembled matrix
// (its near-null space the rigid-body modes), or by the matrix-free
// geometric multigrid of cell_multigrid.h. One preconditioner per
// boundary condition, reused for its load cases.
#include "cell_multigrid.h"

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <chrono>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/cell_problem.h>

namespace tribodyn
{
  namespace homogenization
  {
    using namespace dealii;

    namespace
    {
      /// Run @p solve (a CG solve), turning Trilinos's and deal.II's
      /// failures into errors that say what to change; returns its wall
      /// time (s).
      template <typename F>
      double
      run_cg(const BoundaryCondition bc,
             const unsigned int      load_case,
             const double            rhs_norm,
             const F                &solve)
      {
        const std::string which = "The " + to_string(bc)
                                  + " cell problem, load case "
                                  + std::to_string(load_case);
        const auto start = std::chrono::steady_clock::now();
        try
          {
            solve();
          }
        catch (const SolverControl::NoConvergence &e)
          {
            throw RunError(which + ", did not converge: CG reached "
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
            throw RunError(which + ", failed in CG: " + info.str()
                           + " This happens when 'Cell problem/Solver "
                             "tolerance' is below what double precision "
                             "can reach; raise it (1e-10 is ample).");
          }
        return std::chrono::duration<double>(std::chrono::steady_clock::now()
                                             - start)
          .count();
      }
    } // namespace


    // @sect3{AMG}
    //
    // The rigid-body modes of elasticity as ML's near-null space: the dim
    // translations and the rotations, about the centre of the box and
    // scaled by its largest extent (one rotation in 2D, about z; three in
    // 3D, the rotation about axis a at index dim + a). deal.II 9.4's
    // AdditionalData only takes the translations (constant modes), which
    // makes AMG on elasticity markedly slower.

    template <int dim>
    void
    CellProblem<dim>::setup_preconditioner()
    {
      TimerOutput::Scope scope(timer, "AMG setup");
      const Epetra_Map  &map
        = system_matrix.trilinos_matrix().OperatorDomainMap();
      rigid_body_modes = std::make_unique<Epetra_MultiVector>(map, n_voigt);
      Point<dim> centre;
      double     largest = 0;
      for (unsigned int d = 0; d < dim; ++d)
        {
          centre[d] = 0.5 * Traits::extent(geometry, d);
          largest   = std::max(largest, Traits::extent(geometry, d));
        }
      const double scale = 1. / largest;

      const Quadrature<dim> support_points(fe.get_unit_support_points());
      FEValues<dim> fe_values(fe, support_points, update_quadrature_points);
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            cell->get_dof_indices(dof_indices);
            for (unsigned int i = 0; i < dof_indices.size(); ++i)
              if (locally_owned_dofs.is_element(dof_indices[i]))
                {
                  const auto local
                    = locally_owned_dofs.index_within_set(dof_indices[i]);
                  const unsigned int c = fe.system_to_component_index(i).first;
                  const Tensor<1, dim> x
                    = scale * (fe_values.quadrature_point(i) - centre);
                  for (unsigned int d = 0; d < dim; ++d)
                    (*rigid_body_modes)[d][local] = (c == d ? 1. : 0.);
                  // rotation about axis a: u = e_a x x
                  for (unsigned int a = (dim == 2 ? 2 : 0); a < 3; ++a)
                    {
                      const unsigned int j = (a + 1) % 3, k = (a + 2) % 3;
                      (*rigid_body_modes)[dim == 2 ? 2 : 3 + a][local]
                        = c == j   ? -x[k % dim]
                          : c == k ? x[j % dim]
                                   : 0.;
                    }
                }
          }

      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = parameters.fe_degree > 1;
      data.smoother_sweeps       = 2;
      data.aggregation_threshold = 1e-4;
      Teuchos::ParameterList              ml_parameters;
      std::unique_ptr<Epetra_MultiVector> unused_constant_modes;
      data.set_parameters(ml_parameters, unused_constant_modes, system_matrix);
      ml_parameters.set("null space: type", "pre-computed");
      ml_parameters.set("null space: dimension", int(n_voigt));
      ml_parameters.set("null space: vectors", rigid_body_modes->Values());
      preconditioner.initialize(system_matrix, ml_parameters);
    }


    template <int dim>
    void
    CellProblem<dim>::solve_with_amg(const BoundaryCondition bc,
                                     CellResult<dim>        &result,
                                     const LoadCaseSolved   &solved)
    {
      assemble(bc);
      setup_preconditioner();
      TrilinosWrappers::MPI::Vector solution(locally_owned_dofs,
                                             mpi_communicator);
      for (unsigned int load_case = 0; load_case < n_voigt; ++load_case)
        {
          {
            TimerOutput::Scope         scope(timer, "CG solve");
            const double               rhs_norm = load_scale[load_case];
            SolverControl              control(parameters.max_iterations,
                                  parameters.solver_tolerance * rhs_norm,
                                  /*log_history = */ false,
                                  /*log_result = */ false);
            TrilinosWrappers::SolverCG cg(control);
            result.load_cases[load_case].cg_time
              = run_cg(bc, load_case, rhs_norm, [&]() {
                  solution = 0;
                  cg.solve(system_matrix,
                           solution,
                           system_rhs[load_case],
                           preconditioner);
                });
            result.load_cases[load_case].cg_iterations = control.last_step();
          }
          solved(load_case, solution);
        }
    }


    // @sect3{Geometric multigrid}
    //
    // The levels are those of the mesh's refinement hierarchy. The
    // stiffness over a box (the mean of the elements, each in one pixel or
    // voxel, it covers) gives the elements' stiffness, from which the
    // multilinear fast path builds its Galerkin coarse operators, and the
    // coefficient of a coarse cell for the other degrees.

    template <int dim>
    void
    CellProblem<dim>::solve_with_multigrid(const BoundaryCondition bc,
                                           CellResult<dim>        &result,
                                           const LoadCaseSolved   &solved)
    {
      const auto h = element_size();
      const auto stiffness_over_box
        = [&](const Point<dim> &lower, const Point<dim> &upper) {
            std::array<int, dim> first, count;
            int                  n = 1;
            for (unsigned int d = 0; d < dim; ++d)
              {
                first[d] = static_cast<int>(std::lround(lower[d] / h[d]));
                count[d]
                  = static_cast<int>(std::lround(upper[d] / h[d])) - first[d];
                n *= count[d];
              }
            // x innermost
            VoigtMatrixType sum;
            for (int e = 0; e < n; ++e)
              {
                Point<dim> centre;
                for (int d = 0, rest = e; d < int(dim); rest /= count[d], ++d)
                  centre[d] = (first[d] + rest % count[d] + 0.5) * h[d];
                sum += Traits::stiffness(
                  phases[Traits::material_at(geometry, centre)]);
              }
            return VoigtMatrixType(sum / double(n));
          };

      std::unique_ptr<internal::CellMultigridSolver<dim>> solver;
      {
        internal::LevelConstraintDescription<dim> levels;
        levels.zero_boundary = bc == BoundaryCondition::kubc;
        levels.periodic      = bc == BoundaryCondition::periodic;
        levels.pins          = pinned_vertices(bc);
        if (levels.periodic)
          {
            // the coarsest level's pin: the origin, a vertex of every level
            // that periodicity leaves unconstrained (its images on the
            // upper faces are constrained to it)
            levels.coarse_pins = {{Point<dim>(), levels.pins.front().second}};
          }
        levels.tolerance = 1e-3 * *std::min_element(h.begin(), h.end());
        solver           = internal::make_cell_multigrid_solver<dim>(
          parameters.fe_degree,
          parameters.multigrid_precision == MultigridPrecision::single,
          multigrid_cache,
          dof_handler,
          constraints,
          levels,
          stiffness_over_box,
          timer);
      }
      TrilinosWrappers::MPI::Vector solution(locally_owned_dofs,
                                             mpi_communicator);
      for (unsigned int load_case = 0; load_case < n_voigt; ++load_case)
        {
          {
            TimerOutput::Scope scope(timer, "CG solve");
            const double       rhs_norm
              = solver->assemble_rhs(unit_load(load_case),
                                     bc != BoundaryCondition::subc);
            SolverControl control(parameters.max_iterations,
                                  parameters.solver_tolerance * rhs_norm,
                                  /*log_history = */ false,
                                  /*log_result = */ false);
            result.load_cases[load_case].cg_time
              = run_cg(bc, load_case, rhs_norm, [&]() {
                  solver->solve(control, solution);
                });
            result.load_cases[load_case].cg_iterations = control.last_step();
          }
          solved(load_case, solution);
        }
    }


#define TRIBODYN_INSTANTIATE(dim)                         \
  template void CellProblem<dim>::setup_preconditioner(); \
  template void CellProblem<dim>::solve_with_amg(         \
    const BoundaryCondition,                              \
    CellResult<dim> &,                                    \
    const CellProblem<dim>::LoadCaseSolved &);            \
  template void CellProblem<dim>::solve_with_multigrid(   \
    const BoundaryCondition,                              \
    CellResult<dim> &,                                    \
    const CellProblem<dim>::LoadCaseSolved &);
    TRIBODYN_INSTANTIATE(2)
    TRIBODYN_INSTANTIATE(3)
#undef TRIBODYN_INSTANTIATE
  } // namespace homogenization
} // namespace tribodyn
