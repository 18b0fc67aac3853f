// The study's tables (table2.csv, table2.md, cases.csv), summary.json and
// the call of the plot script. Definitions: doc/user_guide/study.md.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <deal.II/base/mpi.h>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/statistics.h>
#include <tribodyn/study/study_problem.h>

namespace tribodyn
{
  namespace study
  {
    namespace
    {
      /// Seed 001, Table 2 (time-averaged mu_global) and the regimes of §3.
      double
      seed_mu(const double pressure, const PinModel model)
      {
        const double P = pressure / 1e6;
        const int    k = std::abs(P - 0.5) < 1e-9   ? 0
                         : std::abs(P - 2.5) < 1e-9 ? 1
                         : std::abs(P - 5.) < 1e-9  ? 2
                                                    : -1;
        if (k < 0)
          return std::nan("");
        const double matrix[3] = {0.183, 0.234, 0.245},
                     homog[3]  = {0.173, 0.213, 0.247},
                     meso[3]   = {0.176, 0.210, 0.246};
        return model == PinModel::homogeneous_matrix ? matrix[k]
               : model == PinModel::homogenized      ? homog[k]
                                                     : meso[k];
      }


      std::string
      seed_regime(const double pressure)
      {
        const double P = pressure / 1e6;
        return std::abs(P - 0.5) < 1e-9   ? "slip-separation"
               : std::abs(P - 2.5) < 1e-9 ? "stick-slip-separation"
               : std::abs(P - 5.) < 1e-9  ? "slip"
                                          : "";
      }


      /// A run's time average of mu_global and its blocking error.
      statistics::MeanWithError
      run_mean(const CaseResult &r)
      {
        statistics::MeanWithError m;
        m.mean           = r.mu_mean;
        m.standard_error = r.mu_stderr;
        m.plateau_found  = r.plateau_found > 0;
        return m;
      }


      /// The repeats of one morphology as one sample of the material: their
      /// mean, with the error of their blocking errors, sqrt(sum e_r^2) / r
      /// (their spread is not an independent sample's).
      statistics::MeanWithError
      repeats_mean(const std::vector<statistics::MeanWithError> &repeats)
      {
        statistics::MeanWithError m;
        double                    variance = 0;
        for (const auto &r : repeats)
          {
            m.mean += r.mean / repeats.size();
            variance += r.standard_error * r.standard_error;
          }
        m.standard_error = std::sqrt(variance) / repeats.size();
        return m;
      }
    } // namespace


    JsonValue
    StudyProblem::write_paired_differences(
      const std::vector<CaseResult> &results,
      std::ostream                  &md) const
    {
      const auto has = [&](const PinModel m) {
        return std::find(parameters.models.begin(), parameters.models.end(), m)
               != parameters.models.end();
      };
      if (parameters.homogenized_pin
            != StudyParameters::HomogenizedPin::each_morphology
          || !has(PinModel::meso) || !has(PinModel::homogenized))
        return JsonValue();

      // Per pressure: d_k = (meso - homogenized) of morphology k, each the
      // mean of its repeats; the mean of the d_k and its standard error as
      // in Table 2 (the spread between morphologies, or the runs' blocking
      // errors when larger).
      const double       threshold = base.output.regime_threshold;
      std::ostringstream csv;
      csv << "pressure,n_morphologies,mu_meso_minus_homogenized,"
             "mu_stderr,regimes_agree\n"
          << std::setprecision(6);
      md << "\n## Meso - homogenized, paired by morphology\n\n"
         << "Each morphology's meso pin against the homogenized pin of its "
            "own constants (Homogenized pin = each morphology): the mean of "
            "the differences of their mu_mean, its standard error over the "
            "morphologies (or the runs' blocking errors when larger), and "
            "the morphologies whose two pins have the same regime (contact "
            "face).\n\n"
         << "| P (MPa) | morphologies | mu(meso) - mu(homogenized) ± stderr | "
            "same regime |\n|---|---|---|---|\n";
      JsonValue          list = JsonValue::array();
      const unsigned int n    = parameters.n_morphologies;
      for (unsigned int p = 0; p < parameters.pressures.size(); ++p)
        {
          // per morphology: meso - homogenized, each its repeats' mean
          std::vector<statistics::MeanWithError> differences(n);
          unsigned int                           agree = 0;
          for (unsigned int k = 0; k < n; ++k)
            {
              std::vector<statistics::MeanWithError> runs[2];
              double fr[2][3] = {{0, 0, 0}, {0, 0, 0}};
              for (const PinModel model :
                   {PinModel::meso, PinModel::homogenized})
                {
                  const int    m = model == PinModel::meso ? 0 : 1;
                  const double r = parameters.repeats;
                  for (unsigned int i = 0; i < study_cases.size(); ++i)
                    {
                      const StudyCase &c = study_cases[i];
                      if (c.pressure_index != p || c.model != model
                          || c.seed != first_morphology() + k)
                        continue;
                      runs[m].push_back(run_mean(results[i]));
                      fr[m][0] += results[i].stick / r;
                      fr[m][1] += results[i].slip / r;
                      fr[m][2] += results[i].separation / r;
                    }
                }
              const statistics::MeanWithError meso = repeats_mean(runs[0]),
                                              homogenized
                                              = repeats_mean(runs[1]);
              differences[k].mean = meso.mean - homogenized.mean;
              differences[k].standard_error
                = std::hypot(meso.standard_error, homogenized.standard_error);
              agree += contact::classify_regime(fr[0][0],
                                                fr[0][1],
                                                fr[0][2],
                                                threshold)
                       == contact::classify_regime(fr[1][0],
                                                   fr[1][1],
                                                   fr[1][2],
                                                   threshold);
            }
          const statistics::MeanWithError d
            = statistics::mean_of_means(differences);
          const double mean = d.mean, se = d.standard_error;
          const double P = parameters.pressures[p];
          csv << P << "," << n << "," << mean << "," << se << "," << agree
              << "\n";
          md << std::fixed << std::setprecision(3) << "| " << P / 1e6 << " | "
             << n << " | " << std::showpos << mean << std::noshowpos << " ± "
             << std::setprecision(4) << se << " | " << agree << " of " << n
             << " |\n";
          JsonValue entry                    = JsonValue::object();
          entry["pressure"]                  = P;
          entry["n_morphologies"]            = n;
          entry["mu_meso_minus_homogenized"] = mean;
          entry["mu_stderr"]                 = se;
          entry["regimes_agree"]             = agree;
          list.push_back(entry);
        }
      write_file_atomically(join_path(context.output_directory, "paired.csv"),
                            csv.str());
      return list;
    }


    void
    StudyProblem::write_tables(const std::vector<CaseResult> &results,
                               const double                   wall_time) const
    {
      const std::string &dir       = context.output_directory;
      const double       threshold = base.output.regime_threshold;

      // cases.csv: one row per run.
      {
        std::ostringstream out;
        out << "case,pressure,model,seed,repeat,mu_mean,mu_stderr_blocking,"
               "mu_stderr_naive,plateau_found,stick_fraction,slip_fraction,"
               "separation_fraction,M_stick_fraction,M_slip_fraction,"
               "M_separation_fraction,mu_contact_mean,dominant_frequency_hz,"
               "wall_time_s\n"
            << std::setprecision(8);
        for (unsigned int i = 0; i < study_cases.size(); ++i)
          {
            const StudyCase  &c = study_cases[i];
            const CaseResult &r = results[i];
            out << c.name << "," << parameters.pressures[c.pressure_index]
                << "," << to_string(c.model) << "," << c.seed << "," << c.repeat
                << "," << r.mu_mean << "," << r.mu_stderr << ","
                << r.mu_naive_stderr << "," << r.plateau_found << "," << r.stick
                << "," << r.slip << "," << r.separation << "," << r.M_stick
                << "," << r.M_slip << "," << r.M_separation << ","
                << r.mu_contact_mean << "," << r.dominant_frequency_hz << ","
                << r.wall_time_s << "\n";
          }
        write_file_atomically(join_path(dir, "cases.csv"), out.str());
      }

      // Table 2: per pressure and model. The mean over the n runs (equal
      // windows) of the runs' time averages; its standard error combines
      // the spread between runs and the blocking error of each run's time
      // average:
      //   se^2 = max(s_between^2 / g, sum_i se_i^2 / n^2),
      // s_between the sample standard deviation of the g morphologies'
      // means (each the mean of its repeats; with one morphology, of the
      // n repeats' means, g = n).
      std::ostringstream csv, md;
      csv << "pressure,model,n_runs,mu_mean,mu_stderr,stick_fraction,"
             "slip_fraction,separation_fraction,regime,dominant_frequency_hz\n"
          << std::setprecision(6);
      md
        << "# Table 2 (seed 001): time-averaged global friction coefficient\n\n"
        << "mu_stderr combines morphologies/repeats and block averaging in "
           "time; regime from the time fractions of all contact "
           "node-samples (threshold "
        << threshold << "). Seed values in the last columns.\n\n"
        << "| P (MPa) | model | runs | mu_mean ± stderr | stick / slip / "
           "separation | regime (contact face) | regime (point M) | spectrum "
           "peak (kHz) | seed mu | seed regime |\n"
        << "|---|---|---|---|---|---|---|---|---|---|\n";
      JsonValue table = JsonValue::array();
      for (unsigned int p = 0; p < parameters.pressures.size(); ++p)
        for (const PinModel model : parameters.models)
          {
            std::vector<const CaseResult *> runs;
            // the runs, and per morphology its repeats
            std::vector<statistics::MeanWithError> run_means;
            std::map<unsigned int, std::vector<statistics::MeanWithError>>
              per_morphology;
            for (unsigned int i = 0; i < study_cases.size(); ++i)
              if (study_cases[i].pressure_index == p
                  && study_cases[i].model == model)
                {
                  runs.push_back(&results[i]);
                  run_means.push_back(run_mean(results[i]));
                  per_morphology[study_cases[i].seed].push_back(
                    run_means.back());
                }
            const double n     = runs.size();
            double       fr[3] = {0, 0, 0}, M[3] = {0, 0, 0}, peak = 0;
            for (const CaseResult *r : runs)
              {
                peak += r->dominant_frequency_hz / n;
                fr[0] += r->stick / n;
                fr[1] += r->slip / n;
                fr[2] += r->separation / n;
                M[0] += r->M_stick / n;
                M[1] += r->M_slip / n;
                M[2] += r->M_separation / n;
              }
            // The spread between the morphologies' means (their repeats
            // averaged first: repeats of one morphology are not independent
            // samples of the material), or between the repeats of the one
            // morphology; or the runs' blocking errors when larger.
            std::vector<statistics::MeanWithError> samples = run_means;
            if (per_morphology.size() > 1)
              {
                samples.clear();
                for (const auto &[seed, repeats] : per_morphology)
                  samples.push_back(repeats_mean(repeats));
              }
            const statistics::MeanWithError mu
              = statistics::mean_of_means(samples);
            const double      mean = mu.mean, se = mu.standard_error;
            const std::string regime
              = contact::classify_regime(fr[0], fr[1], fr[2], threshold);
            const std::string regime_M
              = contact::classify_regime(M[0], M[1], M[2], threshold);
            const double P = parameters.pressures[p];
            csv << P << "," << to_string(model) << "," << runs.size() << ","
                << mean << "," << se << "," << fr[0] << "," << fr[1] << ","
                << fr[2] << "," << regime << "," << peak << "\n";
            const double seed = seed_mu(P, model);
            // a run whose blocking curve found no plateau gives a lower
            // bound of its error bar: marked, and said below the table
            bool lower_bound = false;
            for (const CaseResult *r : runs)
              lower_bound = lower_bound || !(r->plateau_found > 0);
            std::ostringstream row;
            row << std::fixed << std::setprecision(3) << "| " << P / 1e6
                << " | " << to_string(model) << " | " << runs.size() << " | "
                << mean << " ± " << std::setprecision(4) << se
                << (lower_bound ? " *" : "") << " | " << std::setprecision(3)
                << fr[0] << " / " << fr[1] << " / " << fr[2] << " | " << regime
                << " | " << regime_M << " | " << std::setprecision(1)
                << peak / 1e3 << " | " << std::setprecision(3);
            if (std::isnan(seed))
              row << "– | – |";
            else
              row << seed << " | " << seed_regime(P) << " |";
            md << row.str() << "\n";
            JsonValue entry                = JsonValue::object();
            entry["pressure"]              = P;
            entry["model"]                 = to_string(model);
            entry["n_runs"]                = runs.size();
            entry["mu_mean"]               = mean;
            entry["mu_stderr"]             = se;
            entry["stick_fraction"]        = fr[0];
            entry["slip_fraction"]         = fr[1];
            entry["separation_fraction"]   = fr[2];
            entry["regime"]                = regime;
            entry["regime_point_M"]        = regime_M;
            entry["dominant_frequency_hz"] = peak;
            entry["seed_mu"]               = seed;
            table.push_back(entry);
          }
      unsigned int n_without_plateau = 0;
      for (const CaseResult &r : results)
        n_without_plateau += !(r.plateau_found > 0);
      if (n_without_plateau > 0)
        md << "\n\\* " << n_without_plateau << " of " << results.size()
           << " cases found no plateau in their blocking curve (cases.csv, "
              "plateau_found = 0): the averaging window holds too few "
              "independent blocks, and their error bars are lower bounds. A "
              "longer window ('Output/Averaging start time' earlier or a "
              "later 'Time/End time') gives a plateau.\n";
      write_file_atomically(join_path(dir, "table2.csv"), csv.str());
      const JsonValue paired = write_paired_differences(results, md);
      write_file_atomically(join_path(dir, "table2.md"), md.str());

      JsonValue summary = summary_header("study", context.mpi_communicator);
      summary["n_case_groups"] = n_case_groups();
      summary["n_cases"]       = study_cases.size();
      // cases whose error bar is a lower bound (no blocking plateau)
      summary["n_cases_without_plateau"] = n_without_plateau;
      summary["mesh_size"]               = base.geometry.mesh_size;
      summary["end_time"]                = base.time.end_time;
      summary["averaging_window"]
        = json_array({base.output.average_start,
                      base.output.average_end < 0 ? base.time.end_time
                                                  : base.output.average_end});
      summary["regime_threshold"] = threshold;
      summary["table2"]           = table;
      if (paired.type() == JsonValue::Type::array)
        summary["paired_meso_minus_homogenized"] = paired;
      double case_time = 0;
      for (const CaseResult &r : results)
        case_time += r.wall_time_s;
      summary["sum_of_case_wall_times_s"] = case_time;
      summary["wall_time_s"]              = wall_time;
      write_file_atomically(join_path(dir, "summary.json"),
                            summary.dump() + "\n");
      std::cout << "\n"
                << md.str() << "\nStudy written to " << dir
                << "/ (table2.csv, table2.md, cases.csv, summary.json, "
                   "cases/*/)"
                << std::endl;

      // Plots.
      run_plot_script(parameters.plot_script,
                      "plot_study",
                      "Study/Plot script",
                      dir);
    }
  } // namespace study
} // namespace tribodyn
