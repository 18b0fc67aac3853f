#ifndef tribodyn_homogenization_rve_study_h
#define tribodyn_homogenization_rve_study_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <memory>
#include <string>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/plugin_registry.h>
#include <tribodyn/core/problem.h>
#include <tribodyn/homogenization/cell_problem.h>
#include <tribodyn/homogenization/homogenization_problem.h>
#include <tribodyn/homogenization/rve_statistics.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    /// Parameters of the subsection "RVE study".
    struct RveStudyParameters
    {
      /// Where the windows come from.
      enum class Source
      {
        /// Cut at uniformly random positions from the morphology of the
        /// subsection "Morphology" (a new realisation of it per window
        /// when its generator is random, the one map otherwise).
        crops,
        /// The generator of "Morphology" run at the window's size, one
        /// seed per window (the seed's own way: independent cells).
        realisations
      };

      /// Window sizes in pixels (x, y), increasing.
      std::vector<std::array<unsigned int, 2>> window_sizes
        = {{{70, 20}}, {{140, 40}}, {{280, 80}}};
      /// Windows of each size (one per size).
      std::vector<unsigned int> windows_per_size = {8, 8, 8};
      Source                    source           = Source::crops;
      /// Seed of the window positions (crops).
      unsigned int random_seed = 1;
      /// Wanted relative error of the mean (e.g. 0.01).
      double relative_error = 0.01;
      /// Numbers of realisations n for which the RVE size is reported.
      std::vector<unsigned int> realisations = {1, 6};
      /// MPI ranks per window (the group size).
      unsigned int ranks_per_window = 1;
      /// Solve the cell problems (false: only the phase fractions).
      bool solve_cell_problems = true;
      /// Python script drawing rve.png ("auto", "none" or a path).
      std::string plot_script = "auto";
      /// The outputs to write ('Outputs': all, or a list of the names of
      /// rve_outputs/).
      PluginSelection outputs;

      /// The entries of "RVE study", bound to the members above (their
      /// initial values are the defaults).
      ParameterBinding
      binding();

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// One window of the study: its size, which realisation, where.
    struct RveWindow
    {
      unsigned int size_index = 0;
      /// Index among the windows of its size and among all windows.
      unsigned int index = 0, global_index = 0;
      /// Seed of the morphology the window is made from.
      unsigned int morphology_seed = 0;
      /// Lower-left pixel in that morphology (crops).
      unsigned int i0 = 0, j0 = 0;
    };

    /// The sample of one (size, boundary condition, property).
    struct RveSample
    {
      unsigned int          size_index = 0;
      std::string           boundary_condition; ///< "none" for fractions
      std::string           property;
      rve::SampleStatistics statistics;
      /// Relative bias against the largest windows' mean (same BC).
      double bias = 0;
    };

    /// The fit of one (boundary condition, property) over the sizes.
    struct RveFit
    {
      std::string      boundary_condition;
      std::string      property;
      rve::VarianceFit fit;
      /// Mean of the largest windows (the Z of the relative error).
      double mean = 0;
      /// V(eps_rel, n) (m^2) for each number of realisations asked for.
      std::vector<double> rve_area;
    };

    /**
     * `set Problem = rve`: the RVE-size study of Kanit et al. (2003)
     * in one parameter file. Windows of the sizes of "RVE study/Window
     * sizes", "Windows per size" of each, are cut from (or generated as)
     * the morphology of "Morphology"; each is homogenized under the
     * boundary conditions of "Cell problem"; the windows are spread
     * round-robin over groups of "Ranks per window" MPI ranks. Writes
     * rve.csv, rve.md, rve.png (scripts/plot_rve) and summary.json.
     */
    class RveStudy : public Problem
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      RveStudy(dealii::ParameterHandler &prm, const RunContext &context);

      void
      run() override;

    private:
      /// The windows, the same list on every rank.
      void
      plan_windows();
      /// The material map of window @p w.
      Morphology
      make_window(const RveWindow &w) const;
      /// The values of window @p w (fractions, then per BC the constants)
      /// on the communicator @p group; the cell problems time themselves
      /// in @p timer.
      std::vector<double>
      measure(const RveWindow     &w,
              const MPI_Comm       group,
              dealii::TimerOutput &timer) const;
      /// The boundary conditions solved (none without cell problems).
      const std::vector<BoundaryCondition> &
      boundary_conditions() const;
      /// Names of the values measure() returns and their BC ("none").
      std::vector<std::pair<std::string, std::string>>
      value_names() const;
      /// Point variance of each value (0 when it has none).
      std::vector<double>
      point_variances(const std::vector<double> &fractions) const;
      /// rve.csv, rve.md, summary.json and the plot (rank 0).
      void
      write_results(const std::vector<RveSample> &samples,
                    const std::vector<RveFit>    &fits,
                    const unsigned int            n_groups,
                    const double                  wall_time) const;

      RunContext            context;
      MorphologyParameters  morphology_parameters;
      MaterialsParameters   materials;
      CellProblemParameters cell_problem_parameters;
      RveStudyParameters    parameters;
      /// The map windows are cut from (crops of a map without a seed).
      std::unique_ptr<Morphology> fixed_map;
      /// Pixel size of the windows (m).
      double                 pixel_width = 0, pixel_height = 0;
      std::vector<RveWindow> windows;
    };

    /// The constants reported for each boundary condition.
    const std::vector<std::string> &
    rve_constant_names();
  } // namespace homogenization
} // namespace tribodyn

#endif
