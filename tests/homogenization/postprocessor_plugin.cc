// A new homogenization output is one file (issue #52 item 2): this test
// adds a postprocessor the way a contributor would (a class and a
// registration line in this file, nothing else in tribodyn), runs the
// homogenization problem on a small random morphology with KUBC, SUBC and
// periodic conditions, and checks that the run calls the interface
// (include/tribodyn/homogenization/postprocessor.h) as it says:
//
// - started() once, after the output directory is claimed (its file is in
//   the directory beside summary.json, not moved away as a previous run's);
// - solved() once per boundary condition, in the order of `Cell
//   problem/Boundary conditions`, with the result the run reports: the
//   trace C11 + C22 it records equals that of summary.json's C under the
//   same name, to the last bit (both written by the same JSON writer);
// - finish() adds its key in the list's order: after "bounds" (the
//   effective properties, order 10) and before Huet's
//   "kubc_minus_subc_min_eigenvalue" (order 20), this plugin's order 15.
#include "../run_parameter_text.h"
#include "../test_utilities.h"

#include <algorithm>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/postprocessor.h>
#include <vector>

using namespace tribodyn::homogenization;

namespace
{
  unsigned int n_started = 0;

  class Traces : public Postprocessor<2>
  {
  public:
    explicit Traces(const PostprocessorInputs<2> &in)
        : directory(in.output_directory)
        , root(in.root)
    {
    }
    void
    started(std::ostream &) override
    {
      ++n_started;
      if (root)
        std::ofstream(tribodyn::join_path(directory, "plugin_started.txt"))
          << "started\n";
    }
    void
    solved(const CellProblemResult &r,
           tribodyn::JsonValue &,
           std::ostream &) override
    {
      names.push_back(to_string(r.boundary_condition));
      traces.push_back(r.properties.C[0][0] + r.properties.C[1][1]);
    }
    void
    finish(tribodyn::JsonValue &summary, std::ostream &) const override
    {
      tribodyn::JsonValue j = tribodyn::JsonValue::object();
      for (std::size_t k = 0; k < names.size(); ++k)
        j[names[k]] = traces[k];
      summary["plugin_traces"] = j;
    }

  private:
    std::string              directory;
    bool                     root;
    std::vector<std::string> names;
    std::vector<double>      traces;
  };

  const bool registered = PostprocessorRegistry<2>::add(
    {"traces", 15, [](const PostprocessorInputs<2> &in) {
       return std::make_unique<Traces>(in);
     }});

  const char *const prm = R"(
set Problem          = homogenization
set Output directory = output-homogenization-postprocessor-plugin
subsection Morphology
  set Generator                = random vertical
  set Width                    = 0.0028
  set Height                   = 0.0008
  set Pixels in x              = 28
  set Pixels in y              = 8
  set Volume fraction          = 0.1
  set Heterogeneity width      = 0.0001
  set Heterogeneity min height = 0.0002
  set Heterogeneity max height = 0.0006
end
subsection Cell problem
  set Boundary conditions = KUBC, SUBC, periodic
end
subsection Output
  set Write fields     = false
  set Write morphology = false
end
)";
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using tribodyn_test::check;
  (void)registered;
  // run twice: the second run moves the first one's files away, so the
  // plugin's file must be the second run's
  for (unsigned int run = 0; run < 2; ++run)
    {
      check(tribodyn_test::run_parameter_text(
              "homogenization_postprocessor_plugin.prm", prm)
              == 0,
            "run " + std::to_string(run + 1) + " succeeds");
    }
  check(n_started == 2,
        "started() once per run (" + std::to_string(n_started)
          + " calls in two runs)");
  const std::string dir = "output-homogenization-postprocessor-plugin/";
  check(std::ifstream(dir + "plugin_started.txt").good(),
        "the plugin's file is in the run's directory after the run");

  std::ifstream                in(dir + "summary.json");
  const nlohmann::ordered_json summary = nlohmann::ordered_json::parse(in);
  const auto                  &traces  = summary.at("plugin_traces");
  std::vector<std::string>     order;
  unsigned int                 exact = 0;
  for (auto it = traces.begin(); it != traces.end(); ++it)
    {
      order.push_back(it.key());
      const auto  &C     = summary.at(it.key()).at("C");
      const double trace = C[0][0].get<double>() + C[1][1].get<double>();
      exact += it.value().get<double>() == trace;
    }
  check(order == std::vector<std::string>{"KUBC", "SUBC", "periodic"}
          && exact == 3,
        "solved(): KUBC, SUBC, periodic in order; C11 + C22 equal to "
        "summary.json's in "
          + std::to_string(exact) + " of 3");
  std::vector<std::string> keys;
  for (auto it = summary.begin(); it != summary.end(); ++it)
    keys.push_back(it.key());
  const auto at = [&](const std::string &k) {
    return std::find(keys.begin(), keys.end(), k) - keys.begin();
  };
  check(at("bounds") + 1 == at("plugin_traces")
          && at("plugin_traces") + 1 == at("kubc_minus_subc_min_eigenvalue"),
        "finish(): 'plugin_traces' between 'bounds' and "
        "'kubc_minus_subc_min_eigenvalue' (positions "
          + std::to_string(at("bounds")) + ", "
          + std::to_string(at("plugin_traces")) + ", "
          + std::to_string(at("kubc_minus_subc_min_eigenvalue")) + ")");
  return tribodyn_test::result();
}
