// A new contact output is one file: this test adds a postprocessor the way
// a contributor would (a class and a registration line, nothing else), runs
// tribodyn's contact problem in two legs (10 us with a checkpoint, then
// resumed to 20 us) and checks that the run loop honours the interface
// (include/tribodyn/contact/postprocessor.h):
//
// - sample() once per sample, in step with friction.csv: the plugin's file
//   has the same times, row for row, over both legs;
// - after_step() once per step, before the step's sample (the order of the
//   common time loop, core/time_loop.h): the steps counted at each sample
//   equal time / dt + 1 exactly (a sample of step n has the time t_n and
//   comes after that step), across the restart (save()/load() carry the
//   count: without them the second leg would count from 0);
// - open() is told whether the run resumes; close() ends each leg;
// - finish() (core/postprocessor.h) adds its keys to summary.json after
//   the run's own: the steps of the whole run, equal to the end time / dt
//   exactly, the last key before the wall time;
// - a sampled figure of its own is one file too: the plugin sums the
//   contact nodes' normal multipliers from the solver's public state
//   (ContactSolver::contact_node_states(), its own reduction over the ranks) at
//   each sample, and its column equals friction.csv's
//   contact_normal_force, which the solver computes, in every row (as
//   written: the same writer, the same digits).
#include "../run_parameter_text.h"
#include "../test_utilities.h"

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/contact/postprocessor.h>
#include <tribodyn/core/output.h>

using namespace tribodyn::contact;

namespace
{
  unsigned int opened_resumed = 0, closed = 0;

  class StepCounter : public Postprocessor
  {
  public:
    explicit StepCounter(const PostprocessorInputs &in)
        : path(tribodyn::join_path(in.directory, "plugin_steps.csv"))
        , root(in.root)
        , solver(in.solver)
        , comm(in.comm)
    {
    }
    void
    open(const bool resumed) override
    {
      opened_resumed += resumed;
      const std::vector<std::string> columns{"time",
                                             "steps",
                                             "contact_normal_force"};
      csv = resumed
              ? std::make_unique<tribodyn::CsvWriter>(path, columns, root, rows)
              : std::make_unique<tribodyn::CsvWriter>(path, columns, root);
    }
    void
    sample(const Sample &s) override
    {
      double local = 0, normal = 0;
      for (const ContactNode &node : solver.contact_node_states())
        local += node.lambda_n;
      MPI_Allreduce(&local, &normal, 1, MPI_DOUBLE, MPI_SUM, comm);
      csv->add_row({s.time, double(steps), normal});
    }
    void
    after_step(const double) override
    {
      ++steps;
    }
    void
    flush(const bool complete) override
    {
      csv->flush(complete);
    }
    void
    close() override
    {
      ++closed;
    }
    void
    finish(tribodyn::JsonValue &summary, std::ostream &) const override
    {
      summary["plugin_steps"] = steps;
    }
    void
    save(boost::archive::binary_oarchive &ar) const override
    {
      const std::size_t n = csv->n_rows();
      ar << steps << n;
    }
    void
    load(boost::archive::binary_iarchive &ar) override
    {
      ar >> steps >> rows;
    }

  private:
    std::string                          path;
    bool                                 root;
    const ContactSolver                 &solver;
    MPI_Comm                             comm;
    std::unique_ptr<tribodyn::CsvWriter> csv;
    unsigned long                        steps = 0;
    std::size_t                          rows  = 0;
  };

  const bool registered = PostprocessorRegistry::add(
    {"step counter", 35, [](const PostprocessorInputs &in) {
       return std::make_unique<StepCounter>(in);
     }});

  std::string
  leg(const double end_time, const bool resume)
  {
    return std::string(R"(
set Problem = contact
set Output directory = output-contact-postprocessor-plugin
set Progress interval = 1000
subsection Geometry
  set Width = 4e-3
  set Height = 2e-3
  set Mesh size = 0.25e-3
end
subsection Time
  set Time step = 5e-9
  set End time = )")
           + tribodyn::format_number(end_time) + R"(
end
subsection Output
  set Sample interval = 7
  set Averaging start time = 0
end
subsection Checkpoint
  set Interval = 1
  set Resume = )"
           + (resume ? "true" : "false") + "\nend\n";
  }

  std::vector<std::vector<double>>
  read_csv(const std::string &path)
  {
    std::ifstream                    in(path);
    std::vector<std::vector<double>> rows;
    std::string                      line;
    std::getline(in, line);
    while (std::getline(in, line))
      {
        std::vector<double> values;
        std::istringstream  s(line);
        for (std::string c; std::getline(s, c, ',');)
          values.push_back(std::stod(c));
        rows.push_back(values);
      }
    return rows;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using tribodyn_test::check;
  (void)registered;
  for (const bool resume : {false, true})
    {
      check(
        tribodyn_test::run_parameter_text("contact_postprocessor_plugin.prm",
                                          leg(resume ? 20e-6 : 10e-6, resume))
          == 0,
        std::string("leg ") + (resume ? "2 (resumed)" : "1") + " succeeds");
    }
  check(opened_resumed == 1 && closed == 2,
        "open() told of the resume once, close() at the end of both legs");

  const std::string dir        = "output-contact-postprocessor-plugin/";
  const auto        friction   = read_csv(dir + "friction.csv");
  const auto        mine       = read_csv(dir + "plugin_steps.csv");
  const double      dt         = 5e-9;
  unsigned int      misaligned = 0;
  // every sample, the end-of-run one included, comes after its step's
  // after_step(): the count is that step's number plus one
  const std::size_t n       = std::min(friction.size(), mine.size());
  unsigned int      unequal = 0;
  for (std::size_t k = 0; k < n; ++k)
    {
      misaligned += mine[k][0] != friction[k][0]
                    || mine[k][1] != std::round(mine[k][0] / dt) + 1;
      // friction.csv's column 4: contact_normal_force
      unequal += mine[k][2] != friction[k][4];
    }
  check(friction.size() == mine.size() && friction.size() > 500
          && misaligned == 0,
        "plugin_steps.csv: " + std::to_string(mine.size()) + " rows, "
          + std::to_string(friction.size()) + " in friction.csv; "
          + std::to_string(misaligned)
          + " rows off the sample times or with steps != time / dt + 1");

  {
    std::ifstream header(dir + "friction.csv");
    std::string   columns;
    std::getline(header, columns);
    check(columns.rfind("time,normal_force,tangential_force,mu_global,"
                        "contact_normal_force,",
                        0)
            == 0,
          "friction.csv's column 4 is contact_normal_force");
  }
  check(unequal == 0 && n > 500,
        "the plugin's own contact_normal_force equals friction.csv's in "
          + std::to_string(n - unequal) + " of " + std::to_string(n) + " rows");

  std::ifstream        in(dir + "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in);
  const auto           steps   = summary.value("plugin_steps", -1.);
  check(steps == std::round(20e-6 / dt),
        "summary.json: plugin_steps = " + std::to_string(steps)
          + " from finish(), the steps of both legs (20 us / dt = "
          + std::to_string(std::round(20e-6 / dt)) + ")");
  return tribodyn_test::result();
}
