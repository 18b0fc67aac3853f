// The deferred second half kick (AutomatonSystem::step() with may_defer,
// BoundaryLoads::kick_kick_drift()): velocity Verlet's second half kick of
// a step, its constraints, the first half kick of the next step, its
// constraints and its drift in one pass over the automata must give the
// numbers of the separate passes, bit for bit.
//
// The scene exercises every branch of the kicks: the staged friction
// loading of seed 000 (friction_loading.cc's rough interface, 4 x 4 x 8
// FCC cells of steel) with plasticity, bond breaking and bond formation: a
// loading plate (force group) with its damping layer, a prescribed-velocity
// group with a ramp and a switch at the contact, pair-list rebuilds while
// the kicks are deferred. Two systems run side by side, one stepping as
// before, one deferring every kick it may; every 7 steps and at the end
// the second completes its step, and then:
// - positions, velocities, angular velocities and forces of every owned
//   automaton, the energies with the works (the kicks' works are summed in
//   other loops), the groups' reactions and mean displacements and the
//   rebuild counts are equal, bit for bit (exact: the same IEEE operations
//   in the same order);
// - each step's end is checked for speed once: the counts of automata
//   faster than a limit that 38 % of the automaton-steps exceed, taken after
//   every step as the driver takes them (take_unstable_count()), sum to those
//   of the undeferred system's steps (exact);
// - the comparison covers deferred steps and at least two rebuilds.
// On 1 and 2 ranks.

#include "mca_test_tools.h"

using namespace tribodyn_test;

namespace
{
  const double d = 7.5e-9;

  Parameters
  scene()
  {
    std::ostringstream text;
    text << std::setprecision(17) << rough_interface_geometry(d)
         << "subsection Materials\nsubsection Steel\n"
         << "set Hardening = linear\nset Yield stress = 800e6\n"
         << "set Hardening modulus = 2e9\nset Bond breaking stress = 1.2e9\n"
         << "end\nend\n"
         << "subsection Interaction\nset Plasticity = true\n"
         << "set Bond breaking = true\nset Bond formation = true\n"
         << "set Friction coefficient = 0.3\nend\n"
         << "subsection Boundary conditions\nset Ramp time = 1e-10\nend\n"
         << "subsection Friction loading\nset Enabled = true\n"
         << "set Approach velocity = 20\nset Pressure = 300e6\n"
         << "set Sliding velocity = 40\nend\n";
    return parameters_from_text(text.str());
  }

  /// Are the first @p n three-vectors of @p x and @p y the same numbers,
  /// bit for bit?
  template <class Array>
  bool
  same(const std::vector<Array> &x,
       const std::vector<Array> &y,
       const unsigned int        n)
  {
    if (x.size() < n || y.size() < n)
      return false;
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int c = 0; c < 3; ++c)
        if (!(x[k][c] == y[k][c]))
          return false;
    return true;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Parameters                         p = scene();
  AutomatonSystem plain(p, MPI_COMM_WORLD), deferred(p, MPI_COMM_WORLD);
  plain.setup();
  deferred.setup();
  // a speed that 38 % of the automaton-steps exceed (the layers approach at
  // 20 m/s, slide at 40 m/s)
  const double limit = 25;
  deferred.defer_second_kicks(limit);

  unsigned long unstable_plain = 0, unstable_deferred = 0;
  unsigned int  n_deferred = 0, n_compared = 0, mismatches = 0;
  std::string   first_mismatch;
  const double  t_end = 0.5e-9;
  for (unsigned int n = 0; plain.time() < t_end; ++n)
    {
      plain.step();
      unstable_plain += plain.count_unstable_automata(limit);
      deferred.step(true);
      n_deferred += !deferred.step_complete();
      unstable_deferred += deferred.take_unstable_count(limit);
      if (n % 7 != 6 && plain.time() < t_end)
        continue;
      deferred.complete_step();
      unstable_deferred += deferred.take_unstable_count(limit);
      ++n_compared;
      const unsigned int n_owned = plain.n_owned_automata();
      const auto         ep = plain.energies(), ed = deferred.energies();
      const auto         rp = plain.boundary_loads().reactions(),
                 rd         = deferred.boundary_loads().reactions();
      const auto mp         = plain.boundary_loads().mean_displacements(),
                 md         = deferred.boundary_loads().mean_displacements();
      std::string what;
      if (deferred.n_owned_automata() != n_owned)
        what = "the number of owned automata";
      else if (!same(plain.positions(), deferred.positions(), n_owned))
        what = "the positions";
      else if (!same(plain.velocities(), deferred.velocities(), n_owned))
        what = "the velocities";
      else if (!same(plain.angular_velocities(),
                     deferred.angular_velocities(),
                     n_owned))
        what = "the angular velocities";
      else if (!same(plain.forces(), deferred.forces(), n_owned))
        what = "the forces";
      else if (ep.value != ed.value)
        what = "the energies and works";
      else if (!same(rp, rd, rp.size()) || !same(mp, md, mp.size()))
        what = "the groups' reactions or displacements";
      else if (plain.n_rebuilds() != deferred.n_rebuilds())
        what = "the rebuilds";
      if (!what.empty() && mismatches++ == 0)
        first_mismatch = what + " after step " + std::to_string(n + 1);
    }
  check(mismatches == 0,
        "the deferred kicks give the same state at "
          + std::to_string(n_compared) + " comparisons"
          + (mismatches ? " (first differing: " + first_mismatch + ")" : ""));
  check(unstable_plain == unstable_deferred,
        "automata faster than " + std::to_string(limit) + " m/s, summed over "
          + "the steps: " + std::to_string(unstable_plain) + " undeferred, "
          + std::to_string(unstable_deferred) + " deferred");
  const unsigned long steps = plain.step_number();
  check(unstable_plain > 0 && unstable_plain < steps * plain.n_owned_automata(),
        "the speed limit splits the automata (" + std::to_string(unstable_plain)
          + " of " + std::to_string(steps * plain.n_owned_automata())
          + " automaton-steps above it)");
  check(n_deferred > steps / 2,
        std::to_string(n_deferred) + " of " + std::to_string(steps)
          + " steps deferred their second half kick");
  check(plain.n_rebuilds() >= 3,
        std::to_string(plain.n_rebuilds())
          + " pair-list rebuilds (at least 2 after the set-up's)");
  check(plain.contact_time() > 0,
        "the bodies touch at t = " + std::to_string(plain.contact_time() * 1e9)
          + " ns");
  return result();
}
