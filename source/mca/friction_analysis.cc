#include <algorithm>
#include <cmath>
#include <deal.II/base/array_view.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/mca/friction_analysis.h>
#include <utility>

namespace tribodyn
{
  namespace mca
  {
    FrictionAnalysis
    analyse_friction(const std::vector<double>        &time,
                     const std::vector<double>        &normal_force,
                     const std::vector<double>        &tangential_force,
                     const FrictionAnalysisParameters &parameters)
    {
      const std::size_t n = time.size();
      if (normal_force.size() != n || tangential_force.size() != n)
        throw InputError("Friction analysis: the time, normal force and "
                         "tangential force series differ in length ("
                         + std::to_string(n) + ", "
                         + std::to_string(normal_force.size()) + ", "
                         + std::to_string(tangential_force.size()) + ").");
      if (n == 0)
        throw InputError("Friction analysis: the friction record is empty "
                         "(no output step was written; is the end time "
                         "shorter than the output interval?).");
      check_parameter_range("Friction analysis/Smoothing window",
                            parameters.smoothing_window,
                            0,
                            1e300,
                            false,
                            false);

      FrictionAnalysis result;
      result.mu.resize(n);
      for (std::size_t i = 0; i < n; ++i)
        {
          const double fn = std::abs(normal_force[i]);
          result.mu[i]    = fn > parameters.min_normal_force && fn > 0
                              ? std::abs(tangential_force[i]) / fn
                              : 0.;
        }
      result.mu_smoothed
        = statistics::moving_average(time,
                                     result.mu,
                                     parameters.smoothing_window);
      result.steady = statistics::detect_steady_state(
        time,
        result.mu_smoothed,
        parameters.steady_relative_band,
        parameters.steady_min_duration_fraction);

      std::size_t first = result.steady.start_index;
      if (!result.steady.found)
        {
          // Fall back to the last part of the record of the minimum
          // duration (flagged by steady.found == false).
          const double from = time.back()
                              - parameters.steady_min_duration_fraction
                                  * (time.back() - time.front());
          first = 0;
          while (first + 1 < n && time[first] < from)
            ++first;
        }
      result.averaged_from = first;
      const std::vector<double> steady_part(result.mu.begin() + first,
                                            result.mu.end());
      result.mu_steady
        = statistics::block_average(steady_part, parameters.min_blocks);
      return result;
    }


    LayerProfile
    quasi_fluid_layer_profile(const std::vector<double> &z,
                              const std::vector<double> &indicator,
                              const double               z_min,
                              const double               z_max,
                              const double               bin_width,
                              const double               threshold_fraction,
                              const MPI_Comm             comm)
    {
      if (z.size() != indicator.size())
        throw InputError("Quasi-fluid layer: positions and indicator values "
                         "differ in number ("
                         + std::to_string(z.size()) + " and "
                         + std::to_string(indicator.size()) + ").");
      if (!(z_max > z_min))
        throw InputError("Quasi-fluid layer: the z range must be non-empty "
                         "(z_min = "
                         + format_number(z_min)
                         + ", z_max = " + format_number(z_max) + ").");
      check_parameter_range("Quasi-fluid layer/Bin width",
                            bin_width,
                            0,
                            z_max - z_min,
                            true,
                            false);
      check_parameter_range("Quasi-fluid layer/Threshold fraction",
                            threshold_fraction,
                            0,
                            1,
                            true,
                            true);

      LayerProfile profile;
      profile.z_min     = z_min;
      profile.bin_width = bin_width;
      const auto n_bins
        = static_cast<unsigned int>(std::ceil((z_max - z_min) / bin_width));
      // Sums and counts in one vector: one reduction instead of two.
      std::vector<double> local(2 * n_bins, 0.);
      for (std::size_t i = 0; i < z.size(); ++i)
        {
          if (!(z[i] >= z_min && z[i] < z_max))
            continue;
          const auto k
            = std::min(n_bins - 1,
                       static_cast<unsigned int>((z[i] - z_min) / bin_width));
          local[k] += indicator[i];
          local[n_bins + k] += 1;
        }
      // ArrayView overload: instantiated in libdeal.ii for double.
      std::vector<double> global(local.size());
      dealii::Utilities::MPI::sum(dealii::make_array_view(std::as_const(local)),
                                  comm,
                                  dealii::make_array_view(global));

      profile.count.assign(global.begin() + n_bins, global.end());
      profile.mean.resize(n_bins);
      for (unsigned int k = 0; k < n_bins; ++k)
        profile.mean[k]
          = profile.count[k] > 0 ? global[k] / profile.count[k] : 0.;
      for (unsigned int k = 0; k < n_bins; ++k)
        if (profile.mean[k] > profile.peak)
          {
            profile.peak     = profile.mean[k];
            profile.peak_bin = k;
          }
      if (!(profile.peak > 0))
        return profile;
      profile.found = true;

      // Walk out from the peak to the first bin below the threshold and
      // interpolate linearly between that bin's centre and its neighbour's.
      const double threshold = threshold_fraction * profile.peak;
      const auto  &m         = profile.mean;
      const auto   crossing  = [&](const unsigned int inside,
                                const unsigned int outside) {
        const double t = (m[inside] - threshold) / (m[inside] - m[outside]);
        return profile.bin_center(inside)
               + t * (profile.bin_center(outside) - profile.bin_center(inside));
      };
      unsigned int k = profile.peak_bin;
      while (k > 0 && m[k - 1] >= threshold)
        --k;
      profile.lower = k > 0 ? crossing(k, k - 1) : z_min;
      k             = profile.peak_bin;
      while (k + 1 < n_bins && m[k + 1] >= threshold)
        ++k;
      profile.upper     = k + 1 < n_bins ? crossing(k, k + 1) : z_max;
      profile.thickness = profile.upper - profile.lower;
      profile.center    = 0.5 * (profile.lower + profile.upper);
      return profile;
    }
  } // namespace mca
} // namespace tribodyn
