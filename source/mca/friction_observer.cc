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
    FrictionObserver::record_layer(const double           time,
                                   const AutomatonSystem &system,
                                   const MPI_Comm         comm)
    {
      const unsigned int  a    = prm.analysis.axis;
      const unsigned int  n    = system.n_owned_automata();
      const auto         &x    = system.positions();
      const auto          free = system.unbonded_contact_counts();
      const auto         &eps  = system.plastic_strains();
      std::vector<double> z(n), contacts(n), strain(n);
      double              lo = 1e300, hi = -1e300;
      for (unsigned int k = 0; k < n; ++k)
        {
          z[k]        = x[k][a];
          contacts[k] = free[k];
          strain[k]   = eps[k];
          lo          = std::min(lo, z[k]);
          hi          = std::max(hi, z[k]);
        }
      lo = dealii::Utilities::MPI::min(lo, comm);
      hi = dealii::Utilities::MPI::max(hi, comm);
      hi += 1e-9 * (hi - lo) + 1e-300; // the topmost automaton inside
      const double width = prm.analysis.layer_bin_width > 0
                             ? prm.analysis.layer_bin_width
                             : prm.geometry.automaton_size;
      const double bin   = std::min(width, hi - lo);
      const double th    = prm.analysis.layer_threshold;
      last_contacts
        = quasi_fluid_layer_profile(z, contacts, lo, hi, bin, th, comm);
      last_strain = quasi_fluid_layer_profile(z, strain, lo, hi, bin, th, comm);
      const double nan = std::nan("");
      layer_times.push_back(time);
      layer_thickness.push_back(last_contacts.found ? last_contacts.thickness
                                                    : nan);
      layer_center.push_back(last_contacts.found ? last_contacts.center : nan);
      layer_peak.push_back(last_contacts.peak);
      strain_thickness.push_back(last_strain.found ? last_strain.thickness
                                                   : nan);
      strain_center.push_back(last_strain.found ? last_strain.center : nan);
    }


    void
    FrictionObserver::write_layer(const std::string      &output_directory,
                                  const bool              root,
                                  JsonValue              &summary,
                                  std::ostream           &figures,
                                  const FrictionAnalysis &fa) const
    {
      if (layer_times.empty())
        return;
      {
        CsvWriter csv(join_path(output_directory, "layer.csv"),
                      {"time",
                       "thickness",
                       "center",
                       "peak_unbonded_contacts",
                       "strain_thickness",
                       "strain_center"},
                      root);
        for (std::size_t k = 0; k < layer_times.size(); ++k)
          csv.add_row({layer_times[k],
                       layer_thickness[k],
                       layer_center[k],
                       layer_peak[k],
                       strain_thickness[k],
                       strain_center[k]});
        csv.flush(true);
      }
      {
        CsvWriter csv(join_path(output_directory, "layer_profile.csv"),
                      {"z", "unbonded_contacts", "plastic_strain", "count"},
                      root);
        for (unsigned int k = 0; k < last_contacts.mean.size(); ++k)
          csv.add_row({last_contacts.bin_center(k),
                       last_contacts.mean[k],
                       k < last_strain.mean.size() ? last_strain.mean[k] : 0.,
                       last_contacts.count[k]});
        csv.flush(true);
      }
      // Means over the quasi-steady part of mu (the same time window).
      const double from = times.empty() ? 0. : times[fa.averaged_from];
      auto         mean = [&](const std::vector<double> &values) {
        double       sum = 0;
        unsigned int n   = 0;
        for (std::size_t k = 0; k < layer_times.size(); ++k)
          if (layer_times[k] >= from && std::isfinite(values[k]))
            {
              sum += values[k];
              ++n;
            }
        return n > 0 ? sum / n : std::nan("");
      };
      auto json = [](const double value) {
        return std::isfinite(value) ? JsonValue(value) : JsonValue();
      };
      const double thickness                    = mean(layer_thickness);
      const double strain_thickness_mean        = mean(strain_thickness);
      summary["quasi_fluid_layer_thickness"]    = json(thickness);
      summary["quasi_fluid_layer_center"]       = json(mean(layer_center));
      summary["plastic_strain_layer_thickness"] = json(strain_thickness_mean);
      summary["plastic_strain_layer_center"]    = json(mean(strain_center));
      summary["quasi_fluid_layer_thickness_final"]
        = json(layer_thickness.back());
      figures << "Quasi-fluid layer (FWHM of the unbonded contacts per "
                 "automaton) from t = "
              << from << " s: mean thickness " << thickness
              << " m; plastic-strain layer " << strain_thickness_mean << " m"
              << std::endl;
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
      write_layer(output_directory, root, summary, figures, fa);
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
