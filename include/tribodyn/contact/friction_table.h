#ifndef tribodyn_contact_friction_table_h
#define tribodyn_contact_friction_table_h

#include <string>
#include <vector>

namespace tribodyn
{
  namespace contact
  {
    /**
     * A friction coefficient tabulated on a grid of contact pressure p and
     * slip speed v, read from a CSV file with a header line that names the
     * columns `pressure` (Pa), `speed` (m/s) and `mu` (others, e.g.
     * `mu_stderr`, are ignored; rows in any order; '#' lines are comments):
     * one row per grid point of a full rectangular grid, at least two
     * pressures and two speeds. mu(p, v) is bilinear in each grid cell,
     * exact at the grid points; outside the grid p and v are clamped to its
     * edges (counted: clamped()).
     */
    class FrictionTable
    {
    public:
      FrictionTable() = default;

      /// Read @p file; @p parameter (e.g. "Contact/Tabulated friction/
      /// File") names the entry in error messages (InputError).
      FrictionTable(const std::string &file, const std::string &parameter);

      /// Make a table from its grid (sorted, strictly increasing axes) and
      /// the values mu[i_p * n_v + i_v].
      FrictionTable(std::vector<double> pressures,
                    std::vector<double> speeds,
                    std::vector<double> mu);

      /// mu at pressure @p p and speed @p v (clamped outside the grid).
      double
      operator()(const double p, const double v) const
      {
        bool outside        = false;
        const auto [ip, tp] = locate(pressures, p, outside);
        const auto [iv, tv] = locate(speeds, v, outside);
        if (outside)
          ++n_clamped;
        const std::size_t n    = speeds.size();
        const double     *m0   = mu.data() + ip * n + iv;
        const double     *m1   = m0 + n;
        const double      low  = blend(m0[0], m0[1], tv);
        const double      high = blend(m1[0], m1[1], tv);
        return blend(low, high, tp);
      }

      /// Evaluations with p or v outside the grid, since the start.
      unsigned long long
      clamped() const
      {
        return n_clamped;
      }

      const std::vector<double> &
      pressure_axis() const
      {
        return pressures;
      }
      const std::vector<double> &
      speed_axis() const
      {
        return speeds;
      }

    private:
      /// a + t (b - a), exactly a at t = 0 and b at t = 1 (and exact where
      /// the table is constant).
      static double
      blend(const double a, const double b, const double t)
      {
        return t == 1 ? b : a + t * (b - a);
      }

      /// Cell index and local coordinate in [0, 1] of @p x on @p axis.
      static std::pair<std::size_t, double>
      locate(const std::vector<double> &axis, const double x, bool &outside)
      {
        if (!(x > axis.front()))
          {
            outside = outside || x < axis.front();
            return {0, 0.};
          }
        if (!(x < axis.back()))
          {
            outside = outside || x > axis.back();
            return {axis.size() - 2, 1.};
          }
        std::size_t k = 0;
        while (axis[k + 1] <= x) // a grid point starts its cell (t = 0)
          ++k;
        return {k, (x - axis[k]) / (axis[k + 1] - axis[k])};
      }

      std::vector<double>        pressures, speeds, mu;
      mutable unsigned long long n_clamped = 0;
    };
  } // namespace contact
} // namespace tribodyn

#endif
