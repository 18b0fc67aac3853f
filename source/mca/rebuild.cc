// Pair-list rebuilds: the automata migrate, are repartitioned and receive
// their ghosts (the partition, automaton_partition.h), and the pair states
// follow them and are carried over to the new pair list.

#include "record_bits.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/mca/automaton_system.h>

namespace tribodyn
{
  namespace mca
  {
    using records::bits_to_double;
    using records::double_to_bits;
    using records::pair_key;

    namespace
    {
      /// Append the pair-state records of @p buf (a key, then the state in
      /// id order: @p width doubles each) to the kept states and keys.
      void
      keep_pair_records(
        const std::vector<double>                            &buf,
        const unsigned int                                    width,
        std::vector<std::pair<std::uint64_t, std::uint32_t>> &kept_keys,
        std::vector<double>                                  &kept_states)
      {
        for (std::size_t o = 0; o + width <= buf.size(); o += width)
          {
            kept_keys.emplace_back(double_to_bits(buf[o]), kept_keys.size());
            kept_states.insert(kept_states.end(),
                               buf.begin() + o + 1,
                               buf.begin() + o + width);
          }
      }
    } // namespace


    void
    AutomatonSystem::rebuild(const bool initial)
    {
      // a displacement agreed before this rebuild is measured from the
      // previous one
      agreed_displacement2 = -1;
      // the many-body energy before the rebuild; the many-body stresses
      // of the sides move with the pairs as their offsets
      // (doc/theory/mca.md §8.4)
      const double mb_energy_before = initial ? 0. : many_body_energy();
      if (!initial)
        {
          fold_many_body_stress();
          // the partition weighted anew when the work drifted apart
          // (automaton_partition.cc): the migration then carries every pair
          // state
          const bool rebalance = partition.rebalance_due();
          migrate(rebalance);
          if (rebalance)
            repartition_automata();
        }
      partition.order_owned_automata();
      partition.exchange_ghosts();
      build_pair_list();
      // the order keys are needed again at the next rebuild only
      std::vector<std::uint64_t>().swap(order);
      restore_pair_states(initial);
      changed.assign(n_local, 1);
      mb_mu.assign(n_local, 0);
      update_neighbourhood_weights(true);
      // (the weights anew: the change of the many-body energy is booked)
      work[switching_work] += mb_energy_before - many_body_energy();
      // the positions for the skin test (stored last: at the first
      // rebuild they then take memory the weights' j-side lists freed)
      x_at_rebuild.resize(n_owned);
      for (unsigned int k = 0; k < n_owned; ++k)
        for (unsigned int c = 0; c < 3; ++c)
          x_at_rebuild[k][c] = static_cast<float>(x[k][c]);
      known_displacement2 = -1;
      ++rebuild_count;
    }


    void
    AutomatonSystem::migrate(const bool all_pair_states)
    {
      // Identity of the old pairs (their states are restored by ids).
      const unsigned int n_old = pi.size();
      old_pairs.resize(n_old);
      old_flags.resize(n_old);
      for (unsigned int p = 0; p < n_old; ++p)
        {
          const std::uint32_t a = id[pi[p]], b = id[pj[p]];
          old_pairs[p] = {std::min(a, b), std::max(a, b), p};
          old_flags[p] = a > b ? 1 : 0;
          // a bonded pair now beyond the pair-list range drops out of every
          // rank's list: its bond is lost (counted once, by i's owner)
          if (bonded[p] && owned(pi[p]))
            {
              const Vec3 dn = pair_vector(p);
              if (dot(dn, dn) >= pair_range2(pi[p], pj[p]))
                ++dropped_bonds;
            }
        }

      // Before a repartition (repartition_automata()) every pair state
      // travels: this rank's too, as records like the received ones (key,
      // state in id order), packed while the pair vectors are at hand.
      const unsigned int  width = 1 + pair_fields.width();
      std::vector<double> own_records;
      if (all_pair_states)
        {
          own_records.resize(std::size_t(n_old) * width);
          for (unsigned int p = 0; p < n_old; ++p)
            {
              double *r = own_records.data() + std::size_t(p) * width;
              r[0]      = bits_to_double(pair_key(id[pi[p]], id[pj[p]]));
              pair_fields.pack(p, old_flags[p] != 0, pair_distance(p), r + 1);
            }
          old_pairs.clear();
        }

      // Where the automata go (the partition: their new cells and ranks).
      const AutomatonPartition::Migration plan = partition.plan_migration();
      const auto                         &destination = plan.destination;

      // Pair states of the pairs of departing automata go to their new
      // owners (neighbour ranks).
      const auto &nb_ranks = partition.cells().neighbour_ranks();
      std::vector<std::vector<double>> out_pairs(nb_ranks.size());
      // A record: the key (raw 64-bit word), then the state in id order.
      for (unsigned int p = 0; p < n_old; ++p)
        for (const unsigned int k : {pi[p], pj[p]})
          if (k < n_owned && destination[k] != rank)
            {
              auto &buf
                = out_pairs[partition.cells().neighbour_index(destination[k])];
              const std::size_t start = buf.size();
              buf.resize(start + width);
              buf[start] = bits_to_double(pair_key(id[pi[p]], id[pj[p]]));
              pair_fields.pack(p,
                               id[pi[p]] > id[pj[p]],
                               pair_distance(p),
                               buf.data() + start + 1);
            }
      auto in_pairs = partition.neighbours().exchange(out_pairs, 81);
      // The automata follow (x wrapped into the box: the pair vectors
      // above used the unwrapped positions).
      partition.migrate(plan);

      // Received pair states by key, for the restore.
      kept_states.clear();
      kept_keys.clear();
      in_pairs.push_back(std::move(own_records));
      for (const auto &buf : in_pairs)
        keep_pair_records(buf, width, kept_keys, kept_states);
      std::sort(kept_keys.begin(), kept_keys.end());
      // This rank's old pairs by ids (their states stay in the pair arrays
      // until restore_pair_states() gathers them).
      std::sort(old_pairs.begin(),
                old_pairs.end(),
                [](const OldPair &a, const OldPair &b) {
                  return a.lo != b.lo ? a.lo < b.lo : a.hi < b.hi;
                });
    }


    void
    AutomatonSystem::repartition_automata()
    {
      // The pair-state records of migrate(true), one copy at each owned
      // automaton of the pair (both automata may go to different ranks).
      const unsigned int width = 1 + pair_fields.width();
      std::vector<std::pair<std::uint32_t, unsigned int>> by_id(n_owned);
      for (unsigned int k = 0; k < n_owned; ++k)
        by_id[k] = {id[k], k};
      std::sort(by_id.begin(), by_id.end());
      std::vector<unsigned int> attached_to;
      std::vector<double>       records;
      for (const auto &[key, index] : kept_keys)
        for (const std::uint32_t a :
             {std::uint32_t(key >> 32), std::uint32_t(key & 0xffffffffu)})
          {
            const auto it = std::lower_bound(by_id.begin(),
                                             by_id.end(),
                                             std::make_pair(a, 0u),
                                             [](const auto &e, const auto &v) {
                                               return e.first < v.first;
                                             });
            if (it == by_id.end() || it->first != a)
              continue;
            attached_to.push_back(it->second);
            records.push_back(bits_to_double(key));
            records.insert(records.end(),
                           kept_states.begin()
                             + std::size_t(index) * (width - 1),
                           kept_states.begin()
                             + std::size_t(index + 1) * (width - 1));
          }
      std::vector<double>().swap(kept_states);
      std::vector<std::pair<std::uint64_t, std::uint32_t>>().swap(kept_keys);

      const std::vector<double> received
        = partition.repartition(attached_to, records, width);
      std::vector<double>().swap(records);

      kept_keys.reserve(received.size() / width);
      kept_states.reserve(received.size() / width * (width - 1));
      keep_pair_records(received, width, kept_keys, kept_states);
      std::sort(kept_keys.begin(), kept_keys.end());
    }


    void
    AutomatonSystem::restore_pair_states(const bool initial)
    {
      const unsigned int n_pairs = pi.size();
      // Source of each new pair's state: an old pair of this rank, a
      // received state, or none (a new pair); and whether the sides swap
      // (the old state had i = the other automaton).
      constexpr std::uint32_t    none     = PairFieldTable::none;
      constexpr std::uint32_t    received = PairFieldTable::received;
      std::vector<std::uint32_t> source(n_pairs, none);
      std::vector<unsigned char> swap(n_pairs, 0);
      if (!initial)
        for (unsigned int p = 0; p < n_pairs; ++p)
          {
            const std::uint32_t a = id[pi[p]], b = id[pj[p]];
            const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
            const bool          flip = a > b;
            const auto          it
              = std::lower_bound(old_pairs.begin(),
                                 old_pairs.end(),
                                 OldPair{lo, hi, 0},
                                 [](const OldPair &x, const OldPair &y) {
                                   return x.lo != y.lo ? x.lo < y.lo
                                                       : x.hi < y.hi;
                                 });
            if (it != old_pairs.end() && it->lo == lo && it->hi == hi)
              {
                source[p] = it->index;
                swap[p]   = ((old_flags[it->index] & 1) != 0) != flip;
                continue;
              }
            const std::uint64_t key = pair_key(a, b);
            const auto          jt  = std::lower_bound(
              kept_keys.begin(),
              kept_keys.end(),
              key,
              [](const std::pair<std::uint64_t, std::uint32_t> &e,
                 const std::uint64_t k) { return e.first < k; });
            if (jt != kept_keys.end() && jt->first == key)
              {
                source[p] = received | jt->second;
                swap[p]   = flip; // received states are in id order
              }
          }
      std::vector<OldPair>().swap(old_pairs);
      std::vector<unsigned char>().swap(old_flags);

      // Every persistent pair field, from its source (pair_fields: the one
      // list of them and of their relabelling rules); the shear factors
      // carried once any rank stores them (the old pairs' factors, all 1
      // where this rank did not).
      allocate_side_states(bonded.size(), false);
      pair_fields.remap(source, swap, kept_states, [this](const unsigned p) {
        return pair_distance(p);
      });
      std::vector<double>().swap(kept_states);
      std::vector<std::pair<std::uint64_t, std::uint32_t>>().swap(kept_keys);

      // Bonds and contacts of the initial pairs: pairs of a body at the
      // contact distance are bonded (graded scenes: the pairs near a change
      // of size that share a Voronoi face, in setup_graded_geometry()).
      if (initial)
        for (unsigned int p = 0; p < n_pairs; ++p)
          {
            const double r     = pair_distance(p);
            const double touch = graded ? 2 * pair_half_rest[p] : d;
            bonded[p]          = body_index(pi[p]) == body_index(pj[p])
                        && r < touch * (1 + 1e-6);
            in_contact[p] = r < touch * (1 + 1e-6);
          }
      if (graded)
        {
          if (initial)
            setup_graded_geometry();
          drop_inert_pairs();
        }
      allocate_side_states(pi.size(), true);
    }


    void
    AutomatonSystem::allocate_side_states(const std::size_t n_pairs,
                                          const bool        check_pairs)
    {
      // Plastic and bond scenes store them from the start, on every rank
      // alike (no message at their rebuilds); otherwise the ranks agree
      // (sticky: once stored, factors other than 1 may exist).
      bool needed = plastic_scene || bond_scene;
      if (!needed)
        {
          needed = shear_factors;
          if (check_pairs)
            for (unsigned int p = 0; p < pi.size() && !needed; ++p)
              needed = !bonded[p] || mat[pi[p]] != mat[pj[p]];
          if (n_ranks > 1)
            needed
              = dealii::Utilities::MPI::max(static_cast<int>(needed), comm);
        }
      if (needed && !shear_factors)
        {
          tau_scale_i.assign(n_pairs, 1.);
          tau_scale_j.assign(n_pairs, 1.);
        }
      shear_factors = needed;
      // The sides' many-body offsets and normal stresses from then on too,
      // once the new pairs are in place (the old ones are not at the first
      // call): each side the common offset of its automaton, the ghosts'
      // as their owners sent it, and the normal stress sig_e + m of its
      // side (PairArrays::sig_e: every pair until now a bonded pair of one
      // material; the new ones, unbonded, hold no stress). (At a rebuild
      // mu has been folded into the offsets: m = c.)
      if (check_pairs && shear_factors && !mb_stored)
        {
          Assert(mb_offset.size() >= n_local, dealii::ExcInternalError());
          Assert(sig_e.size() == n_pairs, dealii::ExcInternalError());
          mb_i.resize(n_pairs);
          mb_j.resize(n_pairs);
          sig_i.resize(n_pairs);
          sig_j.resize(n_pairs);
          for (unsigned int p = 0; p < n_pairs; ++p)
            {
              Assert(bonded[p] || sig_e[p] == 0, dealii::ExcInternalError());
              mb_i[p]  = mb_offset[pi[p]];
              mb_j[p]  = mb_offset[pj[p]];
              sig_i[p] = bonded[p] ? sig_e[p] + mb_i[p] : 0.;
              sig_j[p] = bonded[p] ? sig_e[p] + mb_j[p] : 0.;
            }
          std::vector<double>().swap(mb_offset);
          std::vector<double>().swap(sig_e);
          mb_stored = true;
        }
    }
  } // namespace mca
} // namespace tribodyn
