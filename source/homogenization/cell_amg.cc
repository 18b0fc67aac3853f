// The AMG path of the cell problems ('Cell problem/Preconditioner = AMG',
// and the periodic problems): the assembled stiffness matrix and ML's
// smoothed aggregation with the rigid-body modes. The rest of CellProblem
// is in cell_problem.cc.
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <tribodyn/homogenization/cell_problem.h>

namespace tribodyn
{
  namespace homogenization
  {
    using namespace dealii;

    namespace
    {
      /// Voigt strain (xx, yy, gamma_xy) of vector shape function i.
      inline VoigtVector
      shape_strain(const FEValues<2>      &fe_values,
                   const FiniteElement<2> &fe,
                   const unsigned int      i,
                   const unsigned int      q)
      {
        const unsigned int  component = fe.system_to_component_index(i).first;
        const Tensor<1, 2> &grad      = fe_values.shape_grad(i, q);
        VoigtVector         B;
        if (component == 0)
          {
            B[0] = grad[0];
            B[2] = grad[1];
          }
        else
          {
            B[1] = grad[1];
            B[2] = grad[0];
          }
        return B;
      }


    } // namespace


    void
    CellProblem::assemble(const BoundaryCondition bc)
    {
      TimerOutput::Scope     scope(timer, "assemble");
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

      const bool         strain_driven = bc != BoundaryCondition::subc;
      const QGauss<2>    quadrature(parameters.fe_degree + 1);
      FEValues<2>        fe_values(fe,
                            quadrature,
                            update_gradients | update_JxW_values);
      const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
      FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
      std::array<Vector<double>, 3> cell_rhs;
      for (auto &r : cell_rhs)
        r.reinit(dofs_per_cell);
      std::vector<VoigtVector> B(dofs_per_cell);
      load_scale.fill(0.);
      std::vector<types::global_dof_index> dof_indices(dofs_per_cell);

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            cell_matrix = 0;
            for (auto &r : cell_rhs)
              r = 0;
            const VoigtMatrix C = phases[cell->material_id()].C;
            // Load per unit macroscopic strain (C E) or stress (Sigma).
            std::array<VoigtVector, 3> load;
            for (unsigned int k = 0; k < 3; ++k)
              load[k] = strain_driven ? -(C * unit_load(k)) : unit_load(k);

            for (const unsigned int q : fe_values.quadrature_point_indices())
              {
                const double JxW = fe_values.JxW(q);
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  B[i] = shape_strain(fe_values, fe, i, q);
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  {
                    const VoigtVector CB_i = C * B[i];
                    for (unsigned int j = 0; j < dofs_per_cell; ++j)
                      cell_matrix(i, j) += (CB_i * B[j]) * JxW;
                    for (unsigned int k = 0; k < 3; ++k)
                      cell_rhs[k](i) += (B[i] * load[k]) * JxW;
                  }
              }
            for (unsigned int k = 0; k < 3; ++k)
              load_scale[k] += cell_rhs[k].norm_sqr();
            cell->get_dof_indices(dof_indices);
            constraints.distribute_local_to_global(cell_matrix,
                                                   cell_rhs[0],
                                                   dof_indices,
                                                   system_matrix,
                                                   system_rhs[0]);
            // The constraints are homogeneous, so the other right-hand
            // sides need no matrix.
            for (unsigned int k = 1; k < 3; ++k)
              constraints.distribute_local_to_global(cell_rhs[k],
                                                     dof_indices,
                                                     system_rhs[k]);
          }
      system_matrix.compress(VectorOperation::add);
      for (auto &rhs : system_rhs)
        rhs.compress(VectorOperation::add);
      for (double &scale : load_scale)
        scale = std::sqrt(Utilities::MPI::sum(scale, mpi_communicator));
    }


    void
    CellProblem::setup_preconditioner()
    {
      TimerOutput::Scope scope(timer, "AMG setup");
      // Rigid-body modes of 2D elasticity (two translations and the
      // rotation about the centre) as ML's near-null space: deal.II 9.4's
      // AdditionalData only takes the translations (constant modes), which
      // makes AMG on elasticity markedly slower.
      const Epetra_Map &map
        = system_matrix.trilinos_matrix().OperatorDomainMap();
      rigid_body_modes = std::make_unique<Epetra_MultiVector>(map, 3);
      const Point<2> centre(0.5 * morphology.width(),
                            0.5 * morphology.height());
      const double   scale
        = 1. / std::max(morphology.width(), morphology.height());

      const Quadrature<2> support_points(fe.get_unit_support_points());
      FEValues<2> fe_values(fe, support_points, update_quadrature_points);
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
                  const Point<2>    &x = fe_values.quadrature_point(i);
                  (*rigid_body_modes)[0][local] = (c == 0 ? 1. : 0.);
                  (*rigid_body_modes)[1][local] = (c == 1 ? 1. : 0.);
                  (*rigid_body_modes)[2][local]
                    = scale
                      * (c == 0 ? -(x[1] - centre[1]) : (x[0] - centre[0]));
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
      ml_parameters.set("null space: dimension", 3);
      ml_parameters.set("null space: vectors", rigid_body_modes->Values());
      preconditioner.initialize(system_matrix, ml_parameters);
    }
  } // namespace homogenization
} // namespace tribodyn
