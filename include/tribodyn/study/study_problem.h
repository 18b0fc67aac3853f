#ifndef tribodyn_study_study_problem_h
#define tribodyn_study_study_problem_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <memory>
#include <string>
#include <tribodyn/contact/contact_parameters.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/problem.h>
#include <tribodyn/homogenization/homogenization_problem.h>
#include <vector>

namespace tribodyn
{
  namespace study
  {
    /// The pin models a study compares (seed 001 Table 2).
    enum class PinModel
    {
      homogeneous_matrix, ///< matrix properties only
      homogenized, ///< constants of homogenization runs on the morphologies
      meso         ///< the heterogeneous pin, one run per morphology
    };

    /// Name used in the tables ("homogeneous matrix", "homogenized", "meso").
    std::string
    to_string(const PinModel model);

    /// Subsection "Study".
    struct StudyParameters
    {
      std::vector<double>   pressures = {0.5e6, 2.5e6, 5e6};
      std::vector<PinModel> models
        = {PinModel::homogeneous_matrix, PinModel::homogenized, PinModel::meso};
      unsigned int n_morphologies     = 6;
      unsigned int first_seed         = 1;
      unsigned int repeats            = 1;
      double       perturbation       = 1e-6;
      std::string  boundary_condition = "KUBC";
      unsigned int ranks_per_case     = 1;
      bool         write_case_fields  = false;
      std::string  plot_script        = "auto";
      /// Take finished cases from their files (see the parameter).
      bool reuse_cases = false;
      /// Windows of a map (an image or a grid file): their size in pixels
      /// (x, y); {0, 0}: the morphologies are the generator's seeds.
      std::array<unsigned int, 2> window_size = {{0, 0}};
      /// One homogenized pin of the morphologies' mean stiffness, or one
      /// per morphology (paired with its meso pin).
      enum class HomogenizedPin
      {
        mean_of_morphologies,
        each_morphology
      };
      HomogenizedPin homogenized_pin = HomogenizedPin::mean_of_morphologies;

      /// The entries of "Study", bound to the members above (their initial
      /// values are the defaults).
      ParameterBinding
      binding();

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// One run of a study.
    struct StudyCase
    {
      unsigned int pressure_index = 0;
      PinModel     model          = PinModel::meso;
      /// The morphology (meso, and homogenized per morphology): its seed,
      /// or the window's number (from 1) for windows of a map.
      unsigned int seed   = 1;
      unsigned int repeat = 0; ///< 0: unperturbed
      std::string  name;
    };

    /// What a case reports back to the study (one row of cases.csv).
    struct CaseResult
    {
      double mu_mean = 0, mu_stderr = 0, mu_naive_stderr = 0;
      double plateau_found = 0;
      double stick = 0, slip = 0, separation = 0;
      double M_stick = 0, M_slip = 0, M_separation = 0;
      double mu_contact_mean = 0, dominant_frequency_hz = 0;
      double wall_time_s = 0, n_dofs = 0, n_samples = 0;

      static constexpr unsigned int size = 16;
      void
      to(double *v) const;
      void
      from(const double *v);
    };

    /**
     * `set Problem = study`: seed 001's Table 2 study. Sweeps the pressures
     * x pin models (x morphologies for the meso pin) x repeats, chains the
     * homogenization runs that give the homogenized pin its constants, runs
     * every case (spread over groups of MPI ranks), and writes table2.csv,
     * table2.md, cases.csv, summary.json and the plots (scripts/plot_study).
     * See doc/user_guide/study.md.
     */
    class StudyProblem : public Problem
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      StudyProblem(dealii::ParameterHandler &prm, const RunContext &context);

      void
      run() override;

      /// The cases of the study in the order they are numbered.
      const std::vector<StudyCase> &
      cases() const
      {
        return study_cases;
      }

    private:
      /// Groups of 'Ranks per case' consecutive ranks that run cases side
      /// by side (the remainder of the ranks joins the last group).
      unsigned int
      n_case_groups() const;
      /// Run the homogenization of each morphology on the rank groups and
      /// set the homogenized material (averaged apparent stiffness).
      void
      homogenize(const MPI_Comm group, const unsigned int n_groups);
      contact::ContactParameters
      case_parameters(const StudyCase &c) const;
      /// Cut the windows of the map (windows of a map only): their lower-
      /// left pixels, tiles of 'Study/Window size' from the map's top-left
      /// corner, row by row.
      void
      cut_windows();
      /// Write each window's map (OUTPUT/windows/windowK.txt, the grid
      /// files its pin and its homogenization read) and windows.csv.
      void
      write_windows() const;
      /// The morphology number @p seed (StudyCase::seed): the generator
      /// with that seed, or the window's grid file.
      MorphologyParameters
      morphology_parameters(const unsigned int seed) const;
      /// The pin models' material for morphology number @p seed: the
      /// homogenized stiffness of that morphology, or the mean one.
      void
      set_homogenized_material(contact::ContactParameters &p,
                               const unsigned int          seed) const;
      /// The morphologies' numbers: seeds First seed, +1, ..., or windows
      /// 1, 2, ...
      unsigned int
      first_morphology() const;
      /// "seed3" or "window3": the morphology's directory and case suffix.
      std::string
      morphology_name(const unsigned int seed) const;
      void
      write_tables(const std::vector<CaseResult> &results,
                   const double                   wall_time) const;
      /// With a homogenized pin per morphology next to the meso pins:
      /// paired.csv and a section of table2.md (@p md) with meso -
      /// homogenized per pressure; its rows for summary.json (a null value
      /// otherwise).
      JsonValue
      write_paired_differences(const std::vector<CaseResult> &results,
                               std::ostream                  &md) const;

      RunContext                 context;
      StudyParameters            parameters;
      contact::ContactParameters base;
      /// The homogenization runs' parameters: the study's morphology, the
      /// rest at their defaults (homogenize() sets the seed, the phases,
      /// the boundary condition and the mesh of each run).
      homogenization::HomogenizationParameters parameters_of_homogenization;
      std::vector<StudyCase>                   study_cases;
      /// The homogenized pin: stiffness, out-of-plane row, density.
      contact::VoigtStiffness homogenized_C;
      dealii::Tensor<1, 3>    homogenized_c_z;
      double                  homogenized_density = 0;
      /// The same of each morphology (Homogenized pin = each morphology).
      std::vector<contact::VoigtStiffness> morphology_C;
      std::vector<dealii::Tensor<1, 3>>    morphology_c_z;
      std::vector<double>                  morphology_density;
      /// Windows of a map: the whole map and each window's lower-left pixel.
      std::unique_ptr<Morphology>              whole_map;
      std::vector<std::array<unsigned int, 2>> window_origins;
    };
  } // namespace study
} // namespace tribodyn

#endif
