// `set Problem = rve`: the RVE-size study of 2D morphologies (the study's
// procedure: rve_study.cc). A window is a map of pixels, cut from the
// morphology of "Morphology" or generated at the window's size; it is
// measured by the plane-strain cell problems of "Cell problem".
#include <tribodyn/core/errors.h>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/morphology_source.h>
#include <tribodyn/homogenization/homogenization_problem.h>
#include <tribodyn/homogenization/rve_study.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      using dealii::ParameterHandler;
      using Source = RveStudyParameters::Source;

      class PlaneRveStudy : public RveStudy
      {
      public:
        static void
        declare_parameters(ParameterHandler &prm)
        {
          MorphologyParameters::declare_parameters(prm);
          MaterialsParameters::declare_parameters(prm);
          CellProblemParameters::declare_parameters(prm);
          RveStudy::declare_parameters(prm);
        }

        PlaneRveStudy(ParameterHandler &prm, const RunContext &context)
            : RveStudy(context, 2)
        {
          morphology_parameters.parse_parameters(prm);
          materials.parse_parameters(prm);
          cell_problem_parameters.parse_parameters(prm);
          parameters.parse_parameters(prm, 2);

          random = morphology_parameters.source->uses_seed();
          if (parameters.source == Source::realisations)
            {
              check_parameter(random,
                              "RVE study/Source",
                              "'realisations' runs the morphology generator "
                              "at each window size with a new seed, which "
                              "needs a random generator ('Morphology/Generator "
                              "= random vertical'). For an image, a grid file "
                              "or a laminate use 'Source = crops'.");
              element_size = {
                {morphology_parameters.width / morphology_parameters.n_pixels_x,
                 morphology_parameters.height
                   / morphology_parameters.n_pixels_y,
                 1.}};
            }
          else
            {
              // The map the windows are cut from (for a random generator,
              // the first of the per-window realisations: same size).
              const Morphology map = Morphology::create(morphology_parameters);
              element_size = {{map.pixel_width(), map.pixel_height(), 1.}};
              map_size     = {{map.n_pixels_x(), map.n_pixels_y(), 1}};
              if (!random)
                fixed_map = std::make_unique<Morphology>(map);
            }
          plan_windows(morphology_parameters.random_seed);

          // Every phase of the maps has a name and constants.
          if (fixed_map)
            check_phases_named(fixed_map->n_phases(), "the morphology");
          if (parameters.source == Source::realisations)
            make_first_windows([this](const RveWindow &w) { make_window(w); });
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
          return cell_problem_parameters.boundary_conditions;
        }

        const std::vector<std::string> &
        constant_names() const override
        {
          static const std::vector<std::string> names
            = {"E_L", "E_T", "G_LT", "nu_LT", "nu_TT"};
          return names;
        }

        std::vector<std::vector<double>>
        phase_constants() const override
        {
          // each constant of each phase, as the cell problems' constants
          // are read (E_L, E_T, G_LT, nu_LT, nu_TT: E, E, G, nu, nu when
          // isotropic)
          std::vector<std::vector<double>> constant(5);
          for (const auto &p : materials.phases())
            {
              const EngineeringConstants c
                = properties_from_stiffness(p.C, p.c_z).constants;
              constant[0].push_back(c.E_L);
              constant[1].push_back(c.E_T);
              constant[2].push_back(c.G_LT);
              constant[3].push_back(c.nu_LT);
              constant[4].push_back(c.nu_TT);
            }
          return constant;
        }

        std::vector<double>
        measure(const RveWindow     &w,
                const MPI_Comm       group,
                dealii::TimerOutput &timer) const override
        {
          const Morphology    window = make_window(w);
          std::vector<double> values
            = fraction_values(window.phase_fractions(), window.n_phases());
          if (boundary_conditions().empty())
            return values;
          const auto     phases = materials.phases();
          CellProblem<2> cell(
            group, window, phases, cell_problem_parameters, timer);
          for (const BoundaryCondition bc : boundary_conditions())
            {
              const EngineeringConstants c
                = cell.solve(bc).properties.constants;
              for (const double v : {c.E_L, c.E_T, c.G_LT, c.nu_LT, c.nu_TT})
                values.push_back(v);
            }
          return values;
        }

      private:
        /// The material map of window @p w.
        Morphology
        make_window(const RveWindow &w) const
        {
          const auto &size = parameters.window_sizes[w.size_index];
          if (fixed_map)
            return fixed_map->window(w.first[0], w.first[1], size[0], size[1]);
          MorphologyParameters p = morphology_parameters;
          p.random_seed          = w.morphology_seed;
          if (parameters.source == Source::crops)
            return Morphology::create(p).window(w.first[0],
                                                w.first[1],
                                                size[0],
                                                size[1]);
          p.n_pixels_x = size[0];
          p.n_pixels_y = size[1];
          p.width      = size[0] * element_size[0];
          p.height     = size[1] * element_size[1];
          return Morphology::create(p);
        }

        MorphologyParameters  morphology_parameters;
        MaterialsParameters   materials;
        CellProblemParameters cell_problem_parameters;
        /// The map windows are cut from (crops of a map without a seed).
        std::unique_ptr<Morphology> fixed_map;
      };


      const bool rve_study_registered = register_problem(
        {"rve",
         "RVE-size study (Kanit et al. 2003): apparent constants of windows "
         "of growing size, their mean and variance per boundary condition, "
         "the fitted integral range and the RVE size for a relative error",
         &PlaneRveStudy::declare_parameters,
         [](ParameterHandler &prm, const RunContext &context) {
           return std::unique_ptr<Problem>(new PlaneRveStudy(prm, context));
         },
         {},
         &MorphologyMaterials::declare_material_sections});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
