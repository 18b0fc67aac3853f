// The RVE study's results: its summary.json keys, and the call of its
// outputs (rve_output.h; the files are written by rve_outputs/).
// Definitions: doc/user_guide/homogenization.md, "RVE-size study".

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <tribodyn/core/json.h>
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/rve_output.h>
#include <tribodyn/homogenization/rve_study.h>

namespace tribodyn
{
  namespace homogenization
  {
    const RveFit &
    RveResults::fit_of(const RveSample &sample) const
    {
      for (const RveFit &f : fits)
        if (f.property == sample.property
            && f.boundary_condition == sample.boundary_condition)
          return f;
      return fits.front();
    }


    const RveSample *
    RveResults::sample_of(const std::string &property,
                          const std::string &boundary_condition,
                          const unsigned int size) const
    {
      for (const RveSample &s : samples)
        if (s.property == property && s.boundary_condition == boundary_condition
            && s.size_index == size)
          return &s;
      return nullptr;
    }


    std::string
    RveResults::as_window(const double area) const
    {
      const auto &sizes = parameters.window_sizes;
      // (mm, of the largest size's aspect ratio)
      const double aspect = (1. * sizes.back()[0] * pixel_width)
                            / (sizes.back()[1] * pixel_height);
      if (!std::isfinite(area))
        return std::string("–");
      std::ostringstream s;
      s << std::setprecision(3) << area * 1e6 << " mm² (≈ "
        << std::sqrt(area * aspect) * 1e3 << " × "
        << std::sqrt(area / aspect) * 1e3 << " mm)";
      return s.str();
    }


    void
    RveStudy::write_results(const std::vector<RveSample> &samples,
                            const std::vector<RveFit>    &fits,
                            const unsigned int            n_groups,
                            const double                  wall_time) const
    {
      const std::string &dir        = context.output_directory;
      const auto        &sizes      = parameters.window_sizes;
      const auto        &ns         = parameters.realisations;
      const double       pixel_area = pixel_width * pixel_height;
      const double       eps        = parameters.relative_error;
      // summary.json
      JsonValue summary = summary_header("rve", context.mpi_communicator);
      summary["n_window_groups"] = n_groups;
      summary["n_windows"]       = static_cast<unsigned int>(windows.size());
      summary["source"] = parameters.source == RveStudyParameters::Source::crops
                            ? "crops"
                            : "realisations";
      summary["pixel_width"]    = pixel_width;
      summary["pixel_height"]   = pixel_height;
      summary["relative_error"] = eps;
      JsonValue jsizes          = JsonValue::array();
      for (const auto &s : sizes)
        {
          JsonValue j = JsonValue::array();
          j.push_back(s[0]);
          j.push_back(s[1]);
          jsizes.push_back(j);
        }
      summary["window_sizes_px"] = jsizes;
      JsonValue jn               = JsonValue::array();
      for (const unsigned int n : ns)
        jn.push_back(n);
      summary["realisations"] = jn;
      JsonValue jfits         = JsonValue::array();
      for (const RveFit &f : fits)
        {
          JsonValue j             = JsonValue::object();
          j["property"]           = f.property;
          j["boundary_condition"] = f.boundary_condition;
          j["mean_largest"]       = f.mean;
          j["point_variance"]     = f.fit.point_variance;
          j["K"]                  = f.fit.K;
          j["alpha"]              = f.fit.alpha;
          j["alpha_se"]           = f.fit.alpha_se;
          j["integral_range_px"]  = f.fit.integral_range / pixel_area;
          j["integral_range_alpha1_px"]
            = f.fit.integral_range_alpha1 / pixel_area;
          j["integral_range_alpha1_rel_se"] = f.fit.integral_range_alpha1_se;
          j["chi2_dof"]                     = f.fit.chi2_dof;
          j["rve_area_m2"]                  = json_array(f.rve_area);
          jfits.push_back(j);
        }
      summary["fits"]        = jfits;
      summary["wall_time_s"] = wall_time;
      write_file_atomically(join_path(dir, "summary.json"),
                            summary.dump() + "\n");
      // the outputs, in their list's order
      const std::vector<std::string>        phases = materials.names();
      const std::vector<BoundaryCondition> &bcs    = boundary_conditions();
      const auto has = [&](const BoundaryCondition bc) {
        return std::find(bcs.begin(), bcs.end(), bc) != bcs.end();
      };
      const RveResults         results{parameters,
                               samples,
                               fits,
                               phases,
                               has(BoundaryCondition::kubc)
                                 && has(BoundaryCondition::subc),
                               static_cast<unsigned int>(windows.size()),
                               pixel_width,
                               pixel_height,
                               dir};
      std::vector<std::string> names;
      std::string              files;
      for (const auto &output :
           RveOutputRegistry::create_all(parameters, names, parameters.outputs))
        {
          output->write(results, std::cout);
          std::cout.flush(); // (before an output's subprocess writes)
          files += output->files() + ", ";
        }
      std::cout << "\nRVE study written to " << dir << "/ (" << files
                << "summary.json) in " << std::fixed << std::setprecision(1)
                << wall_time << " s" << std::endl;
    }
  } // namespace homogenization
} // namespace tribodyn
