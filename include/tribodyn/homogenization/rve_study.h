#ifndef tribodyn_homogenization_rve_study_h
#define tribodyn_homogenization_rve_study_h

#include <array>
#include <cstdint>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <functional>
#include <memory>
#include <string>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/plugin_registry.h>
#include <tribodyn/core/problem.h>
#include <tribodyn/homogenization/cell_problem.h>
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

      /// Window sizes in pixels (x, y; the third 1) or voxels (x, y, z),
      /// increasing.
      std::vector<std::array<unsigned int, 3>> window_sizes
        = {{{70, 20, 1}}, {{140, 40, 1}}, {{280, 80, 1}}};
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
      /// Read the entries for a study of dimension @p dim: a window size
      /// is one number (a square or a cube) or @p dim numbers.
      void
      parse_parameters(dealii::ParameterHandler &prm, const unsigned int dim);
      /// Pixels or voxels of the windows of size @p size.
      double
      window_elements(const unsigned int size) const
      {
        const auto &s = window_sizes[size];
        return 1. * s[0] * s[1] * s[2];
      }
    };

    /// "140x40" or "16x16x8": the first @p dim numbers of @p size joined
    /// by @p separator.
    std::string
    format_window_size(const std::array<unsigned int, 3> &size,
                       const unsigned int                 dim,
                       const std::string                 &separator = "x");

    /// One window of the study: its size, which realisation, where.
    struct RveWindow
    {
      unsigned int size_index = 0;
      /// Index among the windows of its size and among all windows.
      unsigned int index = 0, global_index = 0;
      /// Seed of the morphology the window is made from.
      unsigned int morphology_seed = 0;
      /// First pixel or voxel (lowest x, y, z) in that morphology (crops).
      std::array<unsigned int, 3> first = {{0, 0, 0}};
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
      /// V(eps_rel, n) (m^2 in 2D, m^3 in 3D) for each number of
      /// realisations asked for.
      std::vector<double> rve_measure;
    };

    /**
     * The RVE-size study of Kanit et al. (2003) in one parameter file, in
     * 2D (`set Problem = rve`: windows of a 2D morphology, plane-strain
     * cell problems; rve_study_plane.cc) and in 3D (`set Problem =
     * volume_rve`: windows of a voxel volume, 3D cell problems;
     * rve_study_volume.cc). Windows of the sizes of "RVE study/Window
     * sizes", "Windows per size" of each, are cut from (or generated as)
     * the morphology of "Morphology"; each is homogenized under the
     * boundary conditions of "Cell problem"; the windows are spread
     * round-robin over groups of "Ranks per window" MPI ranks. Writes
     * rve.csv, rve.md, rve.png (scripts/plot_rve) and summary.json.
     *
     * This class is the study's procedure, the same in both dimensions:
     * the windows' positions, their distribution over the rank groups with
     * progress and failures, the statistics and fits, the results. A
     * derived class says what a window of its morphology is and what is
     * measured on it.
     */
    class RveStudy : public Problem
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      void
      run() override;

    protected:
      /// The derived class reads its subsections and "RVE study"
      /// (parameters.parse_parameters(prm, dim)), sets the geometry below
      /// and calls plan_windows().
      RveStudy(const RunContext &context, const unsigned int dim);

      /// The windows, the same list on every rank: positions drawn in the
      /// map of map_size (crops), seeds Morphology/Seed + window number
      /// when the generator is random.
      void
      plan_windows(const std::uint64_t morphology_seed);

      /// The phases' names (the fractions' properties).
      virtual std::vector<std::string>
      phase_names() const = 0;
      /// The boundary conditions of "Cell problem".
      virtual const std::vector<BoundaryCondition> &
      cell_boundary_conditions() const = 0;
      /// The constants measured per boundary condition.
      virtual const std::vector<std::string> &
      constant_names() const = 0;
      /// The value of each constant in each phase ([constant][phase]), for
      /// the point variances.
      virtual std::vector<std::vector<double>>
      phase_constants() const = 0;
      /// The values of window @p w on the communicator @p group: the phase
      /// fractions, then per boundary condition solved the constants; the
      /// cell problems time themselves in @p timer.
      virtual std::vector<double>
      measure(const RveWindow     &w,
              const MPI_Comm       group,
              dealii::TimerOutput &timer) const = 0;

      /// "140x40" or "16x16x16".
      std::string
      size_text(const unsigned int size_index) const;
      /// Refuse (InputError on 'Materials/Names') @p what holding more
      /// phases, @p n_phases, than the materials name.
      void
      check_phases_named(const unsigned int n_phases,
                         const std::string &what) const;
      /// The first values of measure(): the phase fractions @p fractions of
      /// a window of @p n_phases phases (checked against the names), one
      /// per named phase.
      std::vector<double>
      fraction_values(const std::vector<double> &fractions,
                      const unsigned int         n_phases) const;
      /// Call @p make on the first window of each size, so that a
      /// generator that cannot fill a window is refused before an hour of
      /// cell problems (its InputError, with the size and the fix).
      void
      make_first_windows(
        const std::function<void(const RveWindow &)> &make) const;
      /// The boundary conditions solved (none without cell problems).
      const std::vector<BoundaryCondition> &
      boundary_conditions() const;

      RunContext         context;
      RveStudyParameters parameters;
      const unsigned int dim;
      /// Edges of a pixel (the third 1) or a voxel (m).
      std::array<double, 3> element_size = {{1, 1, 1}};
      /// Size of the map crops are cut from (pixels or voxels).
      std::array<unsigned int, 3> map_size = {{1, 1, 1}};
      /// Whether the morphology's generator draws a new map per seed.
      bool                   random = false;
      std::vector<RveWindow> windows;

    private:
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
    };

  } // namespace homogenization
} // namespace tribodyn

#endif
