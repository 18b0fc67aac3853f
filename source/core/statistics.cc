#include <algorithm>
#include <cmath>
#include <limits>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/statistics.h>

namespace tribodyn
{
  namespace statistics
  {
    namespace
    {
      /// 99 % quantile of the chi^2 distribution with @p dof degrees of
      /// freedom (Wilson-Hilferty cube-root normal approximation; 6.59
      /// instead of 6.63 for one degree of freedom, closer beyond).
      double
      chi_square_quantile_99(const unsigned int dof)
      {
        const double z = 2.3263478740408408; // 99 % normal quantile
        const double k = dof;
        const double c = 1 - 2 / (9 * k) + z * std::sqrt(2 / (9 * k));
        return k * c * c * c;
      }

      /// One blocking level: its size, its error estimate and the squared
      /// normalised lag-1 autocorrelation weighted by the number of blocks
      /// (the level's term in Jonsson's M statistic).
      struct Level
      {
        std::size_t n;
        double      error;
        double      m_term;
      };
    } // namespace


    MeanWithError
    block_average(const std::vector<double> &series,
                  const unsigned int         min_blocks,
                  const unsigned int         base_block)
    {
      if (series.empty())
        throw InputError("block_average: the time series is empty, there "
                         "is no mean to estimate (is the averaging window "
                         "empty?).");
      MeanWithError result;
      double        sum = 0;
      for (const double x : series)
        sum += x;
      result.mean = sum / series.size();
      if (series.size() == 1)
        {
          result.standard_error = std::numeric_limits<double>::infinity();
          result.n_blocks       = 1;
          result.block_length   = 1;
          return result;
        }

      {
        // as if the samples were independent: sigma / sqrt(n)
        double c0 = 0;
        for (const double v : series)
          c0 += (v - result.mean) * (v - result.mean);
        result.naive_standard_error
          = std::sqrt(c0 / series.size() / (series.size() - 1.));
      }

      std::vector<Level>  levels;
      std::vector<double> x;
      const unsigned int  base
        = base_block > 1 && series.size() >= 2 * std::size_t(base_block)
            ? base_block
            : 1;
      if (base > 1)
        {
          // Means of whole base blocks; the mean is then that of the
          // samples they hold (a trailing partial block is dropped).
          const std::size_t n_base = series.size() / base;
          double            kept   = 0;
          x.resize(n_base);
          for (std::size_t b = 0; b < n_base; ++b)
            {
              double s = 0;
              for (std::size_t i = 0; i < base; ++i)
                s += series[b * base + i];
              x[b] = s / base;
              kept += s;
            }
          result.mean = kept / (n_base * base);
        }
      else
        x = series;
      while (x.size() >= 2)
        {
          const std::size_t n    = x.size();
          double            mean = 0;
          for (const double v : x)
            mean += v;
          mean /= n;
          double c0 = 0, gamma = 0;
          for (std::size_t i = 0; i < n; ++i)
            {
              c0 += (x[i] - mean) * (x[i] - mean);
              if (i + 1 < n)
                gamma += (x[i] - mean) * (x[i + 1] - mean);
            }
          c0 /= n;
          gamma /= n;
          // A constant level (c0 = 0, to round-off relative to the mean)
          // has no correlation to detect.
          const bool flat = c0 <= 1e-28 * (mean * mean + 1e-300);
          levels.push_back({n,
                            flat ? 0. : std::sqrt(c0 / (n - 1)),
                            flat ? 0. : n * (gamma / c0) * (gamma / c0)});
          // Halve: means of consecutive pairs, a trailing odd one dropped.
          std::vector<double> next(n / 2);
          for (std::size_t i = 0; i < next.size(); ++i)
            next[i] = 0.5 * (x[2 * i] + x[2 * i + 1]);
          x.swap(next);
        }

      // Plateau: the first level j whose block means are uncorrelated at
      // all levels >= j (M_j below the quantile), with enough blocks, and
      // confirmed by the next level: it too has enough blocks and its
      // estimate agrees within twice the combined uncertainty
      // e_k / sqrt(2 (n_k - 1)). The confirmation is what "plateau" means
      // (two levels, flat) and rejects a drifting record whose last few
      // blocks are too few for the correlation test to have any power.
      const std::size_t   K = levels.size();
      std::vector<double> M(K + 1, 0.);
      for (std::size_t k = K; k-- > 0;)
        M[k] = M[k + 1] + levels[k].m_term;
      const auto uncertainty = [&](const std::size_t k) {
        return levels[k].error / std::sqrt(2. * (levels[k].n - 1));
      };
      for (std::size_t j = 0; j + 1 < K; ++j)
        if (M[j] < chi_square_quantile_99(K - j) && levels[j].n >= min_blocks
            && levels[j + 1].n >= min_blocks
            && std::abs(levels[j + 1].error - levels[j].error)
                 <= 2 * std::hypot(uncertainty(j), uncertainty(j + 1)))
          {
            result.plateau_found  = true;
            result.standard_error = levels[j].error;
            result.n_blocks       = levels[j].n;
            result.block_length   = base << j;
            return result;
          }

      // No plateau with enough blocks: the largest estimate among the
      // trustworthy levels is a lower bound of the error.
      std::size_t best = 0;
      for (std::size_t k = 0; k < K; ++k)
        if (levels[k].n >= min_blocks && levels[k].error > levels[best].error)
          best = k;
      result.plateau_found  = false;
      result.standard_error = levels[best].error;
      result.n_blocks       = levels[best].n;
      result.block_length   = base << best;
      return result;
    }


    MeanWithError
    mean_of_means(const std::vector<MeanWithError> &runs)
    {
      if (runs.empty())
        throw InputError("mean_of_means: no runs to combine (the ensemble "
                         "is empty).");
      if (runs.size() == 1)
        return runs[0];
      const double  R = runs.size();
      MeanWithError result;
      result.plateau_found = true;
      double sum = 0, within = 0;
      for (const auto &r : runs)
        {
          sum += r.mean;
          within += r.standard_error * r.standard_error;
          result.block_length  = std::max(result.block_length, r.block_length);
          result.plateau_found = result.plateau_found && r.plateau_found;
        }
      result.mean   = sum / R;
      double spread = 0;
      for (const auto &r : runs)
        spread += (r.mean - result.mean) * (r.mean - result.mean);
      const double between_error = std::sqrt(spread / (R - 1) / R);
      const double within_error  = std::sqrt(within) / R;
      result.standard_error      = std::max(between_error, within_error);
      result.n_blocks            = runs.size();
      return result;
    }


    std::vector<double>
    moving_average(const std::vector<double> &t,
                   const std::vector<double> &y,
                   const double               window)
    {
      if (t.size() != y.size())
        throw InputError("moving_average: time and value series differ in "
                         "length ("
                         + std::to_string(t.size()) + " and "
                         + std::to_string(y.size()) + ").");
      if (!(window >= 0))
        throw InputError("moving_average: the smoothing window must be >= 0, "
                         "not "
                         + format_number(window) + ".");
      for (std::size_t i = 1; i < t.size(); ++i)
        if (t[i] < t[i - 1])
          throw InputError("moving_average: times must be non-decreasing "
                           "(sample "
                           + std::to_string(i) + ").");
      const double        h = 0.5 * window;
      std::vector<double> result(y.size());
      std::size_t         lo = 0, hi = 0; // window is [lo, hi)
      double              sum = 0;
      for (std::size_t i = 0; i < t.size(); ++i)
        {
          while (hi < t.size() && t[hi] <= t[i] + h)
            sum += y[hi++];
          while (t[lo] < t[i] - h)
            sum -= y[lo++];
          result[i] = sum / (hi - lo);
        }
      // The running sum accumulates round-off over long records; it stays
      // at the level of n * eps * max|y|, far below any physical band.
      return result;
    }


    SteadyState
    detect_steady_state(const std::vector<double> &t,
                        const std::vector<double> &smoothed,
                        const double               relative_band,
                        const double               min_duration_fraction)
    {
      if (t.size() != smoothed.size())
        throw InputError("detect_steady_state: time and value series differ "
                         "in length.");
      if (!(relative_band > 0))
        throw InputError("detect_steady_state: the relative band must be "
                         "positive, not "
                         + format_number(relative_band) + ".");
      if (!(min_duration_fraction >= 0 && min_duration_fraction <= 1))
        throw InputError("detect_steady_state: the minimum duration "
                         "fraction must be in [0, 1], not "
                         + format_number(min_duration_fraction) + ".");
      SteadyState result;
      result.found        = false;
      result.start_index  = t.size();
      result.start_time   = std::numeric_limits<double>::quiet_NaN();
      const std::size_t n = t.size();
      if (n == 0)
        return result;

      double scale = 0;
      for (const double v : smoothed)
        scale = std::max(scale, std::abs(v));
      const double floor = 1e-3 * scale;

      // Suffix sums, minima and maxima: the band test for every start i.
      std::vector<double> suffix_sum(n + 1, 0.), suffix_min(n + 1),
        suffix_max(n + 1);
      suffix_min[n] = std::numeric_limits<double>::infinity();
      suffix_max[n] = -std::numeric_limits<double>::infinity();
      for (std::size_t i = n; i-- > 0;)
        {
          suffix_sum[i] = suffix_sum[i + 1] + smoothed[i];
          suffix_min[i] = std::min(suffix_min[i + 1], smoothed[i]);
          suffix_max[i] = std::max(suffix_max[i + 1], smoothed[i]);
        }
      const double required = min_duration_fraction * (t[n - 1] - t[0]);
      for (std::size_t i = 0; i < n; ++i)
        {
          // Later starts only get shorter: stop at the first too short one.
          if (t[n - 1] - t[i] < required)
            break;
          const double mean = suffix_sum[i] / (n - i);
          const double band = std::max(relative_band * std::abs(mean), floor);
          if (suffix_max[i] - mean <= band && mean - suffix_min[i] <= band)
            {
              result.found       = true;
              result.start_index = i;
              result.start_time  = t[i];
              result.band        = band;
              return result;
            }
        }
      return result;
    }
  } // namespace statistics
} // namespace tribodyn
