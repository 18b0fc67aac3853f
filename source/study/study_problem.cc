// The study driver: cases, homogenization chaining, MPI groups, results.
// Tables and plots: study_tables.cc.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tribodyn/contact/contact_problem.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/morphology_sources/grid_file.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/statistics.h>
#include <tribodyn/homogenization/homogenization_problem.h>
#include <tribodyn/study/study_problem.h>

namespace tribodyn
{
  namespace study
  {
    using dealii::ParameterHandler;

    void
    StudyProblem::declare_parameters(ParameterHandler &prm)
    {
      contact::ContactParameters::declare_parameters(prm);
      StudyParameters::declare_parameters(prm);
    }


    StudyProblem::StudyProblem(ParameterHandler &prm, const RunContext &context)
        : context(context)
    {
      base.parse_parameters(prm, false);
      base.check_averaging_window(false);
      parameters.parse_parameters(prm);
      parameters_of_homogenization
        = homogenization::HomogenizationParameters::defaults();
      parameters_of_homogenization.morphology = base.morphology;
      // 'homogeneous matrix': the isotropic pin of Materials/Pin material
      if (std::find(parameters.models.begin(),
                    parameters.models.end(),
                    PinModel::homogeneous_matrix)
          != parameters.models.end())
        base.material.check_isotropic_pin(
          base.material.pin_index,
          "Materials/Pin material",
          "the pin of the model 'homogeneous matrix' (Study/Models)");
      const bool is_map = base.morphology.is_map();
      if (parameters.window_size[0] > 0)
        {
          check_parameter(is_map,
                          "Study/Window size",
                          "empty unless 'Morphology/Generator' is 'image' or "
                          "'grid file': windows are cut from a map, a "
                          "generator's morphologies are its seeds");
          cut_windows();
        }
      else if (is_map)
        check_parameter(parameters.n_morphologies == 1,
                        "Study/Number of morphologies",
                        "1 for a map without windows (the map is one "
                        "morphology): give 'Study/Window size' to cut "
                        "windows from it");

      // The same mesh for every model: the morphology's pixel grid times
      // the subdivisions, which must be square.
      const auto        &m  = base.morphology;
      const unsigned int s  = base.geometry.subdivisions_per_pixel;
      const double       hx = m.width / (m.n_pixels_x * s),
                   hy       = m.height / (m.n_pixels_y * s);
      if (std::abs(hx - hy) > 1e-6 * hx)
        throw InputError(
          "A study uses the same mesh for every model, the morphology's "
          "pixel grid: its pixels must be square, but 'Morphology/Width' / "
          "'Morphology/Pixels in x' = "
          + format_number(m.width / m.n_pixels_x)
          + " m differs from 'Morphology/Height' / 'Morphology/Pixels in y' "
            "= "
          + format_number(m.height / m.n_pixels_y)
          + " m. Change 'Morphology/Pixels in y'.");
      base.geometry.width     = m.width;
      base.geometry.height    = m.height;
      base.geometry.mesh_size = hx;
      if (whole_map)
        {
          base.geometry.width
            = parameters.window_size[0] * whole_map->pixel_width();
          base.geometry.height
            = parameters.window_size[1] * whole_map->pixel_height();
        }
      if (!parameters.write_case_fields)
        base.output.field_interval = 0;

      // Cases: pressure x model x morphology (meso) x repeat.
      for (unsigned int p = 0; p < parameters.pressures.size(); ++p)
        for (const PinModel model : parameters.models)
          {
            const bool per_morphology
              = model == PinModel::meso
                || (model == PinModel::homogenized
                    && parameters.homogenized_pin
                         == StudyParameters::HomogenizedPin::each_morphology);
            const unsigned int n_seeds
              = per_morphology ? parameters.n_morphologies : 1;
            for (unsigned int k = 0; k < n_seeds; ++k)
              for (unsigned int r = 0; r < parameters.repeats; ++r)
                {
                  StudyCase c;
                  c.pressure_index = p;
                  c.model          = model;
                  c.seed           = first_morphology() + k;
                  c.repeat         = r;
                  std::ostringstream name;
                  name << "P" << parameters.pressures[p] / 1e6 << "MPa_"
                       << (model == PinModel::homogeneous_matrix ? "matrix"
                           : model == PinModel::homogenized      ? "homogenized"
                                                                 : "meso");
                  if (per_morphology)
                    name << "_" << morphology_name(c.seed);
                  if (parameters.repeats > 1)
                    name << "_r" << r;
                  c.name = name.str();
                  study_cases.push_back(c);
                }
          }
    }


    unsigned int
    StudyProblem::n_case_groups() const
    {
      return std::max(1u,
                      dealii::Utilities::MPI::n_mpi_processes(
                        context.mpi_communicator)
                        / parameters.ranks_per_case);
    }


    void
    StudyProblem::homogenize(const MPI_Comm group, const unsigned int n_groups)
    {
      const MPI_Comm     world = context.mpi_communicator;
      const unsigned int color = dealii::Utilities::MPI::this_mpi_process(world)
                                 / parameters.ranks_per_case;
      const std::string root_dir
        = join_path(context.output_directory, "homogenization");
      std::vector<std::string> summaries;
      for (unsigned int k = 0; k < parameters.n_morphologies; ++k)
        {
          const unsigned int seed = first_morphology() + k;
          const std::string  dir  = join_path(root_dir, morphology_name(seed));
          summaries.push_back(join_path(dir, "summary.json"));
          if (k % n_groups != std::min(color, n_groups - 1))
            continue;
          if (parameters.reuse_cases && file_exists(summaries.back()))
            continue;
          // The homogenization problem on the study's morphology (its seed
          // or its window) and the study's phases; its other parameters at
          // their defaults.
          auto hp       = parameters_of_homogenization;
          hp.morphology = morphology_parameters(seed);
          hp.materials  = base.material.composite;
          hp.cell_problem.boundary_conditions
            = {homogenization::boundary_condition_named(
              parameters.boundary_condition)};
          hp.cell_problem.subdivisions_per_pixel
            = base.geometry.subdivisions_per_pixel;
          hp.output.write_fields = false;
          RunContext hc          = context;
          hc.mpi_communicator    = group;
          hc.output_directory    = dir;
          hc.parameters_text     = nullptr;
          homogenization::HomogenizationProblem problem(hp, hc);
          problem.run();
        }
      MPI_Barrier(world);

      // Each morphology's apparent stiffness and density (the phases'
      // densities by their area fractions), and their averages.
      homogenized_C       = 0;
      homogenized_c_z     = 0;
      homogenized_density = 0;
      morphology_C.clear();
      morphology_c_z.clear();
      morphology_density.clear();
      nlohmann::ordered_json record;
      record["boundary_condition"] = parameters.boundary_condition;
      for (const std::string &file : summaries)
        {
          dealii::Tensor<1, 3> cz;
          morphology_C.push_back(contact::read_homogenization_stiffness(
            file, parameters.boundary_condition, cz));
          morphology_c_z.push_back(cz);
          homogenized_C += morphology_C.back();
          homogenized_c_z += cz;
          std::ifstream        in(file);
          const nlohmann::json j = nlohmann::json::parse(in);
          const double         f = j.at("volume_fraction").get<double>();
          // rho = rho_0 + sum_k>0 f_k (rho_k - rho_0): exactly rho_0 when
          // the phases share their density, whatever the rounding of the
          // fractions
          const auto  &phases  = j.at("phases");
          const double rho_0   = phases.at(0).at("density").get<double>();
          double       density = rho_0;
          for (std::size_t k = 1; k < phases.size(); ++k)
            density += phases[k].at("fraction").get<double>()
                       * (phases[k].at("density").get<double>() - rho_0);
          morphology_density.push_back(density);
          homogenized_density += density;
          record["summaries"].push_back(file);
          record["volume_fractions"].push_back(f);
          record["densities"].push_back(density);
        }
      const double n = summaries.size();
      homogenized_C /= n;
      homogenized_c_z /= n;
      homogenized_density /= n;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          record["C"][i].push_back(homogenized_C[i][j]);
      record["density"] = homogenized_density;
      if (dealii::Utilities::MPI::this_mpi_process(world) == 0)
        write_file_atomically(join_path(root_dir, "homogenized_stiffness.json"),
                              record.dump(2) + "\n");
    }


    namespace
    {
      /// The statistics of one case from its mu_global samples in the
      /// averaging window (spacing @p spacing, s) and its run summary.
      CaseResult
      case_statistics(const std::vector<double> &mu,
                      const double               spacing,
                      const contact::RunSummary &s)
      {
        // Base blocks of one period of mu_global's dominant oscillation
        // (the pin's shear mode): each block averages whole cycles.
        const unsigned int base_block
          = s.dominant_frequency_hz > 0 ? std::max<long>(
              1, std::lround(1. / (s.dominant_frequency_hz * spacing)))
                                        : 1;
        const statistics::MeanWithError b
          = statistics::block_average(mu, 8, base_block);
        CaseResult r;
        r.mu_mean               = s.mu_global_mean;
        r.mu_stderr             = b.standard_error;
        r.mu_naive_stderr       = b.naive_standard_error;
        r.plateau_found         = b.plateau_found;
        r.stick                 = s.stick_fraction;
        r.slip                  = s.slip_fraction;
        r.separation            = s.separation_fraction;
        r.M_stick               = s.M_stick_fraction;
        r.M_slip                = s.M_slip_fraction;
        r.M_separation          = s.M_separation_fraction;
        r.mu_contact_mean       = s.mu_contact_mean;
        r.dominant_frequency_hz = s.dominant_frequency_hz;
        r.wall_time_s           = s.wall_time_s;
        r.n_samples             = mu.size();
        return r;
      }


      /// A case that finished earlier in @p dir: its summary and its
      /// mu_global samples in [t0, t1] (friction.csv). Throws when the run
      /// there does not match @p cp.
      CaseResult
      read_finished_case(const std::string                &dir,
                         const contact::ContactParameters &cp,
                         const double                      t0,
                         const double                      t1)
      {
        const std::string file = join_path(dir, "summary.json");
        std::ifstream     in(file);
        nlohmann::json    j;
        try
          {
            j = nlohmann::json::parse(in);
          }
        catch (const std::exception &e)
          {
            throw InputError("'Study/Reuse finished cases': cannot read " + file
                             + " (" + e.what()
                             + "). Delete that case's directory to run it "
                               "again.");
          }
        auto same
          = [&](const char *key, const double wanted, const double got) {
              if (std::abs(got - wanted) > 1e-9 * std::abs(wanted))
                throw InputError(
                  "'Study/Reuse finished cases': the run in " + dir + " has "
                  + key + " = " + format_number(got) + ", the study asks "
                  + format_number(wanted)
                  + ". Delete that case's directory (or set 'Reuse finished "
                    "cases' to false) to run it again.");
            };
        same("pressure", cp.loading.pressure, j.at("pressure").get<double>());
        same("dt", cp.time.time_step, j.at("dt").get<double>());
        same("end_time", cp.time.end_time, j.at("end_time").get<double>());
        same("averaging_window[0]",
             t0,
             j.at("averaging_window").at(0).get<double>());
        same("averaging_window[1]",
             t1,
             j.at("averaging_window").at(1).get<double>());
        contact::RunSummary s;
        s.mu_global_mean        = j.at("mu_global_mean").get<double>();
        s.mu_contact_mean       = j.at("mu_contact_mean").get<double>();
        s.dominant_frequency_hz = j.at("dominant_frequency_hz").get<double>();
        s.stick_fraction        = j.at("stick_fraction").get<double>();
        s.slip_fraction         = j.at("slip_fraction").get<double>();
        s.separation_fraction   = j.at("separation_fraction").get<double>();
        s.M_stick_fraction = j.at("point_M").at("stick_fraction").get<double>();
        s.M_slip_fraction  = j.at("point_M").at("slip_fraction").get<double>();
        s.M_separation_fraction
          = j.at("point_M").at("separation_fraction").get<double>();
        s.wall_time_s = j.at("wall_time_s").get<double>();

        // mu_global column of friction.csv
        const std::string csv_file = join_path(dir, "friction.csv");
        std::vector<std::vector<double>> columns;
        if (!read_csv_columns(csv_file, {"time", "mu_global"}, columns))
          throw InputError("'Study/Reuse finished cases': " + csv_file
                           + " is missing or has no time and mu_global "
                             "columns. Delete that case's directory to run it "
                             "again.");
        const std::vector<double> &times = columns[0];
        std::vector<double>        mu;
        for (std::size_t k = 0; k < times.size(); ++k)
          if (times[k] >= t0 && times[k] <= t1)
            mu.push_back(columns[1][k]);
        const double spacing
          = times.size() > 1 ? times[1] - times[0] : cp.time.time_step;
        return case_statistics(mu, spacing, s);
      }
    } // namespace


    contact::ContactParameters
    StudyProblem::case_parameters(const StudyCase &c) const
    {
      using Type                   = contact::ContactMaterialParameters::Type;
      contact::ContactParameters p = base;
      p.loading.pressure           = parameters.pressures[c.pressure_index];
      switch (c.model)
        {
          case PinModel::homogeneous_matrix:
            p.material.type = Type::isotropic;
            p.material.isotropic
              = base.material.composite.given().at(base.material.pin_index);
            break;
          case PinModel::homogenized:
            set_homogenized_material(p, c.seed);
            break;
          case PinModel::meso:
            p.material.type = Type::morphology;
            p.morphology    = morphology_parameters(c.seed);
            break;
        }
      if (c.repeat > 0)
        {
          p.loading.velocity_perturbation = parameters.perturbation;
          p.loading.perturbation_seed     = c.repeat;
        }
      return p;
    }


    void
    StudyProblem::set_homogenized_material(contact::ContactParameters &p,
                                           const unsigned int seed) const
    {
      p.material.type = contact::ContactMaterialParameters::Type::anisotropic;
      if (parameters.homogenized_pin
          == StudyParameters::HomogenizedPin::each_morphology)
        {
          const unsigned int k             = seed - first_morphology();
          p.material.anisotropic_stiffness = morphology_C.at(k);
          p.material.anisotropic_c_z       = morphology_c_z.at(k);
          p.material.density               = morphology_density.at(k);
        }
      else
        {
          p.material.anisotropic_stiffness = homogenized_C;
          p.material.anisotropic_c_z       = homogenized_c_z;
          p.material.density               = homogenized_density;
        }
    }


    unsigned int
    StudyProblem::first_morphology() const
    {
      return whole_map ? 1 : parameters.first_seed;
    }


    std::string
    StudyProblem::morphology_name(const unsigned int seed) const
    {
      return (whole_map ? "window" : "seed") + std::to_string(seed);
    }


    void
    StudyProblem::cut_windows()
    {
      whole_map
        = std::make_unique<Morphology>(Morphology::create(base.morphology));
      const unsigned int wx      = parameters.window_size[0],
                         wy      = parameters.window_size[1];
      const unsigned int nx      = whole_map->n_pixels_x(),
                         ny      = whole_map->n_pixels_y();
      const unsigned int columns = nx / wx, rows = ny / wy;
      check_parameter(
        columns * rows >= parameters.n_morphologies,
        "Study/Window size",
        "windows that fit the map " + std::to_string(parameters.n_morphologies)
          + " times ('Study/Number of morphologies'), but the map of "
          + std::to_string(nx) + " x " + std::to_string(ny)
          + " pixels holds only " + std::to_string(columns * rows)
          + " windows of " + std::to_string(wx) + "x" + std::to_string(wy)
          + " side by side. Give smaller windows or fewer morphologies");
      window_origins.clear();
      for (unsigned int k = 0; k < parameters.n_morphologies; ++k)
        {
          // columns left to right, rows from the top; origins from the
          // bottom-left pixel, as Morphology counts them
          const unsigned int c = k % columns, r = k / columns;
          window_origins.push_back({{c * wx, ny - (r + 1) * wy}});
        }
    }


    MorphologyParameters
    StudyProblem::morphology_parameters(const unsigned int seed) const
    {
      MorphologyParameters m = base.morphology;
      if (!whole_map)
        {
          m.random_seed = seed;
          return m;
        }
      const auto grid = std::make_shared<GridFileMorphology>();
      grid->file   = join_path(join_path(context.output_directory, "windows"),
                             morphology_name(seed) + ".txt");
      m.source     = grid;
      m.n_pixels_x = parameters.window_size[0];
      m.n_pixels_y = parameters.window_size[1];
      m.width      = m.n_pixels_x * whole_map->pixel_width();
      m.height     = m.n_pixels_y * whole_map->pixel_height();
      return m;
    }


    void
    StudyProblem::write_windows() const
    {
      if (!whole_map
          || dealii::Utilities::MPI::this_mpi_process(context.mpi_communicator)
               != 0)
        return;
      const std::string  dir = join_path(context.output_directory, "windows");
      std::ostringstream csv;
      csv << "window,first_column,first_row_from_top,width_px,height_px";
      for (unsigned int k = 0; k < whole_map->n_phases(); ++k)
        csv << ",fraction_" << base.material.composite.names().at(k);
      csv << "\n" << std::setprecision(8);
      create_output_directory(dir);
      for (unsigned int k = 0; k < window_origins.size(); ++k)
        {
          const auto [i0, j0] = window_origins[k];
          const Morphology w  = whole_map->window(i0,
                                                 j0,
                                                 parameters.window_size[0],
                                                 parameters.window_size[1]);
          w.write_grid_file(
            join_path(dir, morphology_name(first_morphology() + k) + ".txt"));
          csv << first_morphology() + k << "," << i0 << ","
              << whole_map->n_pixels_y() - j0 - parameters.window_size[1] << ","
              << parameters.window_size[0] << "," << parameters.window_size[1];
          const std::vector<double> f = w.phase_fractions();
          for (unsigned int p = 0; p < whole_map->n_phases(); ++p)
            csv << "," << (p < f.size() ? f[p] : 0.);
          csv << "\n";
        }
      write_file_atomically(join_path(dir, "windows.csv"), csv.str());
    }


    void
    StudyProblem::run()
    {
      const auto         start = std::chrono::steady_clock::now();
      const MPI_Comm     world = context.mpi_communicator;
      const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(world);
      dealii::ConditionalOStream pcout(std::cout, rank == 0);
      const unsigned int         n_groups = n_case_groups();
      const unsigned int         color
        = std::min(rank / parameters.ranks_per_case, n_groups - 1);
      MPI_Comm group;
      MPI_Comm_split(world, color, rank, &group);
      const bool group_root
        = dealii::Utilities::MPI::this_mpi_process(group) == 0;

      pcout << "Study: " << study_cases.size() << " cases on " << n_groups
            << " group(s) of ranks; mesh h = " << base.geometry.mesh_size
            << " m for every model" << std::endl;

      // The study's own files; its cases and homogenization runs claim
      // their own directories (and a study that reuses finished cases
      // finds them in place).
      context.claim_output(OutputClaim::fresh, {"cases", "homogenization"});
      write_windows();
      MPI_Barrier(world);

      bool needs_homogenization = false;
      for (const PinModel m : parameters.models)
        needs_homogenization |= (m == PinModel::homogenized);
      if (needs_homogenization)
        homogenize(group, n_groups);

      std::vector<double> local(study_cases.size() * CaseResult::size, 0.);
      for (unsigned int i = 0; i < study_cases.size(); ++i)
        {
          if (i % n_groups != color)
            continue;
          const StudyCase &c  = study_cases[i];
          RunContext       cc = context;
          cc.mpi_communicator = group;
          cc.output_directory
            = join_path(join_path(context.output_directory, "cases"), c.name);
          cc.parameters_text = nullptr;
          if (group_root)
            std::cout << "Case " << i + 1 << "/" << study_cases.size() << ": "
                      << c.name << std::endl;
          const contact::ContactParameters cp = case_parameters(c);
          const double                     t0 = cp.output.average_start;
          const double t1 = cp.output.average_end < 0 ? cp.time.end_time
                                                      : cp.output.average_end;
          CaseResult   r;
          if (parameters.reuse_cases
              && file_exists(join_path(cc.output_directory, "summary.json")))
            {
              if (group_root)
                std::cout << "  reused: " << cc.output_directory << std::endl;
              r = read_finished_case(cc.output_directory, cp, t0, t1);
            }
          else
            {
              contact::ContactProblem problem(cp, cc);
              problem.run();
              // Blocking of mu_global over the averaging window.
              std::vector<double> mu;
              for (const contact::Sample &s : problem.samples())
                if (s.time >= t0 && s.time <= t1)
                  mu.push_back(s.mu_global);
              const auto  &series  = problem.samples();
              const double spacing = series.size() > 1
                                       ? series[1].time - series[0].time
                                       : cp.time.time_step;
              r = case_statistics(mu, spacing, problem.summary());
            }
          if (group_root)
            r.to(&local[i * CaseResult::size]);
        }
      std::vector<double> all(local.size());
      MPI_Allreduce(
        local.data(), all.data(), local.size(), MPI_DOUBLE, MPI_SUM, world);
      MPI_Comm_free(&group);

      std::vector<CaseResult> results(study_cases.size());
      for (unsigned int i = 0; i < study_cases.size(); ++i)
        results[i].from(&all[i * CaseResult::size]);
      const double wall_time = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - start)
                                 .count();
      if (rank == 0)
        write_tables(results, wall_time);
      MPI_Barrier(world);
    }


    namespace
    {
      const bool study_problem_registered = register_problem(
        {"study",
         "seed 001's Table 2 study: pressures x pin models (homogeneous "
         "matrix, homogenized, meso with N morphologies) x repeats, with "
         "error bars, tables and plots",
         &StudyProblem::declare_parameters,
         [](ParameterHandler &prm, const RunContext &context) {
           return std::unique_ptr<Problem>(new StudyProblem(prm, context));
         },
         {},
         &MorphologyMaterials::declare_material_sections});
    } // namespace
  }   // namespace study
} // namespace tribodyn
