#ifndef tribodyn_homogenization_rve_statistics_h
#define tribodyn_homogenization_rve_statistics_h

#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    /**
     * The statistics of the RVE-size method of Kanit, Forest, Galliet,
     * Mounoury and Jeulin (Int. J. Solids Struct. 40, 3647, 2003), theory
     * in doc/theory/homogenization.md, "RVE size". A property Z (an
     * apparent constant, or a phase's area fraction) measured on n windows
     * of area V has the variance D_Z^2(V); for a medium of finite integral
     * range A it falls as
     *
     *   D_Z^2(V) = D_Z^2 (A / V)^alpha = K V^-alpha,
     *
     * alpha = 1 when the fluctuations of disjoint regions are independent,
     * D_Z^2 the point variance (p (1 - p) for the area fraction p of a
     * phase, sum_k f_k (Z_k - <Z>)^2 for a property whose phase values are
     * Z_k). The mean of n windows is then known within
     * eps_abs = 2 D_Z(V) / sqrt(n) (two standard errors, ~95 %), relative
     * eps_rel = eps_abs / Z, and the RVE size for a wanted eps_rel is
     *
     *   V(eps_rel, n) = (4 K / (eps_rel^2 Z^2 n))^(1/alpha).
     */
    namespace rve
    {
      /// Mean, unbiased (n - 1) variance and standard deviation of a sample.
      struct SampleStatistics
      {
        unsigned int n        = 0;
        double       mean     = 0;
        double       variance = 0;
        double       std      = 0;
      };

      /// Statistics of @p values (variance 0 for fewer than two values).
      SampleStatistics
      sample_statistics(const std::vector<double> &values);

      /**
       * Point variance of a property whose value in phase k is
       * @p phase_values[k] and whose phases have the area fractions
       * @p fractions: sum_k f_k (Z_k - sum_j f_j Z_j)^2; p (1 - p) (Z_1 -
       * Z_0)^2 for two phases, p (1 - p) for the indicator of a phase.
       * Zero when the phase values are equal (to 1e-12 relative).
       */
      double
      point_variance(const std::vector<double> &fractions,
                     const std::vector<double> &phase_values);

      /**
       * The fitted variance law of one property. Two fits of
       * y_i = ln s_i^2 against x_i = ln V_i over the window sizes i:
       * - free: y = ln K - alpha x, weighted least squares;
       * - alpha = 1: ln A_1 = weighted mean of y_i + x_i - ln D_Z^2.
       * Weights w_i = 1 / Var(ln s_i^2) from the sampling distribution of
       * a sample variance of n_i normal values (chi^2 with n_i - 1 degrees
       * of freedom): Var(ln s^2) = psi'(k) ~ 1/k + 1/(2 k^2) + 1/(6 k^3)
       * and E[ln s^2] - ln D^2(V) = psi(k) - ln k ~ -1/(2k) - 1/(12 k^2),
       * k = (n_i - 1)/2, which the fit removes from y_i. The standard
       * errors follow from these weights (not from the scatter of the
       * points); chi2_per_dof compares the scatter with them (~1 when the
       * power law and the weights are right).
       */
      struct VarianceFit
      {
        /// At least two window sizes with a nonzero variance.
        bool         valid   = false;
        unsigned int n_sizes = 0;
        /// Free fit: D_Z^2(V) = K V^-alpha (V in the unit of @p areas).
        double K        = 0;
        double ln_K_se  = 0;
        double alpha    = 0;
        double alpha_se = 0;
        double chi2_dof = 0;
        /// Point variance D_Z^2 given to the fit (0: none, A undefined).
        double point_variance = 0;
        /// A = (K / D_Z^2)^(1/alpha) from the free fit; NaN without D_Z^2.
        double integral_range = 0;
        /// A_1 of the fit with alpha = 1 and the standard error of ln A_1
        /// (the relative error of A_1); NaN without D_Z^2.
        double integral_range_alpha1    = 0;
        double integral_range_alpha1_se = 0;
      };

      /// Fit the variances of @p stats (one per window size, at the areas
      /// @p areas) with the point variance @p point_variance (0 if none).
      VarianceFit
      fit_variance(const std::vector<double>           &areas,
                   const std::vector<SampleStatistics> &stats,
                   const double                         point_variance);

      /// eps_rel = 2 std / (|mean| sqrt(n)) for n realisations.
      double
      relative_error(const double       std,
                     const double       mean,
                     const unsigned int n_realisations);

      /// The RVE area V(eps_rel, n) of the free fit for a property of
      /// mean @p mean; NaN for an invalid fit, a zero mean, or a fit that
      /// does not show the variance falling with the area (alpha <= 2
      /// alpha_se: the power law would extrapolate noise).
      double
      rve_area(const VarianceFit &fit,
               const double       mean,
               const double       relative_error,
               const unsigned int n_realisations);
    } // namespace rve
  }   // namespace homogenization
} // namespace tribodyn

#endif
