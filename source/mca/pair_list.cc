// The pair list (pair_list.h): all pairs of automata closer than the
// interaction range (automaton size times 1 + skin; graded scenes: by the
// sizes of the two automata) with at least one owned member, found through
// the cells of the decomposition, with the periodic image shift of each
// pair cached; and the pairs of each owned automaton.

#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <numeric>
#include <tribodyn/mca/decomposition.h>
#include <tribodyn/mca/pair_list.h>

namespace tribodyn
{
  namespace mca
  {
    void
    PairList::build(const Decomposition               &cells,
                    const AutomatonArrays             &automata,
                    const double                       range,
                    const AutomatonArrays::RangeTable *graded_range)
    {
      const unsigned int n_local = automata.n_local, n_owned = automata.n_owned;
      const auto        &cell_of = automata.cell_of;
      const auto        &order   = automata.order;
      const auto        &x       = automata.x;
      // Automata of each local cell (owned and ghost), CSR.
      const unsigned int        n_cells = cells.n_local_cells();
      std::vector<unsigned int> first(n_cells + 1, 0), members(n_local);
      for (unsigned int k = 0; k < n_local; ++k)
        ++first[cell_of[k] + 1];
      std::partial_sum(first.begin(), first.end(), first.begin());
      {
        std::vector<unsigned int> fill(first.begin(), first.end() - 1);
        for (unsigned int k = 0; k < n_local; ++k)
          members[fill[cell_of[k]]++] = k;
      }

      struct Candidate // 12 bytes: the peak memory of a rebuild
      {
        std::uint32_t i, j;
        unsigned char shift;
      };
      std::vector<Candidate> found;
      found.reserve(std::size_t(n_owned) * 7);
      const double range2 = range * range;
      for (unsigned int c = 0; c < cells.n_owned_cells(); ++c)
        cells.for_each_neighbour(c, [&](const Decomposition::Neighbour &nb) {
          const auto &s = cells.shift_vector(nb.shift);
          for (unsigned int ia = first[c]; ia < first[c + 1]; ++ia)
            {
              const unsigned int a = members[ia];
              for (unsigned int ib = first[nb.cell]; ib < first[nb.cell + 1];
                   ++ib)
                {
                  const unsigned int b = members[ib];
                  // an owned-owned pair is found from both sides: keep it
                  // once, from the automaton of smaller key
                  if (b < n_owned && order[b] <= order[a])
                    continue;
                  double r2 = 0;
                  Vec3   dn;
                  for (unsigned int e = 0; e < 3; ++e)
                    {
                      dn[e] = (x[b][e] - x[a][e]) + s[e];
                      r2 += dn[e] * dn[e];
                    }
                  if (graded_range)
                    {
                      const double r = AutomatonArrays::pair_list_range(
                        *graded_range,
                        automata.size_level[a],
                        automata.size_level[b]);
                      if (r2 >= r * r)
                        continue;
                    }
                  else if (r2 >= range2)
                    continue;
                  // i is the automaton of smaller key: the same pair and
                  // orientation on every rank and partition
                  if (order[a] < order[b])
                    found.push_back({a, b, nb.shift});
                  else
                    found.push_back(
                      {b, a, Decomposition::opposite_shift(nb.shift)});
                }
            }
        });
      // Order of the pairs: by the keys of i then j, so that every
      // automaton sums its pairs' forces in the same order on any
      // partition (the results do not depend on the number of ranks).
      std::sort(found.begin(),
                found.end(),
                [&](const Candidate &p, const Candidate &q) {
                  return order[p.i] != order[q.i] ? order[p.i] < order[q.i]
                                                  : order[p.j] < order[q.j];
                });
      const unsigned int n_pairs = found.size();
      pi.resize(n_pairs);
      pj.resize(n_pairs);
      pshift.resize(n_pairs);
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          pi[p]     = found[p].i;
          pj[p]     = found[p].j;
          pshift[p] = found[p].shift;
        }
      std::vector<Candidate>().swap(found);
      pi.shrink_to_fit(), pj.shrink_to_fit(), pshift.shrink_to_fit();
    }


    void
    PairList::compact(const std::vector<unsigned char> &keep)
    {
      unsigned int q = 0;
      for (unsigned int p = 0; p < pi.size(); ++p)
        if (keep[p])
          {
            pi[q]     = pi[p];
            pj[q]     = pj[p];
            pshift[q] = pshift[p];
            ++q;
          }
      pi.resize(q);
      pj.resize(q);
      pshift.resize(q);
    }


    void
    PairList::index_by_automaton(const unsigned int n_owned)
    {
      const unsigned int n_pairs = pi.size();
      i_pairs_first.assign(n_owned, 0);
      i_pairs_count.assign(n_owned, 0);
      for (unsigned int p = 0; p < n_pairs; ++p)
        if (pi[p] < n_owned)
          {
            if (i_pairs_count[pi[p]]++ == 0)
              i_pairs_first[pi[p]] = p;
            Assert(i_pairs_first[pi[p]] + i_pairs_count[pi[p]] == p + 1,
                   dealii::ExcInternalError());
          }
      index_j_side();
    }


    void
    PairList::release_j_lists()
    {
      std::vector<unsigned int>().swap(j_pairs_first);
      std::vector<unsigned int>().swap(j_pairs);
    }


    void
    PairList::index_j_side() const
    {
      const unsigned int n_pairs = pi.size(), n_owned = i_pairs_first.size();
      j_pairs_first.assign(n_owned + 1, 0);
      for (unsigned int p = 0; p < n_pairs; ++p)
        if (pj[p] < n_owned)
          ++j_pairs_first[pj[p] + 1];
      for (unsigned int k = 0; k < n_owned; ++k)
        j_pairs_first[k + 1] += j_pairs_first[k];
      j_pairs.resize(j_pairs_first[n_owned]);
      std::vector<unsigned int> fill(j_pairs_first.begin(),
                                     j_pairs_first.end() - 1);
      for (unsigned int p = 0; p < n_pairs; ++p)
        if (pj[p] < n_owned)
          j_pairs[fill[pj[p]]++] = p;
    }


    void
    PairList::memory_by_part(MemoryParts &parts) const
    {
      add_memory_part(parts, "pair list (i, j, image shift)", pi, pj, pshift);
      add_memory_part(parts,
                      "pair list by automaton",
                      i_pairs_first,
                      i_pairs_count,
                      j_pairs_first,
                      j_pairs);
    }
  } // namespace mca
} // namespace tribodyn
