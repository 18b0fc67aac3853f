// Postprocessor "effective properties" of 2D homogenization: for each
// boundary condition solved, the apparent stiffness, its engineering
// constants (axes L = x, T = y) and the CG iterations, then the Voigt and
// Reuss estimates of the phases: a row of each in effective_properties.csv
// and in the screen table, an entry of each in summary.json (under the
// name of the boundary condition; "bounds": "voigt", "reuss").
#include <iomanip>
#include <memory>
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/effective_properties.h>
#include <tribodyn/homogenization/homogenization_problem.h>
#include <tribodyn/homogenization/postprocessor.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
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


      class EffectiveProperties : public Postprocessor<2>
      {
      public:
        explicit EffectiveProperties(const PostprocessorInputs<2> &in)
            : in(in)
            , csv(join_path(in.output_directory, "effective_properties.csv"),
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
                  in.root)
        {
        }

        void
        started(std::ostream &table) override
        {
          table << "\nEffective properties (moduli in GPa), axes L = x, T = "
                   "y:\n"
                << std::left << std::setw(10) << "estimate" << std::right
                << std::setw(10) << "E_L" << std::setw(10) << "E_T"
                << std::setw(10) << "G_LT" << std::setw(10) << "nu_LT"
                << std::setw(10) << "nu_TT"
                << "\n";
        }

        void
        solved(const CellProblemResult &r,
               JsonValue               &summary,
               std::ostream            &table) override
        {
          JsonValue j          = to_json(r.properties);
          JsonValue iterations = JsonValue::array();
          for (const auto &lc : r.load_cases)
            iterations.push_back(lc.cg_iterations);
          j["cg_iterations"]                       = iterations;
          summary[to_string(r.boundary_condition)] = j;
          print_table_row(table,
                          to_string(r.boundary_condition),
                          r.properties.constants);
          csv.add_row({to_string(r.boundary_condition)},
                      csv_values(r.properties));
        }

        void
        finish(JsonValue &summary, std::ostream &table) const override
        {
          const ApparentProperties voigt
            = voigt_estimate(in.phases, in.fractions);
          const ApparentProperties reuss
            = reuss_estimate(in.phases, in.fractions);
          JsonValue bounds  = JsonValue::object();
          bounds["voigt"]   = to_json(voigt);
          bounds["reuss"]   = to_json(reuss);
          summary["bounds"] = bounds;
          print_table_row(table, "Voigt", voigt.constants);
          print_table_row(table, "Reuss", reuss.constants);
          csv.add_row({"Voigt"}, csv_values(voigt));
          csv.add_row({"Reuss"}, csv_values(reuss));
          csv.flush(true);
        }

      private:
        const PostprocessorInputs<2> in;
        /// (rows are added at the end too: finish() completes the file)
        mutable CsvWriter csv;
      };

      const bool effective_properties_registered
        = PostprocessorRegistry<2>::add(
          {"effective properties",
           10,
           [](const PostprocessorInputs<2> &in)
             -> std::unique_ptr<Postprocessor<2>> {
             return std::make_unique<EffectiveProperties>(in);
           }});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
