// Two automata: bond breaking, no tension, sliding at the friction force,
// bonding again (issue #4).
//
// Two steel automata at contact distance d along n = (1, 1, 0)/sqrt 2 are
// moved by imposed increments (no inertia):
//  1. pulled apart in increments of 1e-4 d: the bonded pair breaks at the
//     first increment where the von Mises stress of its stress state (for
//     an isolated pair: |sigma_n|) reaches the bond breaking stress; the
//     breaking stress must lie within one stress increment above it;
//  2. pulled further: the unbonded pair takes no tension (sigma = 0,
//     exactly), and no stress appears while they approach until r = d;
//  3. pushed into compression, then slid tangentially: the shear stress
//     grows elastically, then stays at mu |sigma| (Amontons-Coulomb), to
//     1e-12 relative, while sliding;
//  4. bonding: with plastic heat 0.6 E_b but compression below the yield
//     stress, or with compression beyond the yield stress but heat
//     0.49 E_b, the pair stays unbonded; with heat 0.51 E_b and
//     compression beyond the yield stress it bonds (E_b = w_b S r).

#include "mca_test_tools.h"

using namespace tribodyn_test;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             d = 1e-3;
  Parameters                               p = two_automata_parameters(d);
  p.interaction.plasticity                   = true;
  p.interaction.bond_breaking.get<VonMisesBondBreaking>().on      = true;
  p.interaction.bond_formation.get<PlasticHeatBondFormation>().on = true;
  p.interaction.friction.get<Coulomb>().mu                        = 0.3;
  const auto     &m = p.materials[0];
  AutomatonSystem system(p, MPI_COMM_WORLD);
  system.setup();
  check(system.n_global_automata() == 2,
        "two automata (" + std::to_string(system.n_global_automata()) + ")");
  if (system.n_global_automata() != 2)
    return result();
  // automaton 1 is moved, automaton 0 stays
  const unsigned int moving = system.ids()[0] == 1 ? 0 : 1;
  Vec3               n, t;
  {
    const auto  &x = system.positions();
    const double r = x[0].distance(x[1]);
    for (unsigned int c = 0; c < 3; ++c)
      n[c] = (x[moving][c] - x[1 - moving][c]) / r;
    t = {{-n[1], n[0], 0}};
  }
  auto move = [&](const Vec3 &dir, const double amount) {
    unsigned int k = 0;
    system.impose_motion(
      [&](const Point3 &, Vec3 &du, Vec3 &dtheta) {
        for (unsigned int c = 0; c < 3; ++c)
          du[c] = k == moving ? amount * dir[c] : 0;
        dtheta = {{0, 0, 0}};
        ++k;
      },
      1e-9);
    return system.pair_views().at(0);
  };

  // 1. tension until the bond breaks
  double previous = 0, at_break = -1, increment = 0;
  for (unsigned int s = 0; s < 100000; ++s)
    {
      const auto pv = move(n, 1e-4 * d);
      if (!pv.bonded)
        {
          at_break  = pv.sigma;
          increment = pv.sigma - previous;
          break;
        }
      previous = pv.sigma;
    }
  check(at_break >= m.bond_breaking_stress && previous < m.bond_breaking_stress
          && at_break - m.bond_breaking_stress <= increment,
        "bond breaks at the first increment reaching the breaking stress: "
          + std::to_string(previous / 1e6) + " MPa before, "
          + std::to_string(at_break / 1e6) + " MPa at the break (threshold "
          + std::to_string(m.bond_breaking_stress / 1e6) + " MPa)");

  // 2. no tension
  auto pv = move(n, 1e-4 * d);
  check(pv.sigma == 0 && pv.tau[0] == 0 && pv.tau[1] == 0 && pv.tau[2] == 0,
        "unbonded pair under tension carries no stress");
  double worst_gap = 0;
  while (system.pair_views().at(0).distance > d * (1 + 1e-9))
    {
      pv        = move(n, -1e-5 * d);
      worst_gap = std::max(worst_gap, std::abs(pv.sigma));
    }
  check(worst_gap == 0, "no stress while approaching across the gap");

  // 3. compression, then sliding
  for (unsigned int s = 0; s < 20; ++s)
    pv = move(n, -1e-5 * d);
  check(pv.sigma < 0 && !pv.bonded,
        "unbonded pair in compression: sigma = "
          + std::to_string(pv.sigma / 1e6) + " MPa");
  double worst_coulomb = 0;
  bool   slid = false, exceeded = false;
  for (unsigned int s = 0; s < 200; ++s)
    {
      pv              = move(t, 1e-6 * d);
      const double tn = std::sqrt(pv.tau[0] * pv.tau[0] + pv.tau[1] * pv.tau[1]
                                  + pv.tau[2] * pv.tau[2]);
      const double limit = p.interaction.friction.get<Coulomb>().mu * -pv.sigma;
      if (tn >= limit * (1 - 1e-12))
        {
          slid          = true;
          worst_coulomb = std::max(worst_coulomb, std::abs(tn - limit) / limit);
        }
      if (tn > limit * (1 + 1e-12))
        exceeded = true;
    }
  check(!exceeded, "the shear stress never exceeds mu |sigma|");
  check(slid, "the pair slides");
  check_relative(
    worst_coulomb, 0, 1e-12, "while sliding |tau| = mu |sigma|", 1.);

  // 4. bonding again
  const double Eb
    = m.bond_energy_density * (d * d / (2 * std::sqrt(2.))) * pv.distance;
  system.set_pair_heat(0.6 * Eb);
  pv = move(n, 0);
  check(!pv.bonded && pv.sigma > -m.yield_stress,
        "heat 0.6 E_b, compression " + std::to_string(-pv.sigma / 1e6)
          + " MPa below yield: stays unbonded");
  while (pv.sigma > -m.yield_stress)
    {
      system.set_pair_heat(0.49 * Eb);
      pv = move(n, -2e-5 * d);
    }
  pv = move(n, 0);
  check(!pv.bonded, "compression beyond yield, heat 0.49 E_b: stays unbonded");
  system.set_pair_heat(0.51 * Eb);
  pv = move(n, 0);
  check(pv.bonded, "compression beyond yield, heat 0.51 E_b: bonds");
  return result();
}
