#ifndef tribodyn_study_mca_study_h
#define tribodyn_study_mca_study_h

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/problem.h>
#include <utility>
#include <vector>

namespace tribodyn
{
  namespace study
  {
    /**
     * The parameters of `set Problem = mca_study`: subsection "Study" and a
     * study-wide "Time/End time". See doc/user_guide/mca_study.md.
     */
    struct McaStudyParameters
    {
      /// A base scene: an mca parameter file, named.
      struct Base
      {
        std::string name, file;
      };
      /// A factor: a parameter path and its values (one scene each).
      struct Factor
      {
        std::string              path;
        std::vector<std::string> values;
      };

      /// The scenes' parameters the study sets itself.
      static inline const std::string roughness_seed_path
        = "Geometry/Rough interface/Seed";
      static inline const std::string inclusion_seed_path
        = "Geometry/Inclusions/Seed";
      static inline const std::string end_time_path = "Time/End time";

      std::vector<Base> bases;
      /// The base the others are compared with.
      std::string reference;
      /// Geometry/Rough interface/Seed of the scenes, one pairing each.
      std::vector<unsigned int> roughness_seeds = {1};
      /// Geometry/Inclusions/Seed, paired with the roughness seeds (empty:
      /// equal to them).
      std::vector<unsigned int> inclusion_seeds;
      std::vector<Factor>       factors;
      /// "Path = value" set in every scene.
      std::vector<std::pair<std::string, std::string>> settings;
      /// > 0: every scene's Time/End time.
      double end_time = 0;
      /// > 0: every scene's Checkpoint/Interval.
      double       checkpoint_interval = 1e-9;
      unsigned int ranks_per_scene     = 1;
      std::string  plot_script         = "auto";

      /// The study-wide 'Time/End time'.
      ParameterBinding
      time_binding();
      /// The entries of "Study"; relative base files are read from
      /// @p directory (that of the study's parameter file).
      ParameterBinding
      study_binding(const std::string &directory);

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /// @p study_file: the study's parameter file, whose directory
      /// relative base paths are read from.
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &study_file);

    private:
      void
      read_bases(const std::string &text, const std::string &directory);
      void
      read_factors(const std::string &text, const std::string &where);
    };


    /// One scene of an automata study: a base with its factors' levels.
    struct McaScene
    {
      std::string  name; ///< directory name under scenes/
      unsigned int base           = 0;
      unsigned int roughness_seed = 1, inclusion_seed = 1;
      /// Index of the pairing (seed) and of the factors' level combination.
      unsigned int seed_index = 0, level_index = 0;
      /// One value per factor.
      std::vector<std::string> levels;
    };


    /**
     * `set Problem = mca_study`: an automata study in one parameter file
     * (seed 000's question: does the composite rub less than steel?). Base
     * scenes (mca parameter files, e.g. steel and composite) x roughness
     * seeds (each with its inclusion seed) x factor levels (any parameter
     * by path) are run on groups of MPI ranks, each scene in
     * `scenes/NAME/` with checkpoints; a study started again with the same
     * file reuses its finished scenes, resumes its interrupted ones from
     * their checkpoints (on any number of ranks) and runs the others. The
     * analysis (McaStudyAnalysis, mca_study_analysis.cc) pairs each base
     * with the reference base on the same seed and levels.
     */
    class McaStudyProblem : public Problem
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      McaStudyProblem(dealii::ParameterHandler &prm, const RunContext &context);

      void
      run() override;

      const std::vector<McaScene> &
      scenes() const
      {
        return study_scenes;
      }

    private:
      /// How a scene's run starts.
      enum class Start
      {
        fresh,
        resume,
        reuse,
        /// a finished run whose analysis-only parameters changed: resumed
        /// from its checkpoint at the end time, no step run
        reanalyse
      };

      /// The scene's mca parameters: its base file with the study's
      /// changes (seeds, factor levels, settings, end time, checkpoints).
      void
      scene_parameters(const McaScene           &scene,
                       dealii::ParameterHandler &prm) const;
      /// What the scene's directory holds: a finished run of the same
      /// parameters (reuse), one that differs only in analysis-only
      /// entries and kept its last checkpoint (reanalyse), an interrupted
      /// one (resume), or none of these. @p changed receives the entries
      /// a re-analysis changes. Throws InputError for a finished run that
      /// differs only in analysis-only entries but has no checkpoint at
      /// its end time (rather than run the scene again over it).
      Start
      scene_start(const McaScene           &scene,
                  dealii::ParameterHandler &prm,
                  std::vector<std::string> &changed) const;
      /// Run (or resume) one scene on @p group; appends the leg to the
      /// scene's legs.csv.
      void
      run_scene(const McaScene &scene, const MPI_Comm group) const;
      /// Refuse (InputError) a scene of a base without inclusions on a
      /// roughness seed the study lists more than once: the same scene
      /// again.
      void
      refuse_repeated_scene(const McaScene           &scene,
                            dealii::ParameterHandler &prm) const;
      std::string
      scene_directory(const McaScene &scene) const;

      RunContext            context;
      McaStudyParameters    parameters;
      std::vector<McaScene> study_scenes;
    };
  } // namespace study
} // namespace tribodyn

#endif
