// Integration of a cell problem's fields over one cell, shared by the
// volume averages (source/homogenization/cell_assembly.cc) and the field
// output (source/homogenization/cell_output.cc). Private to the
// homogenization sources.
#ifndef tribodyn_source_homogenization_cell_integrals_h
#define tribodyn_source_homogenization_cell_integrals_h

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_vector.h>
#include <tribodyn/homogenization/cell_problem.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      using dealii::FEValues;
      using dealii::Function;
      using dealii::Point;
      using dealii::SymmetricTensor;
      namespace FEValuesExtractors = dealii::FEValuesExtractors;
      namespace TrilinosWrappers   = dealii::TrilinosWrappers;

      /// u = E x for the Voigt strain E (engineering shears): (e_xx, e_yy,
      /// gamma_xy) in 2D, (e_xx, e_yy, e_zz, gamma_yz, gamma_xz, gamma_xy)
      /// in 3D.
      template <int dim>
      class AffineDisplacement : public Function<dim>
      {
      public:
        using Voigt = typename CellProblem<dim>::Voigt;

        explicit AffineDisplacement(const Voigt &strain)
            : Function<dim>(dim)
            , strain(strain)
        {
        }

        double
        value(const Point<dim> &p, const unsigned int component) const override
        {
          double u = 0;
          for (unsigned int d = 0; d < dim; ++d)
            // the shear of the axes (component, d): in 3D that of the
            // plane normal to the third axis a = 3 - component - d, Voigt
            // index 3 + a
            u += (d == component
                    ? strain[d]
                    : 0.5 * strain[dim == 2 ? 2 : 6 - component - d])
                 * p[d];
          return u;
        }

      private:
        const Voigt strain;
      };


      /// Integrate eps = E + eps(solution) (E = 0 for SUBC), sigma = C eps
      /// and sigma_zz = c_z . eps of plane strain over the cell
      /// @p fe_values was reinitialized on (Voigt vectors of 3 entries).
      /// @p strains is scratch space.
      template <typename VectorType>
      inline ElementIntegrals<3>
      integrate_cell(const FEValues<2>                  &fe_values,
                     const VectorType                   &solution,
                     const VoigtVector                  &macro_strain,
                     const ElasticPhase                 &phase,
                     std::vector<SymmetricTensor<2, 2>> &strains)
      {
        const FEValuesExtractors::Vector displacement(0);
        fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                 strains);
        const VoigtMatrix  &C = phase.C;
        ElementIntegrals<3> integrals;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const VoigtVector eps
              = macro_strain
                + VoigtVector(
                  {strains[q][0][0], strains[q][1][1], 2 * strains[q][0][1]});
            const double JxW = fe_values.JxW(q);
            integrals.strain += eps * JxW;
            integrals.stress += (C * eps) * JxW;
            integrals.stress_zz += (phase.c_z * eps) * JxW;
            integrals.measure += JxW;
          }
        return integrals;
      }
    } // namespace internal


    // Tabulated elements (3D): on an element of phase m, int eps = G u_K +
    // E |K| and int sigma = C_m int eps, G the strain integrals of the
    // shape functions (tabulate_elements()). Otherwise (2D) the strains
    // are integrated at the Gauss points (degree + 1 per direction) of
    // every cell, with the plane-strain sigma_zz.
    template <int dim>
    template <typename F>
    void
    CellProblem<dim>::for_each_element_integral(
      const BoundaryCondition          bc,
      const std::vector<unsigned int> &load_cases,
      const std::vector<
        const dealii::LinearAlgebra::distributed::Vector<double> *> &fields,
      const F                                                       &f) const
    {
      const bool strain_driven = bc != BoundaryCondition::subc;
      if constexpr (tabulated_elements)
        {
          const unsigned int                           n = fe.n_dofs_per_cell();
          std::vector<dealii::types::global_dof_index> dofs(n);
          dealii::Vector<double>                       u(n), eps(n_voigt);
          const auto                                   h = element_size();
          double                                       cell_measure = h[0];
          for (unsigned int d = 1; d < dim; ++d)
            cell_measure *= h[d];
          ElementIntegrals integrals;
          integrals.measure = cell_measure;
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                cell->get_dof_indices(dofs);
                const VoigtMatrixType &C
                  = Traits::stiffness(phases[cell->material_id()]);
                for (unsigned int k = 0; k < fields.size(); ++k)
                  {
                    for (unsigned int i = 0; i < n; ++i)
                      u[i] = (*fields[k])[dofs[i]];
                    strain_integral.vmult(eps, u);
                    for (unsigned int a = 0; a < n_voigt; ++a)
                      integrals.strain[a]
                        = eps[a]
                          + (strain_driven && a == load_cases[k] ? cell_measure
                                                                 : 0.);
                    integrals.stress = C * integrals.strain;
                    f(cell, k, integrals);
                  }
              }
        }
      else
        {
          static_assert(dim == 2, "per-cell integrals: plane strain only");
          const dealii::QGauss<2> quadrature(parameters.fe_degree + 1);
          dealii::FEValues<2>     fe_values(fe,
                                        quadrature,
                                        dealii::update_gradients
                                          | dealii::update_JxW_values);
          std::vector<dealii::SymmetricTensor<2, 2>> strains(quadrature.size());
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                fe_values.reinit(cell);
                for (unsigned int k = 0; k < fields.size(); ++k)
                  f(cell,
                    k,
                    internal::integrate_cell(fe_values,
                                             *fields[k],
                                             strain_driven
                                               ? unit_load(load_cases[k])
                                               : Voigt(),
                                             phases[cell->material_id()],
                                             strains));
              }
        }
    }
  } // namespace homogenization
} // namespace tribodyn

#endif
