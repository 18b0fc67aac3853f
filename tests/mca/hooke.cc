// Homogeneous strain of an FCC block gives Hooke's stress (issue #4).
//
// An affine displacement u = eps x is imposed in one pseudo-step on a block
// of 6 x 6 x 6 FCC cells; the automaton stress (seed eq. 4) of every
// automaton whose neighbours all have complete (12-neighbour)
// neighbourhoods is compared with Hooke's law sigma = lambda tr(eps) I +
// 2 G eps, for steel and carbon. The MCA kinematics are finite (pair
// distances), so sigma(eps) = C:eps + O(|eps|^2); the central difference
// (sigma(eps) - sigma(-eps))/2 removes the quadratic term and must equal
// C:eps to round-off: tolerance 1e-8 relative (strain amplitude 1e-6,
// positions ~1e-2 m: round-off of the increments ~1e-10). The one-sided
// stress must agree to 10 |eps|.

#include "mca_test_tools.h"

using namespace tribodyn_test;

namespace
{
  /// Stresses of the interior automata after imposing eps (sign s).
  std::vector<Sym3>
  interior_stresses(const int     material,
                    const double  eps[3][3],
                    const double  sign,
                    unsigned int &n_interior)
  {
    const Parameters p = block_parameters(6, 1e-3, material);
    AutomatonSystem  system(p, MPI_COMM_WORLD);
    system.setup();
    impose_affine_strain(system, eps, sign);
    // interior: all 12 bonded neighbours have 12 bonded neighbours
    const auto counts = system.bonded_neighbour_counts();
    const auto pairs  = system.pair_views();
    std::map<std::uint64_t, unsigned int> index;
    for (unsigned int k = 0; k < system.ids().size(); ++k)
      index[system.ids()[k]] = k;
    std::vector<bool> interior(system.ids().size(), true);
    for (unsigned int k = 0; k < counts.size(); ++k)
      if (counts[k] < 12)
        interior[k] = false;
    std::vector<bool> deep = interior;
    for (const auto &pv : pairs)
      {
        const unsigned int i = index[pv.id_i], j = index[pv.id_j];
        if (!interior[i])
          deep[j] = false;
        if (!interior[j])
          deep[i] = false;
      }
    std::vector<Sym3> out;
    n_interior = 0;
    for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
      if (deep[k])
        {
          out.push_back(system.automaton_stress(k));
          ++n_interior;
        }
    return out;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             amplitude = 1e-6;
  double                                   eps[3][3];
  general_strain(eps, amplitude);

  const Parameters defaults;
  for (const int material : {0, 1})
    {
      const auto  &m      = defaults.materials[material];
      const Sym3   ref    = hooke(m, eps);
      unsigned int n_plus = 0, n_minus = 0;
      const auto   plus  = interior_stresses(material, eps, +1, n_plus);
      const auto   minus = interior_stresses(material, eps, -1, n_minus);
      check(n_plus > 10 && n_plus == n_minus,
            m.name + ": " + std::to_string(n_plus) + " interior automata");
      double worst_central = 0, worst_one_sided = 0;
      for (unsigned int k = 0; k < plus.size(); ++k)
        {
          Sym3 central, one;
          for (unsigned int c = 0; c < 6; ++c)
            {
              central[c] = 0.5 * (plus[k][c] - minus[k][c]) - ref[c];
              one[c]     = plus[k][c] - ref[c];
            }
          worst_central   = std::max(worst_central, sym_norm(central));
          worst_one_sided = std::max(worst_one_sided, sym_norm(one));
        }
      check_relative(worst_central,
                     0,
                     1e-8,
                     m.name
                       + ": |central-difference stress - Hooke| / "
                         "|Hooke|",
                     sym_norm(ref));
      check_relative(worst_one_sided,
                     0,
                     10 * amplitude,
                     m.name
                       + ": |stress - Hooke| / |Hooke| (one-sided, "
                         "O(eps))",
                     sym_norm(ref));
    }
  return result();
}
