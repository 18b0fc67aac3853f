// The assembly of the cell problems (declared in cell_problem.h): the
// element integrals of linear elasticity in Voigt notation, the assembled
// matrix and right-hand sides of the AMG path, and the volume averages of
// the solutions. The same integrals serve both dimensions; what changes
// is where they are evaluated (see tabulated_elements below).
#include "cell_integrals.h"

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

    // @sect3{The element integrals}
    //
    // With Voigt vectors the strain of a vector-valued shape function
    // phi_i = N e_c is B_i: the normal strain eps_cc = dN/dx_c and, for
    // each shear of the plane of axes (j, k), gamma_jk = dN/dx_k when c =
    // j and dN/dx_j when c = k. In 2D the only shear is xy (Voigt index
    // 2); in 3D the shear of the plane normal to axis a is at index 3 + a
    // (yz, xz, xy).

    namespace
    {
      template <int dim>
      Tensor<1, CellTraits<dim>::n_voigt>
      shape_strain(const FEValues<dim>      &fe_values,
                   const FiniteElement<dim> &fe,
                   const unsigned int        i,
                   const unsigned int        q)
      {
        const unsigned int    c = fe.system_to_component_index(i).first;
        const Tensor<1, dim> &g = fe_values.shape_grad(i, q);
        Tensor<1, CellTraits<dim>::n_voigt> B;
        B[c] = g[c];
        for (unsigned int a = (dim == 2 ? 2 : 0); a < 3; ++a)
          {
            const unsigned int j = (a + 1) % 3, k = (a + 2) % 3;
            const unsigned int shear = dim == 2 ? 2 : 3 + a;
            if (c == j)
              B[shear] += g[k];
            if (c == k)
              B[shear] += g[j];
          }
        return B;
      }


      /// Add the integrals of the element matrix int B_i . C B_j and of
      /// the element loads of the unit loads, int B_i . (-C E_k) for the
      /// strain-driven conditions and int B_i . Sigma_k for SUBC, over the
      /// cell @p fe_values was reinitialized on. @p B is scratch space.
      template <int dim, typename Voigt, typename VoigtMatrixType>
      void
      add_element_integrals(
        const FEValues<dim>                                  &fe_values,
        const FiniteElement<dim>                             &fe,
        const VoigtMatrixType                                &C,
        const bool                                            strain_driven,
        std::vector<Voigt>                                   &B,
        FullMatrix<double>                                   &matrix,
        std::array<Vector<double>, CellTraits<dim>::n_voigt> &loads)
      {
        constexpr unsigned int     n_voigt = CellTraits<dim>::n_voigt;
        const unsigned int         n       = fe.n_dofs_per_cell();
        std::array<Voigt, n_voigt> load;
        for (unsigned int k = 0; k < n_voigt; ++k)
          {
            Voigt unit;
            unit[k] = 1.;
            load[k] = strain_driven ? Voigt(-(C * unit)) : unit;
          }
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const double JxW = fe_values.JxW(q);
            for (unsigned int i = 0; i < n; ++i)
              B[i] = shape_strain(fe_values, fe, i, q);
            for (unsigned int i = 0; i < n; ++i)
              {
                const Voigt CB_i = C * B[i];
                for (unsigned int j = 0; j < n; ++j)
                  matrix(i, j) += (CB_i * B[j]) * JxW;
                for (unsigned int k = 0; k < n_voigt; ++k)
                  loads[k](i) += (B[i] * load[k]) * JxW;
              }
          }
      }
    } // namespace


    // @sect3{Tabulated elements}
    //
    // Every element is the same box, so its matrix and loads depend on its
    // phase only: in 3D they are computed once per phase here (integrating
    // a 24 x 24 matrix on each of 10^6 cells would dominate the set-up),
    // and the averages use the integrals over the element of the strains
    // of the shape functions. In 2D they are still evaluated on every cell
    // (tabulated_elements is false): the results are the same to
    // round-off, not to the bit, and the 2D results are the reference of
    // its tests and benches.

    template <int dim>
    void
    CellProblem<dim>::tabulate_elements(const BoundaryCondition bc)
    {
      const QGauss<dim> quadrature(parameters.fe_degree + 1);
      FEValues<dim>     fe_values(fe,
                              quadrature,
                              update_gradients | update_JxW_values);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            break;
          }
      const unsigned int n = fe.n_dofs_per_cell();
      std::vector<Voigt> B(n);
      element_matrix.assign(phases.size(), FullMatrix<double>(n, n));
      element_load.resize(phases.size());
      for (unsigned int m = 0; m < phases.size(); ++m)
        {
          for (auto &load : element_load[m])
            load.reinit(n);
          add_element_integrals(fe_values,
                                fe,
                                Traits::stiffness(phases[m]),
                                bc != BoundaryCondition::subc,
                                B,
                                element_matrix[m],
                                element_load[m]);
        }
      strain_integral.reinit(n_voigt, n);
      for (const unsigned int q : fe_values.quadrature_point_indices())
        for (unsigned int i = 0; i < n; ++i)
          {
            const Voigt B_i = shape_strain(fe_values, fe, i, q);
            for (unsigned int a = 0; a < n_voigt; ++a)
              strain_integral(a, i) += B_i[a] * fe_values.JxW(q);
          }
    }


    // @sect3{The assembled system of the AMG path}

    template <int dim>
    void
    CellProblem<dim>::assemble(const BoundaryCondition bc)
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
      const QGauss<dim>  quadrature(parameters.fe_degree + 1);
      FEValues<dim>      fe_values(fe,
                              quadrature,
                              update_gradients | update_JxW_values);
      const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
      FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
      std::array<Vector<double>, n_voigt> cell_rhs;
      for (auto &r : cell_rhs)
        r.reinit(dofs_per_cell);
      std::vector<Voigt> B(dofs_per_cell);
      load_scale.fill(0.);
      std::vector<types::global_dof_index> dof_indices(dofs_per_cell);

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const FullMatrix<double>                  *matrix = &cell_matrix;
            const std::array<Vector<double>, n_voigt> *loads  = &cell_rhs;
            if constexpr (tabulated_elements)
              {
                matrix = &element_matrix[cell->material_id()];
                loads  = &element_load[cell->material_id()];
              }
            else
              {
                fe_values.reinit(cell);
                cell_matrix = 0;
                for (auto &r : cell_rhs)
                  r = 0;
                add_element_integrals(fe_values,
                                      fe,
                                      Traits::stiffness(
                                        phases[cell->material_id()]),
                                      strain_driven,
                                      B,
                                      cell_matrix,
                                      cell_rhs);
              }
            for (unsigned int k = 0; k < n_voigt; ++k)
              load_scale[k] += (*loads)[k].norm_sqr();
            cell->get_dof_indices(dof_indices);
            constraints.distribute_local_to_global(
              *matrix, (*loads)[0], dof_indices, system_matrix, system_rhs[0]);
            // The constraints are homogeneous, so the other right-hand
            // sides need no matrix.
            for (unsigned int k = 1; k < n_voigt; ++k)
              constraints.distribute_local_to_global((*loads)[k],
                                                     dof_indices,
                                                     system_rhs[k]);
          }
      system_matrix.compress(VectorOperation::add);
      for (auto &rhs : system_rhs)
        rhs.compress(VectorOperation::add);
      for (double &scale : load_scale)
        scale = std::sqrt(Utilities::MPI::sum(scale, mpi_communicator));
    }


    // @sect3{The volume averages}
    //
    // The sums over the cells of the element integrals
    // (for_each_element_integral() in cell_integrals.h, shared with the
    // field output).

    template <int dim>
    CellLoadCase<dim>
    CellProblem<dim>::postprocess(
      const BoundaryCondition                           bc,
      const unsigned int                                load_case,
      const LinearAlgebra::distributed::Vector<double> &field) const
    {
      // Sums: stress, strain (n_voigt each), sigma_zz.
      std::vector<double> sum(2 * n_voigt + 1, 0.);
      for_each_element_integral(bc,
                                {load_case},
                                {&field},
                                [&](const auto &,
                                    const unsigned int,
                                    const ElementIntegrals &integrals) {
                                  for (unsigned int a = 0; a < n_voigt; ++a)
                                    {
                                      sum[a] += integrals.stress[a];
                                      sum[n_voigt + a] += integrals.strain[a];
                                    }
                                  sum[2 * n_voigt] += integrals.stress_zz;
                                });
      Utilities::MPI::sum(sum, mpi_communicator, sum);
      const double      total = measure();
      CellLoadCase<dim> r;
      for (unsigned int a = 0; a < n_voigt; ++a)
        {
          r.mean_stress[a] = sum[a] / total;
          r.mean_strain[a] = sum[n_voigt + a] / total;
        }
      r.mean_stress_zz = sum[2 * n_voigt] / total;
      return r;
    }


#define TRIBODYN_INSTANTIATE(dim)                                    \
  template void CellProblem<dim>::assemble(const BoundaryCondition); \
  template CellLoadCase<dim> CellProblem<dim>::postprocess(          \
    const BoundaryCondition,                                         \
    const unsigned int,                                              \
    const LinearAlgebra::distributed::Vector<double> &) const;
    TRIBODYN_INSTANTIATE(2)
    TRIBODYN_INSTANTIATE(3)
#undef TRIBODYN_INSTANTIATE
    template void
    CellProblem<2>::tabulate_elements(const BoundaryCondition);
    template void
    CellProblem<3>::tabulate_elements(const BoundaryCondition);
  } // namespace homogenization
} // namespace tribodyn
