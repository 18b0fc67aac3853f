#ifndef tribodyn_homogenization_homogenization_problem_h
#define tribodyn_homogenization_homogenization_problem_h

#include <deal.II/base/parameter_handler.h>
#include <ostream>
#include <tribodyn/core/json.h>
#include <tribodyn/core/material.h>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/phase_materials.h>
#include <tribodyn/core/plugin_registry.h>
#include <tribodyn/core/problem.h>
#include <tribodyn/homogenization/cell_problem.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    /// The subsection "Materials": the phases of the morphology, named
    /// (core/phase_materials.h).
    using MaterialsParameters = MorphologyMaterials;

    /// Parameters of the subsection "Output" of the homogenization problem.
    struct HomogenizationOutputParameters
    {
      /// Write the stress/strain fields of every load case (VTU).
      bool write_fields = true;
      /// Write the material map (VTU) and the morphology grid (text).
      bool write_morphology = true;
      /// Output/Postprocessors: the outputs the user chose
      /// (source/homogenization/postprocessors/).
      PluginSelection postprocessors;

      /// The entries of "Output", bound to the members above.
      ParameterBinding
      binding();

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /**
     * All the parameters of a homogenization run: what a study sets
     * member by member to run one (study_problem.cc), what a parameter
     * file gives through parse_parameters().
     */
    struct HomogenizationParameters
    {
      MorphologyParameters           morphology;
      MaterialsParameters            materials;
      CellProblemParameters          cell_problem;
      HomogenizationOutputParameters output;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
      /// Every entry at its declared default.
      static HomogenizationParameters
      defaults();
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
      HomogenizationProblem(const HomogenizationParameters &parameters,
                            const RunContext               &context);

      void
      run() override;

    private:
      /// Name, constants and area fraction of each phase (summary.json).
      JsonValue
      phases_to_json(const std::vector<double> &fractions) const;

      RunContext               context;
      HomogenizationParameters parameters;
    };
  } // namespace homogenization
} // namespace tribodyn

#endif
