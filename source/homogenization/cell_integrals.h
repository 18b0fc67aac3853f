// Integration of a cell problem's fields over one cell, shared by the
// postprocessing (source/homogenization/cell_problem.cc) and the field
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

      /// u = E x for the Voigt strain E = (e_xx, e_yy, gamma_xy).
      class AffineDisplacement : public Function<2>
      {
      public:
        explicit AffineDisplacement(const VoigtVector &strain)
            : Function<2>(2)
            , strain(strain)
        {
        }

        double
        value(const Point<2> &p, const unsigned int component) const override
        {
          const double e_xy = 0.5 * strain[2];
          return component == 0 ? strain[0] * p[0] + e_xy * p[1]
                                : e_xy * p[0] + strain[1] * p[1];
        }

      private:
        const VoigtVector strain;
      };


      /// Integrals over one cell of the strain, the stress and sigma_zz.
      struct CellIntegrals
      {
        VoigtVector strain;
        VoigtVector stress;
        double      stress_zz = 0;
        double      measure   = 0;
      };


      /// Integrate eps = E + eps(solution) (E = 0 for SUBC), sigma = C eps
      /// and sigma_zz = c_z . eps over the cell @p fe_values
      /// was reinitialized on. @p strains is scratch space.
      template <typename VectorType>
      inline CellIntegrals
      integrate_cell(const FEValues<2>                  &fe_values,
                     const VectorType                   &solution,
                     const VoigtVector                  &macro_strain,
                     const ElasticPhase                 &phase,
                     std::vector<SymmetricTensor<2, 2>> &strains)
      {
        const FEValuesExtractors::Vector displacement(0);
        fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                 strains);
        const VoigtMatrix &C = phase.C;
        CellIntegrals      integrals;
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


      /// Call @p f(cell, k, integrals) for every locally owned cell of
      /// @p dof_handler and every field k of @p solutions (with its
      /// macroscopic strain @p macro_strains[k]) with the integrals of
      /// integrate_cell() (Gauss quadrature of degree + 1 points per
      /// direction): one pass over the cells for all fields.
      template <typename VectorType, typename F>
      void
      for_each_owned_cell_integral(
        const dealii::DoFHandler<2>           &dof_handler,
        const dealii::FiniteElement<2>        &fe,
        const unsigned int                     degree,
        const std::vector<ElasticPhase>       &phases,
        const std::vector<const VectorType *> &solutions,
        const std::vector<VoigtVector>        &macro_strains,
        const F                               &f)
      {
        const dealii::QGauss<2> quadrature(degree + 1);
        FEValues<2>             fe_values(
          fe, quadrature, dealii::update_gradients | dealii::update_JxW_values);
        std::vector<SymmetricTensor<2, 2>> strains(quadrature.size());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fe_values.reinit(cell);
              for (unsigned int k = 0; k < solutions.size(); ++k)
                f(cell,
                  k,
                  integrate_cell(fe_values,
                                 *solutions[k],
                                 macro_strains[k],
                                 phases[cell->material_id()],
                                 strains));
            }
      }
    } // namespace internal
  }   // namespace homogenization
} // namespace tribodyn

#endif
