// A new mca output is one file: this test adds a postprocessor the way a
// contributor would (a class and a registration line, nothing else), runs
// tribodyn's mca problem on a small uniaxial scene and checks that the run
// loop honours the interface (include/tribodyn/mca/postprocessor.h):
//
// - its column sits in series.csv where its order key puts it (15: after
//   the energies' columns, 10, and before the boundary groups', 20);
// - after_step() is called once per step and record() once per sample, in
//   step with the time column: the steps it counted equal time / dt at every
//   sample, exactly (an integer);
// - finish() writes its summary keys: steps = n_steps, samples = the rows
//   of series.csv.
#include "../run_parameter_text.h"
#include "../test_utilities.h"

#include <deal.II/base/mpi.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tribodyn/mca/postprocessor.h>

using namespace tribodyn::mca;

namespace
{
  class StepCounter : public Postprocessor
  {
  public:
    std::vector<std::string>
    series_columns() const override
    {
      return {"plugin_steps"};
    }
    void
    after_step() override
    {
      ++steps;
    }
    void
    record(const SeriesSample &, std::vector<double> &row) override
    {
      row.push_back(steps);
      ++samples;
    }
    void
    finish(tribodyn::JsonValue &summary, std::ostream &) const override
    {
      summary["plugin_steps"]   = steps;
      summary["plugin_samples"] = samples;
    }

  private:
    unsigned long steps = 0, samples = 0;
  };

  const bool registered = PostprocessorRegistry::add(
    {"step counter", 15, [](const PostprocessorInputs &) {
       return std::make_unique<StepCounter>();
     }});

  const char *scene = R"(
set Problem          = mca
set Output directory = output-postprocessor-plugin
subsection Geometry
  set Automaton size = 7.5e-9
  set Domain lower   = 0, 0, -1e-8
  set Domain upper   = 3.18198e-8, 3.18198e-8, 1.1607e-7
  set Bodies         = 0 0 0 3.18198e-8 3.18198e-8 1.06066e-7 steel
end
subsection Boundary conditions
  set Groups    = top velocity -1 -1 1.01e-7 1 1 1 * * -0.73; \
                  bottom velocity -1 -1 -1 1 1 5e-9 * * 0.73
  set Ramp time = 1e-10
end
subsection Time
  set End time       = 2e-10
  set Courant factor = 0.2
end
subsection Output
  set Series interval = 5e-12
end
subsection Analysis
  set Type          = uniaxial
  set Axis          = z
  set Loaded group  = top
  set Support group = bottom
end
)";
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using tribodyn_test::check;
  (void)registered;
  check(tribodyn_test::run_parameter_text("postprocessor_plugin.prm", scene)
          == 0,
        "the run succeeds");

  std::ifstream csv("output-postprocessor-plugin/series.csv");
  std::string   line;
  std::getline(csv, line);
  std::vector<std::string> header;
  {
    std::istringstream s(line);
    for (std::string c; std::getline(s, c, ',');)
      header.push_back(c);
  }
  const auto column = [&](const std::string &c) {
    for (std::size_t k = 0; k < header.size(); ++k)
      if (header[k] == c)
        return int(k);
    return -1;
  };
  const int mine = column("plugin_steps");
  // (the energies' last column: the ledger's last term)
  const std::string last_energy = energy_ledger.back().name;
  check(mine >= 0 && mine == column(last_energy) + 1
          && column("top_fx") == mine + 1,
        "series.csv: plugin_steps (order 15) between " + last_energy
          + " (energies, 10) and top_fx (boundary groups, 20); at column "
          + std::to_string(mine));

  nlohmann::json summary;
  std::ifstream("output-postprocessor-plugin/summary.json") >> summary;
  const double dt   = summary["dt"].get<double>();
  unsigned     rows = 0, misaligned = 0;
  while (std::getline(csv, line) && mine >= 0)
    {
      std::vector<double> values;
      std::istringstream  s(line);
      for (std::string c; std::getline(s, c, ',');)
        values.push_back(std::stod(c));
      const double steps = std::round(values[0] / dt);
      if (values[mine] != steps)
        ++misaligned;
      ++rows;
    }
  check(rows > 10 && misaligned == 0,
        "after_step() once per step, record() in step with the time column: "
          + std::to_string(misaligned) + " of " + std::to_string(rows)
          + " samples differ from time / dt");
  check(summary["plugin_steps"].get<unsigned long>()
          == summary["n_steps"].get<unsigned long>(),
        "finish(): plugin_steps " + summary["plugin_steps"].dump()
          + " = n_steps " + summary["n_steps"].dump());
  check(summary["plugin_samples"].get<unsigned>() == rows,
        "finish(): plugin_samples " + summary["plugin_samples"].dump()
          + " = rows of series.csv " + std::to_string(rows));
  return tribodyn_test::result();
}
