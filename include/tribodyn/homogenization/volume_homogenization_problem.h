#ifndef tribodyn_homogenization_volume_homogenization_problem_h
#define tribodyn_homogenization_volume_homogenization_problem_h

#include <deal.II/base/parameter_handler.h>
#include <tribodyn/core/phase_materials.h>
#include <tribodyn/core/plugin_registry.h>
#include <tribodyn/core/problem.h>
#include <tribodyn/homogenization/cell_problem.h>
#include <tribodyn/homogenization/voxel_volume.h>

namespace tribodyn
{
  namespace homogenization
  {
    /// Parameters of the subsection "Output" of the 3D problem.
    struct VolumeOutputParameters
    {
      /// Write the volume as morphology.raw with its header morphology.hdr.
      bool write_morphology = true;
      /// Write the fields of every load case as VTU (fields_<BC>.pvd); off
      /// by default: they take more memory and disk than the solve.
      bool write_fields = false;
      /// Write the mid-x, mid-y and mid-z slices of the volume and of a
      /// field (slices.json) and draw them (plot_script).
      bool write_slices = true;
      /// Script drawing the slices as PNG: "auto", "none" or a path.
      std::string plot_script = "auto";
      /// Output/Postprocessors: the outputs the user chose
      /// (source/homogenization/postprocessors/volume_*.cc).
      PluginSelection postprocessors;

      /// The entries of "Output", bound to the member above.
      ParameterBinding
      binding();
    };

    /// All the parameters of a 3D homogenization run.
    struct VolumeHomogenizationParameters
    {
      VolumeMorphologyParameters  morphology;
      MorphologyMaterials         materials;
      VolumeCellProblemParameters cell_problem;
      VolumeOutputParameters      output;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /**
     * `set Problem = volume_homogenization`: the 3D counterpart of `set
     * Problem = homogenization` on a voxel volume. Builds the volume,
     * solves the six load cases of each boundary condition and reports the
     * apparent 6x6 stiffness and compliance, the engineering constants,
     * the Voigt/Reuss and Hashin-Shtrikman bounds and Huet's ordering
     * (screen table, effective_properties.csv, summary.json); optionally
     * the volume (morphology.raw), the fields (VTU) and slices of the
     * volume and of a field (slices.json and the PNGs of
     * scripts/plot_volume).
     */
    class VolumeHomogenizationProblem : public Problem
    {
    public:
      VolumeHomogenizationProblem(
        const VolumeHomogenizationParameters &parameters,
        const RunContext                     &context);

      void
      run() override;

    private:
      RunContext                     context;
      VolumeHomogenizationParameters parameters;
    };
  } // namespace homogenization
} // namespace tribodyn

#endif
