#ifndef tribodyn_mca_friction_analysis_h
#define tribodyn_mca_friction_analysis_h

#include <deal.II/base/mpi.h>
#include <tribodyn/core/statistics.h>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    /**
     * How the friction series is reduced to a steady friction coefficient
     * (seed 000, Fig. 5: raw and smoothed mu(t), quasi-steady regime after
     * ~350 ns of 600 ns).
     */
    struct FrictionAnalysisParameters
    {
      /// Width of the centred moving-average window of mu_smoothed (s).
      double smoothing_window = 20e-9;
      /// The smoothed mu must stay within +-band = relative_band * mean
      /// (see statistics::detect_steady_state) to count as steady.
      double steady_relative_band = 0.05;
      /// The steady part must last at least this fraction of the record.
      double steady_min_duration_fraction = 0.2;
      /// |F_n| below this (N) means "no contact": mu is set to 0 there.
      double min_normal_force = 0;
      /// Blocks required for the blocking plateau of the error bar.
      unsigned int min_blocks = 8;
    };


    /// mu(t), its smoothed curve and the quasi-steady mean.
    struct FrictionAnalysis
    {
      /// |F_t| / |F_n| per sample (0 while |F_n| <= min_normal_force).
      std::vector<double> mu;
      /// Centred moving average of mu over smoothing_window.
      std::vector<double> mu_smoothed;
      /// Start of the quasi-steady regime found on mu_smoothed.
      statistics::SteadyState steady;
      /// Mean of the raw mu over the steady part [steady.start_index, end)
      /// with its blocking standard error. When no steady regime is found,
      /// the last steady_min_duration_fraction of the record is used and
      /// steady.found stays false (report it as "not converged"). The band
      /// test admits a start where a decaying transient is still up to
      /// ~band: mu_steady may then carry a bias up to ~band * tau / record
      /// (tau the transient's time constant); a tighter band or a longer
      /// record reduces it.
      statistics::MeanWithError mu_steady;
      /// Index of the first sample averaged into mu_steady.
      std::size_t averaged_from = 0;
    };


    /**
     * mu = |F_t| / |F_n| (magnitudes: the sign of the tangential force only
     * tells the sliding direction), its smoothed curve, the quasi-steady
     * start and mu_steady +- standard error. The raw mu, not the smoothed
     * one, is averaged: blocking accounts for its correlation, whereas the
     * smoothed curve's would hide it. All series share the time axis
     * @p time (non-decreasing); InputError on mismatched sizes or an
     * empty record.
     */
    FrictionAnalysis
    analyse_friction(const std::vector<double>        &time,
                     const std::vector<double>        &normal_force,
                     const std::vector<double>        &tangential_force,
                     const FrictionAnalysisParameters &parameters);


    /// z-profile of a per-automaton indicator and the layer it outlines.
    struct LayerProfile
    {
      double z_min = 0, bin_width = 0;
      /// Per bin: automata counted and mean indicator (0 in empty bins).
      std::vector<double> count, mean;
      /// Largest bin mean, and the bin holding it.
      double       peak     = 0;
      unsigned int peak_bin = 0;
      /// Where the profile crosses threshold_fraction * peak on either side
      /// of the peak (linear interpolation between bin centres; the profile
      /// end when it never drops below), thickness = upper - lower, and
      /// center = (lower + upper) / 2.
      double lower = 0, upper = 0, thickness = 0, center = 0;
      /// False when the profile is zero everywhere (no layer).
      bool found = false;

      /// Centre of bin @p k.
      double
      bin_center(const unsigned int k) const
      {
        return z_min + (k + 0.5) * bin_width;
      }
    };


    /**
     * Quasi-fluid layer (seed 000, Fig. 3: unbonded pairs and high strains
     * concentrate in a layer around the contact): bin the automata of this
     * rank by z into bins of @p bin_width over [z_min, z_max) (automata
     * outside are ignored), sum the @p indicator (e.g. number of unbonded
     * contacts, bonds broken and re-formed, equivalent strain) and the
     * counts per bin, reduce both over @p comm (Utilities::MPI::sum), and
     * take the mean per automaton in each bin (so the profile does not
     * depend on how many automata a bin happens to hold).
     *
     * The layer is the connected z-range around the peak bin where the
     * mean exceeds @p threshold_fraction of the peak: threshold 0.5 gives
     * the full width at half maximum (for a Gaussian profile of standard
     * deviation s, thickness = 2 sqrt(2 ln 2) s = 2.355 s). Only the range
     * connected to the peak counts, so a second, separate band (e.g.
     * strain localised around an inclusion, seed Fig. 4b) does not widen
     * the layer. Collective over @p comm; every rank gets the same result.
     */
    LayerProfile
    quasi_fluid_layer_profile(const std::vector<double> &z,
                              const std::vector<double> &indicator,
                              const double               z_min,
                              const double               z_max,
                              const double               bin_width,
                              const double               threshold_fraction,
                              const MPI_Comm             comm);
  } // namespace mca
} // namespace tribodyn

#endif
