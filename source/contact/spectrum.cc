#include <cmath>
#include <tribodyn/contact/spectrum.h>

namespace tribodyn
{
  namespace contact
  {
    void
    fft(std::vector<std::complex<double>> &data)
    {
      const std::size_t n = data.size();
      // Bit reversal.
      for (std::size_t i = 1, j = 0; i < n; ++i)
        {
          std::size_t bit = n >> 1;
          for (; j & bit; bit >>= 1)
            j ^= bit;
          j ^= bit;
          if (i < j)
            std::swap(data[i], data[j]);
        }
      for (std::size_t length = 2; length <= n; length <<= 1)
        {
          const double angle = -2. * M_PI / static_cast<double>(length);
          const std::complex<double> root(std::cos(angle), std::sin(angle));
          for (std::size_t start = 0; start < n; start += length)
            {
              std::complex<double> w(1.);
              for (std::size_t k = 0; k < length / 2; ++k)
                {
                  const std::complex<double> even = data[start + k];
                  const std::complex<double> odd
                    = data[start + k + length / 2] * w;
                  data[start + k]              = even + odd;
                  data[start + k + length / 2] = even - odd;
                  w *= root;
                }
            }
        }
    }


    std::vector<std::pair<double, double>>
    amplitude_spectrum(const std::vector<double> &samples,
                       const double               sample_spacing)
    {
      std::vector<std::pair<double, double>> result;
      const std::size_t                      m = samples.size();
      if (m < 4)
        return result;
      double mean = 0;
      for (const double s : samples)
        mean += s;
      mean /= m;
      std::size_t n = 1;
      while (n < 4 * m)
        n <<= 1;
      std::vector<std::complex<double>> data(n, 0.);
      double                            window_sum = 0;
      for (std::size_t i = 0; i < m; ++i)
        {
          const double hann
            = 0.5 * (1. - std::cos(2. * M_PI * i / static_cast<double>(m - 1)));
          window_sum += hann;
          data[i] = (samples[i] - mean) * hann;
        }
      fft(data);
      result.reserve(n / 2 + 1);
      for (std::size_t k = 0; k <= n / 2; ++k)
        result.emplace_back(k / (n * sample_spacing),
                            2. * std::abs(data[k]) / window_sum);
      return result;
    }


    double
    dominant_frequency(const std::vector<std::pair<double, double>> &spectrum)
    {
      double best = -1, frequency = 0;
      for (std::size_t k = 1; k < spectrum.size(); ++k)
        if (spectrum[k].second > best)
          {
            best      = spectrum[k].second;
            frequency = spectrum[k].first;
          }
      return frequency;
    }
  } // namespace contact
} // namespace tribodyn
