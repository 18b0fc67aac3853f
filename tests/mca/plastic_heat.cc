// Plastic heat of unbonded pairs and bond formation driven by real plastic
// flow (issue #8; seed 000 Sec. 2.1-2.2: a pair of unbonded automata bonds
// when it is compressed at the yield stress and the plastic heat generated
// in it while unbonded reaches half of the bond energy).
//
// Two steel blocks meet along a flat interface (a rough interface of zero
// amplitude: the pairs across it start unbonded), 3 x 3 FCC cells periodic
// in x and y, 4 cells high. A uniaxial strain along z is imposed in
// increments of 1e-4 (no inertia) well past yield; the heat is never set by
// hand. The interface friction coefficient is 1: the pairs across the
// interface carry the shear of uniaxial strain (|tau|/|sigma| = 1 - 2 nu =
// 0.44 on their 45-degree planes) without slipping, so the plastic flow is
// the plastic flow of the material.
//
// Checks (tolerances; doc/theory/mca.md Sec. 8.4). The plastic work is
// what the pair sides release at their plastic returns, the deviatoric
// part (1 - M^2) S ((sigma - sigma_m)^2 + |tau|^2) / 2k of their springs'
// energy; it is compared with independent, first-order models of it:
// - against the J2 dissipation of the automata, sum V (sigma_y,old +
//   sigma_y,new)/2 d eps_p from their plastic strains and linear
//   hardening: measured +8.8 % (2026-11-27); half of this block's automata
//   are at its held faces or at the interface, whose contact springs the
//   homogenized stress does not see. Tolerance 15 %: a plastic work not
//   booked, or booked twice, fails;
// - the heat of every unbonded pair against its share of the two
//   automata's J2 dissipation in proportion to q S over the pairs that
//   interact (bonded or in contact; q = r/2 for identical materials):
//   dQ_ij = dW_i r_ij / sum_k r_ik + dW_j r_ij / sum_k r_jk (the rule of
//   the code until 2026-11-27). The pair's own release depends on its own
//   deviatoric stress, which the share ignores: measured largest
//   difference 35 % of the largest heat. Tolerance 50 %: a heat not
//   accumulated (difference 100 %) fails;
// - every interface pair bonds once its heat reaches half of the bond
//   energy E_b = w_b S r (and the pair is compressed beyond the current
//   yield stress): none bonds while its predicted heat is below
//   (1 - 50 %) E_b / 2 or stays unbonded beyond (1 + 50 %) E_b / 2; and
//   none bonds before yield.

#include "mca_test_tools.h"

#include <map>

using namespace tribodyn_test;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             d = 7.5e-9, a = d * std::sqrt(2.);
  const Parameters p = interface_blocks_parameters(d, 1.0);
  const auto      &m = p.materials[0];
  AutomatonSystem  system(p, MPI_COMM_WORLD);
  system.setup();
  const unsigned int                    n = system.n_owned_automata();
  std::map<std::uint64_t, unsigned int> local;
  for (unsigned int k = 0; k < n; ++k)
    local[system.ids()[k]] = k;

  const double V = d * d * d / std::sqrt(2.), S = d * d / (2 * std::sqrt(2.));
  const double work_tolerance = 0.15, heat_tolerance = 0.5;
  std::map<std::pair<std::uint64_t, std::uint64_t>, double> predicted;
  std::map<std::pair<std::uint64_t, std::uint64_t>, int>    bonded_at;
  std::vector<double>                                       eps_old(n, 0.);
  double worst_heat = 0, sum_work = 0, scale = 0;
  int    bonds_early = 0, bonds_late = 0, bonds_formed = 0, first_yield = -1;
  for (int step = 1; step <= 300; ++step)
    {
      system.impose_motion(
        [&](const Point3 &x, Vec3 &du, Vec3 &dtheta) {
          du     = {{0, 0, -1e-4 * (x[2] - 2 * a)}};
          dtheta = {{0, 0, 0}};
        },
        1e-12);
      std::vector<double> eps(system.n_owned_automata());
      for (unsigned int k = 0; k < eps.size(); ++k)
        eps[k] = system.plastic_strain(k);
      // plastic work of each automaton in this increment
      std::vector<double> dW(n, 0.);
      double              total = 0;
      for (unsigned int k = 0; k < n; ++k)
        {
          const double s0 = m.yield_stress_at(eps_old[k]);
          const double s1 = m.yield_stress_at(eps[k]);
          dW[k]           = V * 0.5 * (s0 + s1) * (eps[k] - eps_old[k]);
          total += dW[k];
          eps_old[k] = eps[k];
        }
      if (first_yield < 0 && total > 0)
        first_yield = step;
      sum_work += total;
      // shares: sum of r over the interacting pairs of each automaton
      const auto          pairs = system.pair_views();
      std::vector<double> sum_r(n, 0.);
      for (const auto &pv : pairs)
        if (pv.bonded || pv.distance < d)
          {
            sum_r[local[pv.id_i]] += pv.distance;
            sum_r[local[pv.id_j]] += pv.distance;
          }
      for (const auto &pv : pairs)
        {
          const auto key = std::make_pair(pv.id_i, pv.id_j);
          if (bonded_at.count(key))
            continue;
          const unsigned int i = local[pv.id_i], j = local[pv.id_j];
          if (pv.bonded && !predicted.count(key))
            continue; // bonded from the start
          if (!predicted.count(key))
            predicted[key] = 0;
          if (pv.distance < d)
            predicted[key] += dW[i] * pv.distance / sum_r[i]
                              + dW[j] * pv.distance / sum_r[j];
          // (due within the heat's tolerance: the prediction is first
          // order, see above)
          const double Eb = m.bond_energy_density * S * pv.distance;
          if (pv.bonded)
            {
              bonded_at[key] = step;
              ++bonds_formed;
              if (predicted[key] < (1 - heat_tolerance) * 0.5 * Eb)
                ++bonds_early;
            }
          else
            {
              if (predicted[key] >= (1 + heat_tolerance) * 0.5 * Eb
                  && pv.sigma <= 0 && -pv.sigma >= m.yield_stress_at(eps[i]))
                ++bonds_late;
              scale = std::max(scale, predicted[key]);
              worst_heat
                = std::max(worst_heat, std::abs(pv.heat - predicted[key]));
            }
        }
    }
  check(first_yield > 0,
        "the blocks yield (first at increment " + std::to_string(first_yield)
          + ")");
  check_relative(system.energies()[Energy::plastic],
                 sum_work,
                 work_tolerance,
                 "plastic work released by the pair sides against the J2 "
                 "dissipation of the automata");
  check_relative(worst_heat,
                 0,
                 heat_tolerance,
                 "heat of unbonded pairs against the shares of the automata's "
                 "J2 dissipation",
                 scale);
  check(bonds_formed > 0 && bonds_early == 0 && bonds_late == 0,
        std::to_string(bonds_formed) + " interface pairs bonded, "
          + std::to_string(bonds_early) + " before their heat reached E_b/2, "
          + std::to_string(bonds_late) + " later than due");
  return result();
}
