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
    namespace
    {
      /// A group of automata of one cell, numbered consecutively in the
      /// cell's member list, with the bounding box of their positions and
      /// the summary of their size levels (the largest level, and the
      /// transitional flag if any has it): no automaton of the group lies
      /// outside the box, and none has a larger pair-list range against
      /// another automaton than the summary has.
      struct Bin
      {
        double        lo[3], hi[3];
        unsigned int  begin, end;
        unsigned char level;
      };

      /// The box and level summary of the automata members[begin ... end).
      Bin
      bin_of(const std::vector<unsigned int> &members,
             const unsigned int               begin,
             const unsigned int               end,
             const AutomatonArrays           &automata)
      {
        Bin bin{{0, 0, 0}, {0, 0, 0}, begin, end, 0};
        for (unsigned int e = 0; e < 3; ++e)
          bin.lo[e] = bin.hi[e] = automata.x[members[begin]][e];
        for (unsigned int k = begin; k < end; ++k)
          {
            const unsigned int a = members[k];
            for (unsigned int e = 0; e < 3; ++e)
              {
                bin.lo[e] = std::min(bin.lo[e], automata.x[a][e]);
                bin.hi[e] = std::max(bin.hi[e], automata.x[a][e]);
              }
            if (!automata.size_level.empty())
              bin.level
                = AutomatonArrays::merge_level_summary(bin.level,
                                                       automata.size_level[a]);
          }
        return bin;
      }

      /// The squared distance between the boxes of bins @p a and @p b, the
      /// latter shifted by @p s: for automata x_a in a and x_b in b, each
      /// component of (x_b - x_a) + s, as the search computes it, lies
      /// between those of the boxes as computed here (rounding is
      /// monotone), so this is at most the squared distance the search
      /// computes for x_a and x_b, but for the rounding of the sums of
      /// squares.
      double
      box_distance2(const Bin &a, const Bin &b, const std::array<double, 3> &s)
      {
        double g2 = 0;
        for (unsigned int e = 0; e < 3; ++e)
          {
            const double below = (b.lo[e] - a.hi[e]) + s[e],
                         above = (b.hi[e] - a.lo[e]) + s[e];
            const double g     = below > 0 ? below : above < 0 ? -above : 0.;
            g2 += g * g;
          }
        return g2;
      }
    } // namespace


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

      // The members of a cell of many automata in bins by their position in
      // the cell's bounding box (in cells of at least 24 automata: m^3
      // bins, the largest m <= 4 that leaves at least three automata a bin
      // on average). The cells are as wide as the largest pair-list range:
      // in a graded scene a cell of the finest automata holds ~170 of them,
      // of which an automaton's range reaches a few dozen. The search
      // compares boxes first (a cell's, then its bins'), then the automata
      // of the bins it cannot rule out; which pairs it finds is the same
      // (box_distance2(), the margin below). A uniform scene's cells hold
      // about two automata: no cell is binned and the tables stay empty (a
      // rebuild's peak memory unchanged).
      constexpr unsigned int binned_from = 24;
      std::vector<Bin>       bins, cell_box;
      // (per local cell, its bins bins_first[c] ... bins_first[c + 1],
      // none where the cell is not binned; empty where none is)
      std::vector<unsigned int> bins_first;
      for (unsigned int c = 0; c < n_cells && bins_first.empty(); ++c)
        if (first[c + 1] - first[c] >= binned_from)
          {
            bins_first.assign(n_cells + 1, 0);
            cell_box.resize(n_cells);
          }
      if (!bins_first.empty())
        {
          std::vector<unsigned int> key, count, sorted;
          for (unsigned int c = 0; c < n_cells; ++c)
            {
              bins_first[c]        = bins.size();
              const unsigned int n = first[c + 1] - first[c];
              if (n < binned_from)
                continue;
              cell_box[c] = bin_of(members, first[c], first[c + 1], automata);
              unsigned int m = 2;
              while (m < 4 && 3 * (m + 1) * (m + 1) * (m + 1) <= n)
                ++m;
              // counting sort of the cell's members by bin (stable)
              const Bin &box = cell_box[c];
              key.resize(n);
              count.assign(m * m * m + 1, 0);
              for (unsigned int k = 0; k < n; ++k)
                {
                  unsigned int b = 0;
                  for (unsigned int e = 0; e < 3; ++e)
                    {
                      const double w = box.hi[e] - box.lo[e];
                      const double f
                        = w > 0 ? (x[members[first[c] + k]][e] - box.lo[e]) / w
                                : 0.;
                      b = b * m
                          + std::min(m - 1, static_cast<unsigned int>(f * m));
                    }
                  key[k] = b;
                  ++count[b + 1];
                }
              std::partial_sum(count.begin(), count.end(), count.begin());
              sorted.resize(n);
              for (unsigned int k = 0; k < n; ++k)
                sorted[count[key[k]]++] = members[first[c] + k];
              std::copy(sorted.begin(),
                        sorted.end(),
                        members.begin() + first[c]);
              // (count[b] is now the end of bin b)
              unsigned int begin = 0;
              for (unsigned int b = 0; b < m * m * m; ++b)
                {
                  if (count[b] > begin)
                    bins.push_back(bin_of(members,
                                          first[c] + begin,
                                          first[c] + count[b],
                                          automata));
                  begin = count[b];
                }
            }
          bins_first[n_cells] = bins.size();
        }
      const auto binned = [&](const unsigned int c) {
        return !bins_first.empty() && bins_first[c] < bins_first[c + 1];
      };
      // The largest pair-list range of two groups of automata: that of their
      // summaries, for the ranges grow with the size level and are larger
      // near a change of size (checked here).
      if (graded_range)
        for (unsigned int L = 0; L < (*graded_range)[0].size(); ++L)
          Assert((*graded_range)[1][L] >= (*graded_range)[0][L]
                   && (L == 0
                       || ((*graded_range)[0][L] >= (*graded_range)[0][L - 1]
                           && (*graded_range)[1][L]
                                >= (*graded_range)[1][L - 1])),
                 dealii::ExcInternalError());
      // Boxes closer than the range may hold a pair: the relative margin
      // covers the rounding of the sums of squares (box_distance2()).
      const auto may_hold_pairs
        = [&](const Bin &a, const Bin &b, const std::array<double, 3> &s) {
            const double r = graded_range
                               ? AutomatonArrays::pair_list_range(*graded_range,
                                                                  a.level,
                                                                  b.level)
                               : range;
            return box_distance2(a, b, s) < r * r * (1 + 1e-9);
          };

      struct Candidate // 12 bytes: the peak memory of a rebuild
      {
        std::uint32_t i, j;
        unsigned char shift;
      };
      std::vector<Candidate> found;
      found.reserve(std::size_t(n_owned) * 7);
      const double range2 = range * range;
      // Every pair of automata a of members[a_begin ... a_end) and b of
      // members[b_begin ... b_end), b seen through image shift code @p shift.
      const auto search = [&](const unsigned int  a_begin,
                              const unsigned int  a_end,
                              const unsigned int  b_begin,
                              const unsigned int  b_end,
                              const unsigned char shift) {
        const auto &s = cells.shift_vector(shift);
        for (unsigned int ia = a_begin; ia < a_end; ++ia)
          {
            const unsigned int a = members[ia];
            for (unsigned int ib = b_begin; ib < b_end; ++ib)
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
                  found.push_back({a, b, shift});
                else
                  found.push_back({b, a, Decomposition::opposite_shift(shift)});
              }
          }
      };
      for (unsigned int c = 0; c < cells.n_owned_cells(); ++c)
        cells.for_each_neighbour(c, [&](const Decomposition::Neighbour &nb) {
          const auto &s = cells.shift_vector(nb.shift);
          if (!binned(c))
            search(first[c],
                   first[c + 1],
                   first[nb.cell],
                   first[nb.cell + 1],
                   nb.shift);
          else
            for (unsigned int ka = bins_first[c]; ka < bins_first[c + 1]; ++ka)
              {
                const Bin &bin_a = bins[ka];
                if (!binned(nb.cell))
                  search(bin_a.begin,
                         bin_a.end,
                         first[nb.cell],
                         first[nb.cell + 1],
                         nb.shift);
                else if (may_hold_pairs(bin_a, cell_box[nb.cell], s))
                  for (unsigned int kb = bins_first[nb.cell];
                       kb < bins_first[nb.cell + 1];
                       ++kb)
                    if (may_hold_pairs(bin_a, bins[kb], s))
                      search(bin_a.begin,
                             bin_a.end,
                             bins[kb].begin,
                             bins[kb].end,
                             nb.shift);
              }
        });
      std::vector<Bin>().swap(bins);
      std::vector<Bin>().swap(cell_box);
      std::vector<unsigned int>().swap(bins_first);
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
      chunk_for_pipeline(n_owned);
    }


    void
    PairList::chunk_for_pipeline(const unsigned int n_owned)
    {
      const unsigned int n_pairs = pi.size();
      chunk_automaton.assign({0u});
      chunk_pair.assign({0u});
      chunk_lag     = 0;
      bool in_order = true;
      for (unsigned int p = 0; p < n_pairs && in_order; ++p)
        in_order = pi[p] < n_owned && pj[p] < n_owned
                   && (p == 0 || pi[p] >= pi[p - 1]);
      if (!in_order)
        {
          chunk_automaton.push_back(n_owned);
          chunk_pair.push_back(n_pairs);
          return;
        }
      // chunks of whole automata (their pairs as i), the last one of the
      // rest; each automaton's chunk, for the lag
      std::vector<unsigned int> chunk_of(n_owned);
      for (unsigned int k = 0, p = 0; k < n_owned; ++k)
        {
          chunk_of[k] = chunk_automaton.size() - 1;
          while (p < n_pairs && pi[p] == k)
            ++p;
          if (p - chunk_pair.back() >= pairs_per_chunk || k + 1 == n_owned)
            {
              chunk_automaton.push_back(k + 1);
              chunk_pair.push_back(p);
            }
        }
      if (n_owned == 0)
        {
          chunk_automaton.push_back(0);
          chunk_pair.push_back(n_pairs);
        }
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          Assert(chunk_of[pj[p]] >= chunk_of[pi[p]],
                 dealii::ExcInternalError());
          chunk_lag = std::max(chunk_lag, chunk_of[pj[p]] - chunk_of[pi[p]]);
        }
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
                      j_pairs,
                      chunk_automaton,
                      chunk_pair);
    }
  } // namespace mca
} // namespace tribodyn
