// The spectrum behind dominant_frequency_hz and spectrum.csv (issue #21),
// on signals whose frequencies are known:
// (1) fft() equals the direct sum X_k = sum_j x_j exp(-2 pi i j k / n) on
//     a random vector of odd length 21 to 1e-13 of sum |x_j| (round-off);
// (2) the grid: n/2 + 1 frequencies k / (n dt), n the power of two at
//     least 4 m (m samples), from 0 to the Nyquist frequency 1 / (2 dt);
// (3) x(t) = 3 + 2 sin(2 pi f1 t + 0.3) + 0.7 sin(2 pi f2 t + 1.1), f1 =
//     137 kHz, f2 = 412 kHz, 1000 samples at 10 MHz: the dominant
//     frequency is f1 within half a grid spacing (1221 Hz: the grid's own
//     resolution; the code picks a grid point), the largest amplitude near
//     f2 is that of f2 within the same half spacing; the amplitudes are 2
//     and 0.7 within 2 % (Hann window with 4x zero padding: the peak can
//     fall 1/8 of a native bin off, where the Hann lobe is 1.0 % lower;
//     the other component's leakage is below 0.1 %); the mean 3 is removed:
//     the amplitude at 0 Hz is below 0.1 where a kept mean would give 6
//     (measured 0.054: twice the sines' own mean over their 13.7 and 41.2
//     periods, which the plain mean removes and the Hann window does not);
// (4) a signal too short for a spectrum (3 samples) gives none, and
//     dominant_frequency() of it is 0.

#include "../test_utilities.h"

#include <cmath>
#include <complex>
#include <deal.II/base/mpi.h>
#include <random>
#include <tribodyn/contact/spectrum.h>

using namespace tribodyn_test;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using tribodyn::contact::amplitude_spectrum;
  using tribodyn::contact::dominant_frequency;

  // (1) fft against the direct sum
  {
    std::mt19937                           rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    const std::size_t                      n = 21;
    std::vector<std::complex<double>>      x(n), X;
    double                                 norm1 = 0;
    for (auto &v : x)
      {
        v = {u(rng), u(rng)};
        norm1 += std::abs(v);
      }
    X = x;
    tribodyn::contact::fft(X);
    double worst = 0;
    for (std::size_t k = 0; k < n; ++k)
      {
        std::complex<double> direct = 0;
        for (std::size_t j = 0; j < n; ++j)
          direct += x[j] * std::polar(1., -2 * M_PI * double(j * k) / n);
        worst = std::max(worst, std::abs(direct - X[k]) / norm1);
      }
    check(worst <= 1e-13,
          "fft = direct DFT (n = 21): " + std::to_string(worst));
  }

  // (2), (3) two sines and a mean
  const double        dt = 1e-7, f1 = 137e3, f2 = 412e3;
  const std::size_t   m = 1000;
  std::vector<double> x(m);
  for (std::size_t i = 0; i < m; ++i)
    {
      const double t = i * dt;
      x[i]           = 3 + 2 * std::sin(2 * M_PI * f1 * t + 0.3)
             + 0.7 * std::sin(2 * M_PI * f2 * t + 1.1);
    }
  const auto        s = amplitude_spectrum(x, dt);
  const std::size_t n = 4096; // the power of two >= 4 m
  check(s.size() == n / 2 + 1,
        "n/2 + 1 = 2049 frequencies: " + std::to_string(s.size()));
  check_relative(s[1].first, 1 / (n * dt), 1e-14, "grid spacing 1/(n dt)");
  check_relative(s.back().first, 1 / (2 * dt), 1e-14, "last = Nyquist");
  const double df = 1 / (n * dt);

  const double fd = dominant_frequency(s);
  check(std::abs(fd - f1) <= df / 2,
        "dominant frequency " + std::to_string(fd) + " Hz = f1 = 137 kHz "
          + "within df/2 = " + std::to_string(df / 2) + " Hz");
  auto peak_near = [&](const double f) {
    std::size_t best = 0;
    for (std::size_t k = 0; k < s.size(); ++k)
      if (std::abs(s[k].first - f) < 10 * df
          && (best == 0 || s[k].second > s[best].second))
        best = k;
    return best;
  };
  const std::size_t k1 = peak_near(f1), k2 = peak_near(f2);
  check(std::abs(s[k2].first - f2) <= df / 2,
        "second peak " + std::to_string(s[k2].first)
          + " Hz = f2 = 412 kHz within df/2");
  check_relative(s[k1].second, 2., 0.02, "amplitude of the f1 sine");
  check_relative(s[k2].second, 0.7, 0.02, "amplitude of the f2 sine");
  check(s[0].second < 0.1,
        "mean removed: amplitude at 0 Hz " + std::to_string(s[0].second)
          + " < 0.1 (a kept mean 3 would show 6)");

  // (4) too short
  const auto none = amplitude_spectrum({1., 2., 3.}, dt);
  check(none.empty() && dominant_frequency(none) == 0,
        "3 samples: no spectrum, dominant frequency 0");
  return result();
}
