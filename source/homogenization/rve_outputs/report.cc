// Output 'report' of the RVE study: rve.md (the tables of means and
// standard deviations, the variance law and the RVE sizes, which windows
// are RVEs, the KUBC - SUBC gap), also shown on the screen.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/rve_output.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      /// "31.92 GPa" or "0.2001": a value of @p property for rve.md.
      std::string
      format_value(const std::string &property, const double v)
      {
        std::ostringstream s;
        if (RveResults::is_modulus(property))
          s << std::fixed << std::setprecision(3) << v / 1e9;
        else
          s << std::fixed << std::setprecision(4) << v;
        return s.str();
      }


      std::string
      format_general(const double v, const int digits = 3)
      {
        if (!std::isfinite(v))
          return "–";
        std::ostringstream s;
        s << std::setprecision(digits) << v;
        return s.str();
      }


      std::string
      percent(const double v, const int digits = 2)
      {
        if (!std::isfinite(v))
          return "–";
        std::ostringstream s;
        s << std::fixed << std::setprecision(digits) << 100 * v << " %";
        return s.str();
      }


      class Report : public RveOutput
      {
      public:
        void
        write(const RveResults &r, std::ostream &screen) const override
        {
          const RveStudyParameters &parameters = r.parameters;
          const auto               &sizes      = parameters.window_sizes;
          const auto               &ns         = parameters.realisations;
          const double              element    = r.element_measure();
          const std::string         unit       = r.element_unit();
          const std::string        &dir        = r.output_directory;
          const double              eps        = parameters.relative_error;
          const auto               &samples    = r.samples;
          const auto               &fits       = r.fits;
          // rve.md
          std::ostringstream md;
          md << "# RVE-size study (Kanit et al. 2003)\n\n"
             << r.n_windows << " windows ("
             << (parameters.source == RveStudyParameters::Source::crops
                   ? "cut at random positions"
                   : "independent generator realisations")
             << "), " << (r.dim == 2 ? "pixel " : "voxel ")
             << r.element_size[0] * 1e3 << " × " << r.element_size[1] * 1e3;
          if (r.dim == 3)
            md << " × " << r.element_size[2] * 1e3;
          md
            << " mm; moduli in GPa. `std` is the sample standard deviation of "
               "the windows of one size; `bias` is the mean against the "
               "largest windows' mean (same boundary condition); `eps_rel(n) = "
               "2 std / (mean sqrt(n))` is the relative error of the mean of n "
               "such windows (two standard errors).\n\n"
            << "## Means and standard deviations\n\n"
            << "| property | BC | window (" << unit
            << ") | window (mm) | n | mean | std | "
               "std/mean | bias |";
          for (const unsigned int n : ns)
            md << " eps_rel(n=" << n << ") |";
          md << "\n|---|---|---|---|---|---|---|---|---|";
          for (std::size_t i = 0; i < ns.size(); ++i)
            md << "---|";
          md << "\n";
          for (const RveSample &row : samples)
            {
              const auto &st = row.statistics;
              md << "| " << row.property << " | " << row.boundary_condition
                 << " | " << r.size_text(row.size_index) << " | "
                 << r.size_text(row.size_index, " × ", true) << " | " << st.n
                 << " | " << format_value(row.property, st.mean) << " | "
                 << format_value(row.property, st.std) << " | "
                 << percent(st.mean != 0 ? st.std / std::abs(st.mean) : 0.)
                 << " | " << percent(row.bias) << " |";
              for (const unsigned int n : ns)
                md << " " << percent(rve::relative_error(st.std, st.mean, n))
                   << " |";
              md << "\n";
            }

          md
            << "\n## Variance law D²(V) = K V^-α = D² (A/V)^α and RVE size\n\n"
            << "Weighted least squares of ln s² against ln V (weights from the "
               "sampling error of a variance, 1/Var(ln s²) ≈ (n − 1)/2); D² is "
               "the point variance (Σ f_k (Z_k − Z̄)², f_k the mean phase "
               "fractions); A from the free fit, A₁ from the fit with α = 1 "
               "(± its relative standard error), both in "
            << (r.dim == 2 ? "pixels" : "voxels")
            << "; V_RVE = (4 K / (ε² Z̄² n))^(1/α) for ε = " << percent(eps, 1)
            << ", Z̄ the mean of the largest windows, as "
            << (r.dim == 2 ? "an area" : "a volume")
            << " and as a window of the largest windows' aspect ratio.\n\n"
            << "| property | BC | Z̄ | D² | α ± se | A (" << unit << ") | A₁ ("
            << unit << ") | χ²/dof |";
          for (const unsigned int n : ns)
            md << " V_RVE (n=" << n << ") |";
          md << "\n|---|---|---|---|---|---|---|---|";
          for (std::size_t i = 0; i < ns.size(); ++i)
            md << "---|";
          md << "\n";
          for (const RveFit &f : fits)
            {
              md << "| " << f.property << " | " << f.boundary_condition << " | "
                 << format_value(f.property, f.mean) << " | "
                 << format_general(f.fit.point_variance) << " | "
                 << format_general(f.fit.alpha) << " ± "
                 << format_general(f.fit.alpha_se, 2) << " | "
                 << format_general(f.fit.integral_range / element) << " | "
                 << format_general(f.fit.integral_range_alpha1 / element)
                 << " ± " << percent(f.fit.integral_range_alpha1_se, 0) << " | "
                 << format_general(f.fit.chi2_dof, 2) << " |";
              for (const double a : f.rve_measure)
                md << " " << r.as_window(a) << " |";
              md << "\n";
            }

          // The answer: for each constant, BC and n, which window sizes are
          // RVEs at eps (measured), and the fitted size; then the systematic
          // error, the KUBC - SUBC gap.
          const auto size_name
            = [&](const unsigned int i) { return r.size_text(i, "×"); };
          md << "\n## Which windows are RVEs at " << percent(eps, 1) << "?\n\n"
             << "A size is an RVE for a constant, a boundary condition and n "
                "realisations when the mean of n such windows is within "
             << percent(eps, 1)
             << " with ~95 % confidence, eps_rel(n) <= eps (measured from the "
                "standard deviation of its windows; the fitted V_RVE "
                "interpolates). This is the statistical error only; the "
                "systematic one (bias, KUBC–SUBC gap) follows.\n\n"
             << "| property | BC | n | eps_rel(n) per window size (" << unit
             << ") | "
                "smallest RVE size (measured) | V_RVE (fit) |\n"
             << "|---|---|---|---|---|---|\n";
          for (const RveFit &f : fits)
            {
              // nu_TT hardly varies; the first phase's fraction (the matrix)
              // mirrors the others' for two phases.
              if (f.property == "nu_TT"
                  || f.property == "fraction_" + r.phase_names[0])
                continue;
              for (unsigned int k = 0; k < ns.size(); ++k)
                {
                  md << "| " << f.property << " | " << f.boundary_condition
                     << " | " << ns[k] << " | ";
                  int smallest = -1;
                  for (unsigned int i = 0; i < sizes.size(); ++i)
                    {
                      const RveSample *s
                        = r.sample_of(f.property, f.boundary_condition, i);
                      const double e = rve::relative_error(s->statistics.std,
                                                           s->statistics.mean,
                                                           ns[k]);
                      md << (i == 0 ? "" : ", ") << size_name(i) << ": "
                         << percent(e);
                      if (smallest < 0 && e <= eps)
                        smallest = i;
                    }
                  md << " | "
                     << (smallest < 0 ? std::string("none of them")
                                      : size_name(smallest) + " " + unit)
                     << " | " << r.as_window(f.rve_measure[k]) << " |\n";
                }
            }

          if (r.kubc_and_subc)
            {
              md
                << "\n## Systematic error: KUBC − SUBC\n\n"
                << "Huet (1990): in the mean over windows, the apparent KUBC "
                   "stiffness lies above the effective one and the inverse of "
                   "the "
                   "mean SUBC compliance below it, so the gap between the KUBC "
                   "and SUBC means bounds the bias of either (up to the spread "
                   "of "
                   "the windows). An RVE at "
                << percent(eps, 1) << " also needs it below " << percent(eps, 1)
                << ".\n\n| property | window (" << unit
                << ") | KUBC | SUBC | (KUBC − SUBC)/SUBC "
                   "|\n|---|---|---|---|---|"
                   "\n";
              // the moduli, in the order of the constants
              for (const RveFit &f : fits)
                {
                  if (f.boundary_condition != "KUBC"
                      || !RveResults::is_modulus(f.property))
                    continue;
                  const std::string &c = f.property;
                  for (unsigned int i = 0; i < sizes.size(); ++i)
                    {
                      const double K
                        = r.sample_of(c, "KUBC", i)->statistics.mean,
                        S = r.sample_of(c, "SUBC", i)->statistics.mean;
                      md << "| " << c << " | " << size_name(i) << " | "
                         << format_value(c, K) << " | " << format_value(c, S)
                         << " | " << percent(K / S - 1) << " |\n";
                    }
                }
            }
          write_file_atomically(join_path(dir, "rve.md"), md.str());
          screen << "\n" << md.str();
        }

        std::string
        files() const override
        {
          return "rve.md";
        }
      };

      const bool rve_report_registered
        = RveOutputRegistry::add({"report", 1, [](const RveStudyParameters &) {
                                    return std::make_unique<Report>();
                                  }});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
