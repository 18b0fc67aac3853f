// What makes two runs the same run for a resume or a reuse
// (core/checkpoint.h, ResumableParameters): their parameters agree but for
// entries at their defaults. A stored run of an older version, which did
// not know an entry declared since, is the same run while the new run
// leaves that entry at its default, and not once it sets it otherwise; an
// entry a stored run left at a default that this version changed is a
// difference; numbers compare by value; the end time, the Checkpoint
// subsection and the Output directory never count, nor does an entry of
// the work's layout (ParameterBinding::layout_only(): the automata's order)
// whatever either run sets it to. The stored run is a parameters.prm
// written here by hand, as an older version wrote it.
#include "../test_utilities.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <sstream>
#include <string>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/resumable_parameters.h>
#include <vector>

using namespace tribodyn;
using tribodyn_test::check;

namespace
{
  /// A run's parameters: three entries of subsection Partition (one of
  /// the layout only) and the end time; @p cells, @p speed and @p order
  /// set when not empty.
  ResumableParameters
  run(const std::string &cells,
      const std::string &speed,
      const std::string &order = "")
  {
    dealii::ParameterHandler prm;
    prm.declare_entry("Output directory", "out", dealii::Patterns::Anything());
    prm.enter_subsection("Partition");
    prm.declare_entry("Mesh cells per rank",
                      "1000",
                      dealii::Patterns::Integer());
    prm.declare_entry("Ranks", "1", dealii::Patterns::Integer());
    prm.declare_entry("Order",
                      "slabs",
                      dealii::Patterns::Anything(),
                      std::string("The order.")
                        + ParameterBinding::layout_only_tag);
    prm.leave_subsection();
    prm.enter_subsection("Time");
    prm.declare_entry("End time", "1e-9", dealii::Patterns::Double());
    prm.declare_entry("Speed", "0.5e6", dealii::Patterns::Double());
    prm.leave_subsection();
    prm.enter_subsection("Partition");
    if (!cells.empty())
      prm.set("Mesh cells per rank", cells);
    if (!order.empty())
      prm.set("Order", order);
    prm.leave_subsection();
    prm.enter_subsection("Time");
    if (!speed.empty())
      prm.set("Speed", speed);
    prm.set("End time", "2e-9");
    prm.leave_subsection();
    return resumable_parameters(prm, "Time/End time");
  }

  std::string
  names(const std::vector<std::string> &list)
  {
    std::string s;
    for (const auto &n : list)
      s += (s.empty() ? "" : ", ") + n;
    return "[" + s + "]";
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // An older version's parameters.prm (as a finished study scene keeps
  // it): no 'Mesh cells per rank', the speed spelled otherwise, another
  // end time and output directory; read as the study reads it.
  std::istringstream             text("set Output directory = elsewhere\n"
                                      "subsection Partition\n"
                                      "  set Ranks = 1\n"
                                      "end\n"
                                      "subsection Time\n"
                                      "  set End time = 1e-9\n"
                                      "  set Speed    = 500000\n"
                                      "end\n");
  double                         stored_end = 0;
  const std::vector<std::string> older
    = resumable_parameter_lines(text, "Time/End time", &stored_end);
  check(stored_end == 1e-9 && older.size() == 2,
        "the older run's lines: " + names(older) + ", its end time read");
  const auto at_default = run("", "");
  check(at_default.same_as(older),
        "the entry added since, at its default, and the speed written as "
        "500000 against 0.5e6: the same run (differing: "
          + names(at_default.differing(older)) + ")");

  const auto changed = run("500", "");
  check(changed.differing(older)
          == std::vector<std::string>{"Partition/Mesh cells per rank"},
        "the added entry set to 500: the runs differ in it alone ("
          + names(changed.differing(older)) + ")");

  const auto faster = run("", "6e5");
  check(faster.differing(older) == std::vector<std::string>{"Time/Speed"},
        "a speed of 6e5: the runs differ in it alone ("
          + names(faster.differing(older)) + ")");

  // A stored run that set the entry to what is now its default is the
  // same run; one that left it at a default that has changed since (its
  // line says the old default) is not.
  const std::vector<std::string> explicit_default
    = {"Partition/Mesh cells per rank = 1000",
       "Partition/Ranks = 1",
       "Time/Speed = 5e5"};
  check(at_default.same_as(explicit_default),
        "a stored line at today's default: the same run");
  const std::vector<std::string> old_default
    = {"Partition/Mesh cells per rank = 800",
       "Partition/Ranks = 1",
       "Time/Speed = 5e5"};
  check(at_default.differing(old_default)
          == std::vector<std::string>{"Partition/Mesh cells per rank"},
        "a stored line at another default (800): the runs differ in it ("
          + names(at_default.differing(old_default)) + ")");
  // An entry the stored run has and this version does not know (removed
  // since, not renamed): a difference.
  std::vector<std::string> removed = older;
  removed.push_back("Partition/Gone = 3");
  check(at_default.differing(removed)
          == std::vector<std::string>{"Partition/Gone"},
        "an entry this version does not declare: a difference ("
          + names(at_default.differing(removed)) + ")");

  // The layout-only entry: a stored run at another value of it (its old
  // default, written out) is the same run, for this run at its default
  // and at a value of its own; a difference elsewhere still counts.
  std::vector<std::string> other_order = older;
  other_order.push_back("Partition/Order = Morton curve");
  check(at_default.same_as(other_order)
          && run("", "", "rows").same_as(other_order)
          && at_default.differing_in_run(other_order).empty(),
        "a stored run in another order: the same run (differing: "
          + names(at_default.differing(other_order)) + ")");
  check(faster.differing(other_order) == std::vector<std::string>{"Time/Speed"},
        "in another order and at another speed: the runs differ in the "
        "speed alone ("
          + names(faster.differing(other_order)) + ")");

  return tribodyn_test::result();
}
