// Output 'table' of the RVE study: rve.csv, one row per window size,
// boundary condition and property, with its fit repeated (the plot reads
// it).
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
      class Table : public RveOutput
      {
      public:
        void
        write(const RveResults &r, std::ostream &) const override
        {
          const RveStudyParameters &parameters  = r.parameters;
          const auto               &sizes       = parameters.window_sizes;
          const auto               &ns          = parameters.realisations;
          const double              pixel_width = r.pixel_width,
                       pixel_height             = r.pixel_height;
          const double       pixel_area         = pixel_width * pixel_height;
          const std::string &dir                = r.output_directory;
          const auto        &samples            = r.samples;
          std::ostringstream csv;
          csv << "size_x_px,size_y_px,width_m,height_m,area_m2,area_px,"
                 "boundary_condition,property,n,mean,std,relative_std,bias";
          for (const unsigned int n : ns)
            csv << ",eps_rel_n" << n;
          csv << ",point_variance,K,alpha,alpha_se,integral_range_px,"
                 "integral_range_alpha1_px,integral_range_alpha1_rel_se,"
                 "chi2_dof";
          for (const unsigned int n : ns)
            csv << ",rve_area_m2_n" << n;
          csv << "\n" << std::setprecision(10);
          for (const RveSample &row : samples)
            {
              const auto   &s  = sizes[row.size_index];
              const RveFit &f  = r.fit_of(row);
              const auto   &st = row.statistics;
              const double  w = s[0] * pixel_width, h = s[1] * pixel_height;
              csv << s[0] << "," << s[1] << "," << w << "," << h << "," << w * h
                  << "," << s[0] * s[1] << "," << row.boundary_condition << ","
                  << row.property << "," << st.n << "," << st.mean << ","
                  << st.std << ","
                  << (st.mean != 0 ? st.std / std::abs(st.mean) : 0.) << ","
                  << row.bias;
              for (const unsigned int n : ns)
                csv << "," << rve::relative_error(st.std, st.mean, n);
              csv << "," << f.fit.point_variance << "," << f.fit.K << ","
                  << f.fit.alpha << "," << f.fit.alpha_se << ","
                  << f.fit.integral_range / pixel_area << ","
                  << f.fit.integral_range_alpha1 / pixel_area << ","
                  << f.fit.integral_range_alpha1_se << "," << f.fit.chi2_dof;
              for (const double a : f.rve_area)
                csv << "," << a;
              csv << "\n";
            }
          write_file_atomically(join_path(dir, "rve.csv"), csv.str());
        }

        std::string
        files() const override
        {
          return "rve.csv";
        }
      };

      const bool rve_table_registered
        = RveOutputRegistry::add({"table", 0, [](const RveStudyParameters &) {
                                    return std::make_unique<Table>();
                                  }});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
