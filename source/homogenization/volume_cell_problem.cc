// The cell problems of 3D voxel volumes (issue #51): one trilinear
// hexahedron per voxel, six load cases per boundary condition, CG with ML
// AMG on the assembled matrix.
#include "volume_multigrid.h"

#include <Teuchos_ParameterList.hpp>
#include <chrono>
#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/numerics/vector_tools.h>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/volume_cell_problem.h>

namespace tribodyn
{
  namespace homogenization
  {
    using namespace dealii;

    namespace
    {
      constexpr SelectionTable<CellPreconditioner, 2>
        volume_preconditioner_choices{
          {{"multigrid", CellPreconditioner::multigrid},
           {"AMG", CellPreconditioner::amg}}};
    } // namespace


    ParameterBinding
    VolumeCellProblemParameters::binding()
    {
      ParameterBinding b("Cell problem");
      add_boundary_conditions_entry(b, boundary_conditions);
      add_cg_entries(b, solver_tolerance, max_iterations);
      b.add("Preconditioner",
            preconditioner,
            "Preconditioner of CG: 'AMG' (Trilinos ML on the assembled "
            "matrix, the six rigid-body modes as near-null space) or "
            "'multigrid' (KUBC and SUBC: geometric multigrid on the voxel "
            "hierarchy, matrix-free, single-precision V-cycle; a first "
            "version: its KUBC iteration counts do not grow with the "
            "volume, but it is slower than AMG on the volumes measured and "
            "its SUBC counts grow, doc/theory/homogenization.md). Periodic "
            "conditions always use AMG, and so do volumes whose coarsest "
            "mesh (the voxel counts halved while all three are even) keeps "
            "more than 50000 DoFs.",
            volume_preconditioner_choices);
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


    VolumeCellProblem::VolumeCellProblem(
      const MPI_Comm                     comm,
      const VoxelVolume                 &volume,
      const std::vector<VoigtMatrix6>   &stiffness,
      const VolumeCellProblemParameters &parameters,
      TimerOutput                       &timer)
        : mpi_communicator(comm)
        , volume(volume)
        , stiffness(stiffness)
        , parameters(parameters)
        , timer(timer)
        , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
        , triangulation(comm,
                        Triangulation<3>::none,
                        parallel::distributed::Triangulation<
                          3>::construct_multigrid_hierarchy)
        , fe(FE_Q<3>(1), 3)
        , dof_handler(triangulation)
    {
      setup_mesh(parameters.boundary_conditions.front()
                 == BoundaryCondition::periodic);
      setup_dofs();
    }


    void
    VolumeCellProblem::setup_mesh(const bool periodic)
    {
      TimerOutput::Scope scope(timer, "mesh and dofs");
      triangulation.clear();
      // The voxel grid is the coarse box mesh refined L times: p4est keeps
      // one tree per coarse cell, so the coarse mesh is halved while all
      // three counts are even (a 128^3 volume is one tree).
      for (unsigned int d = 0; d < 3; ++d)
        n_coarse_cells[d] = volume.n_voxels(d);
      n_voxel_levels = 0;
      while (n_coarse_cells[0] % 2 == 0 && n_coarse_cells[1] % 2 == 0
             && n_coarse_cells[2] % 2 == 0)
        {
          for (auto &n : n_coarse_cells)
            n /= 2;
          ++n_voxel_levels;
        }
      GridGenerator::subdivided_hyper_rectangle(
        triangulation,
        {n_coarse_cells[0], n_coarse_cells[1], n_coarse_cells[2]},
        Point<3>(0, 0, 0),
        Point<3>(volume.length(0), volume.length(1), volume.length(2)),
        /*colorize = */ true);
      mesh_is_periodic = periodic;
      if (periodic)
        {
          std::vector<GridTools::PeriodicFacePair<
            parallel::distributed::Triangulation<3>::cell_iterator>>
            pairs;
          for (unsigned int d = 0; d < 3; ++d)
            GridTools::collect_periodic_faces(
              triangulation, 2 * d, 2 * d + 1, d, pairs);
          triangulation.add_periodicity(pairs);
        }
      triangulation.refine_global(n_voxel_levels);
      // Each element is one voxel: its material is that of its centre.
      for (const auto &cell : triangulation.active_cell_iterators())
        if (!cell->is_artificial())
          {
            unsigned int index[3];
            for (unsigned int d = 0; d < 3; ++d)
              index[d] = std::min(volume.n_voxels(d) - 1,
                                  static_cast<unsigned int>(
                                    cell->center()[d] / volume.voxel_size(d)));
            cell->set_material_id(volume.voxel(index[0], index[1], index[2]));
          }
    }


    void
    VolumeCellProblem::setup_dofs()
    {
      TimerOutput::Scope scope(timer, "mesh and dofs");
      dof_handler.distribute_dofs(fe);
      // level DoFs only where multigrid runs (not on the periodic mesh)
      if (!mesh_is_periodic && uses_multigrid(BoundaryCondition::kubc))
        dof_handler.distribute_mg_dofs();
      locally_owned_dofs = dof_handler.locally_owned_dofs();
      DoFTools::extract_locally_relevant_dofs(dof_handler,
                                              locally_relevant_dofs);
    }


    types::global_dof_index
    VolumeCellProblem::n_dofs() const
    {
      return dof_handler.n_dofs();
    }


    types::global_cell_index
    VolumeCellProblem::n_cells() const
    {
      return triangulation.n_global_active_cells();
    }


    unsigned int
    VolumeCellProblem::n_coarse_dofs() const
    {
      return 3 * (n_coarse_cells[0] + 1) * (n_coarse_cells[1] + 1)
             * (n_coarse_cells[2] + 1);
    }


    bool
    VolumeCellProblem::uses_multigrid(const BoundaryCondition bc) const
    {
      // As in 2D: deal.II 9.4's matrix-free level transfer does not carry
      // periodicity constraints, so periodic problems keep AMG.
      return parameters.preconditioner == CellPreconditioner::multigrid
             && bc != BoundaryCondition::periodic
             && n_coarse_dofs() <= CellProblem::max_coarse_dofs;
    }


    std::vector<double>
    VolumeCellProblem::phase_fractions() const
    {
      std::vector<double> measure(stiffness.size(), 0.);
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          measure[cell->material_id()] += cell->measure();
      Utilities::MPI::sum(measure, mpi_communicator, measure);
      const double total
        = volume.length(0) * volume.length(1) * volume.length(2);
      for (double &m : measure)
        m /= total;
      return measure;
    }


    namespace
    {
      /// The unit load of case k: Voigt strain or stress e_k.
      VoigtVector6
      unit_load(const unsigned int k)
      {
        VoigtVector6 e;
        e[k] = 1;
        return e;
      }


      /// Voigt strain (xx, yy, zz, gamma_yz, gamma_xz, gamma_xy) of vector
      /// shape function i at quadrature point q.
      VoigtVector6
      shape_strain(const FEValues<3>      &fe_values,
                   const FiniteElement<3> &fe,
                   const unsigned int      i,
                   const unsigned int      q)
      {
        const unsigned int  c = fe.system_to_component_index(i).first;
        const Tensor<1, 3> &g = fe_values.shape_grad(i, q);
        VoigtVector6        B;
        B[c] = g[c];
        // gamma_yz (3), gamma_xz (4), gamma_xy (5): the shear of the plane
        // normal to axis a couples the two other components.
        for (unsigned int a = 0; a < 3; ++a)
          {
            const unsigned int j = (a + 1) % 3, k = (a + 2) % 3;
            if (c == j)
              B[3 + a] += g[k];
            if (c == k)
              B[3 + a] += g[j];
          }
        return B;
      }


      /// Constrain the components @p components of the vertex at @p point
      /// to zero, on every rank that sees that vertex.
      void
      pin_vertex(const DoFHandler<3>             &dof_handler,
                 const Point<3>                  &point,
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


    std::vector<std::pair<Point<3>, std::vector<unsigned int>>>
    VolumeCellProblem::pinned_vertices(const BoundaryCondition bc) const
    {
      switch (bc)
        {
          case BoundaryCondition::periodic:
            // w is periodic up to a translation: pin the interior vertex
            // nearest to the centre (at least 2 voxels along each axis).
            return {{Point<3>((volume.n_voxels(0) / 2) * volume.voxel_size(0),
                              (volume.n_voxels(1) / 2) * volume.voxel_size(1),
                              (volume.n_voxels(2) / 2) * volume.voxel_size(2)),
                     {0, 1, 2}}};
          case BoundaryCondition::subc:
            // Pure traction: remove the six rigid motions at three
            // corners (vertices of the coarsest mesh, so on every
            // multigrid level); the load is self-equilibrated, so these
            // supports carry no force.
            return {{Point<3>(0, 0, 0), {0, 1, 2}},
                    {Point<3>(volume.length(0), 0, 0), {1, 2}},
                    {Point<3>(0, volume.length(1), 0), {2}}};
          case BoundaryCondition::kubc:
            break;
        }
      return {};
    }


    void
    VolumeCellProblem::make_constraints(const BoundaryCondition bc)
    {
      constraints.clear();
      constraints.reinit(locally_relevant_dofs);
      double h = volume.voxel_size(0);
      for (unsigned int d = 1; d < 3; ++d)
        h = std::min(h, volume.voxel_size(d));
      const double tolerance = 1e-3 * h;

      switch (bc)
        {
          case BoundaryCondition::kubc:
            // Fluctuation w = 0 on the six faces.
            for (types::boundary_id id = 0; id < 6; ++id)
              VectorTools::interpolate_boundary_values(
                dof_handler, id, Functions::ZeroFunction<3>(3), constraints);
            break;
          case BoundaryCondition::periodic:
            for (unsigned int d = 0; d < 3; ++d)
              DoFTools::make_periodicity_constraints(
                dof_handler, 2 * d, 2 * d + 1, d, constraints);
            break;
          case BoundaryCondition::subc:
            break;
        }
      const auto pins = pinned_vertices(bc);
      for (const auto &[point, components] : pins)
        pin_vertex(dof_handler,
                   point,
                   components,
                   tolerance,
                   locally_relevant_dofs,
                   constraints);
      constraints.close();
    }


    void
    VolumeCellProblem::compute_element_data(const BoundaryCondition bc)
    {
      // Every element is the same box: its matrix and loads depend on its
      // phase only. Computed on any cell this rank sees.
      const QGauss<3> quadrature(2);
      FEValues<3>     fe_values(fe,
                            quadrature,
                            update_gradients | update_JxW_values);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            break;
          }
      const unsigned int        n = fe.n_dofs_per_cell();
      std::vector<VoigtVector6> B(n);
      strain_integral.reinit(6, n);
      element_matrix.assign(stiffness.size(), FullMatrix<double>(n, n));
      element_load.resize(stiffness.size());
      const bool strain_driven = bc != BoundaryCondition::subc;
      for (unsigned int m = 0; m < stiffness.size(); ++m)
        for (auto &load : element_load[m])
          load.reinit(n);
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const double JxW = fe_values.JxW(q);
          for (unsigned int i = 0; i < n; ++i)
            {
              B[i] = shape_strain(fe_values, fe, i, q);
              for (unsigned int a = 0; a < 6; ++a)
                strain_integral(a, i) += B[i][a] * JxW;
            }
          for (unsigned int m = 0; m < stiffness.size(); ++m)
            {
              const VoigtMatrix6 &C = stiffness[m];
              for (unsigned int i = 0; i < n; ++i)
                {
                  const VoigtVector6 CB_i = C * B[i];
                  for (unsigned int j = 0; j < n; ++j)
                    element_matrix[m](i, j) += (CB_i * B[j]) * JxW;
                  // Load per unit macroscopic strain (-C E) or stress.
                  for (unsigned int k = 0; k < 6; ++k)
                    element_load[m][k](i)
                      += (strain_driven ? -(CB_i * unit_load(k)) : B[i][k])
                         * JxW;
                }
            }
        }
    }


    void
    VolumeCellProblem::assemble(const BoundaryCondition bc)
    {
      TimerOutput::Scope scope(timer, "assemble");
      compute_element_data(bc);
      DynamicSparsityPattern dsp(locally_relevant_dofs);
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 locally_owned_dofs,
                                                 mpi_communicator,
                                                 locally_relevant_dofs);
      system_matrix.reinit(locally_owned_dofs,
                           locally_owned_dofs,
                           dsp,
                           mpi_communicator);
      for (auto &rhs : system_rhs)
        rhs.reinit(locally_owned_dofs, mpi_communicator);
      load_scale.fill(0.);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int m = cell->material_id();
            cell->get_dof_indices(dofs);
            constraints.distribute_local_to_global(element_matrix[m],
                                                   element_load[m][0],
                                                   dofs,
                                                   system_matrix,
                                                   system_rhs[0]);
            // homogeneous constraints: the other loads need no matrix
            for (unsigned int k = 1; k < 6; ++k)
              constraints.distribute_local_to_global(element_load[m][k],
                                                     dofs,
                                                     system_rhs[k]);
            for (unsigned int k = 0; k < 6; ++k)
              load_scale[k] += element_load[m][k].norm_sqr();
          }
      system_matrix.compress(VectorOperation::add);
      for (auto &rhs : system_rhs)
        rhs.compress(VectorOperation::add);
      for (double &scale : load_scale)
        scale = std::sqrt(Utilities::MPI::sum(scale, mpi_communicator));
    }


    void
    VolumeCellProblem::setup_preconditioner()
    {
      TimerOutput::Scope scope(timer, "AMG setup");
      // The six rigid-body modes of 3D elasticity (three translations,
      // three rotations about the centre) as ML's near-null space.
      const Epetra_Map &map
        = system_matrix.trilinos_matrix().OperatorDomainMap();
      rigid_body_modes = std::make_unique<Epetra_MultiVector>(map, 6);
      const Point<3> centre(0.5 * volume.length(0),
                            0.5 * volume.length(1),
                            0.5 * volume.length(2));
      const double   scale
        = 1. / std::max({volume.length(0), volume.length(1), volume.length(2)});
      const Quadrature<3> support_points(fe.get_unit_support_points());
      FEValues<3> fe_values(fe, support_points, update_quadrature_points);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (locally_owned_dofs.is_element(dofs[i]))
                {
                  const auto local
                    = locally_owned_dofs.index_within_set(dofs[i]);
                  const unsigned int c = fe.system_to_component_index(i).first;
                  const Tensor<1, 3> x
                    = scale * (fe_values.quadrature_point(i) - centre);
                  for (unsigned int d = 0; d < 3; ++d)
                    (*rigid_body_modes)[d][local] = (c == d ? 1. : 0.);
                  // rotation about axis a: u = e_a x x
                  for (unsigned int a = 0; a < 3; ++a)
                    {
                      const unsigned int j = (a + 1) % 3, k = (a + 2) % 3;
                      (*rigid_body_modes)[3 + a][local] = c == j   ? -x[k]
                                                          : c == k ? x[j]
                                                                   : 0.;
                    }
                }
          }
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = false;
      data.smoother_sweeps       = 2;
      data.aggregation_threshold = 1e-4;
      Teuchos::ParameterList              ml_parameters;
      std::unique_ptr<Epetra_MultiVector> unused_constant_modes;
      data.set_parameters(ml_parameters, unused_constant_modes, system_matrix);
      ml_parameters.set("null space: type", "pre-computed");
      ml_parameters.set("null space: dimension", 6);
      ml_parameters.set("null space: vectors", rigid_body_modes->Values());
      preconditioner.initialize(system_matrix, ml_parameters);
    }


    namespace
    {
      /// Run @p solve (a CG solve), turning Trilinos's and deal.II's
      /// failures into errors that say what to change.
      template <typename F>
      void
      run_volume_cg(const BoundaryCondition bc,
                    const unsigned int      load_case,
                    const double            rhs_norm,
                    const F                &solve)
      {
        const std::string which = "The " + to_string(bc)
                                  + " cell problem, load case "
                                  + std::to_string(load_case);
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
                           + ". Raise 'Cell problem/Max iterations' or "
                             "'Cell problem/Solver tolerance'.");
          }
        catch (const ExceptionBase &e)
          {
            std::ostringstream info;
            e.print_info(info);
            throw RunError(which + ", failed in CG: " + info.str()
                           + " This happens when 'Cell problem/Solver "
                             "tolerance' is below what double precision "
                             "can reach; raise it (1e-10 is ample).");
          }
      }
    } // namespace


    void
    VolumeCellProblem::solve_with_amg(
      const BoundaryCondition                       bc,
      std::array<TrilinosWrappers::MPI::Vector, 6> &solutions,
      VolumeCellProblemResult                      &result)
    {
      assemble(bc);
      setup_preconditioner();
      for (unsigned int k = 0; k < 6; ++k)
        {
          TimerOutput::Scope         scope(timer, "CG solve");
          SolverControl              control(parameters.max_iterations,
                                parameters.solver_tolerance * load_scale[k],
                                /*log_history = */ false,
                                /*log_result = */ false);
          TrilinosWrappers::SolverCG cg(control);
          run_volume_cg(bc, k, load_scale[k], [&]() {
            cg.solve(system_matrix,
                     solutions[k],
                     system_rhs[k],
                     preconditioner);
          });
          result.load_cases[k].cg_iterations = control.last_step();
        }
    }


    void
    VolumeCellProblem::solve_with_multigrid(
      const BoundaryCondition                       bc,
      std::array<TrilinosWrappers::MPI::Vector, 6> &solutions,
      VolumeCellProblemResult                      &result)
    {
      // The element data of the averages (the assembly computes them on
      // the AMG path).
      compute_element_data(bc);
      internal::VolumeLevelConstraints levels;
      levels.zero_boundary = bc == BoundaryCondition::kubc;
      levels.pins          = pinned_vertices(bc);
      levels.tolerance
        = 1e-3
          * std::min(
            {volume.voxel_size(0), volume.voxel_size(1), volume.voxel_size(2)});
      // The coefficient of a cell on any level: the mean stiffness of the
      // voxels it covers.
      const auto stiffness_over_box = [&](const Point<3> &lower,
                                          const Point<3> &upper) {
        int first[3], last[3];
        for (unsigned int d = 0; d < 3; ++d)
          {
            first[d]
              = static_cast<int>(std::lround(lower[d] / volume.voxel_size(d)));
            last[d]
              = static_cast<int>(std::lround(upper[d] / volume.voxel_size(d)));
          }
        VoigtMatrix6 sum;
        for (int k = first[2]; k < last[2]; ++k)
          for (int j = first[1]; j < last[1]; ++j)
            for (int i = first[0]; i < last[0]; ++i)
              sum += stiffness[volume.voxel(i, j, k)];
        return VoigtMatrix6(sum
                            / double((last[0] - first[0]) * (last[1] - first[1])
                                     * (last[2] - first[2])));
      };
      const auto solver = internal::make_volume_multigrid_solver(
        dof_handler, constraints, levels, stiffness_over_box, timer);
      for (unsigned int k = 0; k < 6; ++k)
        {
          TimerOutput::Scope scope(timer, "CG solve");
          const double       rhs_norm
            = solver->assemble_rhs(unit_load(k), bc != BoundaryCondition::subc);
          SolverControl control(parameters.max_iterations,
                                parameters.solver_tolerance * rhs_norm,
                                /*log_history = */ false,
                                /*log_result = */ false);
          run_volume_cg(bc, k, rhs_norm, [&]() {
            solver->solve(control, solutions[k]);
          });
          result.load_cases[k].cg_iterations = control.last_step();
        }
    }


    VolumeCellProblemResult
    VolumeCellProblem::solve(const BoundaryCondition bc)
    {
      const auto start = std::chrono::steady_clock::now();
      if ((bc == BoundaryCondition::periodic) != mesh_is_periodic)
        {
          setup_mesh(bc == BoundaryCondition::periodic);
          setup_dofs();
        }
      make_constraints(bc);

      VolumeCellProblemResult result;
      result.boundary_condition = bc;
      result.multigrid          = uses_multigrid(bc);
      const bool strain_driven  = bc != BoundaryCondition::subc;
      std::array<TrilinosWrappers::MPI::Vector, 6> solutions;
      for (auto &solution : solutions)
        solution.reinit(locally_owned_dofs, mpi_communicator);
      if (result.multigrid)
        solve_with_multigrid(bc, solutions, result);
      else
        solve_with_amg(bc, solutions, result);
      std::array<TrilinosWrappers::MPI::Vector, 6> fields;
      for (unsigned int k = 0; k < 6; ++k)
        {
          constraints.distribute(solutions[k]);
          fields[k].reinit(locally_owned_dofs,
                           locally_relevant_dofs,
                           mpi_communicator);
          fields[k] = solutions[k];
        }

      // Volume averages: on an element of phase m, int eps = G u_K (+ E
      // |K|), int sigma = C_m int eps, G the strain integrals of the shape
      // functions.
      {
        TimerOutput::Scope                   scope(timer, "averages");
        std::vector<double>                  sums(6 * 12, 0.);
        const unsigned int                   n = fe.n_dofs_per_cell();
        std::vector<types::global_dof_index> dofs(n);
        Vector<double>                       u(n), eps(6);
        const double                         cell_measure
          = volume.voxel_size(0) * volume.voxel_size(1) * volume.voxel_size(2);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dofs);
              const VoigtMatrix6 &C = stiffness[cell->material_id()];
              for (unsigned int k = 0; k < 6; ++k)
                {
                  for (unsigned int i = 0; i < n; ++i)
                    u[i] = fields[k][dofs[i]];
                  strain_integral.vmult(eps, u);
                  VoigtVector6 e;
                  for (unsigned int a = 0; a < 6; ++a)
                    e[a]
                      = eps[a] + (strain_driven && a == k ? cell_measure : 0.);
                  const VoigtVector6 s = C * e;
                  for (unsigned int a = 0; a < 6; ++a)
                    {
                      sums[12 * k + a] += s[a];
                      sums[12 * k + 6 + a] += e[a];
                    }
                }
            }
        Utilities::MPI::sum(sums, mpi_communicator, sums);
        const double total
          = volume.length(0) * volume.length(1) * volume.length(2);
        for (unsigned int k = 0; k < 6; ++k)
          for (unsigned int a = 0; a < 6; ++a)
            {
              result.load_cases[k].mean_stress[a] = sums[12 * k + a] / total;
              result.load_cases[k].mean_strain[a]
                = sums[12 * k + 6 + a] / total;
            }
      }

      // Columns of C (strain-driven) or of S (SUBC).
      VoigtMatrix6 M;
      for (unsigned int j = 0; j < 6; ++j)
        for (unsigned int i = 0; i < 6; ++i)
          M[i][j] = strain_driven ? result.load_cases[j].mean_stress[i]
                                  : result.load_cases[j].mean_strain[i];
      result.properties = strain_driven ? volume_properties_from_stiffness(M)
                                        : volume_properties_from_compliance(M);
      result.wall_time  = std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start)
                           .count();
      return result;
    }
  } // namespace homogenization
} // namespace tribodyn
