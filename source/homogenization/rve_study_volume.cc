// `set Problem = volume_rve` (issue #51 item 2): the RVE-size study of 3D
// voxel volumes (the study's procedure: rve_study.cc). A window is a box
// of voxels, cut from the volume of "Morphology" (a new realisation of a
// random generator per window, or the one volume of a raw file or image
// stack) or generated at the window's size; it is measured by the 3D cell
// problems of "Cell problem", on the voxel grid where it can (else on the
// mesh).
#include <tribodyn/core/errors.h>
#include <tribodyn/core/morphology_source.h>
#include <tribodyn/core/phase_materials.h>
#include <tribodyn/homogenization/rve_study.h>
#include <tribodyn/homogenization/volume_properties.h>
#include <tribodyn/homogenization/volume_source.h>
#include <tribodyn/homogenization/voxel_grid_solver.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      using dealii::ParameterHandler;
      using Source = RveStudyParameters::Source;

      class VolumeRveStudy : public RveStudy
      {
      public:
        static void
        declare_parameters(ParameterHandler &prm)
        {
          VolumeMorphologyParameters::declare_parameters(prm);
          MorphologyMaterials::declare_parameters(prm);
          VolumeCellProblemParameters::declare_parameters(prm);
          RveStudy::declare_parameters(prm);
        }

        VolumeRveStudy(ParameterHandler &prm, const RunContext &context)
            : RveStudy(context, 3)
        {
          morphology.parse_parameters(prm);
          materials.parse_parameters(prm);
          cell_problem.parse_parameters(prm);
          parameters.parse_parameters(prm, 3);

          random = morphology.source->uses_seed();
          if (parameters.source == Source::realisations)
            {
              check_parameter(random,
                              "RVE study/Source",
                              "'realisations' runs the volume generator at "
                              "each window size with a new seed, which "
                              "needs a random generator ('Morphology/"
                              "Generator = spheres' or 'fibres'). For a raw "
                              "file, an image stack or a laminate use "
                              "'Source = crops'.");
              element_size.fill(morphology.voxel_size);
            }
          else
            {
              // The volume the windows are cut from (for a random
              // generator, the first of the per-window realisations).
              VoxelVolume volume = VoxelVolume::create(morphology);
              for (unsigned int d = 0; d < 3; ++d)
                {
                  element_size[d] = volume.voxel_size(d);
                  map_size[d]     = volume.n_voxels(d);
                }
              if (!random)
                fixed_volume = std::make_unique<VoxelVolume>(std::move(volume));
            }
          plan_windows(morphology.random_seed);

          if (fixed_volume)
            check_phases_named(fixed_volume->n_phases(), "the volume");
          for (const auto &phase : materials.phases())
            stiffness.push_back(stiffness_3d(phase));
          if (parameters.source == Source::realisations)
            make_first_windows([this](const RveWindow &w) { make_window(w); });
          // A window size the grid cannot solve with 'Grid = voxel grid' is
          // refused now too.
          if (cell_problem.grid == VolumeGrid::voxel_grid)
            for (const RveWindow &w : windows)
              if (w.index == 0)
                {
                  std::string why;
                  VoxelGridSolver::chosen(cell_problem,
                                          make_window(w),
                                          false,
                                          why);
                }
        }

      protected:
        std::vector<std::string>
        phase_names() const override
        {
          return materials.names();
        }

        const std::vector<BoundaryCondition> &
        cell_boundary_conditions() const override
        {
          return cell_problem.boundary_conditions;
        }

        /// The isotropic projection's bulk and shear moduli (Kanit et al.'s
        /// properties), the Young and shear moduli along the axes and
        /// nu_xy.
        const std::vector<std::string> &
        constant_names() const override
        {
          static const std::vector<std::string> names
            = {"k", "mu", "E_x", "E_y", "E_z", "G_yz", "G_xz", "G_xy", "nu_xy"};
          return names;
        }

        std::vector<std::vector<double>>
        phase_constants() const override
        {
          std::vector<std::vector<double>> constant(constant_names().size());
          for (const VoigtMatrix6 &C : stiffness)
            {
              const auto values = constants(C);
              for (unsigned int c = 0; c < values.size(); ++c)
                constant[c].push_back(values[c]);
            }
          return constant;
        }

        std::vector<double>
        measure(const RveWindow     &w,
                const MPI_Comm       group,
                dealii::TimerOutput &timer) const override
        {
          const VoxelVolume   window = make_window(w);
          std::vector<double> values
            = fraction_values(window.phase_fractions(), window.n_phases());
          if (boundary_conditions().empty())
            return values;

          std::string                      why;
          std::unique_ptr<VoxelGridSolver> grid;
          std::unique_ptr<CellProblem<3>>  mesh;
          if (VoxelGridSolver::chosen(cell_problem, window, false, why))
            grid = std::make_unique<VoxelGridSolver>(group,
                                                     window,
                                                     stiffness,
                                                     cell_problem);
          else
            mesh = std::make_unique<CellProblem<3>>(
              group, window, stiffness, cell_problem, timer);
          for (const BoundaryCondition bc : boundary_conditions())
            {
              const CellResult<3> r = grid ? grid->solve(bc) : mesh->solve(bc);
              for (const double v : constants(r.properties.C))
                values.push_back(v);
            }
          return values;
        }

      private:
        /// The values of constant_names() of the stiffness @p C.
        static std::vector<double>
        constants(const VoigtMatrix6 &C)
        {
          const IsotropicModuli        m = isotropic_projection_3d(C);
          const EngineeringConstants3D e
            = volume_properties_from_stiffness(C).constants;
          return {
            m.k, m.mu, e.E_x, e.E_y, e.E_z, e.G_yz, e.G_xz, e.G_xy, e.nu_xy};
        }

        /// The voxels of window @p w.
        VoxelVolume
        make_window(const RveWindow &w) const
        {
          const auto &size = parameters.window_sizes[w.size_index];
          if (fixed_volume)
            return fixed_volume->window(w.first, size);
          VolumeMorphologyParameters p = morphology;
          p.random_seed                = w.morphology_seed;
          if (parameters.source == Source::crops)
            return VoxelVolume::create(p).window(w.first, size);
          p.n_voxels = size;
          return VoxelVolume::create(p);
        }

        VolumeMorphologyParameters  morphology;
        MorphologyMaterials         materials;
        VolumeCellProblemParameters cell_problem;
        /// The Voigt stiffness of each material id.
        std::vector<VoigtMatrix6> stiffness;
        /// The volume windows are cut from (crops of a volume without a
        /// seed).
        std::unique_ptr<VoxelVolume> fixed_volume;
      };


      const bool volume_rve_study_registered = register_problem(
        {"volume_rve",
         "RVE-size study of a 3D voxel volume (Kanit et al. 2003): apparent "
         "bulk, shear and Young's moduli of windows of growing size, their "
         "mean and variance per boundary condition, the fitted integral "
         "range and the RVE size for a relative error",
         &VolumeRveStudy::declare_parameters,
         [](ParameterHandler &prm, const RunContext &context) {
           return std::unique_ptr<Problem>(new VolumeRveStudy(prm, context));
         },
         {},
         &MorphologyMaterials::declare_material_sections});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
