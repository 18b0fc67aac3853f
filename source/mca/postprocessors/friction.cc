// Postprocessor "friction" (`Analysis/Type = friction`): mu of the loaded
// group at each series sample (column "mu"), the quasi-fluid layer, and at
// the end friction.csv, layer.csv, layer_profile.csv, the quasi-steady
// regime and the block-averaged steady mu with its standard error.
#include <cmath>
#include <tribodyn/core/output.h>
#include <tribodyn/mca/friction_analysis.h>
#include <tribodyn/mca/postprocessor.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      /**
       * The friction observer of `Analysis/Type = friction`: at each series
       * sample, the normal force (along `Analysis/Axis`) and the tangential
       * force on the loaded group, mu = |F_t| / |F_n| and the pair counts; at
       * the end, friction.csv (time, normal_force, tangential_force, mu,
       * mu_smoothed, n_bonded, n_unbonded), the quasi-steady regime and the
       * block-averaged steady mu with its standard error
       * (analyse_friction()), in summary.json.
       */
      class FrictionObserver : public Postprocessor
      {
      public:
        explicit FrictionObserver(const PostprocessorInputs &in);

        /// Column "mu"; before the first contact of a staged loading 0
        std::vector<std::string>
        series_columns() const override
        {
          return {"mu"};
        }

        /// One sample of mu and of the layer.
        void
        record(const SeriesSample &sample, std::vector<double> &row) override;

        std::string
        key_figure() const override;

        /// friction.csv and layer.csv (by the root rank), layer_profile.csv
        /// (the last profiles), summary keys, a line of figures.
        void
        finish(JsonValue &summary, std::ostream &figures) const override;

        /// friction.csv of the samples so far (also when a run stops early).
        void
        write_partial_results() const override;

        /// The recorded series; the last layer profiles are not saved: the
        /// next sample, at the latest the run's last, recomputes them.
        std::vector<std::vector<double> *>
        saved_series() override
        {
          return {&times,
                  &normal,
                  &tangential,
                  &bonded,
                  &unbonded,
                  &layer_times,
                  &layer_thickness,
                  &layer_center,
                  &strain_thickness,
                  &strain_center,
                  &layer_peak};
        }

      private:
        /// Append one sample of the forces; returns mu.
        double
        record_mu(const SeriesSample &sample);

        /// friction.csv of the samples so far (by the root rank); returns the
        /// analysis.
        FrictionAnalysis
        write_series() const;

        /**
         * Quasi-fluid layer at this sample: z-profiles (bins of Analysis/
         * Layer bin width along the normal axis, over the automata's current
         * extent) of the unbonded contacts per automaton and of the
         * accumulated equivalent plastic strain; the layer
         * (quasi_fluid_layer_profile()) of each. Collective.
         */
        void
        record_layer(const double time);

        /// layer.csv, layer_profile.csv and the layer's summary keys: means
        /// over the samples from the start of the quasi-steady regime.
        void
        write_layer(JsonValue              &summary,
                    std::ostream           &figures,
                    const FrictionAnalysis &fa) const;

        const AutomatonSystem &system;
        const Parameters      &prm;
        const MPI_Comm         comm;
        const std::string      output_directory;
        const bool             root;
        /// the loaded group (Analysis/Loaded group)
        int loaded = -1;
        /// with a staged loading, mu is recorded from the first contact
        bool                staged  = false;
        double              last_mu = 0;
        std::vector<double> times, normal, tangential, bonded, unbonded;
        /// layer.csv columns
        std::vector<double> layer_times, layer_thickness, layer_center,
          strain_thickness, strain_center, layer_peak;
        LayerProfile last_contacts, last_strain;
      };

      FrictionObserver::FrictionObserver(const PostprocessorInputs &in)
          : system(in.system)
          , prm(in.parameters)
          , comm(in.comm)
          , output_directory(in.output_directory)
          , root(in.root)
      {
        // (the parameters refuse a loaded group that does not exist)
        for (unsigned int g = 0; g < prm.boundary.groups.size(); ++g)
          if (prm.boundary.groups[g].name == prm.analysis.loaded_group)
            loaded = g;
        for (const auto &g : prm.boundary.groups)
          staged = staged || g.switch_on_contact;
      }


      void
      FrictionObserver::record(const SeriesSample  &sample,
                               std::vector<double> &row)
      {
        // With a staged loading, mu is recorded from the first contact of the
        // bodies on (before it the layers carry no load).
        last_mu = 0;
        if (!staged || system.contact_time() >= 0)
          {
            last_mu = record_mu(sample);
            record_layer(sample.time);
          }
        row.push_back(last_mu);
      }


      std::string
      FrictionObserver::key_figure() const
      {
        return "mu = " + format_number(last_mu);
      }


      double
      FrictionObserver::record_mu(const SeriesSample &sample)
      {
        const double       time     = sample.time;
        const auto        &energies = sample.energies;
        const unsigned int a        = prm.analysis.axis;
        const Vec3        &f        = sample.group_forces[loaded];
        const double       fn       = std::abs(f[a]);
        double             ft       = 0;
        for (unsigned int c = 0; c < 3; ++c)
          if (c != a)
            ft += f[c] * f[c];
        ft = std::sqrt(ft);
        times.push_back(time);
        normal.push_back(fn);
        tangential.push_back(ft);
        bonded.push_back(energies[Energy::n_bonded]);
        unbonded.push_back(energies[Energy::n_unbonded]);
        return fn > 0 ? ft / fn : 0;
      }


      void
      FrictionObserver::write_partial_results() const
      {
        if (times.size() >= 2)
          write_series();
      }


      FrictionAnalysis
      FrictionObserver::write_series() const
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
      FrictionObserver::record_layer(const double time)
      {
        const unsigned int  a    = prm.analysis.axis;
        const unsigned int  n    = system.n_owned_automata();
        const auto         &x    = system.positions();
        const auto          free = system.unbonded_contact_counts();
        std::vector<double> z(n), contacts(n), strain(n);
        double              lo = 1e300, hi = -1e300;
        for (unsigned int k = 0; k < n; ++k)
          {
            z[k]        = x[k][a];
            contacts[k] = free[k];
            strain[k]   = system.plastic_strain(k);
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
        last_strain
          = quasi_fluid_layer_profile(z, strain, lo, hi, bin, th, comm);
        const double nan = std::nan("");
        layer_times.push_back(time);
        layer_thickness.push_back(last_contacts.found ? last_contacts.thickness
                                                      : nan);
        layer_center.push_back(last_contacts.found ? last_contacts.center
                                                   : nan);
        layer_peak.push_back(last_contacts.peak);
        strain_thickness.push_back(last_strain.found ? last_strain.thickness
                                                     : nan);
        strain_center.push_back(last_strain.found ? last_strain.center : nan);
      }


      void
      FrictionObserver::write_layer(JsonValue              &summary,
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
      FrictionObserver::finish(JsonValue &summary, std::ostream &figures) const
      {
        if (times.size() < 2)
          return;
        const FrictionAnalysis fa = write_series();
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
        // The peak of the smoothed mu once the sliding has started (from the
        // contact plus Friction loading/Sliding delay with a staged loading):
        // with a delay and a slow sliding, the breakaway (static) coefficient.
        const double slide_from
          = staged ? system.contact_time() + prm.loading.sliding_delay
                   : times.front();
        double peak = 0, peak_time = times.front();
        for (std::size_t k = 0; k < times.size(); ++k)
          if (times[k] >= slide_from && fa.mu_smoothed[k] > peak)
            {
              peak      = fa.mu_smoothed[k];
              peak_time = times[k];
            }
        summary["mu_peak"]      = peak;
        summary["mu_peak_time"] = peak_time;
        write_layer(summary, figures, fa);
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


      const bool friction_registered = PostprocessorRegistry::add(
        {"friction",
         30,
         [](const PostprocessorInputs &in) -> std::unique_ptr<Postprocessor> {
           if (in.parameters.analysis.type
               != AnalysisParameters::Type::friction)
             return nullptr;
           return std::make_unique<FrictionObserver>(in);
         },
         "when Analysis/Type = friction"});
    } // namespace
  }   // namespace mca
} // namespace tribodyn
