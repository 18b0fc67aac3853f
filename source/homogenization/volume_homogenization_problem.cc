// `set Problem = volume_homogenization` (issue #51): the cell problems of
// a 3D voxel volume and their report.
#include "moduli_table.h"

#include <algorithm>
#include <chrono>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/volume_homogenization_problem.h>
#include <tuple>

namespace tribodyn
{
  namespace homogenization
  {
    using dealii::ParameterHandler;

    ParameterBinding
    VolumeOutputParameters::binding()
    {
      ParameterBinding b("Output");
      b.add("Write morphology",
            write_morphology,
            "Write the voxel volume as morphology.raw (one byte per voxel, "
            "its material id, x fastest) with its header morphology.hdr, "
            "readable by 'Morphology/Generator = raw file'.");
      b.add("Write fields",
            write_fields,
            "Write the displacement, the stress (with the von Mises stress) "
            "and the strain averaged over each voxel, and its material id, "
            "of every load case of every boundary condition as compressed "
            "binary VTU: fields_<BC>.pvd indexes fields_<BC>_<k>.pvtu, load "
            "case k = 0 to 5 (xx, yy, zz, yz, xz, xy), each made of one "
            "piece per MPI rank (fields_<BC>_<k>.<rank>.vtu). Off by "
            "default: the files take about 145 B per voxel and load case "
            "(36 MB per load case, 0.65 GB for the 18 load cases of a 64^3 "
            "volume), and writing them takes about as long as the solve and "
            "raises the peak memory by some 60 % (64^3 voxels, KUBC: 761 to "
            "1198 MiB).");
      b.add("Write slices",
            write_slices,
            "Write slices.json, the mid-x, mid-y and mid-z slices of the "
            "volume (material ids) and of the von Mises stress and sigma_xx "
            "of the first load case (xx) of KUBC (of the first boundary "
            "condition when KUBC is not solved), and draw them with 'Plot "
            "script' (slice_<axis>_phases.png, slice_z_von_mises.png, "
            "slice_z_stress_xx.png, "
            "volume_slices.png).");
      b.add("Plot script",
            plot_script,
            "Python script drawing the slices (slices.json) as PNG at the "
            "end: 'auto' looks for scripts/plot_volume next to the build "
            "directory (skipped when python3 or matplotlib is missing), "
            "'none' draws nothing, or a path.");
      return b;
    }


    void
    VolumeHomogenizationParameters::declare_parameters(ParameterHandler &prm)
    {
      VolumeMorphologyParameters::declare_parameters(prm);
      MorphologyMaterials::declare_parameters(prm);
      VolumeCellProblemParameters::declare_parameters(prm);
      VolumeOutputParameters().binding().declare(prm);
    }


    void
    VolumeHomogenizationParameters::parse_parameters(ParameterHandler &prm)
    {
      morphology.parse_parameters(prm);
      materials.parse_parameters(prm);
      cell_problem.parse_parameters(prm);
      output.binding().parse(prm);
    }


    VolumeHomogenizationProblem::VolumeHomogenizationProblem(
      const VolumeHomogenizationParameters &parameters,
      const RunContext                     &context)
        : context(context)
        , parameters(parameters)
    {
    }


    namespace
    {
      const char *const volume_constant_names[12] = {"E_x",
                                                     "E_y",
                                                     "E_z",
                                                     "nu_xy",
                                                     "nu_xz",
                                                     "nu_yx",
                                                     "nu_yz",
                                                     "nu_zx",
                                                     "nu_zy",
                                                     "G_yz",
                                                     "G_xz",
                                                     "G_xy"};

      std::vector<double>
      constant_values(const EngineeringConstants3D &c)
      {
        return {c.E_x,
                c.E_y,
                c.E_z,
                c.nu_xy,
                c.nu_xz,
                c.nu_yx,
                c.nu_yz,
                c.nu_zx,
                c.nu_zy,
                c.G_yz,
                c.G_xz,
                c.G_xy};
      }

      /// The CSV row: the twelve constants, then C_ij for i <= j.
      std::vector<double>
      volume_csv_values(const VolumeProperties &p)
      {
        std::vector<double> v = constant_values(p.constants);
        for (unsigned int i = 0; i < 6; ++i)
          for (unsigned int j = i; j < 6; ++j)
            v.push_back(p.C[i][j]);
        return v;
      }

      /// The keys n_voxels and voxel_size of @p volume in @p j.
      void
      add_geometry(JsonValue &j, const VoxelVolume &volume)
      {
        j["n_voxels"]   = json_array({double(volume.n_voxels(0)),
                                      double(volume.n_voxels(1)),
                                      double(volume.n_voxels(2))});
        j["voxel_size"] = json_array(
          {volume.voxel_size(0), volume.voxel_size(1), volume.voxel_size(2)});
      }

      void
      print_volume_row(std::ostream                 &out,
                       const std::string            &label,
                       const EngineeringConstants3D &c)
      {
        out << std::left << std::setw(10) << label << std::right << std::fixed
            << std::setprecision(3);
        for (const double E : {c.E_x, c.E_y, c.E_z, c.G_yz, c.G_xz, c.G_xy})
          out << std::setw(9) << E / 1e9;
        out << std::setprecision(4);
        for (const double nu : {c.nu_xy, c.nu_xz, c.nu_yz})
          out << std::setw(9) << nu;
        out << "\n";
      }
    } // namespace


    void
    VolumeHomogenizationProblem::run()
    {
      const auto     start = std::chrono::steady_clock::now();
      const MPI_Comm comm  = context.mpi_communicator;
      const bool     root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      dealii::ConditionalOStream pcout(std::cout, root);

      const VoxelVolume volume = VoxelVolume::create(parameters.morphology);
      pcout << "Morphology: " << volume.description() << std::endl;
      const auto &materials = parameters.materials;
      const auto  names     = materials.names();
      check_parameter(volume.n_phases() <= names.size(),
                      "Materials/Phases/Names",
                      "the volume has material ids up to "
                        + std::to_string(volume.n_phases() - 1) + " but "
                        + std::to_string(names.size())
                        + " phases are given. Name every phase in "
                          "'Materials/Phases' (Names, Young moduli, Poisson "
                          "ratios, Densities), phase k being material id k.");
      const std::vector<ElasticPhase> phases = materials.phases();
      std::vector<VoigtMatrix6>       stiffness;
      for (const auto &phase : phases)
        stiffness.push_back(stiffness_3d(phase));

      // (the timer after the checks of the input: a refusal prints only
      // its message)
      dealii::TimerOutput timer(comm,
                                pcout,
                                dealii::TimerOutput::summary,
                                dealii::TimerOutput::wall_times);
      CellProblem<3>      cell_problem(
        comm, volume, stiffness, parameters.cell_problem, timer);
      pcout << "Mesh: " << volume.n_voxels(0) << " x " << volume.n_voxels(1)
            << " x " << volume.n_voxels(2) << " voxels, "
            << cell_problem.n_cells() << " hexahedra (Q1), "
            << cell_problem.n_dofs() << " degrees of freedom, "
            << dealii::Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)"
            << std::endl;
      const std::vector<double> fractions = cell_problem.phase_fractions();
      // SUBC loads the faces with Sigma n, pores too: their ersatz material
      // then deforms by about Sigma / E_pore (as in 2D).
      if (std::find(parameters.cell_problem.boundary_conditions.begin(),
                    parameters.cell_problem.boundary_conditions.end(),
                    BoundaryCondition::subc)
          != parameters.cell_problem.boundary_conditions.end())
        {
          const auto         pores = materials.pores();
          const unsigned int nx = volume.n_voxels(0), ny = volume.n_voxels(1),
                             nz = volume.n_voxels(2);
          std::size_t n         = 0;
          for (unsigned int k = 0; k < nz; ++k)
            for (unsigned int j = 0; j < ny; ++j)
              for (unsigned int i = 0; i < nx; ++i)
                if ((i == 0 || j == 0 || k == 0 || i + 1 == nx || j + 1 == ny
                     || k + 1 == nz)
                    && volume.voxel(i, j, k) < pores.size()
                    && pores[volume.voxel(i, j, k)])
                  ++n;
          if (n > 0)
            pcout << "Warning: " << n
                  << " pore voxels touch the boundary. SUBC loads them with "
                     "the traction Sigma n, which a pore cannot carry: the "
                     "SUBC apparent stiffness then reflects the ersatz pore "
                     "stiffness ('Materials/Phases/Pore stiffness ratio') "
                     "and tends to zero with it. Use KUBC and periodic, or a "
                     "volume whose faces cut no pore."
                  << std::endl;
        }
      context.claim_output();
      const std::string &out_dir = context.output_directory;
      if (root && parameters.output.write_morphology)
        volume.write_raw(join_path(out_dir, "morphology.hdr"),
                         join_path(out_dir, "morphology.raw"));

      JsonValue summary     = summary_header("volume_homogenization", comm);
      summary["morphology"] = volume.description();
      add_geometry(summary, volume);
      {
        JsonValue  list  = JsonValue::array();
        const auto given = materials.given();
        const auto pores = materials.pores();
        for (unsigned int k = 0; k < names.size(); ++k)
          {
            JsonValue p        = JsonValue::object();
            p["name"]          = names[k];
            p["material_id"]   = k;
            p["young_modulus"] = given[k].youngs_modulus;
            p["poisson_ratio"] = given[k].poisson_ratio;
            p["pore"]          = static_cast<bool>(pores[k]);
            p["fraction"]      = k < fractions.size() ? fractions[k] : 0.;
            list.push_back(p);
          }
        summary["phases"] = list;
      }
      summary["n_cells"]
        = static_cast<unsigned long long>(cell_problem.n_cells());
      summary["n_dofs"]
        = static_cast<unsigned long long>(cell_problem.n_dofs());

      std::vector<std::string> columns = {"estimate"};
      for (const char *name : volume_constant_names)
        columns.push_back(name);
      for (unsigned int i = 0; i < 6; ++i)
        for (unsigned int j = i; j < 6; ++j)
          columns.push_back("C" + std::to_string(i + 1)
                            + std::to_string(j + 1));
      CsvWriter csv(join_path(out_dir, "effective_properties.csv"),
                    columns,
                    root);

      std::ostringstream table;
      table << "\nEffective properties (moduli in GPa), Voigt order xx, yy, "
               "zz, yz, xz, xy:\n"
            << std::left << std::setw(10) << "estimate" << std::right;
      for (const char *name : {"E_x",
                               "E_y",
                               "E_z",
                               "G_yz",
                               "G_xz",
                               "G_xy",
                               "nu_xy",
                               "nu_xz",
                               "nu_yz"})
        table << std::setw(9) << name;
      table << "\n";

      // The slices: of the first load case of KUBC (of the first condition
      // when KUBC is not solved), across the middle of each axis.
      const auto &conditions = parameters.cell_problem.boundary_conditions;
      const BoundaryCondition sliced_bc = std::find(conditions.begin(),
                                                    conditions.end(),
                                                    BoundaryCondition::kubc)
                                              != conditions.end()
                                            ? BoundaryCondition::kubc
                                            : conditions.front();
      std::vector<SlicePlane> planes;
      if (parameters.output.write_slices)
        for (const unsigned int axis : {2u, 0u, 1u})
          planes.push_back({axis, volume.n_voxels(axis) / 2});

      std::vector<CellResult<3>> results;
      for (const BoundaryCondition bc : conditions)
        {
          const CellResult<3> r = cell_problem.solve(
            bc,
            parameters.output.write_fields ? out_dir : std::string(),
            bc == sliced_bc ? planes : std::vector<SlicePlane>());
          if (bc == sliced_bc && parameters.output.write_slices)
            write_slices(volume, bc, r.slices);
          results.push_back(r);
          JsonValue j          = to_json(r.properties);
          JsonValue iterations = JsonValue::array();
          JsonValue cg_times   = JsonValue::array();
          JsonValue per_dof    = JsonValue::array();
          // time per DoF per CG iteration: of each solve (null when CG
          // took no iteration) and over the six
          const double n_dofs           = cell_problem.n_dofs();
          double       total_time       = 0;
          unsigned int total_iterations = 0;
          for (const auto &lc : r.load_cases)
            {
              iterations.push_back(lc.cg_iterations);
              cg_times.push_back(lc.cg_time);
              per_dof.push_back(lc.cg_iterations > 0 ? JsonValue(
                                  lc.cg_time / (n_dofs * lc.cg_iterations))
                                                     : JsonValue());
              total_time += lc.cg_time;
              total_iterations += lc.cg_iterations;
            }
          const double mean_per_dof
            = total_iterations > 0 ? total_time / (n_dofs * total_iterations)
                                   : 0.;
          j["cg_iterations"]                = iterations;
          j["cg_time_s"]                    = cg_times;
          j["time_per_dof_per_iteration_s"] = per_dof;
          j["mean_time_per_dof_per_iteration_s"]
            = total_iterations > 0 ? JsonValue(mean_per_dof) : JsonValue();
          j["wall_time_s"]       = r.wall_time;
          j["preconditioner"]    = r.multigrid ? "multigrid" : "AMG";
          summary[to_string(bc)] = j;
          print_volume_row(table, to_string(bc), r.properties.constants);
          csv.add_row({to_string(bc)}, volume_csv_values(r.properties));
          pcout << to_string(bc) << ": solved 6 load cases in " << std::fixed
                << std::setprecision(2) << r.wall_time << " s (CG iterations";
          for (const auto &lc : r.load_cases)
            pcout << " " << lc.cg_iterations;
          pcout << "; CG " << total_time << " s, " << std::setprecision(1)
                << 1e9 * mean_per_dof << " ns per DoF per iteration)"
                << std::endl;
        }

      const VolumeProperties voigt  = voigt_estimate_3d(stiffness, fractions);
      const VolumeProperties reuss  = reuss_estimate_3d(stiffness, fractions);
      JsonValue              bounds = JsonValue::object();
      bounds["voigt"]               = to_json(voigt);
      bounds["reuss"]               = to_json(reuss);
      print_volume_row(table, "Voigt", voigt.constants);
      print_volume_row(table, "Reuss", reuss.constants);
      csv.add_row({"Voigt"}, volume_csv_values(voigt));
      csv.add_row({"Reuss"}, volume_csv_values(reuss));

      // Huet's ordering: C^SUBC <= C^periodic <= C^KUBC in the sense of
      // positive semi-definite differences (to the solver's round-off).
      const auto find = [&](const BoundaryCondition bc) {
        for (const auto &r : results)
          if (r.boundary_condition == bc)
            return &r.properties;
        return static_cast<const VolumeProperties *>(nullptr);
      };
      JsonValue huet = JsonValue::object();
      table << "\nHuet's ordering (smallest eigenvalue of the difference, "
               "GPa):\n";
      const std::pair<BoundaryCondition, BoundaryCondition> pairs[3]
        = {{BoundaryCondition::kubc, BoundaryCondition::subc},
           {BoundaryCondition::kubc, BoundaryCondition::periodic},
           {BoundaryCondition::periodic, BoundaryCondition::subc}};
      for (const auto &[upper, lower] : pairs)
        if (find(upper) && find(lower))
          {
            const double e = min_eigenvalue6(find(upper)->C - find(lower)->C);
            const bool   holds = e >= -1e-8 * find(upper)->C.norm();
            const std::string key
              = to_string(upper) + "_minus_" + to_string(lower);
            huet[key + "_min_eigenvalue"] = e;
            huet[key + "_holds"]          = holds;
            table << "  C^" << to_string(upper) << " - C^" << to_string(lower)
                  << ": " << std::scientific << std::setprecision(3) << e / 1e9
                  << " (" << (holds ? "holds" : "VIOLATED") << ")\n";
          }
      summary["huet"] = huet;

      // Isotropic projections next to the Hashin-Shtrikman bounds (which
      // need isotropic phases and bound a statistically isotropic volume).
      bool                         isotropic = true;
      std::vector<IsotropicModuli> moduli;
      for (const auto &phase : phases)
        if (phase.isotropic)
          moduli.push_back(
            {phase.isotropic->bulk_modulus(), phase.isotropic->mu()});
        else
          isotropic = false;
      table << "\nIsotropic projections (GPa): k = (C11 + C22 + C33 + 2 (C12 "
               "+ C13 + C23))/9, mu = (C11 + C22 + C33 - C12 - C13 - C23 + 3 "
               "(C44 + C55 + C66))/15\n"
            << std::left << std::setw(10) << "estimate" << std::right
            << std::setw(10) << "k" << std::setw(10) << "mu" << std::setw(12)
            << "anisotropy\n";
      internal::write_result_rows(
        table, summary, results, "k", [](const VoigtMatrix6 &C) {
          const IsotropicModuli m = isotropic_projection_3d(C);
          return std::tuple(m.k, m.mu, anisotropy_3d(C));
        });
      JsonValue hs; // null unless every phase is isotropic
      if (isotropic)
        {
          const auto [lower, upper]
            = hashin_shtrikman_bounds_3d(moduli, fractions);
          internal::write_moduli_row(table, "HS upper", upper.k, upper.mu);
          internal::write_moduli_row(table, "HS lower", lower.k, lower.mu);
          hs             = JsonValue::object();
          hs["k_lower"]  = lower.k;
          hs["k_upper"]  = upper.k;
          hs["mu_lower"] = lower.mu;
          hs["mu_upper"] = upper.mu;
        }
      bounds["hashin_shtrikman"] = hs;
      summary["bounds"]          = bounds;
      pcout << table.str() << std::endl;

      // Peak resident memory of the ranks, summed, over the DoFs.
      dealii::Utilities::System::MemoryStats stats;
      dealii::Utilities::System::get_memory_stats(stats);
      const double peak
        = dealii::Utilities::MPI::sum(1024. * stats.VmHWM, comm);
      summary["memory_peak_bytes"]    = peak;
      summary["memory_bytes_per_dof"] = peak / cell_problem.n_dofs();
      summary["wall_time_s"]          = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - start)
                                 .count();
      pcout << "Peak memory " << std::fixed << std::setprecision(1)
            << peak / 1048576. << " MiB (" << std::setprecision(0)
            << peak / cell_problem.n_dofs() << " B per DoF)" << std::endl;
      if (root)
        {
          csv.flush(true);
          write_file_atomically(join_path(out_dir, "summary.json"),
                                summary.dump() + "\n");
        }
      const auto &output = parameters.output;
      pcout << "Results written to " << out_dir
            << "/ (summary.json, effective_properties.csv"
            << (output.write_morphology ? ", morphology.hdr, morphology.raw"
                                        : "")
            << (output.write_fields ? ", fields_*.pvd" : "")
            << (output.write_slices ? ", slices.json" : "")
            << (output.write_slices && output.plot_script != "none"
                  ? ", slice_*.png, volume_slices.png"
                  : "")
            << ")" << std::endl;
      if (root && output.write_slices)
        run_plot_script(output.plot_script,
                        "plot_volume",
                        "Output/Plot script",
                        out_dir);
    }


    void
    VolumeHomogenizationProblem::write_slices(
      const VoxelVolume             &volume,
      const BoundaryCondition        bc,
      const std::vector<FieldSlice> &slices) const
    {
      if (dealii::Utilities::MPI::this_mpi_process(context.mpi_communicator)
          != 0)
        return;
      const char *const axis_names[3] = {"x", "y", "z"};
      JsonValue         j             = JsonValue::object();
      add_geometry(j, volume);
      JsonValue names = JsonValue::array();
      for (const std::string &name : parameters.materials.names())
        names.push_back(name);
      j["phases"]             = names;
      j["boundary_condition"] = to_string(bc);
      j["load_case"]          = "xx";
      JsonValue list          = JsonValue::array();
      for (const FieldSlice &s : slices)
        {
          JsonValue o = JsonValue::object();
          o["axis"]   = axis_names[s.plane.axis];
          o["index"]  = s.plane.index;
          o["axes"]   = JsonValue::array();
          o["axes"].push_back(axis_names[s.axes[0]]);
          o["axes"].push_back(axis_names[s.axes[1]]);
          o["n"] = json_array({double(s.n[0]), double(s.n[1])});
          // values[a + n0 b], a along axes[0], b along axes[1]
          for (const std::string field :
               {"material_id", "von_mises", "stress_xx"})
            {
              const auto f = std::find(s.names.begin(), s.names.end(), field)
                             - s.names.begin();
              o[field] = json_array(s.values[f]);
            }
          list.push_back(o);
        }
      j["slices"] = list;
      write_file_atomically(join_path(context.output_directory, "slices.json"),
                            j.dump() + "\n");
    }


    namespace
    {
      const bool volume_homogenization_registered = register_problem(
        {"volume_homogenization",
         "apparent elastic properties of a 3D voxel volume (generated or a "
         "raw micro-CT volume): 6x6 stiffness and compliance from the KUBC, "
         "SUBC and periodic cell problems, with bounds",
         &VolumeHomogenizationParameters::declare_parameters,
         [](ParameterHandler &prm, const RunContext &context) {
           VolumeHomogenizationParameters p;
           p.parse_parameters(prm);
           return std::unique_ptr<Problem>(
             new VolumeHomogenizationProblem(p, context));
         }});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
