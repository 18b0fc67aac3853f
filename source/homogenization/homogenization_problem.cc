#include <algorithm>
#include <chrono>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/morphology_source.h>
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/homogenization_problem.h>
#include <tribodyn/homogenization/postprocessor.h>
#include <tuple>

namespace tribodyn
{
  namespace homogenization
  {
    using dealii::ParameterHandler;

    ParameterBinding
    HomogenizationOutputParameters::binding()
    {
      ParameterBinding b("Output");
      b.add("Write fields",
            write_fields,
            "Write the displacement, stress and strain fields of every load "
            "case as VTU (fields_<BC>.pvd).");
      b.add("Write morphology",
            write_morphology,
            "Write the material map (morphology.vtu) and the morphology as a "
            "grid file (morphology.txt, readable by 'Generator = grid file').");
      PostprocessorRegistry<2>::add_selection(
        b,
        "Postprocessors",
        postprocessors,
        "outputs (the screen's table, files, summary keys)");
      return b;
    }


    void
    HomogenizationOutputParameters::declare_parameters(ParameterHandler &prm)
    {
      HomogenizationOutputParameters().binding().declare(prm);
    }


    void
    HomogenizationOutputParameters::parse_parameters(ParameterHandler &prm)
    {
      binding().parse(prm);
    }


    void
    HomogenizationParameters::declare_parameters(ParameterHandler &prm)
    {
      MorphologyParameters::declare_parameters(prm);
      MaterialsParameters::declare_parameters(prm);
      CellProblemParameters::declare_parameters(prm);
      HomogenizationOutputParameters::declare_parameters(prm);
    }


    void
    HomogenizationParameters::parse_parameters(ParameterHandler &prm)
    {
      morphology.parse_parameters(prm);
      materials.parse_parameters(prm);
      cell_problem.parse_parameters(prm);
      output.parse_parameters(prm);
    }


    HomogenizationParameters
    HomogenizationParameters::defaults()
    {
      ParameterHandler prm;
      declare_parameters(prm);
      HomogenizationParameters p;
      p.parse_parameters(prm);
      return p;
    }


    void
    HomogenizationProblem::declare_parameters(ParameterHandler &prm)
    {
      HomogenizationParameters::declare_parameters(prm);
    }


    namespace
    {
      HomogenizationParameters
      parsed(ParameterHandler &prm)
      {
        HomogenizationParameters p;
        p.parse_parameters(prm);
        return p;
      }
    } // namespace


    HomogenizationProblem::HomogenizationProblem(ParameterHandler &prm,
                                                 const RunContext &context)
        : HomogenizationProblem(parsed(prm), context)
    {
    }


    HomogenizationProblem::HomogenizationProblem(
      const HomogenizationParameters &parameters,
      const RunContext               &context)
        : context(context)
        , parameters(parameters)
    {
      // A map read from a file (image or grid) may hold other phases than
      // those named: refuse it now, with the other parameter errors.
      parameters.materials.check(parameters.morphology);
    }


    namespace
    {
      /// SUBC puts the traction Sigma n on the whole boundary, pores too:
      /// their ersatz material then deforms by about Sigma / E_pore and
      /// the apparent SUBC stiffness falls to the order of E_pore.
      void
      warn_about_boundary_pores(const Morphology        &morphology,
                                const std::vector<bool> &pores,
                                const std::vector<BoundaryCondition> &bcs,
                                dealii::ConditionalOStream           &pcout)
      {
        if (std::find(bcs.begin(), bcs.end(), BoundaryCondition::subc)
            == bcs.end())
          return;
        const unsigned int nx = morphology.n_pixels_x(),
                           ny = morphology.n_pixels_y();
        unsigned int n        = 0;
        for (unsigned int j = 0; j < ny; ++j)
          for (unsigned int i = 0; i < nx; ++i)
            if ((i == 0 || j == 0 || i + 1 == nx || j + 1 == ny)
                && morphology.pixel(i, j) < pores.size()
                && pores[morphology.pixel(i, j)])
              ++n;
        if (n > 0)
          pcout << "Warning: " << n
                << " pore pixels touch the boundary. SUBC loads them with "
                   "the traction Sigma n, which a pore cannot carry: the "
                   "SUBC apparent stiffness then reflects the ersatz pore "
                   "stiffness ('Materials/Pore stiffness ratio') and "
                   "tends to zero with it. Use KUBC and periodic, or crop "
                   "the image so that no pore cuts its edges."
                << std::endl;
      }


    } // namespace


    JsonValue
    HomogenizationProblem::phases_to_json(
      const std::vector<double> &fractions) const
    {
      const auto names = parameters.materials.names();
      const auto pores = parameters.materials.pores();
      const auto given = parameters.materials.given();
      const auto used  = parameters.materials.phases();
      JsonValue  list  = JsonValue::array();
      for (unsigned int k = 0; k < names.size(); ++k)
        {
          JsonValue p        = JsonValue::object();
          p["name"]          = names[k];
          p["material_id"]   = k;
          p["young_modulus"] = given[k].youngs_modulus;
          p["poisson_ratio"] = given[k].poisson_ratio;
          p["density"]       = given[k].density;
          p["pore"]          = static_cast<bool>(pores[k]);
          if (used[k].isotropic)
            p["cell_problem_young_modulus"] = used[k].isotropic->youngs_modulus;
          if (const auto &ti = used[k].transversely_isotropic)
            {
              // young_modulus and poisson_ratio above are E_T and nu_TT
              JsonValue t                 = JsonValue::object();
              t["axis"]                   = std::string(1, "xyz"[ti->axis]);
              t["E_L"]                    = ti->E_L;
              t["E_T"]                    = ti->E_T;
              t["nu_LT"]                  = ti->nu_LT;
              t["nu_TT"]                  = ti->nu_TT;
              t["G_LT"]                   = ti->G_LT;
              p["transversely_isotropic"] = t;
            }
          p["fraction"] = k < fractions.size() ? fractions[k] : 0.;
          list.push_back(p);
        }
      return list;
    }


    void
    HomogenizationProblem::run()
    {
      const auto     start = std::chrono::steady_clock::now();
      const MPI_Comm comm  = context.mpi_communicator;
      const bool     root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      dealii::ConditionalOStream pcout(std::cout, root);
      dealii::TimerOutput        timer(comm,
                                pcout,
                                dealii::TimerOutput::summary,
                                dealii::TimerOutput::wall_times);

      const Morphology morphology = Morphology::create(parameters.morphology);
      pcout << "Morphology: " << morphology.description() << std::endl;
      const std::vector<ElasticPhase> phases = parameters.materials.phases();
      parameters.materials.check(morphology,
                                 parameters.morphology.source->phases_set_by());

      CellProblem<2> cell_problem(
        comm, morphology, phases, parameters.cell_problem, timer);
      pcout << "Mesh: " << cell_problem.n_cells() << " cells, "
            << cell_problem.n_dofs() << " degrees of freedom, "
            << dealii::Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)"
            << std::endl;

      const std::vector<double> fractions = cell_problem.phase_fractions();
      warn_about_boundary_pores(morphology,
                                parameters.materials.pores(),
                                parameters.cell_problem.boundary_conditions,
                                pcout);
      const std::string &out_dir = context.output_directory;
      // Every check passed (morphology, mesh): the directory may be touched.
      context.claim_output();

      JsonValue summary            = summary_header("homogenization", comm);
      summary["morphology"]        = morphology.description();
      summary["volume_fraction"]   = fractions[material_id::heterogeneity];
      summary["n_heterogeneities"] = morphology.n_heterogeneities();
      summary["phases"]            = phases_to_json(fractions);
      summary["n_cells"]
        = static_cast<unsigned long long>(cell_problem.n_cells());
      summary["n_dofs"]
        = static_cast<unsigned long long>(cell_problem.n_dofs());

      // The outputs (source/homogenization/postprocessors/), in their
      // order: each adds its rows to the screen's table and its keys to
      // summary.json.
      std::vector<std::string> output_names;
      const auto               outputs = PostprocessorRegistry<2>::create_all(
        {parameters,
                       morphology,
                       cell_problem,
                       phases,
                       fractions,
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
          const CellProblemResult r = cell_problem.solve(bc, observer);
          for (const auto &o : outputs)
            o->solved(r, summary, table);
          pcout << to_string(bc) << ": solved 3 load cases (CG iterations "
                << r.load_cases[0].cg_iterations << ", "
                << r.load_cases[1].cg_iterations << ", "
                << r.load_cases[2].cg_iterations << ")" << std::endl;
        }
      for (const auto &o : outputs)
        o->finish(summary, table);
      pcout << table.str() << std::endl;

      const double wall_time = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - start)
                                 .count();
      summary["wall_time_s"] = wall_time;
      if (root)
        write_file_atomically(join_path(out_dir, "summary.json"),
                              summary.dump() + "\n");
      pcout << "Results written to " << out_dir
            << "/ (summary.json, effective_properties.csv"
            << (std::count(output_names.begin(), output_names.end(), "fields")
                    > 0
                  ? ", fields_*.pvd"
                  : "")
            << (parameters.output.write_morphology
                  ? ", morphology.vtu, morphology.txt"
                  : "")
            << ")" << std::endl;
    }

    namespace
    {
      const bool homogenization_problem_registered = register_problem(
        {"homogenization",
         "apparent and effective elastic properties of a 2D composite from "
         "its morphology (KUBC, SUBC and periodic cell problems)",
         &HomogenizationProblem::declare_parameters,
         [](ParameterHandler &prm, const RunContext &context) {
           return std::unique_ptr<Problem>(
             new HomogenizationProblem(prm, context));
         },
         {},
         &MorphologyMaterials::declare_material_sections});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
