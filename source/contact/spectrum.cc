#include <cmath>
#include <fftw3.h>
#include <tribodyn/contact/spectrum.h>

namespace tribodyn
{
  namespace contact
  {
    void
    fft(std::vector<std::complex<double>> &data)
    {
      // FFTW, in place (std::complex<double> and fftw_complex have the same
      // layout). FFTW_ESTIMATE: no timing runs, the plan is made in
      // microseconds; one transform per run does not need more.
      if (data.size() < 2)
        return;
      fftw_complex *d    = reinterpret_cast<fftw_complex *>(data.data());
      fftw_plan     plan = fftw_plan_dft_1d(
        static_cast<int>(data.size()), d, d, FFTW_FORWARD, FFTW_ESTIMATE);
      fftw_execute(plan);
      fftw_destroy_plan(plan);
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
