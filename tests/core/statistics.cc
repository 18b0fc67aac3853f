// Error bars of correlated time series (issue #8): block averaging,
// ensembles, smoothing, quasi-steady start.
//
// References:
// - AR(1) x_i = phi x_{i-1} + sqrt(1 - phi^2) sigma xi_i (stationary
//   variance sigma^2): for n >> tau the standard error of the mean is
//   sigma / sqrt(n) * sqrt((1 + phi) / (1 - phi)).
//   Tolerance 15 % on the mean of 6 seeds: the estimate at the level the
//   plateau test picks still carries a bias of order 1/sqrt(n_blocks)
//   (the test stops at the first level whose correlation is undetectable,
//   so the residual lag-1 correlation is ~1/sqrt(n_blocks), ~2-4 % in the
//   error here), and each seed's estimate scatters by 1/sqrt(2 n_blocks)
//   (~2-3 %, ~1 % after averaging six seeds). 15 % leaves a factor > 3 of
//   margin over both, yet fails for the naive sigma/sqrt(n), which is off by
//   a factor 3 (phi = 0.8) or 4.4 (phi = 0.9).
// - White noise: sigma / sqrt(n) within 10 % (one seed; the estimator's
//   scatter at level 0 is 1/sqrt(2n) = 0.1 %, at a higher level picked by
//   chance (1 % of cases) still < 3 %).
// - Step then flat: the smoothed series leaves the old value over one
//   window; the detected start must be within one window of the step.

#include "../test_utilities.h"

#include <cstdint>
#include <random>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/statistics.h>

using namespace tribodyn_test;
namespace st = tribodyn::statistics;

namespace
{
  /// Standard normal numbers by Box-Muller from a 64-bit Mersenne twister
  /// (the test's numbers are then the same on every platform).
  class Normal
  {
  public:
    explicit Normal(const std::uint64_t seed)
        : engine(seed)
    {
    }
    double
    operator()()
    {
      const double u1 = uniform_open(), u2 = uniform_open();
      return std::sqrt(-2 * std::log(u1))
             * std::cos(2 * 3.14159265358979323846 * u2);
    }

  private:
    double
    uniform_open()
    {
      return ((engine() >> 11) + 0.5) * (1.0 / 9007199254740992.0);
    }
    std::mt19937_64 engine;
  };

  std::vector<double>
  ar1(const double phi, const double sigma, const std::size_t n, Normal &g)
  {
    std::vector<double> x(n);
    x[0]           = sigma * g(); // start in the stationary distribution
    const double c = std::sqrt(1 - phi * phi) * sigma;
    for (std::size_t i = 1; i < n; ++i)
      x[i] = phi * x[i - 1] + c * g();
    return x;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             sigma = 0.3;
  const std::size_t                        n     = 1 << 18;

  for (const double phi : {0.8, 0.9})
    {
      double       sum_error = 0, sum_naive = 0;
      bool         all_plateaus = true;
      unsigned int seeds        = 6;
      for (unsigned int s = 0; s < seeds; ++s)
        {
          Normal     g(1000 + s);
          const auto x = ar1(phi, sigma, n, g);
          const auto r = st::block_average(x);
          sum_error += r.standard_error;
          all_plateaus = all_plateaus && r.plateau_found;
          // the raw level-0 estimate, for the record
          double m = 0, v = 0;
          for (const double xi : x)
            m += xi;
          m /= n;
          for (const double xi : x)
            v += (xi - m) * (xi - m);
          sum_naive += std::sqrt(v / (n - 1) / n);
          if (s == 0)
            std::cout << "phi = " << phi << ": block length " << r.block_length
                      << ", " << r.n_blocks << " blocks" << std::endl;
        }
      const double exact
        = sigma / std::sqrt(double(n)) * std::sqrt((1 + phi) / (1 - phi));
      check_relative(sum_error / seeds,
                     exact,
                     0.15,
                     "AR(1) phi = " + std::to_string(phi)
                       + ": blocked standard error (mean of 6 seeds)");
      check(all_plateaus, "AR(1): a plateau is found for every seed");
      check(sum_naive / seeds < 0.5 * exact,
            "AR(1): the naive error is far too small (the test can fail)");
    }

  {
    Normal     g(7);
    const auto x = ar1(0, sigma, n, g);
    const auto r = st::block_average(x);
    check_relative(r.standard_error,
                   sigma / std::sqrt(double(n)),
                   0.10,
                   "white noise: standard error = sigma / sqrt(n)");
    check(r.plateau_found, "white noise: plateau found");
  }

  {
    // A drifting record (transient not over: a trend of 10 sigma plus
    // white noise) and tau ~ 2000 samples > half the record: no plateau.
    Normal              g(11);
    std::vector<double> x(4096);
    for (unsigned int i = 0; i < x.size(); ++i)
      x[i] = 10 * sigma * i / x.size() + sigma * g();
    const auto r = st::block_average(x);
    check(!r.plateau_found, "drifting series: no plateau reported");
    check(r.n_blocks >= 8, "no plateau: the estimate uses >= 8 blocks");
    const auto slow = st::block_average(ar1(0.999, sigma, 4096, g));
    std::cout << "AR(1) phi = 0.999, 4096 samples: plateau "
              << slow.plateau_found << ", block length " << slow.block_length
              << std::endl;
  }

  {
    const auto r = st::block_average(std::vector<double>(100, 2.5));
    check(r.mean == 2.5 && r.standard_error == 0 && r.plateau_found,
          "constant series: exact mean, zero error");
    bool thrown = false;
    try
      {
        st::block_average({});
      }
    catch (const tribodyn::InputError &)
      {
        thrown = true;
      }
    check(thrown, "empty series is an InputError");
  }

  {
    // Ensemble: spread-dominated and error-dominated cases.
    st::MeanWithError a, b, c;
    a.mean = 1.0, a.standard_error = 0.01, a.plateau_found = true;
    b.mean = 1.2, b.standard_error = 0.01, b.plateau_found = true;
    c.mean = 1.1, c.standard_error = 0.01, c.plateau_found = true;
    const auto e = st::mean_of_means({a, b, c});
    check_relative(e.mean, 1.1, 1e-14, "ensemble mean");
    // spread: sample std 0.1, / sqrt(3)
    check_relative(e.standard_error,
                   0.1 / std::sqrt(3.),
                   1e-12,
                   "ensemble error from the spread between runs");
    a.standard_error = b.standard_error = c.standard_error = 1.0;
    const auto f = st::mean_of_means({a, b, c});
    check_relative(f.standard_error,
                   std::sqrt(3.) / 3,
                   1e-12,
                   "ensemble error from the within-run errors");
    check(f.n_blocks == 3 && f.plateau_found, "ensemble: 3 runs, plateaus");
  }

  {
    // Moving average: exact on a linear function away from the ends
    // (symmetric window), truncated window at the ends.
    std::vector<double> t(101), y(101);
    for (unsigned int i = 0; i < t.size(); ++i)
      t[i] = 0.1 * i, y[i] = 3 * t[i] - 1;
    const auto s   = st::moving_average(t, y, 1.0 + 1e-9);
    double     err = 0;
    for (unsigned int i = 5; i + 5 < t.size(); ++i)
      err = std::max(err, std::abs(s[i] - y[i]));
    check(err < 1e-12, "moving average reproduces a linear series inside");
    check_relative(s[0],
                   3 * 0.25 - 1,
                   1e-12,
                   "moving average at the start: mean of the first 6");
  }

  {
    // Step then flat with noise: mu = 0.8 up to t = 300, then 0.5.
    const double        dt = 1, step = 300, window = 50;
    std::vector<double> t, y;
    Normal              g(3);
    for (unsigned int i = 0; i <= 1000; ++i)
      {
        t.push_back(i * dt);
        y.push_back((t.back() < step ? 0.8 : 0.5) + 0.02 * g());
      }
    const auto s     = st::moving_average(t, y, window);
    const auto state = st::detect_steady_state(t, s, 0.02, 0.2);
    check(state.found, "step: steady state found");
    check(std::abs(state.start_time - step) <= window,
          "step: start " + std::to_string(state.start_time)
            + " within one window (" + std::to_string(window)
            + ") of the step at " + std::to_string(step));
    const auto none = st::detect_steady_state(t, s, 0.02, 0.9);
    check(!none.found, "step: no steady state lasting 90 % of the record");
  }

  return result();
}
