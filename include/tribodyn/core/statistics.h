#ifndef tribodyn_core_statistics_h
#define tribodyn_core_statistics_h

#include <cstddef>
#include <vector>

namespace tribodyn
{
  /**
   * Error bars for time series of explicit dynamics (friction coefficient,
   * forces, layer thickness): samples written at every output step are
   * strongly correlated, so the naive sigma/sqrt(n) underestimates the
   * error of their mean by a factor sqrt(2 tau_int). These functions give
   * honest standard errors, smoothing, and the start of a quasi-steady
   * regime (seed 000, Fig. 5: "quasi-steady regime at about 350 ns").
   */
  namespace statistics
  {
    /// A mean with its standard error and how it was obtained.
    struct MeanWithError
    {
      double mean           = 0;
      double standard_error = 0;
      /// Number of (independent) blocks the error was estimated from; for
      /// mean_of_means() the number of runs.
      unsigned int n_blocks = 0;
      /// Samples per block at the chosen blocking level (1 = raw samples);
      /// for mean_of_means() the largest block length of the runs.
      unsigned int block_length = 0;
      /// Standard error as if the samples were independent (sigma /
      /// sqrt(n)), for comparison: the ratio shows the correlation.
      double naive_standard_error = 0;
      /// False when the blocking estimate did not reach a plateau (the
      /// record is too short compared with its correlation time): the
      /// error is then a lower bound.
      bool plateau_found = false;
    };

    /**
     * Mean and standard error of the mean of a correlated, stationary time
     * series by Flyvbjerg-Petersen blocking (J. Chem. Phys. 91, 461, 1989):
     * level k replaces the series by the means of consecutive pairs of
     * level k-1 (a trailing odd sample is dropped), so level k holds
     * n_k blocks of 2^k samples. Its error estimate is
     * e_k = sqrt(c0_k / (n_k - 1)), c0_k the (biased) variance of the block
     * means; e_k rises with k while the blocks are shorter than the
     * correlation time and is flat (a plateau) once they are independent.
     *
     * Plateau criterion: the plateau starts at the first level j with
     * (1) block means uncorrelated at all levels k >= j (Jonsson, Phys.
     *     Rev. E 98, 043304, 2018): M_j = sum_{k>=j} n_k (gamma_k/c0_k)^2
     *     < chi^2_{0.99}(K - j), gamma_k the lag-1 autocovariance of the
     *     block means, K the number of levels with at least two blocks
     *     (under independence sqrt(n_k) gamma_k / c0_k is standard normal,
     *     so M_j is chi^2 distributed; the 99 % quantile comes from the
     *     Wilson-Hilferty formula, within 1 % for one degree of freedom);
     * (2) at least @p min_blocks blocks at levels j and j + 1 (fewer make
     *     e_k itself too uncertain, its relative error being
     *     1/sqrt(2(n_k - 1)));
     * (3) flat: |e_{j+1} - e_j| <= 2 sqrt(de_j^2 + de_{j+1}^2), with
     *     de_k = e_k / sqrt(2(n_k - 1)).
     * (1) replaces judging flatness by eye; (2) and (3) ask that the
     * plateau be seen on two levels, which rejects drifting records whose
     * last few blocks are too few for (1) to have any power.
     * If no level qualifies, plateau_found = false and the largest e_k
     * among the levels with at least @p min_blocks blocks is returned (or
     * level 0 when the series has fewer samples than that): a lower bound.
     * Limitation: a stationary record only a few correlation times long
     * can still show a false plateau (AR(1) with tau_int ~ 2000 on 4096
     * samples does); trust the error for records >~ 50 tau_int, i.e.
     * n_blocks >~ 50 at the chosen level.
     *
     * With @p base_block > 1 the series is first cut into consecutive
     * blocks of base_block samples (a trailing partial block is dropped,
     * from the mean too) and the halving starts from their means. For a
     * series with a dominant oscillation (mu_global of the pin: its shear
     * mode), base_block = one period makes every block average whole
     * cycles; otherwise the estimate peaks at blocks of about half a
     * period (the oscillation's share, not the statistical error) and only
     * falls back beyond a period, often past the last level with enough
     * blocks. block_length is then in samples of the original series.
     *
     * The mean is that of the whole series. A constant series has zero
     * error; a series of one sample has an infinite error. An empty series
     * is an InputError.
     */
    MeanWithError
    block_average(const std::vector<double> &series,
                  const unsigned int         min_blocks = 8,
                  const unsigned int         base_block = 1);

    /**
     * Combine independent runs (an ensemble of seeds) of the same quantity.
     * The mean is the unweighted mean of the run means (runs are equally
     * valid; weighting by 1/error^2 would favour runs that happen to have
     * small fluctuations). Two standard errors are computed:
     * - from the spread between runs, s_m / sqrt(R) (s_m the sample
     *   standard deviation of the R run means), which needs no assumption
     *   on the within-run errors but is itself noisy for few runs;
     * - from the within-run errors, sqrt(sum e_i^2) / R.
     * The larger of the two is reported (conservative: the spread catches
     * run-to-run variability the blocking cannot see, the within-run error
     * protects against an accidentally small spread of few runs). With one
     * run, that run is returned unchanged. n_blocks = R, block_length = the
     * largest block length of the runs, plateau_found = all runs found one.
     * No runs is an InputError.
     */
    MeanWithError
    mean_of_means(const std::vector<MeanWithError> &runs);

    /**
     * Centred moving average in time: value i is the arithmetic mean of the
     * samples j with |t_j - t_i| <= window / 2 (sample average, which is
     * the time average for the uniform output interval the solvers use).
     * Near the ends the window is truncated to the available samples rather
     * than shrunk symmetrically, so the end values still average over about
     * half a window instead of being single noisy samples. @p t must be
     * non-decreasing and of the same size as @p y; window >= 0 (0 returns
     * y). O(n) with two pointers.
     */
    std::vector<double>
    moving_average(const std::vector<double> &t,
                   const std::vector<double> &y,
                   const double               window);

    /// Start of a quasi-steady regime found by detect_steady_state().
    struct SteadyState
    {
      bool found = false;
      /// t[start_index]; NaN when not found.
      double start_time = 0;
      /// Index of the first steady sample; t.size() when not found.
      std::size_t start_index = 0;
      /// Half-width of the tolerance band at the start (absolute units).
      double band = 0;
    };

    /**
     * The earliest sample i from which the (smoothed) series stays within
     * +-band of its own mean over the remainder [i, end], where
     * band = relative_band * |mean over [i, end]|, but at least the
     * absolute floor 1e-3 * max_k |smoothed_k| (so that a mean close to
     * zero, e.g. mu ~ 0, does not make the band vanish; the floor scales
     * with the record so the function is unit-free). The remainder must
     * also last at least min_duration_fraction of the record,
     * t.back() - t[i] >= min_duration_fraction * (t.back() - t.front());
     * otherwise found = false. Pass a smoothed series (moving_average()):
     * the band is meant for the slow drift, not for the raw noise. O(n).
     */
    SteadyState
    detect_steady_state(const std::vector<double> &t,
                        const std::vector<double> &smoothed,
                        const double               relative_band,
                        const double               min_duration_fraction);
  } // namespace statistics
} // namespace tribodyn

#endif
