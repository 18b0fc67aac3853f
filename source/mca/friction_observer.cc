#include <cmath>
#include <tribodyn/core/output.h>
#include <tribodyn/mca/friction_observer.h>

namespace tribodyn
{
  namespace mca
  {
    FrictionObserver::FrictionObserver(const Parameters &parameters,
                                       const int         loaded_group)
        : prm(parameters)
        , loaded(loaded_group)
    {
    }


    double
    FrictionObserver::record(const double             time,
                             const std::vector<Vec3> &group_forces,
                             const SystemEnergies    &energies)
    {
      if (loaded < 0)
        return 0;
      const unsigned int a  = prm.analysis.axis;
      const Vec3        &f  = group_forces[loaded];
      const double       fn = std::abs(f[a]);
      double             ft = 0;
      for (unsigned int c = 0; c < 3; ++c)
        if (c != a)
          ft += f[c] * f[c];
      ft = std::sqrt(ft);
      times.push_back(time);
      normal.push_back(fn);
      tangential.push_back(ft);
      bonded.push_back(energies.n_bonded);
      unbonded.push_back(energies.n_unbonded_contacts);
      return fn > 0 ? ft / fn : 0;
    }


    FrictionAnalysis
    FrictionObserver::write_series(const std::string &output_directory,
                                   const bool         root) const
    {
      FrictionAnalysisParameters ap;
      ap.smoothing_window     = prm.analysis.smoothing_window > 0
                                  ? prm.analysis.smoothing_window
                                  : 0.1 * prm.time.end_time;
      ap.steady_relative_band = prm.analysis.steady_band;
      const FrictionAnalysis fa
        = analyse_friction(times, normal, tangential, ap);
      CsvWriter csv(join_path(output_directory, "friction.csv"),
                    {"time",
                     "normal_force",
                     "tangential_force",
                     "mu",
                     "mu_smoothed",
                     "n_bonded",
                     "n_unbonded"},
                    root);
      for (std::size_t k = 0; k < times.size(); ++k)
        csv.add_row({times[k],
                     normal[k],
                     tangential[k],
                     fa.mu[k],
                     fa.mu_smoothed[k],
                     bonded[k],
                     unbonded[k]});
      csv.flush(true);
      return fa;
    }


    void
    FrictionObserver::finish(const std::string &output_directory,
                             const bool         root,
                             JsonValue         &summary,
                             std::ostream      &figures) const
    {
      if (times.size() < 2)
        return;
      const FrictionAnalysis fa = write_series(output_directory, root);
      // the plain mean from Averaging start (as before), and the steady mu
      double       sum = 0;
      unsigned int n   = 0;
      for (std::size_t k = 0; k < times.size(); ++k)
        if (times[k] >= prm.analysis.averaging_start)
          {
            sum += fa.mu[k];
            ++n;
          }
      const double mean                    = n > 0 ? sum / n : 0.;
      summary["mean_friction_coefficient"] = mean;
      summary["mu_steady"]                 = fa.mu_steady.mean;
      summary["mu_steady_stderr"]          = fa.mu_steady.standard_error;
      summary["steady_state_found"]        = fa.steady.found;
      summary["steady_start_time"]
        = fa.steady.found ? fa.steady.start_time : times[fa.averaged_from];
      figures << "Friction: mean mu = " << mean
              << " over t >= " << prm.analysis.averaging_start << " s (" << n
              << " samples); steady mu = " << fa.mu_steady.mean << " +- "
              << fa.mu_steady.standard_error << " (block averaging"
              << (fa.mu_steady.plateau_found ? "" : ", no plateau: too short")
              << ") from t = "
              << (fa.steady.found ? fa.steady.start_time
                                  : times[fa.averaged_from])
              << " s"
              << (fa.steady.found ? "" : " (no quasi-steady regime detected)")
              << std::endl;
    }
  } // namespace mca
} // namespace tribodyn
