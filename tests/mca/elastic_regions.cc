// Elastic regions (Interaction/Elastic regions) skip the plastic return and
// nothing else.
//
// A 6 x 6 x 6 FCC steel block with a low yield stress (0.8 MPa, so that a
// strain of 1e-4 is far beyond yield; see plasticity.cc for why the yield
// stress is scaled down) takes one homogeneous strain increment of
// amplitude 1e-4 (all six components) three times: with a yield stress
// that is never reached (1e30 Pa: the plastic scene's code path, nothing
// yields), with yielding, and with yielding and the lower half of the
// block (z < L/2) declared elastic. Checked, on the automata whose
// neighbours all have complete neighbourhoods ("deep"):
//  - in the elastic half, away from the region's boundary by more than one
//    pair (so that all their partners are elastic too), the plastic strain
//    is exactly zero and the stress equals that of the run that never
//    yields to 1e-12 relative (the same operations; rounding only);
//  - in the other half, away from the boundary, the stress equals that of
//    the fully plastic run to 1e-12 relative, and the automata did yield
//    (plastic strain > 0), so that the test has something to skip.

#include "mca_test_tools.h"

using namespace tribodyn_test;

namespace
{
  struct State
  {
    std::map<std::uint32_t, Sym3>   stress;
    std::map<std::uint32_t, double> plastic_strain, z;
    std::map<std::uint32_t, bool>   deep;
  };

  State
  run(const double yield_stress, const bool elastic_half)
  {
    const double d = 1e-3, L = 6 * d * std::sqrt(2.);
    Parameters   p                   = block_parameters(6, d, 0);
    p.interaction.plasticity         = true;
    p.materials[0].yield_stress      = yield_stress;
    p.materials[0].hardening         = Hardening::linear;
    p.materials[0].hardening_modulus = 2e9;
    if (elastic_half)
      {
        Region r;
        r.shape                       = Region::Shape::box;
        r.a                           = Point3(-1, -1, -1);
        r.b                           = Point3(1, 1, L / 2);
        p.interaction.elastic_regions = {r};
      }
    AutomatonSystem system(p, MPI_COMM_WORLD);
    system.setup();
    State      s;
    const auto counts = system.bonded_neighbour_counts();
    std::map<std::uint32_t, unsigned int> index;
    for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
      {
        index[system.ids()[k]]  = k;
        s.deep[system.ids()[k]] = counts[k] == 12;
        s.z[system.ids()[k]]    = system.positions()[k][2];
      }
    for (const auto &pv : system.pair_views())
      {
        if (counts[index[pv.id_i]] < 12)
          s.deep[pv.id_j] = false;
        if (counts[index[pv.id_j]] < 12)
          s.deep[pv.id_i] = false;
      }
    double eps[3][3];
    general_strain(eps, 1e-4);
    impose_affine_strain(system, eps, 1.);
    for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
      {
        s.stress[system.ids()[k]]         = system.automaton_stress(k);
        s.plastic_strain[system.ids()[k]] = system.plastic_strain(k);
      }
    return s;
  }

  double
  relative_difference(const Sym3 &a, const Sym3 &b)
  {
    Sym3 diff;
    for (unsigned int c = 0; c < 6; ++c)
      diff[c] = a[c] - b[c];
    return sym_norm(diff) / sym_norm(b);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             d = 1e-3, L = 6 * d * std::sqrt(2.);
  const State elastic = run(1e30, false), plastic = run(0.8e6, false),
              mixed          = run(0.8e6, true);
  double       worst_elastic = 0, worst_plastic = 0, max_ep_elastic = 0;
  double       min_ep_plastic = 1;
  unsigned int n_elastic = 0, n_plastic = 0;
  for (const auto &[id, deep] : mixed.deep)
    {
      if (!deep)
        continue;
      const double z = mixed.z.at(id);
      if (z < L / 2 - 1.01 * d)
        {
          ++n_elastic;
          worst_elastic = std::max(worst_elastic,
                                   relative_difference(mixed.stress.at(id),
                                                       elastic.stress.at(id)));
          max_ep_elastic
            = std::max(max_ep_elastic, mixed.plastic_strain.at(id));
        }
      else if (z > L / 2 + 1.01 * d)
        {
          ++n_plastic;
          worst_plastic = std::max(worst_plastic,
                                   relative_difference(mixed.stress.at(id),
                                                       plastic.stress.at(id)));
          min_ep_plastic
            = std::min(min_ep_plastic, mixed.plastic_strain.at(id));
        }
    }
  check(n_elastic > 0 && n_plastic > 0,
        "deep automata on both sides: " + std::to_string(n_elastic)
          + " elastic, " + std::to_string(n_plastic) + " plastic");
  check(max_ep_elastic == 0,
        "no plastic strain in the elastic region (max "
          + std::to_string(max_ep_elastic) + ")");
  check(min_ep_plastic > 0,
        "the automata outside yielded (min plastic strain "
          + std::to_string(min_ep_plastic) + ")");
  check_relative(worst_elastic,
                 0,
                 1e-12,
                 "elastic region: stress of the run that never yields",
                 1.);
  check_relative(
    worst_plastic, 0, 1e-12, "outside: stress of the plastic run", 1.);
  return result();
}
