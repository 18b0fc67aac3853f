// The analysis of an automata study (`set Problem = mca_study`): the
// scenes' results read back from their directories, the paired differences
// per seed and their means over the seeds, the tables, and each scene's
// cost (its legs). Private to source/study/.

#ifndef tribodyn_study_mca_study_analysis_h
#define tribodyn_study_mca_study_analysis_h

#include <limits>
#include <ostream>
#include <string>
#include <tribodyn/study/mca_study.h>
#include <vector>

namespace tribodyn
{
  namespace study
  {
    /// One run of a scene: how it started, on how many ranks, its wall
    /// time and how it ended (finished, interrupted, failed).
    struct SceneLeg
    {
      std::string  start;
      unsigned int ranks       = 1;
      double       wall_time_s = 0;
      std::string  end;
    };

    /// Append @p leg to the scene's legs file @p file (atomically
    /// rewritten; created with its header).
    void
    append_scene_leg(const std::string &file, const SceneLeg &leg);

    /// The legs recorded in @p file (none if it does not exist).
    std::vector<SceneLeg>
    read_scene_legs(const std::string &file);


    /**
     * Name the scene's factors in its summary.json (key "study_scene": name,
     * base, base file, roughness and inclusion seeds, the factors' values),
     * so that a scene's results say what they are without the study's
     * tables. Does nothing when the scene has no summary.json.
     */
    void
    tag_scene_summary(const std::string        &directory,
                      const McaScene           &scene,
                      const McaStudyParameters &parameters);


    /// What a finished scene reports (its summary.json) and what it cost.
    struct SceneResult
    {
      bool found = false; ///< a finished run was read (its summary.json)
      /// It has a steady friction coefficient (a scene that ends before
      /// its bodies touch has none).
      bool         has_mu             = false;
      double       mu_steady          = 0;
      double       mu_steady_stderr   = 0;
      bool         steady_found       = false;
      double       steady_start_time  = 0;
      double       end_time           = 0;
      double       layer_thickness    = 0; ///< NaN when no layer was found
      double       inclusion_fraction = 0;
      double       n_automata         = 0;
      unsigned int legs               = 0;
      double       wall_time_s        = 0; ///< all legs
      double       core_hours         = 0; ///< all legs: wall x ranks
    };


    /// One comparison: a base against the reference on one seed (or, for
    /// the mean over the seeds, on all of them) at one factor level.
    struct PairedDifference
    {
      unsigned int compare = 0, level = 0;
      int          seed_index = -1; ///< -1: the mean over the seeds
      std::string  scene_reference, scene_compare;
      double       mu_reference = 0, mu_reference_stderr = 0;
      double       mu_compare = 0, mu_compare_stderr = 0;
      /// (mu_compare - mu_reference) / mu_reference and its standard error:
      /// per seed propagated from the two runs' errors; for the mean over
      /// n > 1 seeds, from the scatter between the seeds (the roughness's
      /// variability included), and runs_stderr from the runs' errors.
      double       relative_difference = 0, relative_difference_stderr = 0;
      double       relative_difference_runs_stderr = 0;
      double       layer_reference = 0, layer_compare = 0;
      double       steady_start_reference = 0, steady_start_compare = 0;
      unsigned int n_seeds = 1, n_steady = 0;
      /// The difference paired in time: the two runs share the loading
      /// history, so mu_compare(t) - mu_reference(t), binned onto common
      /// bins over the later of the two averaging starts to the end, is
      /// block-averaged as one series (its error is that of the
      /// difference, not of the two runs as if independent), relative to
      /// the reference's mean over the same bins. For the mean over the
      /// seeds: the mean of the seeds' values, its standard error from
      /// their scatter (runs_stderr from the seeds' own errors). NaN where
      /// a run's friction.csv is missing.
      double in_time             = std::numeric_limits<double>::quiet_NaN();
      double in_time_stderr      = std::numeric_limits<double>::quiet_NaN();
      double in_time_runs_stderr = std::numeric_limits<double>::quiet_NaN();
      /// Start of the common window (s) and its number of bins.
      double       in_time_from = std::numeric_limits<double>::quiet_NaN();
      unsigned int in_time_bins = 0;
    };


    /**
     * The results of a study's scenes, read from their directories, and
     * the tables made from them: scenes.csv (a row per scene, with its
     * cost), study.csv (a row per paired difference and per mean over the
     * seeds: no wall times, so a resumed study's equals an uninterrupted
     * one's), seeds_*.csv (per compared base and factor level, the form
     * scripts/plot_mca_seeds draws), study.md and summary.json.
     */
    class McaStudyAnalysis
    {
    public:
      McaStudyAnalysis(const McaStudyParameters       &parameters,
                       const std::vector<McaScene>    &scenes,
                       const std::vector<std::string> &directories);

      /// Write the tables into @p directory and print the headline on
      /// @p out.
      void
      write(const std::string &directory,
            const double       wall_time_s,
            const unsigned int n_mpi_ranks,
            std::ostream      &out) const;

      const std::vector<PairedDifference> &
      differences() const
      {
        return pairs;
      }

    private:
      /// The scene of @p base on seed @p seed_index at level @p level (by
      /// the scenes' fields).
      unsigned int
      scene_index(const unsigned int base,
                  const unsigned int seed_index,
                  const unsigned int level) const;
      /// The label of factor level @p level ("Pressure = 3e8, ..."), empty
      /// without factors.
      std::string
      level_label(const unsigned int level) const;

      const McaStudyParameters     &parameters;
      const std::vector<McaScene>  &scenes;
      std::vector<std::string>      directories;
      std::vector<SceneResult>      results;
      std::vector<PairedDifference> pairs;
      unsigned int                  n_levels  = 1;
      unsigned int                  reference = 0;
    };
  } // namespace study
} // namespace tribodyn

#endif
