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
    RveResults::element_unit() const
    {
      return dim == 2 ? "px" : "vox";
    }


    std::string
    RveResults::measure_name() const
    {
      return dim == 2 ? "area" : "volume";
    }


    std::string
    RveResults::measure_si_unit() const
    {
      return dim == 2 ? "m2" : "m3";
    }


    double
    RveResults::element_measure() const
    {
      return element_size[0] * element_size[1] * element_size[2];
    }


    double
    RveResults::elements(const unsigned int size) const
    {
      return parameters.window_elements(size);
    }


    std::string
    RveResults::size_text(const unsigned int size,
                          const std::string &separator,
                          const bool         in_mm) const
    {
      if (!in_mm)
        return format_window_size(parameters.window_sizes[size],
                                  dim,
                                  separator);
      std::ostringstream s;
      for (unsigned int d = 0; d < dim; ++d)
        s << (d == 0 ? "" : separator)
          << parameters.window_sizes[size][d] * element_size[d] * 1e3;
      return s.str();
    }


    std::string
    RveResults::as_window(const double measure) const
    {
      if (!std::isfinite(measure))
        return std::string("–");
      // (mm, of the largest size's aspect ratios: edges proportional to
      // its edges, scaled by (measure / its measure)^(1/dim))
      const unsigned int largest = parameters.window_sizes.size() - 1;
      const double       scale
        = std::pow(measure / (elements(largest) * element_measure()), 1. / dim);
      std::ostringstream s;
      s << std::setprecision(3) << measure * (dim == 2 ? 1e6 : 1e9)
        << (dim == 2 ? " mm² (≈ " : " mm³ (≈ ");
      for (unsigned int d = 0; d < dim; ++d)
        s << (d == 0 ? "" : " × ")
          << scale * parameters.window_sizes[largest][d] * element_size[d]
               * 1e3;
      s << " mm)";
      return s.str();
    }


    bool
    RveResults::is_modulus(const std::string &property)
    {
      return property.rfind("E_", 0) == 0 || property.rfind("G_", 0) == 0
             || property == "k" || property == "mu";
    }


    void
    RveStudy::write_results(const std::vector<RveSample> &samples,
                            const std::vector<RveFit>    &fits,
                            const unsigned int            n_groups,
                            const double                  wall_time) const
    {
      const std::string                    &dir    = context.output_directory;
      const auto                           &ns     = parameters.realisations;
      const double                          eps    = parameters.relative_error;
      const std::vector<std::string>        phases = phase_names();
      const std::vector<BoundaryCondition> &bcs    = boundary_conditions();
      const auto has = [&](const BoundaryCondition bc) {
        return std::find(bcs.begin(), bcs.end(), bc) != bcs.end();
      };
      const RveResults  results{parameters,
                               samples,
                               fits,
                               phases,
                               has(BoundaryCondition::kubc)
                                 && has(BoundaryCondition::subc),
                               static_cast<unsigned int>(windows.size()),
                               dim,
                               element_size,
                               dir};
      const std::string unit    = results.element_unit();
      const double      element = results.element_measure();
      // summary.json
      JsonValue summary = summary_header(dim == 2 ? "rve" : "volume_rve",
                                         context.mpi_communicator);
      summary["n_window_groups"] = n_groups;
      summary["n_windows"]       = static_cast<unsigned int>(windows.size());
      summary["source"] = parameters.source == RveStudyParameters::Source::crops
                            ? "crops"
                            : "realisations";
      if (dim == 2)
        {
          summary["pixel_width"]  = element_size[0];
          summary["pixel_height"] = element_size[1];
        }
      else
        summary["voxel_size"]
          = json_array({element_size[0], element_size[1], element_size[2]});
      summary["relative_error"] = eps;
      JsonValue jsizes          = JsonValue::array();
      for (const auto &s : parameters.window_sizes)
        {
          JsonValue j = JsonValue::array();
          for (unsigned int d = 0; d < dim; ++d)
            j.push_back(s[d]);
          jsizes.push_back(j);
        }
      summary["window_sizes_" + unit] = jsizes;
      JsonValue jn                    = JsonValue::array();
      for (const unsigned int n : ns)
        jn.push_back(n);
      summary["realisations"] = jn;
      JsonValue jfits         = JsonValue::array();
      for (const RveFit &f : fits)
        {
          JsonValue j                 = JsonValue::object();
          j["property"]               = f.property;
          j["boundary_condition"]     = f.boundary_condition;
          j["mean_largest"]           = f.mean;
          j["point_variance"]         = f.fit.point_variance;
          j["K"]                      = f.fit.K;
          j["alpha"]                  = f.fit.alpha;
          j["alpha_se"]               = f.fit.alpha_se;
          j["integral_range_" + unit] = f.fit.integral_range / element;
          j["integral_range_alpha1_" + unit]
            = f.fit.integral_range_alpha1 / element;
          j["integral_range_alpha1_rel_se"] = f.fit.integral_range_alpha1_se;
          j["chi2_dof"]                     = f.fit.chi2_dof;
          j["rve_" + results.measure_name() + "_" + results.measure_si_unit()]
            = json_array(f.rve_measure);
          jfits.push_back(j);
        }
      summary["fits"]        = jfits;
      summary["wall_time_s"] = wall_time;
      write_file_atomically(join_path(dir, "summary.json"),
                            summary.dump() + "\n");
      // the outputs, in their list's order
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
