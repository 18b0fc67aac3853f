// The exact check of the RVE-size statistics (issue #19 item 3): the area
// fraction of an i.i.d. Bernoulli(p) pixel map over windows of N pixels has
// the variance p (1 - p) / N, so its variance law is D^2(V) = D^2 A / V
// with D^2 = p (1 - p) and the integral range A = one pixel, alpha = 1.
//
// The map: 1024 x 1024 pixels of 0.5 mm x 0.25 mm (non-square, so that a
// unit mistake between m^2 and pixels shows), p = 0.3. Windows of 4^2,
// 8^2, 16^2, 32^2 and 64^2 pixels, 400 of each, cut at random positions
// with Morphology::window(); their fractions, variances and the fits are
// those of the rve study (rve::sample_statistics, rve::point_variance,
// rve::fit_variance). Overlapping windows correlate: for 64^2 windows in a
// 1024^2 map two windows overlap with probability ~(2 * 64/1024)^2 = 1.6 %,
// sharing on average a quarter of their area, which lowers the expected
// sample variance by ~0.4 %: negligible against the tolerances below.
//
// Tolerances, from the sampling error of a variance: the sample variance
// s^2 of n independent values has the relative standard error
// sqrt(2/(n - 1)) (normal values; the fraction of N >= 16 Bernoulli pixels
// is close to normal: excess kurtosis (1 - 6p(1-p))/(N p(1-p)) = -0.08 at
// N = 16), 7.1 % for n = 400. Checks at three standard errors:
// - each size: s^2 N / (p(1-p)) = 1 within 3 sqrt(2/(n-1)) = 21 %;
// - the fit with alpha = 1: ln A_1 = 0 (A_1 in pixels) within 3 se, se =
//   1/sqrt(sum_i w_i) ~ sqrt(2/(5 * 399)) = 3.2 %, i.e. A_1 = 1 pixel
//   within ~9.5 %;
// - the free fit: alpha = 1 within 3 alpha_se (alpha_se ~ 0.023 here).
// The random streams are seeded, so the test is deterministic; with other
// seeds it would fail about once in 300 runs per check.
//
// Plus two exact checks of the algebra: the fit of exact variances
// K V^-alpha (n = 10^8, where the log-bias correction is 1e-8) returns K
// and alpha to 1e-6, and rve_area() satisfies eps_rel(V_RVE) = eps.

#include "../test_utilities.h"

#include <cstdint>
#include <random>
#include <tribodyn/core/morphology.h>
#include <tribodyn/homogenization/rve_statistics.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace tribodyn;
  using namespace tribodyn::homogenization;
  using namespace tribodyn_test;

  const unsigned int        n_map = 1024;
  const double              p = 0.3, dx = 0.5e-3, dy = 0.25e-3;
  std::mt19937              rng(20031);
  std::vector<unsigned int> ids(n_map * n_map);
  for (auto &id : ids)
    id = (rng() < p * 4294967296.) ? material_id::heterogeneity
                                   : material_id::matrix;
  const Morphology map(n_map * dx, n_map * dy, n_map, n_map, ids, "i.i.d.");

  const std::vector<unsigned int>    sides = {4, 8, 16, 32, 64};
  const unsigned int                 n     = 400;
  std::vector<double>                areas;
  std::vector<rve::SampleStatistics> stats;
  std::vector<double>                all_fractions;
  for (const unsigned int L : sides)
    {
      std::vector<double> f;
      for (unsigned int k = 0; k < n; ++k)
        {
          const auto pick = [&]() {
            return static_cast<unsigned int>(
              (static_cast<std::uint64_t>(rng()) * (n_map - L + 1)) >> 32);
          };
          const unsigned int i0 = pick(), j0 = pick();
          f.push_back(map.window(i0, j0, L, L).heterogeneity_fraction());
        }
      areas.push_back(L * dx * L * dy);
      stats.push_back(rve::sample_statistics(f));
      all_fractions.insert(all_fractions.end(), f.begin(), f.end());
    }
  const double p_hat = rve::sample_statistics(all_fractions).mean;
  // The indicator of the heterogeneity: Z = 0 in the matrix, 1 in it.
  const double D2 = rve::point_variance({1 - p_hat, p_hat}, {0., 1.});
  check_relative(D2, p * (1 - p), 0.02, "point variance p(1-p)");

  const double relative_se = std::sqrt(2. / (n - 1));
  for (unsigned int i = 0; i < sides.size(); ++i)
    check_relative(stats[i].variance * sides[i] * sides[i] / D2,
                   1.,
                   3 * relative_se,
                   "variance x N / (p(1-p)) of " + std::to_string(sides[i])
                     + "^2-pixel windows");

  const rve::VarianceFit fit = rve::fit_variance(areas, stats, D2);
  check(fit.valid && fit.n_sizes == sides.size(), "the fit uses 5 sizes");
  const double A1_pixels = fit.integral_range_alpha1 / (dx * dy);
  {
    std::ostringstream s;
    s << "integral range (alpha = 1) A_1 = " << A1_pixels << " pixel, "
      << "relative standard error " << fit.integral_range_alpha1_se
      << ": |ln A_1| = " << std::abs(std::log(A1_pixels))
      << " <= 3 se = " << 3 * fit.integral_range_alpha1_se;
    check(std::abs(std::log(A1_pixels)) <= 3 * fit.integral_range_alpha1_se,
          s.str());
  }
  {
    std::ostringstream s;
    s << "free fit: alpha = " << fit.alpha << " +- " << fit.alpha_se
      << " (1 within 3 se), A = " << fit.integral_range / (dx * dy)
      << " pixel, chi2/dof = " << fit.chi2_dof;
    check(std::abs(fit.alpha - 1) <= 3 * fit.alpha_se, s.str());
  }

  // Exact algebra: variances K V^-alpha from a huge sample.
  {
    const double                       K = 2.5e-7, alpha = 0.8;
    std::vector<rve::SampleStatistics> exact;
    std::vector<double>                V = {1e-6, 4e-6, 1.6e-5};
    for (const double v : V)
      {
        rve::SampleStatistics s;
        s.n        = 100000000;
        s.mean     = 1;
        s.variance = K * std::pow(v, -alpha);
        s.std      = std::sqrt(s.variance);
        exact.push_back(s);
      }
    const rve::VarianceFit f = rve::fit_variance(V, exact, 0.01);
    check_relative(f.alpha, alpha, 1e-6, "exact data: alpha");
    check_relative(f.K, K, 1e-6, "exact data: K");
    check_relative(f.integral_range,
                   std::pow(K / 0.01, 1 / alpha),
                   1e-6,
                   "exact data: A = (K / D^2)^(1/alpha)");
    const double Z = 2., eps = 0.01;
    const double V_rve = rve::rve_area(f, Z, eps, 6);
    const double D     = std::sqrt(K * std::pow(V_rve, -alpha));
    check_relative(rve::relative_error(D, Z, 6),
                   eps,
                   1e-6,
                   "eps_rel(V_RVE(eps, n = 6)) = eps");
  }
  return result();
}
