// The pair list's search (PairList::build(), issue #48): it finds exactly
// the pairs a brute-force search over all automata finds.
//
// Automata at uniform random positions in a box periodic in x, y and z,
// of 3 x 3 x 3 cells, of size levels 0 (90 %), 1 (8 %) and 3 (2 %), a tenth of
// them with the transitional flag; pair-list ranges r0 2^L, 1.12 times that
// near a change of size (AutomatonSystem::pair_list_ranges()). The cells are
// as wide as the largest range (8.96 r0): 6 000 automata in the lowest layer
// of cells, ~670 a cell, which the search sorts into bins and rules out by
// their bounding boxes before it compares automata; 350 in the two layers
// above, ~19 a cell, most of them cells the search does not bin (fewer than
// 24 automata), some binned: pairs of binned and unbinned cells across the
// layers and the periodic seam. The brute force compares every two automata
// at their nearest image (the period exceeds twice the largest range, so no
// other image can be in range), with the search's own arithmetic: the vector
// (x_j - x_i) + shift from the automaton of smaller key, the squared
// distance against the squared range of the two levels. The found pairs (i,
// j, image shift) must equal its pairs as sets: no tolerance, the same
// comparisons decide. The same with one range for all (the uniform scenes'
// path) in the same cells. Random positions put pairs at every fraction of
// their range: the pairs within 10^-3 of it are counted, to show that the
// margin of the boxes' test is exercised.

#include "mca_test_tools.h"

#include <algorithm>
#include <numeric>
#include <random>
#include <tribodyn/mca/decomposition.h>
#include <tribodyn/mca/pair_list.h>
#include <tuple>

using namespace tribodyn_test;

namespace
{
  using Found = std::tuple<unsigned int, unsigned int, unsigned int>;

  std::vector<Found>
  found_pairs(const PairList &list)
  {
    std::vector<Found> out;
    for (unsigned int p = 0; p < list.n_pairs(); ++p)
      out.emplace_back(list.pi[p], list.pj[p], list.pshift[p]);
    std::sort(out.begin(), out.end());
    return out;
  }

  /// Every pair closer than its range, from the automaton of smaller key,
  /// at the nearest image; @p near counts those within 1e-3 of the range.
  std::vector<Found>
  brute_force(const AutomatonArrays             &automata,
              const Decomposition               &cells,
              const std::array<double, 3>       &period,
              const double                       range,
              const AutomatonArrays::RangeTable *table,
              unsigned int                      &near)
  {
    std::vector<Found> out;
    near                 = 0;
    const unsigned int n = automata.n_local;
    for (unsigned int a = 0; a < n; ++a)
      for (unsigned int b = a + 1; b < n; ++b)
        {
          const bool         a_first = automata.order[a] < automata.order[b];
          const unsigned int i = a_first ? a : b, j = a_first ? b : a;
          unsigned int       code = 0, stride = 1;
          for (unsigned int e = 0; e < 3; ++e, stride *= 3)
            {
              const double dx = automata.x[j][e] - automata.x[i][e];
              const int    s  = dx > period[e] / 2    ? -1
                                : dx < -period[e] / 2 ? 1
                                                      : 0;
              code += (s + 1) * stride;
            }
          const auto &s  = cells.shift_vector(code);
          double      r2 = 0;
          for (unsigned int e = 0; e < 3; ++e)
            {
              const double dn = (automata.x[j][e] - automata.x[i][e]) + s[e];
              r2 += dn * dn;
            }
          const double r
            = table ? AutomatonArrays::pair_list_range(*table,
                                                       automata.size_level[i],
                                                       automata.size_level[j])
                    : range;
          if (r2 < r * r)
            {
              out.emplace_back(i, j, code);
              near += r2 > r * r * (1 - 1e-3);
            }
        }
    std::sort(out.begin(), out.end());
    return out;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             r0 = 1.15, transition = 1.12;
  const unsigned int          n_dense = 6000, n = n_dense + 350, top_level = 3;
  AutomatonArrays::RangeTable table{};
  for (unsigned int L = 0; L < table[0].size(); ++L)
    {
      table[0][L] = r0 * (1u << L);
      table[1][L] = transition * r0 * (1u << L);
    }
  const double largest = table[1][top_level];

  // a box of 3 x 3 x 3 cells of the largest range, periodic
  GeometryParameters g;
  g.automaton_size = 1;
  g.domain_lower   = Point3(0, 0, 0);
  g.domain_upper   = Point3(3.1 * largest, 3.2 * largest, 3.05 * largest);
  g.periodic       = {{true, true, true}};
  const std::array<double, 3> period{
    {g.domain_upper[0], g.domain_upper[1], g.domain_upper[2]}};
  Decomposition cells(
    g, largest, 0, PartitionParameters::AutomatonOrder::curve, MPI_COMM_WORLD);
  cells.setup();

  AutomatonArrays automata;
  automata.n_owned = automata.n_local = n;
  std::mt19937                           random(48);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<std::uint64_t>             keys(n);
  std::iota(keys.begin(), keys.end(), 0);
  std::shuffle(keys.begin(), keys.end(), random);
  for (unsigned int k = 0; k < n; ++k)
    {
      Point3 p;
      for (unsigned int e = 0; e < 3; ++e)
        p[e] = unit(random) * period[e];
      // the lowest layer of cells, or the two above
      p[2]            = k < n_dense ? p[2] / 3 : period[2] / 3 + p[2] * 2 / 3;
      const double  u = unit(random);
      unsigned char level = u < 0.9 ? 0 : u < 0.98 ? 1 : top_level;
      if (unit(random) < 0.1)
        level |= AutomatonArrays::transitional_flag;
      automata.x.push_back(p);
      automata.size_level.push_back(level);
      automata.cell_of.push_back(cells.local_cell(p));
      automata.order.push_back(keys[k]);
    }
  check(cells.n_local_cells() == 27,
        "27 cells of the largest range ("
          + std::to_string(cells.n_local_cells()) + ")");
  // cells the search bins (24 automata or more) and cells it does not
  std::vector<unsigned int> in_cell(cells.n_local_cells(), 0);
  for (const unsigned int c : automata.cell_of)
    ++in_cell[c];
  const auto n_binned
    = std::count_if(in_cell.begin(), in_cell.end(), [](const unsigned int m) {
        return m >= 24;
      });
  check(n_binned >= 9 && n_binned < 27,
        "cells of 24 automata or more, binned: " + std::to_string(n_binned)
          + " of 27");

  for (const bool graded : {true, false})
    {
      const std::string what = graded ? "graded ranges" : "one range";
      PairList          list;
      list.build(cells, automata, r0, graded ? &table : nullptr);
      unsigned int near      = 0;
      const auto   reference = brute_force(
        automata, cells, period, r0, graded ? &table : nullptr, near);
      const auto search = found_pairs(list);
      check(search == reference,
            what + ": the search finds the brute force's "
              + std::to_string(reference.size()) + " pairs ("
              + std::to_string(search.size()) + " found, "
              + std::to_string(near) + " of them within 1e-3 of their range)");
      check(near > 0, what + ": pairs at the edge of their range tested");
    }
  return failure_count();
}
