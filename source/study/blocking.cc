#include <algorithm>
#include <cmath>
#include <tribodyn/study/blocking.h>

namespace tribodyn
{
  namespace study
  {
    BlockingResult
    block_average(const std::vector<double> &series,
                  const unsigned int         min_blocks,
                  const unsigned int         base_block)
    {
      BlockingResult r;
      if (series.empty())
        return r;
      double sum = 0;
      for (const double v : series)
        sum += v;
      r.mean = sum / series.size();
      std::vector<double> x;
      if (base_block > 1 && series.size() >= 2 * base_block)
        {
          // Means of whole base blocks; the mean is then that of the
          // samples they hold.
          const std::size_t n_blocks = series.size() / base_block;
          double            kept     = 0;
          for (std::size_t b = 0; b < n_blocks; ++b)
            {
              double s = 0;
              for (std::size_t i = 0; i < base_block; ++i)
                s += series[b * base_block + i];
              x.push_back(s / base_block);
              kept += s;
            }
          r.mean = kept / (n_blocks * base_block);
        }
      else
        x = series;
      // Levels with at least max(min_blocks, 2) blocks.
      const std::size_t smallest = std::max(2u, min_blocks);
      while (x.size() >= smallest)
        {
          const double n   = static_cast<double>(x.size());
          double       var = 0;
          for (const double v : x)
            var += (v - r.mean) * (v - r.mean);
          var /= n;
          const double e = std::sqrt(var / (n - 1.));
          r.level_stderr.push_back(e);
          r.level_stderr_error.push_back(e / std::sqrt(2. * (n - 1.)));
          std::vector<double> half(x.size() / 2);
          for (std::size_t i = 0; i < half.size(); ++i)
            half[i] = 0.5 * (x[2 * i] + x[2 * i + 1]);
          x.swap(half);
        }
      // As if the samples were uncorrelated.
      {
        const double n    = static_cast<double>(series.size());
        double       mean = 0, var = 0;
        for (const double v : series)
          mean += v / n;
        for (const double v : series)
          var += (v - mean) * (v - mean);
        r.naive_stderr = n > 1 ? std::sqrt(var / n / (n - 1.)) : 0.;
      }
      if (r.level_stderr.empty())
        {
          // Too short to block: the naive estimate of what there is.
          r.stderr_of_mean = r.naive_stderr;
          return r;
        }
      const std::size_t L       = r.level_stderr.size();
      double            largest = 0;
      for (std::size_t k = 0; k < L; ++k)
        largest = std::max(largest, r.level_stderr[k]);
      r.stderr_of_mean = largest;
      r.plateau_level  = L - 1;
      for (std::size_t k = 0; k + 1 < L; ++k)
        {
          bool plateau = true;
          for (std::size_t m = k + 1; m < L; ++m)
            if (r.level_stderr[m] > r.level_stderr[k] + r.level_stderr_error[m])
              {
                plateau = false;
                break;
              }
          if (plateau)
            {
              r.plateau_found  = true;
              r.plateau_level  = k;
              r.stderr_of_mean = r.level_stderr[k];
              break;
            }
        }
      return r;
    }
  } // namespace study
} // namespace tribodyn
