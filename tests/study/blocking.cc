// Block averaging (Flyvbjerg-Petersen, core/statistics, as the study uses
// it: with base blocks of one period) against exact results.
// (1) AR(1) series x_i = phi x_{i-1} + e_i, phi = 0.9, n = 2^17: the
//     standard error of the mean is sigma_x sqrt((1 + phi)/(1 - phi) / n)
//     for large n (integrated autocorrelation time). The blocked estimate
//     must be within 15 % of it: the plateau estimate has a relative error
//     of 1/sqrt(2 (n_b - 1)) with n_b >= 16 blocks (at most 18 %, about
//     4 % at the plateau level found for phi = 0.9), and the average over
//     8 independent series has sqrt(8) less; 15 % is 3 sigma of the
//     worst case. The naive (uncorrelated) estimate must be about
//     sqrt(19) = 4.4 times smaller: the test fails if blocking is skipped.
// (2) Uncorrelated series: plateau at a low level, estimate within 10 %
//     of sigma / sqrt(n).
// (3) A constant series: zero error.
// (4) A sine on top of AR(1): base blocks of one period (below).

#include "../test_utilities.h"

#include <cmath>
#include <random>
#include <tribodyn/core/statistics.h>

int
main(int argc, char **argv)
{
  using namespace tribodyn_test;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       n = 1u << 17;
  std::mt19937_64                          rng(12345);
  std::normal_distribution<double>         normal(0., 1.);

  const double phi       = 0.9;
  double       ratio_sum = 0, naive_ratio_sum = 0;
  bool         plateaus = true;
  for (unsigned int k = 0; k < 8; ++k)
    {
      std::vector<double> x(n);
      double              v = normal(rng) / std::sqrt(1 - phi * phi);
      for (unsigned int i = 0; i < n; ++i)
        {
          v    = phi * v + normal(rng);
          x[i] = v + 0.2; // a mean that must not matter
        }
      const auto   r     = tribodyn::statistics::block_average(x, 16);
      const double sigma = 1. / std::sqrt(1 - phi * phi);
      const double exact = sigma * std::sqrt((1 + phi) / (1 - phi) / n);
      ratio_sum += r.standard_error / exact;
      naive_ratio_sum += r.naive_standard_error / exact;
      plateaus = plateaus && r.plateau_found;
    }
  const double ratio = ratio_sum / 8, naive = naive_ratio_sum / 8;
  std::cout << "AR(1) phi = 0.9: blocked / exact = " << ratio
            << ", naive / exact = " << naive << std::endl;
  check(std::abs(ratio - 1) < 0.15, "AR(1): blocked stderr within 15 %");
  check(std::abs(naive - 1 / std::sqrt(19.)) < 0.05,
        "AR(1): naive stderr = exact / sqrt(19) within 0.05");
  check(plateaus, "AR(1): a plateau is found for every series");

  std::vector<double> w(n);
  for (double &x : w)
    x = normal(rng);
  const auto white = tribodyn::statistics::block_average(w);
  std::cout << "white noise: blocked sqrt(n) = "
            << white.standard_error * std::sqrt(n) << ", block length "
            << white.block_length << std::endl;
  check(std::abs(white.standard_error * std::sqrt(n) - 1) < 0.1,
        "white noise: stderr = 1/sqrt(n) within 10 %");

  // (4) AR(1) (phi = 0.9, sigma_x = 2.29) plus a sine of amplitude 10 and
  // period 128 samples (dominant, as the 71 kHz oscillation of mu_global),
  // 2^17 samples (1024 whole periods): the sine adds
  // nothing to the error of the mean. With base blocks of one period the
  // estimate is the AR(1) one within 20 % (the period blocks, 128 samples
  // against a correlation time of 19, are nearly independent; the
  // estimate's own error is 1/sqrt(2 (n_b - 1)), 9 % at the 64-block
  // level). Plain blocking must get there too: its error estimate peaks
  // near blocks of half a period (the sine's share), but the block means of
  // those levels are correlated (lag-1 autocovariance of the sine), so the
  // plateau test (no correlation at this level and above) passes them over
  // for the level of 128-sample blocks. A plateau criterion by flatness
  // alone would stop on the half-period hump and overestimate 2-3 times.
  {
    std::vector<double> x(n);
    double              v = normal(rng) / std::sqrt(1 - phi * phi);
    for (unsigned int i = 0; i < n; ++i)
      {
        v    = phi * v + normal(rng);
        x[i] = v + 10 * std::sin(2 * M_PI * i / 128.);
      }
    const double exact
      = std::sqrt((1 + phi) / (1 - phi) / n) / std::sqrt(1 - phi * phi);
    const auto plain  = tribodyn::statistics::block_average(x, 8);
    const auto period = tribodyn::statistics::block_average(x, 8, 128);
    std::cout << "AR(1) + sine: plain / exact = "
              << plain.standard_error / exact
              << ", period blocks / exact = " << period.standard_error / exact
              << std::endl;
    check(std::abs(plain.standard_error / exact - 1) < 0.2,
          "AR(1) + sine: plain blocking skips the correlated half-period "
          "levels (within 20 %)");
    check(std::abs(period.standard_error / exact - 1) < 0.2,
          "AR(1) + sine: blocks of one period give the AR(1) error within "
          "20 %");
  }

  const auto flat
    = tribodyn::statistics::block_average(std::vector<double>(1000, 3.));
  check(flat.standard_error == 0 && flat.mean == 3., "constant series");
  return result();
}
