// Kanit et al. (2003): sample statistics, the variance law and the RVE
// size. Formulas: include/tribodyn/homogenization/rve_statistics.h and
// doc/theory/homogenization.md ("RVE size").

#include <algorithm>
#include <cmath>
#include <limits>
#include <tribodyn/homogenization/rve_statistics.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace rve
    {
      SampleStatistics
      sample_statistics(const std::vector<double> &values)
      {
        SampleStatistics s;
        s.n = values.size();
        if (s.n == 0)
          return s;
        for (const double v : values)
          s.mean += v / s.n;
        // Two passes: the deviations from the mean, not sum v^2 - n mean^2,
        // which cancels catastrophically for constants whose spread is
        // 1e-4 of their value.
        if (s.n > 1)
          {
            for (const double v : values)
              s.variance += (v - s.mean) * (v - s.mean);
            s.variance /= (s.n - 1.);
          }
        s.std = std::sqrt(s.variance);
        return s;
      }


      double
      point_variance(const std::vector<double> &fractions,
                     const std::vector<double> &phase_values)
      {
        double mean = 0, total = 0;
        for (unsigned int k = 0; k < fractions.size(); ++k)
          {
            mean += fractions[k] * phase_values[k];
            total += fractions[k];
          }
        if (total <= 0)
          return 0;
        mean /= total;
        double variance = 0, scale = 0;
        for (unsigned int k = 0; k < fractions.size(); ++k)
          {
            variance += fractions[k] * (phase_values[k] - mean)
                        * (phase_values[k] - mean);
            scale = std::max(scale, phase_values[k] * phase_values[k]);
          }
        // Equal phase values (nu of phases with one Poisson ratio): zero,
        // not the round-off of the mean.
        return variance / total > 1e-24 * scale ? variance / total : 0.;
      }


      namespace
      {
        /// Variance of ln s^2 for a sample of n normal values: the trigamma
        /// function psi'(k), k = (n - 1)/2, by its asymptotic series.
        double
        log_variance_variance(const unsigned int n)
        {
          const double k = 0.5 * (n - 1.);
          return 1. / k + 1. / (2 * k * k) + 1. / (6 * k * k * k);
        }

        /// E[ln s^2] - ln sigma^2 = psi(k) - ln k, k = (n - 1)/2.
        double
        log_variance_bias(const unsigned int n)
        {
          const double k = 0.5 * (n - 1.);
          return -1. / (2 * k) - 1. / (12 * k * k);
        }
      } // namespace


      VarianceFit
      fit_variance(const std::vector<double>           &areas,
                   const std::vector<SampleStatistics> &stats,
                   const double                         point_variance)
      {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        VarianceFit  fit;
        fit.point_variance           = point_variance;
        fit.integral_range           = nan;
        fit.integral_range_alpha1    = nan;
        fit.integral_range_alpha1_se = nan;
        fit.K = fit.ln_K_se = fit.alpha = fit.alpha_se = fit.chi2_dof = nan;

        // The points ln V_i, ln s_i^2 (bias removed) and their weights.
        std::vector<double> x, y, w;
        for (unsigned int i = 0; i < stats.size(); ++i)
          if (stats[i].n >= 2 && stats[i].variance > 0 && areas[i] > 0)
            {
              x.push_back(std::log(areas[i]));
              y.push_back(std::log(stats[i].variance)
                          - log_variance_bias(stats[i].n));
              w.push_back(1. / log_variance_variance(stats[i].n));
            }
        fit.n_sizes = x.size();
        if (x.size() < 2)
          return fit;

        double sw = 0, sx = 0, sy = 0;
        for (unsigned int i = 0; i < x.size(); ++i)
          {
            sw += w[i];
            sx += w[i] * x[i];
            sy += w[i] * y[i];
          }
        const double x_mean = sx / sw, y_mean = sy / sw;
        double       sxx = 0, sxy = 0;
        for (unsigned int i = 0; i < x.size(); ++i)
          {
            sxx += w[i] * (x[i] - x_mean) * (x[i] - x_mean);
            sxy += w[i] * (x[i] - x_mean) * (y[i] - y_mean);
          }
        if (sxx <= 0)
          return fit; // all windows of one area
        fit.valid          = true;
        const double slope = sxy / sxx;
        const double ln_K  = y_mean - slope * x_mean;
        fit.alpha          = -slope;
        fit.alpha_se       = 1. / std::sqrt(sxx);
        fit.K              = std::exp(ln_K);
        fit.ln_K_se        = std::sqrt(1. / sw + x_mean * x_mean / sxx);
        double chi2        = 0;
        for (unsigned int i = 0; i < x.size(); ++i)
          chi2 += w[i] * std::pow(y[i] - ln_K - slope * x[i], 2);
        fit.chi2_dof = x.size() > 2 ? chi2 / (x.size() - 2.) : nan;

        if (point_variance > 0)
          {
            // D^2 A^alpha = K.
            fit.integral_range
              = std::pow(fit.K / point_variance, 1. / fit.alpha);
            // alpha = 1: ln A_1 = <y + x> - ln D^2, weighted.
            double s = 0;
            for (unsigned int i = 0; i < x.size(); ++i)
              s += w[i] * (y[i] + x[i]);
            fit.integral_range_alpha1    = std::exp(s / sw) / point_variance;
            fit.integral_range_alpha1_se = 1. / std::sqrt(sw);
          }
        return fit;
      }


      double
      relative_error(const double       std,
                     const double       mean,
                     const unsigned int n_realisations)
      {
        if (mean == 0 || n_realisations == 0)
          return std::numeric_limits<double>::quiet_NaN();
        return 2. * std / (std::abs(mean) * std::sqrt(1. * n_realisations));
      }


      double
      rve_area(const VarianceFit &fit,
               const double       mean,
               const double       relative_error,
               const unsigned int n_realisations)
      {
        if (!fit.valid || mean == 0 || !(fit.alpha > 2 * fit.alpha_se))
          return std::numeric_limits<double>::quiet_NaN();
        // eps^2 Z^2 n / 4 = K V^-alpha.
        return std::pow(4. * fit.K
                          / (relative_error * relative_error * mean * mean
                             * n_realisations),
                        1. / fit.alpha);
      }
    } // namespace rve
  }   // namespace homogenization
} // namespace tribodyn
