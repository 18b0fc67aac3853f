// The outputs of the RVE-size study (`set Problem = rve`) as postprocessors
// (issue #52 item 2; core/postprocessor.h): each registers itself from its
// own file in source/homogenization/rve_outputs/ and owns its file (the
// table rve.csv, the report rve.md, the plot rve.png). The study measures
// the windows, fits the variance law, writes its own summary.json keys and
// hands its results to the outputs the user lists in 'RVE study/Outputs'.
// A new output is one file. Definitions: doc/user_guide/homogenization.md,
// "RVE-size study".
#ifndef tribodyn_homogenization_rve_output_h
#define tribodyn_homogenization_rve_output_h

#include <array>
#include <ostream>
#include <string>
#include <tribodyn/core/plugin_registry.h>
#include <tribodyn/core/postprocessor.h>
#include <tribodyn/homogenization/rve_study.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    /// What the study measured, for its outputs (references: they live
    /// while the outputs write).
    struct RveResults
    {
      const RveStudyParameters     &parameters;
      const std::vector<RveSample> &samples;
      const std::vector<RveFit>    &fits;
      /// The names of the phases (the fractions' properties).
      const std::vector<std::string> &phase_names;
      /// Whether both KUBC and SUBC were solved (the systematic error).
      bool         kubc_and_subc = false;
      unsigned int n_windows     = 0;
      /// 2: windows of pixels (`set Problem = rve`); 3: of voxels
      /// (`set Problem = volume_rve`).
      unsigned int dim = 2;
      /// Edges of a pixel (the third 1) or of a voxel (m).
      std::array<double, 3> element_size = {{1, 1, 1}};
      const std::string    &output_directory;

      /// The fit of the property and boundary condition of @p sample.
      const RveFit &
      fit_of(const RveSample &sample) const;
      /// The sample of @p property, @p boundary_condition and size index
      /// @p size (nullptr: none).
      const RveSample *
      sample_of(const std::string &property,
                const std::string &boundary_condition,
                const unsigned int size) const;
      /// "px" or "vox": the unit of the sizes and integral ranges.
      std::string
      element_unit() const;
      /// "area" or "volume", with the SI unit of the csv columns ("m2",
      /// "m3").
      std::string
      measure_name() const;
      std::string
      measure_si_unit() const;
      /// Area (m^2) or volume (m^3) of a pixel or voxel.
      double
      element_measure() const;
      /// Pixels or voxels of the windows of size @p size.
      double
      elements(const unsigned int size) const;
      /// "70 × 20" or "16 × 16 × 16" (@p separator between the numbers),
      /// in elements or, with @p in_mm, in mm.
      std::string
      size_text(const unsigned int size,
                const std::string &separator = " × ",
                const bool         in_mm     = false) const;
      /// "0.5 mm² (≈ 0.7 × 0.7 mm)": an area or volume as a window of the
      /// largest size's aspect ratios ("–" when not finite).
      std::string
      as_window(const double measure) const;
      /// Whether @p property is a modulus (Pa; GPa in rve.md): E_*, G_*,
      /// k, mu.
      static bool
      is_modulus(const std::string &property);
    };

    class RveOutput : public PostprocessorBase
    {
    public:
      /// Write the output's files (rank 0 only) and what it shows on
      /// @p screen.
      virtual void
      write(const RveResults &results, std::ostream &screen) const = 0;
      /// The files it wrote, for the closing line ("rve.csv").
      virtual std::string
      files() const = 0;
    };

    /// The RVE study's outputs; a factory receives the study's
    /// parameters and returns nullptr when the run does not need its
    /// output.
    using RveOutputRegistry = PluginRegistry<RveOutput, RveStudyParameters>;
  } // namespace homogenization
} // namespace tribodyn

#endif
