// Parameters of 'set Problem = study' (subsection Study) and the record a
// case sends back to the study.

#include <cmath>
#include <deal.II/base/utilities.h>
#include <string>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/selection.h>
#include <tribodyn/study/study_problem.h>

namespace tribodyn
{
  namespace study
  {
    using dealii::ParameterHandler;
    namespace Patterns = dealii::Patterns;

    namespace
    {
      using HomogenizedPin = StudyParameters::HomogenizedPin;
      constexpr SelectionTable<HomogenizedPin, 2> homogenized_pin_choices{
        {{"mean of the morphologies", HomogenizedPin::mean_of_morphologies},
         {"each morphology", HomogenizedPin::each_morphology}}};
    } // namespace

    std::string
    to_string(const PinModel model)
    {
      switch (model)
        {
          case PinModel::homogeneous_matrix:
            return "homogeneous matrix";
          case PinModel::homogenized:
            return "homogenized";
          default:
            return "meso";
        }
    }


    ParameterBinding
    StudyParameters::binding()
    {
      ParameterBinding b("Study");
      b.add("Pressures",
            "0.5e6, 2.5e6, 5e6",
            "Pressures P of the sweep (Pa), comma-separated. Replaces "
            "'Loading/Pressure'. The seed's Table 2 uses 0.5e6, 2.5e6, 5e6.",
            Patterns::Anything(),
            [this, path = b.path("Pressures")](const std::string &text) {
              pressures.clear();
              for (const auto &item :
                   dealii::Utilities::split_string_list(text, ','))
                {
                  double value = 0;
                  try
                    {
                      value = dealii::Utilities::string_to_double(item);
                    }
                  catch (...)
                    {
                      throw InputError("Parameter '" + path
                                       + "' must be a list of comma-separated "
                                         "pressures in Pa; got '"
                                       + text + "'.");
                    }
                  check_parameter_range(path, value, 0, 1e11, true, false);
                  pressures.push_back(value);
                }
              check_parameter(!pressures.empty(),
                              path,
                              "at least one pressure");
            });
      std::string model_names;
      for (const PinModel model : models)
        model_names += (model_names.empty() ? "" : ", ") + to_string(model);
      b.add("Models",
            model_names,
            "Pin models: 'homogeneous matrix' (isotropic, 'Materials/Matrix'), "
            "'homogenized' (anisotropic, the apparent stiffness averaged over "
            "homogenization runs on the study's morphologies, chained "
            "automatically), 'meso' (the heterogeneous pin, one run per "
            "morphology). 'Materials/Type' is ignored.",
            Patterns::MultipleSelection("homogeneous matrix|homogenized|meso"),
            [this, path = b.path("Models")](const std::string &text) {
              models.clear();
              for (const auto &item :
                   dealii::Utilities::split_string_list(text, ','))
                models.push_back(item == "homogeneous matrix"
                                   ? PinModel::homogeneous_matrix
                                 : item == "homogenized" ? PinModel::homogenized
                                                         : PinModel::meso);
              check_parameter(!models.empty(), path, "at least one model");
            });
      b.add("Number of morphologies",
            n_morphologies,
            "Morphologies of the meso pin and of the homogenization runs: "
            "random seeds First seed, +1, ... of the generator (the seed "
            "uses six), or windows of a map ('Window size').",
            Patterns::Integer(1, 1000));
      b.add("Window size",
            "",
            "For a map ('Morphology/Generator = image' or 'grid file'): the "
            "morphologies are windows of it, WIDTHxHEIGHT pixels (e.g. "
            "40x30), cut side by side from its top-left corner, row by row "
            "(non-overlapping, so that they are independent samples), from "
            "the map segmented once as a whole; each window is a pin and a "
            "homogenization cell of its own. Empty: the whole map is the one "
            "morphology.",
            Patterns::Anything(),
            [this, path = b.path("Window size")](const std::string &text) {
              window_size         = {{0, 0}};
              const std::string t = dealii::Utilities::trim(text);
              if (t.empty())
                return;
              const auto x = t.find('x');
              try
                {
                  if (x == std::string::npos)
                    throw 0;
                  const int w
                    = dealii::Utilities::string_to_int(t.substr(0, x)),
                    h = dealii::Utilities::string_to_int(t.substr(x + 1));
                  if (w < 1 || h < 1)
                    throw 0;
                  window_size = {{static_cast<unsigned int>(w),
                                  static_cast<unsigned int>(h)}};
                }
              catch (...)
                {
                  throw InputError("Parameter '" + path + "': '" + text
                                   + "' is not a window size. Give it in "
                                     "pixels as WIDTHxHEIGHT, e.g. 40x30, or "
                                     "leave it empty for the whole map.");
                }
            });
      b.add("Homogenized pin",
            homogenized_pin,
            "'mean of the morphologies': one homogenized pin with the mean "
            "apparent stiffness of the morphologies' homogenization runs "
            "(the seed's Table 2). 'each morphology': one homogenized pin per "
            "morphology with its own constants, paired with its meso pin: the "
            "tables then also give meso - homogenized per morphology, with "
            "the morphology-to-morphology scatter.",
            homogenized_pin_choices);
      b.add("First seed",
            first_seed,
            "Seed of the first morphology; replaces 'Morphology/Seed'.",
            Patterns::Integer(0));
      b.add("Repeats",
            repeats,
            "Runs per (pressure, model, morphology): repeat r > 0 adds a "
            "random initial velocity of amplitude 'Perturbation amplitude' "
            "(seed r), sampling the chaotic sliding dynamics.",
            Patterns::Integer(1, 1000));
      b.add("Perturbation amplitude",
            perturbation,
            "Amplitude of the random initial velocity of the repeats (m/s).",
            Patterns::Double(0));
      b.add("Homogenization boundary condition",
            boundary_condition,
            "Which apparent stiffness of the homogenization runs the "
            "homogenized pin uses.",
            Patterns::Selection("KUBC|SUBC|periodic"));
      b.add("MPI ranks per case",
            ranks_per_case,
            "Ranks of one case. With more ranks than this, MPI_COMM_WORLD is "
            "split into groups of this many ranks that run different cases at "
            "the same time.",
            Patterns::Integer(1));
      b.add("Write case fields",
            write_case_fields,
            "Write the VTU fields of every case (at 'Output/Field interval'); "
            "false: none.");
      b.add("Reuse finished cases",
            reuse_cases,
            "Take every case (and homogenization run) that already finished "
            "in this output directory from its files "
            "(OUTPUT/cases/NAME/summary.json and friction.csv) instead of "
            "running it again, and recompute its statistics (block-averaged "
            "error, tables, plots) with this version of tribodyn. A finished "
            "case must have the same pressure, time step, end time and "
            "averaging window as the study asks (else it is an error); cases "
            "without a summary.json run. For re-analysing a study, or for "
            "finishing one that was interrupted.");
      b.add("Plot script",
            plot_script,
            "Python script making the plots at the end: 'auto' looks for "
            "scripts/plot_study next to the build directory (skipped when "
            "python3 or matplotlib is missing), 'none' makes no plots, or a "
            "path.");
      return b;
    }


    void
    StudyParameters::declare_parameters(ParameterHandler &prm)
    {
      StudyParameters().binding().declare(prm);
    }


    void
    StudyParameters::parse_parameters(ParameterHandler &prm)
    {
      const ParameterBinding b = binding();
      b.parse(prm);
      if (repeats > 1)
        check_parameter(perturbation > 0,
                        b.path("Perturbation amplitude"),
                        "a positive amplitude when '" + b.path("Repeats")
                          + "' > 1 (the solver is deterministic: unperturbed "
                            "repeats would be identical)");
    }


    void
    CaseResult::to(double *v) const
    {
      const double x[size] = {mu_mean,
                              mu_stderr,
                              mu_naive_stderr,
                              plateau_found,
                              stick,
                              slip,
                              separation,
                              M_stick,
                              M_slip,
                              M_separation,
                              mu_contact_mean,
                              dominant_frequency_hz,
                              wall_time_s,
                              n_dofs,
                              n_samples,
                              1.};
      for (unsigned int i = 0; i < size; ++i)
        v[i] = x[i];
    }


    void
    CaseResult::from(const double *v)
    {
      mu_mean               = v[0];
      mu_stderr             = v[1];
      mu_naive_stderr       = v[2];
      plateau_found         = v[3];
      stick                 = v[4];
      slip                  = v[5];
      separation            = v[6];
      M_stick               = v[7];
      M_slip                = v[8];
      M_separation          = v[9];
      mu_contact_mean       = v[10];
      dominant_frequency_hz = v[11];
      wall_time_s           = v[12];
      n_dofs                = v[13];
      n_samples             = v[14];
    }
  } // namespace study
} // namespace tribodyn
