// The analysis of an automata study: scenes' results, paired differences,
// means over the seeds, tables. Definitions: doc/user_guide/mca_study.md.

#include "mca_study_analysis.h"

#include <cmath>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <iomanip>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/statistics.h>
#include <tribodyn/core/version.h>

namespace tribodyn
{
  namespace study
  {
    namespace
    {
      const char *legs_header = "start,ranks,wall_time_s,end";

      double
      number_or_nan(const nlohmann::json &j, const char *key)
      {
        const auto it = j.find(key);
        return it != j.end() && it->is_number()
                 ? it->get<double>()
                 : std::numeric_limits<double>::quiet_NaN();
      }


      /// A number for the CSV files and tables (empty when not finite).
      std::string
      csv(const double value)
      {
        if (!std::isfinite(value))
          return "";
        std::ostringstream s;
        s << std::setprecision(17) << value; // reads back exactly
        return s.str();
      }


      std::string
      fixed(const double value, const int digits)
      {
        if (!std::isfinite(value))
          return "-";
        std::ostringstream s;
        s << std::fixed << std::setprecision(digits) << value;
        return s.str();
      }


      /// Mean of @p values and the standard error of that mean from their
      /// scatter (n > 1; NaN for one value).
      std::pair<double, double>
      mean_and_stderr(const std::vector<double> &values)
      {
        const double n    = values.size();
        double       mean = 0;
        for (const double v : values)
          mean += v;
        mean /= n;
        if (values.size() < 2)
          return {mean, std::numeric_limits<double>::quiet_NaN()};
        double s2 = 0;
        for (const double v : values)
          s2 += (v - mean) * (v - mean);
        return {mean, std::sqrt(s2 / (n - 1) / n)};
      }


      /// (time, mu) of a scene's friction.csv; empty when it cannot be
      /// read.
      void
      read_mu_series(const std::string   &directory,
                     std::vector<double> &t,
                     std::vector<double> &mu)
      {
        std::vector<std::vector<double>> columns;
        read_csv_columns(join_path(directory, "friction.csv"),
                         {"time", "mu"},
                         columns);
        t  = std::move(columns[0]);
        mu = std::move(columns[1]);
      }


      /// Mean sample spacing of @p t (0 for fewer than two samples).
      double
      spacing(const std::vector<double> &t)
      {
        return t.size() < 2 ? 0. : (t.back() - t.front()) / (t.size() - 1);
      }


      /// Means of the samples of (@p t, @p y) in the bins [from + k w,
      /// from + (k + 1) w), k < n; NaN for a bin without samples.
      std::vector<double>
      bin_means(const std::vector<double> &t,
                const std::vector<double> &y,
                const double               from,
                const double               w,
                const unsigned int         n)
      {
        std::vector<double>       sum(n, 0.);
        std::vector<unsigned int> count(n, 0);
        for (std::size_t k = 0; k < t.size(); ++k)
          {
            const double x = (t[k] - from) / w;
            if (x >= 0 && x < n)
              {
                const unsigned int b = static_cast<unsigned int>(x);
                sum[b] += y[k];
                ++count[b];
              }
          }
        for (unsigned int b = 0; b < n; ++b)
          sum[b] = count[b] > 0 ? sum[b] / count[b]
                                : std::numeric_limits<double>::quiet_NaN();
        return sum;
      }


      /**
       * The difference of two runs paired in time (PairedDifference::
       * in_time): both mu(t) binned onto bins of twice the larger sample
       * spacing from the later averaging start @p from to the earlier end;
       * the bins both runs fill give the series d_k = mu_c,k - mu_r,k,
       * block-averaged (statistics::block_average), relative to the mean
       * of mu_r,k over the same bins. @p d's in-time fields stay NaN when
       * a series is missing or leaves fewer than 8 common bins.
       */
      void
      difference_in_time(const std::string &reference,
                         const std::string &compare,
                         const double       from,
                         PairedDifference  &d)
      {
        std::vector<double> tr, mr, tc, mc;
        read_mu_series(reference, tr, mr);
        read_mu_series(compare, tc, mc);
        if (tr.size() < 2 || tc.size() < 2 || !std::isfinite(from))
          return;
        const double w  = 2 * std::max(spacing(tr), spacing(tc));
        const double to = std::min(tr.back(), tc.back());
        if (!(w > 0) || !(to > from))
          return;
        const unsigned int n  = static_cast<unsigned int>((to - from) / w);
        const auto         br = bin_means(tr, mr, from, w, n),
                   bc         = bin_means(tc, mc, from, w, n);
        std::vector<double> difference;
        double              reference_sum = 0;
        for (unsigned int b = 0; b < n; ++b)
          if (std::isfinite(br[b]) && std::isfinite(bc[b]))
            {
              difference.push_back(bc[b] - br[b]);
              reference_sum += br[b];
            }
        if (difference.size() < 8 || !(reference_sum != 0))
          return;
        const double reference_mean = reference_sum / difference.size();
        const statistics::MeanWithError e
          = statistics::block_average(difference);
        d.in_time             = e.mean / reference_mean;
        d.in_time_stderr      = e.standard_error / std::abs(reference_mean);
        d.in_time_runs_stderr = d.in_time_stderr;
        d.in_time_from        = from;
        d.in_time_bins        = difference.size();
      }


      SceneResult
      read_scene(const std::string &directory)
      {
        SceneResult   r;
        std::ifstream in(join_path(directory, "summary.json"));
        if (!in)
          return r;
        nlohmann::json j;
        try
          {
            j = nlohmann::json::parse(in);
          }
        catch (const std::exception &)
          {
            return r;
          }
        r.found     = true;
        r.has_mu    = j.contains("mu_steady") && j["mu_steady"].is_number();
        r.mu_steady = number_or_nan(j, "mu_steady");
        r.mu_steady_stderr   = number_or_nan(j, "mu_steady_stderr");
        r.steady_found       = j.value("steady_state_found", false);
        r.steady_start_time  = number_or_nan(j, "steady_start_time");
        r.end_time           = number_or_nan(j, "end_time");
        r.layer_thickness    = number_or_nan(j, "quasi_fluid_layer_thickness");
        r.inclusion_fraction = number_or_nan(j, "inclusion_volume_fraction");
        r.n_automata         = number_or_nan(j, "n_automata");
        for (const SceneLeg &leg : read_scene_legs(directory + ".legs.csv"))
          {
            ++r.legs;
            r.wall_time_s += leg.wall_time_s;
            r.core_hours += leg.wall_time_s * leg.ranks / 3600.;
          }
        return r;
      }
    } // namespace


    void
    tag_scene_summary(const std::string        &directory,
                      const McaScene           &scene,
                      const McaStudyParameters &parameters)
    {
      const std::string file = join_path(directory, "summary.json");
      std::ifstream     in(file);
      if (!in)
        return;
      nlohmann::ordered_json j;
      try
        {
          j = nlohmann::ordered_json::parse(in);
        }
      catch (const std::exception &)
        {
          return;
        }
      nlohmann::ordered_json tag;
      tag["name"]           = scene.name;
      tag["base"]           = parameters.bases[scene.base].name;
      tag["base_file"]      = parameters.bases[scene.base].file;
      tag["roughness_seed"] = scene.roughness_seed;
      tag["inclusion_seed"] = scene.inclusion_seed;
      tag["factors"]        = nlohmann::ordered_json::object();
      for (std::size_t k = 0; k < parameters.factors.size(); ++k)
        tag["factors"][parameters.factors[k].path] = scene.levels[k];
      if (j.contains("study_scene") && j["study_scene"] == tag)
        return;
      j["study_scene"] = tag;
      write_file_atomically(file, j.dump(2) + "\n");
    }


    void
    append_scene_leg(const std::string &file, const SceneLeg &leg)
    {
      std::ostringstream text;
      std::ifstream      in(file);
      if (in)
        text << in.rdbuf();
      else
        text << legs_header << "\n";
      text << leg.start << "," << leg.ranks << "," << std::setprecision(10)
           << leg.wall_time_s << "," << leg.end << "\n";
      write_file_atomically(file, text.str());
    }


    std::vector<SceneLeg>
    read_scene_legs(const std::string &file)
    {
      std::vector<SceneLeg> legs;
      std::ifstream         in(file);
      std::string           line;
      if (!std::getline(in, line) || line != legs_header)
        return legs;
      while (std::getline(in, line))
        {
          const auto fields = dealii::Utilities::split_string_list(line, ',');
          if (fields.size() != 4)
            continue;
          SceneLeg leg;
          leg.start = fields[0];
          try
            {
              leg.ranks       = std::stoul(fields[1]);
              leg.wall_time_s = std::stod(fields[2]);
            }
          catch (const std::exception &)
            {
              continue;
            }
          leg.end = fields[3];
          legs.push_back(leg);
        }
      return legs;
    }


    McaStudyAnalysis::McaStudyAnalysis(
      const McaStudyParameters       &parameters,
      const std::vector<McaScene>    &scenes,
      const std::vector<std::string> &directories)
        : parameters(parameters)
        , scenes(scenes)
        , directories(directories)
    {
      for (const auto &f : parameters.factors)
        n_levels *= f.values.size();
      for (unsigned int b = 0; b < parameters.bases.size(); ++b)
        if (parameters.bases[b].name == parameters.reference)
          reference = b;
      for (const std::string &dir : directories)
        results.push_back(read_scene(dir));

      // Per seed, then the mean over the seeds, for each compared base and
      // factor level.
      const unsigned int n_seeds = parameters.roughness_seeds.size();
      for (unsigned int c = 0; c < parameters.bases.size(); ++c)
        {
          if (c == reference)
            continue;
          for (unsigned int l = 0; l < n_levels; ++l)
            {
              std::vector<PairedDifference> per_seed;
              for (unsigned int s = 0; s < n_seeds; ++s)
                {
                  const unsigned int ir = scene_index(reference, s, l),
                                     ic = scene_index(c, s, l);
                  const SceneResult &r = results[ir], &m = results[ic];
                  if (!r.has_mu || !m.has_mu)
                    continue;
                  PairedDifference d;
                  d.compare             = c;
                  d.level               = l;
                  d.seed_index          = s;
                  d.scene_reference     = scenes[ir].name;
                  d.scene_compare       = scenes[ic].name;
                  d.mu_reference        = r.mu_steady;
                  d.mu_reference_stderr = r.mu_steady_stderr;
                  d.mu_compare          = m.mu_steady;
                  d.mu_compare_stderr   = m.mu_steady_stderr;
                  const double ratio    = m.mu_steady / r.mu_steady;
                  d.relative_difference = ratio - 1;
                  d.relative_difference_stderr
                    = std::abs(ratio)
                      * std::hypot(m.mu_steady_stderr / m.mu_steady,
                                   r.mu_steady_stderr / r.mu_steady);
                  d.relative_difference_runs_stderr
                    = d.relative_difference_stderr;
                  d.layer_reference        = r.layer_thickness;
                  d.layer_compare          = m.layer_thickness;
                  d.steady_start_reference = r.steady_start_time;
                  d.steady_start_compare   = m.steady_start_time;
                  d.n_steady = r.steady_found && m.steady_found ? 1 : 0;
                  difference_in_time(directories[ir],
                                     directories[ic],
                                     std::max(r.steady_start_time,
                                              m.steady_start_time),
                                     d);
                  per_seed.push_back(d);
                }
              pairs.insert(pairs.end(), per_seed.begin(), per_seed.end());
              if (per_seed.empty())
                continue;

              PairedDifference mean;
              mean.compare    = c;
              mean.level      = l;
              mean.n_seeds    = per_seed.size();
              auto over_seeds = [&](double PairedDifference::*field)
                -> std::pair<double, double> {
                std::vector<double> values;
                for (const auto &d : per_seed)
                  values.push_back(d.*field);
                return mean_and_stderr(values);
              };
              double runs_variance = 0;
              for (const auto &d : per_seed)
                {
                  runs_variance += d.relative_difference_stderr
                                   * d.relative_difference_stderr;
                  mean.n_steady += d.n_steady;
                }
              const double n = per_seed.size();
              std::tie(mean.mu_reference, mean.mu_reference_stderr)
                = over_seeds(&PairedDifference::mu_reference);
              std::tie(mean.mu_compare, mean.mu_compare_stderr)
                = over_seeds(&PairedDifference::mu_compare);
              std::tie(mean.relative_difference,
                       mean.relative_difference_stderr)
                = over_seeds(&PairedDifference::relative_difference);
              mean.relative_difference_runs_stderr
                = std::sqrt(runs_variance) / n;
              if (per_seed.size() == 1)
                {
                  // one seed: the runs' own errors are all there is
                  mean.mu_reference_stderr = per_seed[0].mu_reference_stderr;
                  mean.mu_compare_stderr   = per_seed[0].mu_compare_stderr;
                  mean.relative_difference_stderr
                    = per_seed[0].relative_difference_stderr;
                }
              // the difference in time over the seeds that have one
              {
                std::vector<double> values;
                double              variance = 0;
                for (const auto &d : per_seed)
                  if (std::isfinite(d.in_time))
                    {
                      values.push_back(d.in_time);
                      variance += d.in_time_stderr * d.in_time_stderr;
                    }
                if (values.size() == per_seed.size())
                  {
                    std::tie(mean.in_time, mean.in_time_stderr)
                      = mean_and_stderr(values);
                    mean.in_time_runs_stderr
                      = std::sqrt(variance) / values.size();
                    if (values.size() == 1)
                      mean.in_time_stderr = per_seed[0].in_time_stderr;
                  }
              }
              mean.layer_reference
                = over_seeds(&PairedDifference::layer_reference).first;
              mean.layer_compare
                = over_seeds(&PairedDifference::layer_compare).first;
              mean.steady_start_reference
                = over_seeds(&PairedDifference::steady_start_reference).first;
              mean.steady_start_compare
                = over_seeds(&PairedDifference::steady_start_compare).first;
              pairs.push_back(mean);
            }
        }
    }


    unsigned int
    McaStudyAnalysis::scene_index(const unsigned int base,
                                  const unsigned int seed_index,
                                  const unsigned int level) const
    {
      // by the scenes' own fields, not by the order they were made in
      for (unsigned int i = 0; i < scenes.size(); ++i)
        if (scenes[i].base == base && scenes[i].seed_index == seed_index
            && scenes[i].level_index == level)
          return i;
      throw std::logic_error(
        "McaStudyAnalysis: no scene of base " + std::to_string(base) + ", seed "
        + std::to_string(seed_index) + ", level " + std::to_string(level));
    }


    std::string
    McaStudyAnalysis::level_label(const unsigned int level) const
    {
      std::string label;
      for (std::size_t k = 0; k < parameters.factors.size(); ++k)
        label += (label.empty() ? "" : ", ") + parameters.factors[k].path
                 + " = " + scenes[scene_index(0, 0, level)].levels[k];
      return label;
    }


    void
    McaStudyAnalysis::write(const std::string &directory,
                            const double       wall_time_s,
                            const unsigned int n_mpi_ranks,
                            std::ostream      &out) const
    {
      const auto &bases = parameters.bases;
      std::string factor_columns;
      for (const auto &f : parameters.factors)
        factor_columns += "," + f.path;

      // scenes.csv: a row per scene, with its cost
      {
        std::ostringstream t;
        t << "scene,base,roughness_seed,inclusion_seed" << factor_columns
          << ",mu_steady,mu_steady_stderr,steady_state_found,"
             "steady_start_time,end_time,quasi_fluid_layer_thickness,"
             "inclusion_volume_fraction,n_automata,legs,wall_time_s,"
             "core_hours\n";
        for (std::size_t i = 0; i < scenes.size(); ++i)
          {
            const McaScene    &s = scenes[i];
            const SceneResult &r = results[i];
            t << s.name << "," << bases[s.base].name << "," << s.roughness_seed
              << "," << s.inclusion_seed;
            for (const auto &level : s.levels)
              t << "," << level;
            if (r.has_mu)
              t << "," << csv(r.mu_steady) << "," << csv(r.mu_steady_stderr)
                << "," << (r.steady_found ? 1 : 0) << ","
                << csv(r.steady_start_time) << "," << csv(r.end_time) << ","
                << csv(r.layer_thickness) << "," << csv(r.inclusion_fraction)
                << "," << csv(r.n_automata);
            else
              t << ",,,,,,,,";
            t << "," << r.legs << "," << csv(r.wall_time_s) << ","
              << csv(r.core_hours) << "\n";
          }
        write_file_atomically(join_path(directory, "scenes.csv"), t.str());
      }

      // study.csv: the paired differences and their means (no run times)
      {
        std::ostringstream t;
        t << "row,compare,reference" << factor_columns
          << ",roughness_seed,inclusion_seed,scene_reference,scene_compare,"
             "mu_reference,mu_reference_stderr,mu_compare,mu_compare_stderr,"
             "relative_difference,relative_difference_stderr,"
             "relative_difference_runs_stderr,layer_reference,layer_compare,"
             "steady_start_reference,steady_start_compare,n_seeds,n_steady,"
             "relative_difference_in_time,relative_difference_in_time_stderr,"
             "relative_difference_in_time_runs_stderr,in_time_from,"
             "in_time_bins\n";
        for (const PairedDifference &d : pairs)
          {
            const McaScene &first = scenes[scene_index(
              0, d.seed_index < 0 ? 0 : d.seed_index, d.level)];
            t << (d.seed_index < 0 ? "mean" : "seed") << ","
              << bases[d.compare].name << "," << bases[reference].name;
            for (const auto &level : first.levels)
              t << "," << level;
            if (d.seed_index < 0)
              t << ",,,,";
            else
              t << "," << first.roughness_seed << "," << first.inclusion_seed
                << "," << d.scene_reference << "," << d.scene_compare;
            for (const double v : {d.mu_reference,
                                   d.mu_reference_stderr,
                                   d.mu_compare,
                                   d.mu_compare_stderr,
                                   d.relative_difference,
                                   d.relative_difference_stderr,
                                   d.relative_difference_runs_stderr,
                                   d.layer_reference,
                                   d.layer_compare,
                                   d.steady_start_reference,
                                   d.steady_start_compare})
              t << "," << csv(v);
            t << "," << d.n_seeds << "," << d.n_steady << "," << csv(d.in_time)
              << "," << csv(d.in_time_stderr) << ","
              << csv(d.in_time_runs_stderr) << "," << csv(d.in_time_from) << ","
              << d.in_time_bins << "\n";
          }
        write_file_atomically(join_path(directory, "study.csv"), t.str());
      }

      // seeds_COMPARE[_LEVEL].csv: what scripts/plot_mca_seeds draws
      for (unsigned int c = 0; c < bases.size(); ++c)
        for (unsigned int l = 0; l < n_levels && c != reference; ++l)
          {
            const std::string &rn = bases[reference].name, &cn = bases[c].name;
            std::ostringstream t;
            t << "seed";
            for (const std::string &name : {rn, cn})
              t << "," << name << "_mu_steady," << name << "_mu_steady_stderr,"
                << name << "_quasi_fluid_layer_thickness";
            t << ",relative_difference,relative_difference_stderr\n";
            for (const PairedDifference &d : pairs)
              if (d.compare == c && d.level == l && d.seed_index >= 0)
                t << parameters.roughness_seeds[d.seed_index] << ","
                  << csv(d.mu_reference) << "," << csv(d.mu_reference_stderr)
                  << "," << csv(d.layer_reference) << "," << csv(d.mu_compare)
                  << "," << csv(d.mu_compare_stderr) << ","
                  << csv(d.layer_compare) << "," << csv(d.relative_difference)
                  << "," << csv(d.relative_difference_stderr) << "\n";
            const std::string name
              = "seeds_" + cn
                + (n_levels > 1 ? "_level" + std::to_string(l + 1) : "")
                + ".csv";
            write_file_atomically(join_path(directory, name), t.str());
          }

      // study.md and the headline on the screen
      double core_hours = 0;
      for (const SceneResult &r : results)
        core_hours += r.core_hours;
      std::ostringstream md;
      md << "# MCA study\n\nReference base: **" << bases[reference].name
         << "**. Relative difference = (mu_base - mu_reference) / "
            "mu_reference, paired on each roughness seed; the mean over the "
            "seeds with the standard error of that mean from the scatter "
            "between the seeds (the runs' own errors propagated: "
            "'runs'). Paired in time: the runs' mu(t) binned onto common "
            "bins from the later averaging start, their difference "
            "block-averaged as one series (doc/user_guide/mca_study.md).\n";
      for (unsigned int c = 0; c < bases.size(); ++c)
        for (unsigned int l = 0; l < n_levels && c != reference; ++l)
          {
            md << "\n## " << bases[c].name << " against "
               << bases[reference].name
               << (parameters.factors.empty() ? "" : ", " + level_label(l))
               << "\n\n| roughness seed | mu " << bases[reference].name
               << " | mu " << bases[c].name << " | difference | layer "
               << bases[reference].name << " | layer " << bases[c].name
               << " | steady from | both steady | difference paired in time "
                  "|\n"
                  "|---|---|---|---|---|---|---|---|---|\n";
            for (const PairedDifference &d : pairs)
              {
                if (d.compare != c || d.level != l)
                  continue;
                const bool mean = d.seed_index < 0;
                md << "| "
                   << (mean ? "mean ± standard error over "
                                + std::to_string(d.n_seeds) + " seeds"
                            : std::to_string(
                              parameters.roughness_seeds[d.seed_index]))
                   << " | " << fixed(d.mu_reference, 3) << " ± "
                   << fixed(d.mu_reference_stderr, 3) << " | "
                   << fixed(d.mu_compare, 3) << " ± "
                   << fixed(d.mu_compare_stderr, 3) << " | "
                   << (d.relative_difference >= 0 ? "+" : "−")
                   << fixed(100 * std::abs(d.relative_difference), 1) << " % ± "
                   << fixed(100 * d.relative_difference_stderr, 1) << " %"
                   << (mean && d.n_seeds > 1
                         ? " (runs ± "
                             + fixed(100 * d.relative_difference_runs_stderr, 1)
                             + " %)"
                         : "")
                   << " | " << fixed(1e9 * d.layer_reference, 1) << " nm | "
                   << fixed(1e9 * d.layer_compare, 1) << " nm | "
                   << fixed(1e9 * d.steady_start_reference, 1) << " / "
                   << fixed(1e9 * d.steady_start_compare, 1) << " ns | "
                   << d.n_steady
                   << (mean ? " of " + std::to_string(d.n_seeds)
                            : std::string(d.n_steady ? " (yes)" : " (no)"))
                   << " | "
                   << (std::isfinite(d.in_time)
                         ? std::string(d.in_time >= 0 ? "+" : "−")
                             + fixed(100 * std::abs(d.in_time), 1) + " % ± "
                             + fixed(100 * d.in_time_stderr, 1) + " %"
                         : std::string("-"))
                   << " |\n";
                if (mean)
                  {
                    out << "MCA study: " << bases[c].name << " against "
                        << bases[reference].name
                        << (parameters.factors.empty()
                              ? ""
                              : " (" + level_label(l) + ")")
                        << ": relative difference of mu_steady "
                        << fixed(100 * d.relative_difference, 2) << " % +- "
                        << fixed(100 * d.relative_difference_stderr, 2)
                        << " % over " << d.n_seeds << " seed(s)";
                    if (std::isfinite(d.in_time))
                      out << "; paired in time " << fixed(100 * d.in_time, 2)
                          << " % +- " << fixed(100 * d.in_time_stderr, 2)
                          << " %";
                    if (d.n_steady < d.n_seeds)
                      out << "; " << d.n_seeds - d.n_steady
                          << " pair(s) reached no quasi-steady regime (their "
                             "mu is the record's last part: run longer)";
                    out << std::endl;
                  }
              }
          }
      md << "\nCost: " << fixed(core_hours, 3)
         << " core-hours over the scenes' legs (scenes.csv); this call "
         << fixed(wall_time_s, 1) << " s on " << n_mpi_ranks
         << " MPI rank(s).\n";
      write_file_atomically(join_path(directory, "study.md"), md.str());

      nlohmann::ordered_json j;
      j["problem"]          = "mca_study";
      j["tribodyn_version"] = version_string;
      j["n_mpi_ranks"]      = n_mpi_ranks;
      j["reference_base"]   = bases[reference].name;
      for (const auto &b : bases)
        j["bases"][b.name] = b.file;
      j["roughness_seeds"] = parameters.roughness_seeds;
      j["inclusion_seeds"] = parameters.inclusion_seeds;
      for (const auto &f : parameters.factors)
        j["factors"][f.path] = f.values;
      j["n_scenes"]        = scenes.size();
      unsigned int n_found = 0, n_mu = 0;
      for (const SceneResult &r : results)
        {
          n_found += r.found ? 1 : 0;
          n_mu += r.has_mu ? 1 : 0;
        }
      j["n_scenes_finished"] = n_found;
      j["n_scenes_with_mu"]  = n_mu;
      auto json_number       = [](const double v) {
        return std::isfinite(v) ? nlohmann::ordered_json(v)
                                      : nlohmann::ordered_json();
      };
      for (const PairedDifference &d : pairs)
        if (d.seed_index < 0)
          {
            nlohmann::ordered_json m;
            m["compare"]   = bases[d.compare].name;
            m["reference"] = bases[reference].name;
            for (std::size_t k = 0; k < parameters.factors.size(); ++k)
              m["factors"][parameters.factors[k].path]
                = scenes[scene_index(0, 0, d.level)].levels[k];
            m["n_seeds"]             = d.n_seeds;
            m["n_steady"]            = d.n_steady;
            m["relative_difference"] = json_number(d.relative_difference);
            m["relative_difference_stderr"]
              = json_number(d.relative_difference_stderr);
            m["relative_difference_runs_stderr"]
              = json_number(d.relative_difference_runs_stderr);
            m["relative_difference_in_time"] = json_number(d.in_time);
            m["relative_difference_in_time_stderr"]
              = json_number(d.in_time_stderr);
            m["relative_difference_in_time_runs_stderr"]
              = json_number(d.in_time_runs_stderr);
            m["mu_reference"]    = json_number(d.mu_reference);
            m["mu_compare"]      = json_number(d.mu_compare);
            m["layer_reference"] = json_number(d.layer_reference);
            m["layer_compare"]   = json_number(d.layer_compare);
            j["comparisons"].push_back(m);
          }
      j["core_hours"]  = core_hours;
      j["wall_time_s"] = wall_time_s;
      write_file_atomically(join_path(directory, "summary.json"),
                            j.dump(2) + "\n");
      out << "MCA study: " << n_found << " of " << scenes.size()
          << " scenes finished";
      if (n_mu < n_found)
        out << " (" << n_found - n_mu
            << " without a friction coefficient: they end before their "
               "bodies slide; raise 'Time/End time')";
      out << ", " << fixed(core_hours, 3) << " core-hours in all; tables in "
          << directory << " (study.csv, study.md, scenes.csv)" << std::endl;
    }
  } // namespace study
} // namespace tribodyn
