#ifndef tribodyn_homogenization_homogenization_problem_h
#define tribodyn_homogenization_homogenization_problem_h

#include <deal.II/base/parameter_handler.h>
#include <tribodyn/core/material.h>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/problem.h>
#include <tribodyn/homogenization/cell_problem.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    /// Parameters of the subsection "Materials": the two phases.
    struct MaterialsParameters : TwoPhaseMaterials
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// Parameters of the subsection "Output" of the homogenization problem.
    struct HomogenizationOutputParameters
    {
      /// Write the stress/strain fields of every load case (VTU).
      bool write_fields = true;
      /// Write the material map (VTU) and the morphology grid (text).
      bool write_morphology = true;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /**
     * `set Problem = homogenization`: build the morphology, solve the cell
     * problems for each requested boundary condition, and report apparent
     * stiffnesses, engineering constants and the Voigt/Reuss estimates
     * (screen table, effective_properties.csv, summary.json, VTU fields).
     */
    class HomogenizationProblem : public Problem
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      HomogenizationProblem(dealii::ParameterHandler &prm,
                            const RunContext         &context);

      void
      run() override;

    private:
      RunContext                     context;
      MorphologyParameters           morphology_parameters;
      MaterialsParameters            materials;
      CellProblemParameters          cell_problem_parameters;
      HomogenizationOutputParameters output_parameters;
    };
  } // namespace homogenization
} // namespace tribodyn

#endif
