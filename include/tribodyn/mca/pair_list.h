// The pair list of a rank (design §6; doc/theory/mca.md §1): which pairs of
// automata interact, found through the cells of the decomposition, with
// the periodic image shift of each pair cached, and the pairs of each owned
// automaton. A part of AutomatonSystem (a base, as the automata's arrays
// and the pairs' state): it knows the automata's positions, cells and
// order keys (AutomatonArrays) and nothing of what a pair carries; the
// pairs' state (PairArrays, pair_arrays.h) is indexed by the same pair
// number p, so whoever compacts or rebuilds this list relabels the state.
#ifndef tribodyn_mca_pair_list_h
#define tribodyn_mca_pair_list_h

#include <cstdint>
#include <tribodyn/mca/automaton_arrays.h>
#include <tribodyn/mca/memory_parts.h>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    class Decomposition;

    /**
     * The pairs of automata closer than their pair-list range (automaton
     * size times 1 + skin; graded scenes: by the sizes of the two automata)
     * with at least one owned member. Pair p joins local automata pi[p]
     * and pj[p]; i is the automaton of the smaller global order key, the
     * same on every rank and partition, and the pairs are ordered by the
     * keys of i then j: every automaton sums its pairs' forces in the same
     * order on any number of ranks.
     */
    struct PairList
    {
      std::vector<std::uint32_t> pi, pj;
      std::vector<unsigned char> pshift; ///< image shift code of x_j
      /// Pairs of each owned automaton k. As i: the pairs are ordered by
      /// the key of i, so k's form one block, i_pairs_first[k] ...
      /// + i_pairs_count[k]; as j: j_pairs[j_pairs_first[k] ...
      /// j_pairs_first[k + 1]] (CSR). 32 instead of 52 bytes a list of both.
      std::vector<unsigned int>  i_pairs_first;
      std::vector<std::uint16_t> i_pairs_count;
      /// The j side's lists: built with the i side's by
      /// index_by_automaton(), dropped by release_j_lists() where no step
      /// reads them (a scene without events between its rebuilds: 28 bytes
      /// per automaton neither kept nor moved) and built again, the same,
      /// by the next for_each_pair_of() that needs them (empty: not built).
      mutable std::vector<unsigned int> j_pairs_first, j_pairs;

      unsigned int
      n_pairs() const
      {
        return pi.size();
      }

      /// The pair list of @p automata (owned and ghosts, with their order
      /// keys) in the cells of @p cells: pairs closer than @p range, or,
      /// with @p graded_range, than the range of their two size levels
      /// (AutomatonArrays::pair_list_range()).
      void
      build(const Decomposition               &cells,
            const AutomatonArrays             &automata,
            const double                       range,
            const AutomatonArrays::RangeTable *graded_range);
      /// Keep the pairs p with @p keep[p], in order (the caller relabels
      /// the pairs' state the same way).
      void
      compact(const std::vector<unsigned char> &keep);
      /// The pairs of each of the @p n_owned owned automata, for the list
      /// now (i_pairs_first ... j_pairs).
      void
      index_by_automaton(const unsigned int n_owned);
      /// Drop the j side's lists (the i side's stay): for_each_pair_of()
      /// builds them again when next called.
      void
      release_j_lists();

      /**
       * The pair kernel's pipeline (AutomatonSystem::pair_kernel()):
       * chunk c holds the owned automata chunk_automaton[c] ...
       * chunk_automaton[c + 1] and their pairs as i, chunk_pair[c] ...
       * chunk_pair[c + 1]; a pair of chunk c has its j in chunk c ...
       * c + chunk_lag. Chunks of about @p pairs_per_chunk pairs where every
       * pair joins two owned automata (the list is then ordered by the
       * owned automata), one chunk of all pairs (lag 0) where a ghost takes
       * part: its values come from the neighbour ranks once every owned
       * automaton is done. Set by index_by_automaton().
       */
      std::vector<unsigned int> chunk_automaton, chunk_pair;
      unsigned int              chunk_lag = 0;
      /// (Partition/Pairs per chunk)
      unsigned int pairs_per_chunk = 2048;
      /// Set the pipeline's chunks and lag for the list now (also after a
      /// checkpoint's lists are read back).
      void
      chunk_for_pipeline(const unsigned int n_owned);

      unsigned int
      n_chunks() const
      {
        return chunk_pair.empty() ? 0 : chunk_pair.size() - 1;
      }

      /// Call @p f(p, side) for each pair p of owned automaton @p k (side 0:
      /// k is the pair's i, 1: its j), as i first, in pair order.
      template <typename F>
      void
      for_each_pair_of(const unsigned int k, const F &f) const
      {
        if (j_pairs_first.empty()) [[unlikely]]
          index_j_side();
        const unsigned int first = i_pairs_first[k];
        for (unsigned int p = first; p < first + i_pairs_count[k]; ++p)
          f(p, 0u);
        for (unsigned int a = j_pairs_first[k]; a < j_pairs_first[k + 1]; ++a)
          f(j_pairs[a], 1u);
      }

    private:
      /// The j side's lists of the owned automata of the i side's lists.
      void
      index_j_side() const;

    public:
      /// Bytes of the list and of the pairs by automaton, as two parts
      /// (name, bytes) appended to @p parts.
      void
      memory_by_part(MemoryParts &parts) const;
    };
  } // namespace mca
} // namespace tribodyn

#endif
