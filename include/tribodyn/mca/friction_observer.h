#ifndef tribodyn_mca_friction_observer_h
#define tribodyn_mca_friction_observer_h

#include <ostream>
#include <string>
#include <tribodyn/core/json.h>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/friction_analysis.h>
#include <vector>

namespace tribodyn
{
  namespace mca
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
    class FrictionObserver
    {
    public:
      FrictionObserver(const Parameters &parameters, const int loaded_group);

      /// Record one sample; returns mu.
      double
      record(const double             time,
             const std::vector<Vec3> &group_forces,
             const SystemEnergies    &energies);

      /**
       * Quasi-fluid layer at this sample: z-profiles (bins of Analysis/
       * Layer bin width along the normal axis, over the automata's current
       * extent) of the unbonded contacts per automaton and of the
       * accumulated equivalent plastic strain; the layer
       * (quasi_fluid_layer_profile()) of each. Collective.
       */
      void
      record_layer(const double           time,
                   const AutomatonSystem &system,
                   const MPI_Comm         comm);

      /// friction.csv and layer.csv (by the root rank), layer_profile.csv
      /// (the last profiles), summary keys, a line of figures.
      void
      finish(const std::string &output_directory,
             const bool         root,
             JsonValue         &summary,
             std::ostream      &figures) const;

      /// friction.csv of the samples so far (by the root rank; also when a
      /// run stops early); returns the analysis.
      FrictionAnalysis
      write_series(const std::string &output_directory, const bool root) const;

      /// The recorded series (checkpoints save and restore them); the
      /// friction samples first (their size says whether any was taken).
      /// The last layer profiles are not saved: the next sample, at the
      /// latest the run's last, recomputes them.
      std::vector<std::vector<double> *>
      recorded_series()
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
      /// layer.csv, layer_profile.csv and the layer's summary keys: means
      /// over the samples from the start of the quasi-steady regime.
      void
      write_layer(const std::string      &output_directory,
                  const bool              root,
                  JsonValue              &summary,
                  std::ostream           &figures,
                  const FrictionAnalysis &fa) const;

      const Parameters   &prm;
      const int           loaded;
      std::vector<double> times, normal, tangential, bonded, unbonded;
      /// layer.csv columns
      std::vector<double> layer_times, layer_thickness, layer_center,
        strain_thickness, strain_center, layer_peak;
      LayerProfile last_contacts, last_strain;
    };
  } // namespace mca
} // namespace tribodyn

#endif
