#include <chrono>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/version.h>
#include <tribodyn/homogenization/homogenization_problem.h>

namespace tribodyn
{
  namespace homogenization
  {
    using dealii::ParameterHandler;

    void
    MaterialsParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Materials");
      TwoPhaseMaterials::declare_parameters(prm);
      prm.leave_subsection();
    }


    void
    MaterialsParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Materials");
      TwoPhaseMaterials::parse_parameters(prm, "Materials");
      prm.leave_subsection();
    }


    void
    HomogenizationOutputParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      {
        prm.declare_entry("Write fields",
                          "true",
                          dealii::Patterns::Bool(),
                          "Write the displacement, stress and strain fields "
                          "of every load case as VTU (fields_<BC>.pvd).");
        prm.declare_entry("Write morphology",
                          "true",
                          dealii::Patterns::Bool(),
                          "Write the material map (morphology.vtu) and the "
                          "morphology as a grid file (morphology.txt, "
                          "readable by 'Generator = grid file').");
      }
      prm.leave_subsection();
    }


    void
    HomogenizationOutputParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      {
        write_fields     = prm.get_bool("Write fields");
        write_morphology = prm.get_bool("Write morphology");
      }
      prm.leave_subsection();
    }


    void
    HomogenizationProblem::declare_parameters(ParameterHandler &prm)
    {
      MorphologyParameters::declare_parameters(prm);
      MaterialsParameters::declare_parameters(prm);
      CellProblemParameters::declare_parameters(prm);
      HomogenizationOutputParameters::declare_parameters(prm);
    }


    HomogenizationProblem::HomogenizationProblem(ParameterHandler &prm,
                                                 const RunContext &context)
        : context(context)
    {
      morphology_parameters.parse_parameters(prm);
      materials.parse_parameters(prm);
      cell_problem_parameters.parse_parameters(prm);
      output_parameters.parse_parameters(prm);
    }


    namespace
    {
      void
      print_table_row(std::ostream               &out,
                      const std::string          &label,
                      const EngineeringConstants &c)
      {
        out << std::left << std::setw(10) << label << std::right << std::fixed
            << std::setprecision(3) << std::setw(10) << c.E_L / 1e9
            << std::setw(10) << c.E_T / 1e9 << std::setw(10) << c.G_LT / 1e9
            << std::setprecision(4) << std::setw(10) << c.nu_LT << std::setw(10)
            << c.nu_TT << "\n";
      }


      std::vector<double>
      csv_values(const ApparentProperties &p)
      {
        const auto         &c = p.constants;
        std::vector<double> v = {c.E_L, c.E_T, c.G_LT, c.nu_LT, c.nu_TT};
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            v.push_back(p.C[i][j]);
        v.push_back(p.c_z[0]);
        v.push_back(p.c_z[1]);
        return v;
      }
    } // namespace


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

      const Morphology morphology = Morphology::create(morphology_parameters);
      pcout << "Morphology: " << morphology.description() << std::endl;
      const std::vector<IsotropicElasticMaterial> phases = materials.phases();

      CellProblem cell_problem(
        comm, morphology, phases, cell_problem_parameters, timer);
      pcout << "Mesh: " << cell_problem.n_cells() << " cells, "
            << cell_problem.n_dofs() << " degrees of freedom, "
            << dealii::Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)"
            << std::endl;

      const std::vector<double> fractions = cell_problem.phase_fractions();
      const std::string        &out_dir   = context.output_directory;
      // Every check passed (morphology, mesh): the directory may be touched.
      context.claim_output();
      if (output_parameters.write_morphology)
        {
          cell_problem.write_material_map(out_dir);
          if (root)
            morphology.write_grid_file(join_path(out_dir, "morphology.txt"));
        }

      JsonValue summary           = JsonValue::object();
      summary["problem"]          = "homogenization";
      summary["tribodyn_version"] = version_string;
      summary["n_mpi_ranks"] = dealii::Utilities::MPI::n_mpi_processes(comm);
      summary["morphology"]  = morphology.description();
      summary["volume_fraction"]   = fractions[material_id::heterogeneity];
      summary["n_heterogeneities"] = morphology.n_heterogeneities();
      summary["n_cells"]
        = static_cast<unsigned long long>(cell_problem.n_cells());
      summary["n_dofs"]
        = static_cast<unsigned long long>(cell_problem.n_dofs());

      CsvWriter csv(join_path(out_dir, "effective_properties.csv"),
                    {"estimate",
                     "E_L",
                     "E_T",
                     "G_LT",
                     "nu_LT",
                     "nu_TT",
                     "C11",
                     "C12",
                     "C16",
                     "C21",
                     "C22",
                     "C26",
                     "C61",
                     "C62",
                     "C66",
                     "C13",
                     "C23"},
                    root);

      std::ostringstream table;
      table << "\nEffective properties (moduli in GPa), axes L = x, T = y:\n"
            << std::left << std::setw(10) << "estimate" << std::right
            << std::setw(10) << "E_L" << std::setw(10) << "E_T" << std::setw(10)
            << "G_LT" << std::setw(10) << "nu_LT" << std::setw(10) << "nu_TT"
            << "\n";

      std::vector<CellProblemResult> results;
      for (const BoundaryCondition bc :
           cell_problem_parameters.boundary_conditions)
        {
          const CellProblemResult r = cell_problem.solve(
            bc, output_parameters.write_fields ? out_dir : std::string());
          results.push_back(r);
          JsonValue j          = to_json(r.properties);
          JsonValue iterations = JsonValue::array();
          for (const auto &lc : r.load_cases)
            iterations.push_back(lc.cg_iterations);
          j["cg_iterations"]     = iterations;
          summary[to_string(bc)] = j;
          print_table_row(table, to_string(bc), r.properties.constants);
          csv.add_row({to_string(bc)}, csv_values(r.properties));
          pcout << to_string(bc) << ": solved 3 load cases (CG iterations "
                << r.load_cases[0].cg_iterations << ", "
                << r.load_cases[1].cg_iterations << ", "
                << r.load_cases[2].cg_iterations << ")" << std::endl;
        }

      const ApparentProperties voigt  = voigt_estimate(phases, fractions);
      const ApparentProperties reuss  = reuss_estimate(phases, fractions);
      JsonValue                bounds = JsonValue::object();
      bounds["voigt"]                 = to_json(voigt);
      bounds["reuss"]                 = to_json(reuss);
      summary["bounds"]               = bounds;
      print_table_row(table, "Voigt", voigt.constants);
      print_table_row(table, "Reuss", reuss.constants);
      csv.add_row({"Voigt"}, csv_values(voigt));
      csv.add_row({"Reuss"}, csv_values(reuss));

      // Huet's ordering of the apparent stiffnesses: C^K - (S^S)^-1 >= 0.
      const CellProblemResult *kubc = nullptr, *subc = nullptr;
      for (const auto &r : results)
        {
          if (r.boundary_condition == BoundaryCondition::kubc)
            kubc = &r;
          if (r.boundary_condition == BoundaryCondition::subc)
            subc = &r;
        }
      if (kubc && subc)
        {
          const double min_eigenvalue = min_eigenvalue_of_symmetric_part(
            kubc->properties.C - subc->properties.C);
          summary["kubc_minus_subc_min_eigenvalue"] = min_eigenvalue;
          table << "Huet ordering C^KUBC - C^SUBC >= 0: smallest eigenvalue "
                << std::scientific << std::setprecision(3)
                << min_eigenvalue / 1e9 << " GPa ("
                << (min_eigenvalue >= -1e-8 * kubc->properties.C.norm()
                      ? "holds"
                      : "VIOLATED")
                << ")\n";
        }
      pcout << table.str() << std::endl;

      const double wall_time = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - start)
                                 .count();
      summary["wall_time_s"] = wall_time;
      if (root)
        {
          csv.flush(true);
          write_file_atomically(join_path(out_dir, "summary.json"),
                                summary.dump() + "\n");
        }
      pcout << "Results written to " << out_dir
            << "/ (summary.json, effective_properties.csv"
            << (output_parameters.write_fields ? ", fields_*.pvd" : "")
            << (output_parameters.write_morphology
                  ? ", morphology.vtu, morphology.txt"
                  : "")
            << ")" << std::endl;
    }

    namespace
    {
      const bool registered = register_problem(
        {"homogenization",
         "apparent and effective elastic properties of a 2D composite from "
         "its morphology (KUBC, SUBC and periodic cell problems)",
         &HomogenizationProblem::declare_parameters,
         [](ParameterHandler &prm, const RunContext &context) {
           return std::unique_ptr<Problem>(
             new HomogenizationProblem(prm, context));
         }});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
