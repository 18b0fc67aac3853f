// `set Problem = volume_homogenization` (issue #51): the cell problems of
// a 3D voxel volume and their report.
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
#include <tribodyn/homogenization/postprocessor.h>
#include <tribodyn/homogenization/volume_homogenization_problem.h>
#include <tribodyn/homogenization/voxel_grid_solver.h>
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
      PostprocessorRegistry<3>::add_selection(
        b,
        "Postprocessors",
        postprocessors,
        "outputs (the screen's table, files, summary keys)");
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
                      "Materials/Names",
                      "the volume has material ids up to "
                        + std::to_string(volume.n_phases() - 1) + " but "
                        + std::to_string(names.size())
                        + " materials are named. Name one material per "
                          "phase in 'Materials/Names' (material id k is the "
                          "k-th name), each with its subsection.");
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
      // The discretization: the voxel grid where it can (multigrid, a grid
      // that coarsens to a small one, no VTU fields), else the mesh.
      const auto &cell_parameters = parameters.cell_problem;
      std::string grid_refusal;
      const bool  on_grid = VoxelGridSolver::chosen(
        cell_parameters, volume, parameters.output.write_fields, grid_refusal);
      std::unique_ptr<CellProblem<3>>  mesh_problem;
      std::unique_ptr<VoxelGridSolver> grid_problem;
      if (on_grid)
        grid_problem = std::make_unique<VoxelGridSolver>(comm,
                                                         volume,
                                                         stiffness,
                                                         cell_parameters);
      else
        mesh_problem = std::make_unique<CellProblem<3>>(
          comm, volume, stiffness, cell_parameters, timer);
      const dealii::types::global_dof_index n_dofs
        = on_grid ? grid_problem->n_dofs() : mesh_problem->n_dofs();
      const std::size_t n_voxels = std::size_t(volume.n_voxels(0))
                                   * volume.n_voxels(1) * volume.n_voxels(2);
      pcout << (on_grid ? "Voxel grid: " : "Mesh: ") << volume.n_voxels(0)
            << " x " << volume.n_voxels(1) << " x " << volume.n_voxels(2)
            << " voxels, "
            << (on_grid
                  ? std::to_string(n_voxels) + " trilinear cells"
                  : std::to_string(mesh_problem->n_cells()) + " hexahedra (Q1)")
            << ", " << n_dofs << " degrees of freedom, "
            << dealii::Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)"
            << std::endl;
      if (on_grid)
        pcout << "  multigrid levels " << grid_problem->describe_levels()
              << " (no mesh: 'Cell problem/Grid')" << std::endl;
      else if (cell_parameters.grid == VolumeGrid::automatic)
        pcout << "  on the mesh: the voxel grid cannot solve this run ("
              << grid_refusal << ")" << std::endl;
      const std::vector<double> fractions
        = on_grid ? volume.phase_fractions() : mesh_problem->phase_fractions();
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
                     "stiffness ('Materials/Pore stiffness ratio') "
                     "and tends to zero with it. Use KUBC and periodic, or a "
                     "volume whose faces cut no pore."
                  << std::endl;
        }
      context.claim_output();
      const std::string &out_dir = context.output_directory;

      JsonValue summary      = summary_header("volume_homogenization", comm);
      summary["morphology"]  = volume.description();
      JsonValue geometry     = JsonValue::object();
      geometry["n_voxels"]   = json_array({double(volume.n_voxels(0)),
                                           double(volume.n_voxels(1)),
                                           double(volume.n_voxels(2))});
      geometry["voxel_size"] = json_array(
        {volume.voxel_size(0), volume.voxel_size(1), volume.voxel_size(2)});
      summary["n_voxels"]   = geometry["n_voxels"];
      summary["voxel_size"] = geometry["voxel_size"];
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
      summary["n_cells"] = static_cast<unsigned long long>(
        on_grid ? n_voxels : mesh_problem->n_cells());
      summary["n_dofs"] = static_cast<unsigned long long>(n_dofs);
      summary["grid"]   = on_grid ? "voxel grid" : "mesh";

      // The outputs (source/homogenization/postprocessors/volume_*.cc), in
      // their order: each adds its rows to the screen's table and its keys
      // to summary.json.
      std::vector<std::string> output_names;
      const auto               outputs = PostprocessorRegistry<3>::create_all(
        {parameters,
                       volume,
                       mesh_problem.get(),
                       n_dofs,
                       phases,
                       stiffness,
                       fractions,
                       geometry,
                       out_dir,
                       comm,
                       root},
        output_names,
        parameters.output.postprocessors);
      std::ostringstream table;
      for (const auto &o : outputs)
        o->started(table);

      const auto observer = load_case_observer(outputs);
      for (const BoundaryCondition bc :
           parameters.cell_problem.boundary_conditions)
        {
          std::vector<SlicePlane> planes;
          for (const auto &o : outputs)
            for (const SlicePlane &plane : o->slice_planes(bc))
              planes.push_back(plane);
          const CellResult<3> r = on_grid
                                    ? grid_problem->solve(bc, planes)
                                    : mesh_problem->solve(bc, observer, planes);
          for (const auto &o : outputs)
            o->solved(r, summary, table);
          pcout << to_string(bc) << ": solved 6 load cases in " << std::fixed
                << std::setprecision(2) << r.wall_time << " s (CG iterations";
          for (const auto &lc : r.load_cases)
            pcout << " " << lc.cg_iterations;
          pcout << "; CG " << r.cg_time() << " s, " << std::setprecision(1)
                << (r.cg_iterations() > 0
                      ? 1e9 * r.cg_time() / (double(n_dofs) * r.cg_iterations())
                      : 0.)
                << " ns per DoF per iteration)" << std::endl;
        }
      for (const auto &o : outputs)
        o->finish(summary, table);
      pcout << table.str() << std::endl;

      // Peak resident memory of the ranks, summed, over the DoFs.
      dealii::Utilities::System::MemoryStats stats;
      dealii::Utilities::System::get_memory_stats(stats);
      const double peak
        = dealii::Utilities::MPI::sum(1024. * stats.VmHWM, comm);
      summary["memory_peak_bytes"]    = peak;
      summary["memory_bytes_per_dof"] = peak / n_dofs;
      summary["wall_time_s"]          = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - start)
                                 .count();
      pcout << "Peak memory " << std::fixed << std::setprecision(1)
            << peak / 1048576. << " MiB (" << std::setprecision(0)
            << peak / n_dofs << " B per DoF)" << std::endl;
      if (root)
        write_file_atomically(join_path(out_dir, "summary.json"),
                              summary.dump() + "\n");
      const auto &output = parameters.output;
      pcout << "Results written to " << out_dir
            << "/ (summary.json, effective_properties.csv"
            << (output.write_morphology ? ", morphology.hdr, morphology.raw"
                                        : "")
            << (std::count(output_names.begin(), output_names.end(), "fields")
                    > 0
                  ? ", fields_*.pvd"
                  : "")
            << (output.write_slices ? ", slices.json" : "")
            << (output.write_slices && output.plot_script != "none"
                  ? ", slice_*.png, volume_slices.png"
                  : "")
            << ")" << std::endl;
      for (const auto &o : outputs)
        o->closed();
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
         },
         {},
         &MorphologyMaterials::declare_material_sections});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
