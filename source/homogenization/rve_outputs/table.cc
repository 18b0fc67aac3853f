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
          const auto        &sizes = r.parameters.window_sizes;
          const auto        &ns    = r.parameters.realisations;
          const std::string &dir   = r.output_directory;
          const std::string  unit  = r.element_unit();
          const std::string  measure
            = r.measure_name() + "_" + r.measure_si_unit();
          const double element = r.element_measure();
          // 2D: size_x_px, size_y_px, width_m, height_m, area_m2, area_px;
          // 3D: size_x_vox, ..., size_z_vox, width_m, height_m, depth_m,
          // volume_m3, volume_vox
          const char        *axes[3]  = {"x", "y", "z"};
          const char        *edges[3] = {"width", "height", "depth"};
          std::ostringstream csv;
          for (unsigned int d = 0; d < r.dim; ++d)
            csv << "size_" << axes[d] << "_" << unit << ",";
          for (unsigned int d = 0; d < r.dim; ++d)
            csv << edges[d] << "_m,";
          csv << measure << "," << r.measure_name() << "_" << unit
              << ",boundary_condition,property,n,mean,std,relative_std,bias";
          for (const unsigned int n : ns)
            csv << ",eps_rel_n" << n;
          csv << ",point_variance,K,alpha,alpha_se,integral_range_" << unit
              << ",integral_range_alpha1_" << unit
              << ",integral_range_alpha1_rel_se,chi2_dof";
          for (const unsigned int n : ns)
            csv << ",rve_" << measure << "_n" << n;
          csv << "\n" << std::setprecision(10);
          for (const RveSample &row : r.samples)
            {
              const auto   &s  = sizes[row.size_index];
              const RveFit &f  = r.fit_of(row);
              const auto   &st = row.statistics;
              for (unsigned int d = 0; d < r.dim; ++d)
                csv << s[d] << ",";
              for (unsigned int d = 0; d < r.dim; ++d)
                csv << s[d] * r.element_size[d] << ",";
              csv << r.elements(row.size_index) * element << ","
                  << r.elements(row.size_index) << "," << row.boundary_condition
                  << "," << row.property << "," << st.n << "," << st.mean << ","
                  << st.std << ","
                  << (st.mean != 0 ? st.std / std::abs(st.mean) : 0.) << ","
                  << row.bias;
              for (const unsigned int n : ns)
                csv << "," << rve::relative_error(st.std, st.mean, n);
              csv << "," << f.fit.point_variance << "," << f.fit.K << ","
                  << f.fit.alpha << "," << f.fit.alpha_se << ","
                  << f.fit.integral_range / element << ","
                  << f.fit.integral_range_alpha1 / element << ","
                  << f.fit.integral_range_alpha1_se << "," << f.fit.chi2_dof;
              for (const double a : f.rve_measure)
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
