// Restart on another number of ranks. A checkpoint holds one state per
// writing rank, numbered by that run's partition. On M ranks, each rank
// reads the states of the writers r, r + M, ... (CheckpointStore::read())
// and turns them into records that know their place:
//
//  - an automaton: its position at the last pair-list rebuild (x_at_rebuild)
//    and now, its id, the migration record of a rebuild
//    (automaton_fields.pack()) and what lives from one step to the next
//    beyond it (inverse fabric tensor, the "neighbourhood changed" flag, the
//    damping force of the last step);
//  - a pair state, once for each automaton of the pair its writer owned:
//    that automaton's position at the last rebuild, the pair's key, the
//    automaton's id and its side's neighbourhood weight beta (valid on the
//    owner's side only), then the persistent pair fields in id order
//    (pair_fields.pack(), as a migration carries them);
//
// and sends them to the ranks whose cells held the automaton at the last
// rebuild (PointRouter: deal.II's global bounding-box tree).
// The new owners then redo the last rebuild on this partition: with the
// automata at their positions of then, they order them, exchange ghosts and
// list the pairs (with a range wider by 1e-4 for the single-precision
// positions), keep exactly the pairs of the checkpointed list (those with a
// record), and take back the positions of now, each pair's state, the
// weights beta and the inverse fabric tensors (computed at the last change
// of a neighbourhood, not recomputed). The pair list, its order (the order
// keys depend on the cells of then only) and the next rebuild's step are
// those of the uninterrupted run, which the continued one equals to the
// round-off of sums over ranks (ctests stability_*_restart_ranks_*). The
// partition is this run's set-up one; the rebalances of the checkpointed
// run are not replayed.
#include "record_bits.h"

#include <algorithm>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/redistribution.h>
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
      // An automaton record: position at the last rebuild, id, position
      // now, the migration record, then the step-to-step state beyond it
      // (with flags: present at the writer).
      namespace field
      {
        constexpr unsigned int x_rebuild = 0, id = 3, x = 4, props = 7;
      }
      constexpr unsigned int extras
        = 6 /* fabric */ + 1 /* changed */ + 3 /* f_damp */ + 2 /* flags */;
      // A pair record's head: position at the last rebuild, key, id of the
      // side, its beta.
      constexpr unsigned int pair_head = 6;
      // Pair-list range of the listing on the positions of the last rebuild
      // (single precision), relative: wide enough for their round-off; the
      // pairs beyond the checkpointed list are dropped again.
      constexpr double listing_margin = 1e-4;

    } // namespace


    void
    AutomatonSystem::absorb_current_arrays()
    {
      // the sides' many-body stresses travel as their offsets (mu = 0)
      fold_many_body_stress();
      // This writer's partial sums (the reports sum them over the ranks).
      for (unsigned int i = 0; i < n_works; ++i)
        absorbed.work[i] += work[i];
      absorbed.dropped += dropped_bonds;
      // (the groups' reactions and displacements too)
      const auto add_group_sums
        = [](std::vector<Vec3> &sums, const std::vector<Vec3> &of_writer) {
            sums.resize(of_writer.size(), Vec3{{0, 0, 0}});
            for (unsigned int g = 0; g < of_writer.size(); ++g)
              for (unsigned int c = 0; c < 3; ++c)
                sums[g][c] += of_writer[g][c];
          };
      add_group_sums(absorbed.group_reaction, loads.state().group_reaction);
      add_group_sums(absorbed.group_displacement,
                     loads.state().group_displacement);

      // Its owned automata.
      const bool  has_fabric = fabric_inverse.size() >= n_owned;
      const auto &f_damp     = loads.state().f_damp;
      const bool  has_damp   = loads.damping()
                            && loads.state().f_damp_rebuild == rebuild_count
                            && f_damp.size() == n_owned;
      const unsigned int stride
        = field::props + automaton_fields.record_width() + extras;
      std::vector<double> record(stride, 0.);
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          std::fill(record.begin(), record.end(), 0.);
          for (unsigned int c = 0; c < 3; ++c)
            {
              record[field::x_rebuild + c] = x_at_rebuild[k][c];
              record[field::x + c]         = x[k][c];
            }
          record[field::id] = id[k];
          automaton_fields.pack(k, record.data() + field::props);
          double *e
            = record.data() + field::props + automaton_fields.record_width();
          if (has_fabric)
            std::copy_n(fabric_inverse[k].begin(), 6, e);
          e[6] = k < changed.size() ? changed[k] : 1;
          if (has_damp)
            std::copy_n(f_damp[k].begin(), 3, e + 7);
          e[10] = has_fabric;
          e[11] = has_damp;
          absorbed.automata.insert(absorbed.automata.end(),
                                   record.begin(),
                                   record.end());
        }

      // The states of their pairs, one record per owned automaton of a pair.
      const unsigned int width = pair_head + pair_fields.width();
      record.assign(width, 0.);
      for (unsigned int p = 0; p < pi.size(); ++p)
        for (unsigned int side = 0; side < 2; ++side)
          {
            const unsigned int k = side == 0 ? pi[p] : pj[p];
            if (!owned(k))
              continue;
            for (unsigned int c = 0; c < 3; ++c)
              record[c] = x_at_rebuild[k][c];
            record[3] = bits_to_double(pair_key(id[pi[p]], id[pj[p]]));
            record[4] = id[k];
            record[5] = side == 0 ? beta_i[p] : beta_j[p];
            pair_fields.pack(p,
                             id[pi[p]] > id[pj[p]],
                             pair_distance(p),
                             record.data() + pair_head);
            absorbed.pairs.insert(absorbed.pairs.end(),
                                  record.begin(),
                                  record.end());
          }
    }


    void
    AutomatonSystem::redistribute_absorbed()
    {
      // Each record to the ranks whose cells may hold it: boxes of this
      // rank's cells merged at one level above the cells (a few per rank).
      const int top
        = static_cast<int>(partition.cells().triangulation().n_global_levels())
          - 1;
      const PointRouter<3> router(partition.cells().triangulation(),
                                  static_cast<unsigned int>(
                                    std::max(0, top - 1)),
                                  comm);
      const unsigned int   stride
        = field::props + automaton_fields.record_width() + extras;
      const unsigned int  width       = pair_head + pair_fields.width();
      std::vector<double> in_automata = router.route(absorbed.automata, stride);
      std::vector<double>().swap(absorbed.automata);
      std::vector<double> in_pairs = router.route(absorbed.pairs, width);
      std::vector<double>().swap(absorbed.pairs);
      auto owned_here = [this](const double *r) {
        return partition.cells().local_cell(Point3(r[0], r[1], r[2]))
               < partition.cells().n_owned_cells();
      };

      // Whether the pairs store their sides' many-body offsets, as the
      // writers did (all of them alike; a rank that read no state takes it
      // from rank 0): it decides what the records below carry, the
      // automata's common offsets or the pairs' own.
      mb_stored = dealii::Utilities::MPI::broadcast(comm, mb_stored, 0);
      if (mb_stored)
        std::vector<double>().swap(mb_offset);

      // The automata of the owned cells, at their positions of the last
      // rebuild (the migration's unpacking); the rest of each record by id.
      std::vector<std::size_t> mine;
      for (std::size_t o = 0; o + stride <= in_automata.size(); o += stride)
        if (owned_here(in_automata.data() + o))
          mine.push_back(o);
      n_owned = n_local = mine.size();
      automaton_fields.resize(n_owned);
      std::vector<std::pair<std::uint32_t, std::size_t>> record_of(n_owned);
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          const double *r = in_automata.data() + mine[k];
          partition.unpack_automaton(k,
                                     static_cast<std::uint32_t>(r[field::id]),
                                     Point3(r[0], r[1], r[2]),
                                     r + field::props);
          record_of[k] = {id[k], mine[k]};
        }
      std::sort(record_of.begin(), record_of.end());
      partition.check_automata_arrived(
        0, "the restart on another number of ranks");

      // The pair states of the owned automata (as received over a
      // rebuild), and each owned side's weight beta by (key, id).
      std::vector<std::pair<std::pair<std::uint64_t, std::uint32_t>, double>>
        betas;
      kept_keys.clear();
      kept_states.clear();
      for (std::size_t o = 0; o + width <= in_pairs.size(); o += width)
        {
          const double *r = in_pairs.data() + o;
          if (!owned_here(r))
            continue;
          const std::uint64_t key = double_to_bits(r[3]);
          kept_keys.emplace_back(key, kept_keys.size());
          kept_states.insert(kept_states.end(), r + pair_head, r + width);
          betas.push_back({{key, static_cast<std::uint32_t>(r[4])}, r[5]});
        }
      std::vector<double>().swap(in_pairs);
      std::sort(kept_keys.begin(), kept_keys.end());
      std::sort(betas.begin(), betas.end());

      // The run's counters, the same on every writer (a rank that read no
      // state takes them from rank 0); this run's partition is the set-up
      // one; the sums of this rank's writers.
      std::vector<double> counters = {current_time,
                                      double(n_steps_done),
                                      double(rebuild_count),
                                      double(partition.state().rebalance_count),
                                      loads.contact_time()};
      counters      = dealii::Utilities::MPI::broadcast(comm, counters, 0);
      current_time  = counters[0];
      n_steps_done  = static_cast<unsigned long>(counters[1]);
      rebuild_count = static_cast<unsigned int>(counters[2]);
      partition.state().rebalance_count
        = static_cast<unsigned int>(counters[3]);
      loads.set_contact_time(counters[4]);
      partition.state().rebalance_history.clear();
      work                       = absorbed.work;
      dropped_bonds              = absorbed.dropped;
      auto &loads_state          = loads.state();
      loads_state.group_reaction = absorbed.group_reaction;
      loads_state.group_reaction.resize(prm.boundary.groups.size(),
                                        Vec3{{0, 0, 0}});
      loads_state.group_displacement = absorbed.group_displacement;
      loads_state.group_displacement.resize(prm.boundary.groups.size(),
                                            Vec3{{0, 0, 0}});
      absorbed = Absorbed();

      // The last rebuild again, on this partition, at the positions of
      // then: order, ghosts, pairs (rebuild()), with the range widened by
      // listing_margin; then only the pairs of the checkpointed list.
      agreed_displacement2 = -1;
      old_pairs.clear();
      old_flags.clear();
      partition.order_owned_automata();
      const double     saved_range  = range;
      const RangeTable saved_graded = graded_range;
      range *= 1 + listing_margin;
      for (auto &row : graded_range)
        for (double &r : row)
          r *= 1 + listing_margin;
      partition.exchange_ghosts();
      build_pair_list();
      range        = saved_range;
      graded_range = saved_graded;
      std::vector<std::uint64_t>().swap(order);
      {
        std::vector<unsigned char> keep(pi.size(), 0);
        for (unsigned int p = 0; p < pi.size(); ++p)
          keep[p] = std::binary_search(
            kept_keys.begin(),
            kept_keys.end(),
            std::make_pair(pair_key(id[pi[p]], id[pj[p]]), std::uint32_t(0)),
            [](const auto &a, const auto &b) { return a.first < b.first; });
        PairList::compact(keep);
      }
      // Every checkpointed pair of an owned automaton must be listed again.
      unsigned long long n_missed = 0;
      {
        std::vector<std::uint64_t> listed(pi.size());
        for (unsigned int p = 0; p < pi.size(); ++p)
          listed[p] = pair_key(id[pi[p]], id[pj[p]]);
        std::sort(listed.begin(), listed.end());
        for (const auto &entry : kept_keys)
          n_missed
            += !std::binary_search(listed.begin(), listed.end(), entry.first);
      }
      throw_collectively(comm,
                         n_missed > 0,
                         "Internal error: " + std::to_string(n_missed)
                           + " pairs of the checkpoint were not found again "
                             "on this partition.");

      // The positions of now (and the ghosts' from their owners), the
      // pair states, weights, inverse fabric tensors, flags and damping
      // forces of the checkpoint.
      const bool fabric_stored = plastic_scene || bond_scene;
      fabric_inverse.assign(fabric_stored ? n_owned : 0,
                            Sym3{{1, 1, 1, 0, 0, 0}});
      changed.assign(n_local, 0);
      auto &f_damp = loads_state.f_damp;
      f_damp.assign(loads.damping() ? n_owned : 0, Vec3{{0, 0, 0}});
      x_at_rebuild.resize(n_owned);
      known_displacement2 = -1;
      bool any_damp       = false;
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          const auto it
            = std::lower_bound(record_of.begin(),
                               record_of.end(),
                               std::make_pair(id[k], std::size_t(0)));
          const double *r = in_automata.data() + it->second;
          for (unsigned int c = 0; c < 3; ++c)
            {
              x_at_rebuild[k][c] = static_cast<float>(r[field::x_rebuild + c]);
              x[k][c]            = r[field::x + c];
            }
          const double *e = r + field::props + automaton_fields.record_width();
          if (fabric_stored && e[10] != 0)
            std::copy_n(e, 6, fabric_inverse[k].begin());
          changed[k] = e[6] != 0;
          if (loads.damping())
            {
              std::copy_n(e + 7, 3, f_damp[k].begin());
              any_damp = any_damp || e[11] != 0;
            }
        }
      partition.update_ghost_kinematics();
      restore_pair_states(false);
      index_by_automaton(n_owned);
      const unsigned int n_pairs = pi.size();
      beta_i.assign(n_pairs, 0);
      beta_j.assign(n_pairs, 0);
      for (unsigned int p = 0; p < n_pairs; ++p)
        for (unsigned int side = 0; side < 2; ++side)
          {
            const unsigned int k = side == 0 ? pi[p] : pj[p];
            if (!owned(k))
              continue;
            const std::pair<std::uint64_t, std::uint32_t> which{
              pair_key(id[pi[p]], id[pj[p]]), id[k]};
            const auto it = std::lower_bound(betas.begin(),
                                             betas.end(),
                                             which,
                                             [](const auto &e, const auto &v) {
                                               return e.first < v;
                                             });
            if (it != betas.end() && it->first == which)
              (side == 0 ? beta_i : beta_j)[p] = it->second;
          }
      any_changed = true;
      // kappa, gamma, G of the checkpoint's weights and stresses
      mb_mu.assign(n_local, 0);
      mb_state.assign(n_owned, {});
      mb_shape.assign(n_owned, ManyBodyShape::general);
      for (unsigned int k = 0; k < n_owned; ++k)
        update_many_body_state(k);
      // the damping forces of the last step stay valid when they were
      // (else recomputed at the next half kick, as after any rebuild)
      loads_state.f_damp_rebuild = rebuild_count;
      if (!any_damp)
        std::vector<Vec3>().swap(f_damp);
      partition.state().partition_imbalance = work_imbalance();
    }
  } // namespace mca
} // namespace tribodyn
