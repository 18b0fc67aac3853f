// Homogeneous strain at free surfaces (issue #7, review): the stress of
// automata on the faces, edges and corners of an FCC block under an affine
// displacement matches Hooke's law.
//
// A friction zone is mostly surface, so the Hooke test of the bulk
// (hooke.cc) is not enough. Under u = eps x every pair's normal and shear
// strains are exact; the mean-stress increment comes from the least-squares
// strain fit of the automaton's own neighbourhood, exact whenever the fit
// is full rank; the eq.-(4) stress sym(B^-1 T) with the fabric B of the
// neighbourhood then equals sigma exactly (the pair tractions are sigma n).
// Both hold for the faces of a cube of FCC cells (8 neighbours: the 6 x 6
// fit has full rank, the fabric diag(3, 3, 2) is well conditioned). The
// check: the central difference (removing the O(eps^2) of the finite pair
// kinematics) equals Hooke's stress within 1e-8 relative (round-off of
// increments ~1e-10 of positions ~1e-2 m) for every bulk and face
// automaton, steel and carbon. (Before the fabric correction used the full
// T, faces were off by 1-2 % in the shear components.)
//
// Edges (5 neighbours) and corners (3) are printed, not checked: 5 or 3
// pair directions cannot determine the 6 components of a strain or of a
// stress, so no pair-based automaton stress reproduces Hooke's law there
// (measured: 31-57 % at edges, 58-108 % at corners; doc/theory/mca.md).

#include "mca_test_tools.h"

using namespace tribodyn_test;

namespace
{
  struct Result
  {
    std::vector<Sym3>         stress;
    std::vector<unsigned int> neighbours;
  };

  Result
  stresses(const int material, const double eps[3][3], const double sign)
  {
    const Parameters p = block_parameters(5, 1e-3, material);
    AutomatonSystem  system(p, MPI_COMM_WORLD);
    system.setup();
    impose_affine_strain(system, eps, sign);
    const auto counts = system.bonded_neighbour_counts();
    Result     r;
    for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
      {
        r.stress.push_back(system.automaton_stress(k));
        r.neighbours.push_back(counts[k]);
      }
    return r;
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
      const auto  &m     = defaults.materials[material];
      const Sym3   ref   = hooke(m, eps);
      const Result plus  = stresses(material, eps, +1);
      const Result minus = stresses(material, eps, -1);
      // worst relative error per neighbour count (12: bulk, fewer: surface)
      std::map<unsigned int, std::pair<double, unsigned int>> worst;
      for (unsigned int k = 0; k < plus.stress.size(); ++k)
        {
          Sym3 central;
          for (unsigned int c = 0; c < 6; ++c)
            central[c]
              = 0.5 * (plus.stress[k][c] - minus.stress[k][c]) - ref[c];
          auto &w  = worst[plus.neighbours[k]];
          w.first  = std::max(w.first, sym_norm(central) / sym_norm(ref));
          w.second = w.second + 1;
        }
      check(worst.size() >= 4 && worst.count(8) == 1 && worst.count(12) == 1,
            m.name + ": bulk, face, edge and corner automata present ("
              + std::to_string(worst.size()) + " neighbour counts)");
      for (const auto &[n, w] : worst)
        {
          const std::string what
            = m.name + ": " + std::to_string(w.second) + " automata with "
              + std::to_string(n)
              + " neighbours: |central stress - Hooke| / |Hooke|";
          if (n >= 8)
            check_relative(w.first, 0, 1e-8, what, 1.);
          else
            std::cout << "INFO  " << what << " = " << w.first
                      << " (under-determined: not checked)" << std::endl;
        }
    }
  return result();
}
