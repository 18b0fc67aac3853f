#ifndef tribodyn_study_blocking_h
#define tribodyn_study_blocking_h

#include <vector>

namespace tribodyn
{
  namespace study
  {
    /**
     * Standard error of the mean of a correlated time series by blocking
     * (Flyvbjerg & Petersen, J. Chem. Phys. 91, 461 (1989)): the series is
     * repeatedly halved by averaging neighbouring pairs; at level k with
     * n_k blocks of variance s_k^2 (1/n_k normalization) the estimate is
     * e_k = sqrt(s_k^2 / (n_k - 1)), with its own standard error
     * e_k / sqrt(2 (n_k - 1)). e_k grows with k while the blocks are
     * shorter than the correlation time and stays constant (plateau) once
     * they are longer. The plateau is the first level k whose estimate is
     * not exceeded by any later level (with at least @p min_blocks blocks)
     * by more than that later level's own standard error; without a plateau
     * the largest estimate of those levels is returned (conservative) and
     * plateau_found is false.
     *
     * This is the study's own small implementation (issue #9); a shared
     * statistics module (core/statistics) is being written elsewhere.
     */
    struct BlockingResult
    {
      double       mean           = 0;
      double       naive_stderr   = 0; ///< as if uncorrelated (level 0)
      double       stderr_of_mean = 0; ///< plateau value
      unsigned int plateau_level  = 0;
      bool         plateau_found  = false;
      /// Estimate and its error per level.
      std::vector<double> level_stderr, level_stderr_error;
    };

    /**
     * With @p base_block > 1 the series is first cut into consecutive blocks
     * of base_block samples (the remainder at the end is dropped from the
     * blocking, not from the mean), and the halving starts from their means.
     * For a series with a dominant oscillation (mu_global of the pin: its
     * 71 kHz shear mode), base_block = one period makes every block average
     * whole cycles; otherwise the blocked estimate peaks at blocks of about
     * half a period (the oscillation's share, not the statistical error) and
     * only falls back beyond a period, often past the last level with
     * enough blocks.
     */
    BlockingResult
    block_average(const std::vector<double> &series,
                  const unsigned int         min_blocks = 16,
                  const unsigned int         base_block = 1);
  } // namespace study
} // namespace tribodyn

#endif
