// The stress tensors the bond criteria read (seed eq. 4, doc/theory/mca.md
// Sec. 5) are those of the pair stresses at the end of the step.
//
// Pass C of a plastic bond kernel sums the final tensor anew only for the
// automata whose sides it can change (a plastic return, an unbonded contact,
// an elastic region) and keeps pass B's trial tensor for the others
// (source/mca/pair_kernel.cc). This test compares, after every step, the
// tensors the bond criteria read (AutomatonSystem::bond_criterion_stresses())
// with the tensors computed afresh from the pairs' final stresses
// (AutomatonSystem::stresses(), an independent loop over each automaton's
// pairs).
//
// Scene: two steel blocks across a flat unbonded interface (plastic_heat.cc's:
// 3 x 3 FCC cells periodic in x and y, 4 cells high), plasticity and bond
// formation on, friction coefficient 0.2, compressed along z and sheared
// along x in increments (no inertia) well past yield, so that automata
// return plastically, interface contacts slip, and pairs bond during the run.
// (Bond breaking is off: formation leaves the set of interacting pairs as it
// is, so both tensors sum the same pairs; a broken bond would leave it.)
//
// Tolerance 1e-12 of the largest tensor component: the two loops add the
// same terms in the same pair order, from the same positions, with their
// products rounded apart (measured: 5.3e-16). A kept trial tensor where a
// plastic return changed the sides differs by the return's correction, of the
// order of the yield stress: the test fails.

#include "mca_test_tools.h"

using namespace tribodyn_test;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             d = 7.5e-9, a = d * std::sqrt(2.);
  const Parameters p = interface_blocks_parameters(d, 0.2);
  AutomatonSystem  system(p, MPI_COMM_WORLD);
  system.setup();
  const unsigned int n = system.n_owned_automata();

  double       worst = 0, largest = 0;
  unsigned int steps_with_returns = 0, steps_with_contacts = 0,
               steps_compared = 0;
  std::vector<double> eps_old(n, 0.);
  for (int step = 1; step <= 200; ++step)
    {
      system.impose_motion(
        [&](const Point3 &x, Vec3 &du, Vec3 &dtheta) {
          du     = {{5e-5 * (x[2] - 2 * a), 0, -1e-4 * (x[2] - 2 * a)}};
          dtheta = {{0, 0, 0}};
        },
        1e-12);
      bool returned = false;
      for (unsigned int k = 0; k < n; ++k)
        {
          returned   = returned || system.plastic_strain(k) > eps_old[k];
          eps_old[k] = system.plastic_strain(k);
        }
      steps_with_returns += returned;
      bool unbonded_contact = false;
      for (const auto &pv : system.pair_views())
        unbonded_contact = unbonded_contact || (!pv.bonded && pv.distance < d);
      steps_with_contacts += unbonded_contact;
      const std::vector<Sym3> used = system.bond_criterion_stresses(),
                              now  = system.stresses();
      for (unsigned int k = 0; k < n; ++k)
        for (unsigned int c = 0; c < 6; ++c)
          {
            worst   = std::max(worst, std::abs(used[k][c] - now[k][c]));
            largest = std::max(largest, std::abs(now[k][c]));
          }
      ++steps_compared;
    }
  check(steps_with_returns >= 50,
        std::to_string(steps_with_returns) + " of "
          + std::to_string(steps_compared)
          + " steps with plastic returns (at least 50)");
  check(steps_with_contacts >= 50,
        std::to_string(steps_with_contacts)
          + " steps with unbonded contacts (at least 50)");
  check_relative(worst,
                 0,
                 1e-12,
                 "tensors read by the bond criteria against the final pair "
                 "stresses' (largest component difference over "
                   + std::to_string(steps_compared) + " steps)",
                 largest);
  return result();
}
