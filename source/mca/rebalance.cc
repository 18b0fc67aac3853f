// The partition weighted anew during a run. At set-up p4est cuts its curve
// so that the ranks hold equal work (the cells weighted by the automata the
// packing puts there, AutomatonSystem::setup()). The automata then move:
// the upper body of a friction scene slides over the lower one, a body
// compresses, and the work of the ranks drifts apart. At a pair-list
// rebuild where the imbalance (largest rank's automata over the mean) has
// passed Partition/Rebalance threshold, the cells are weighted by the
// automata they hold now and partitioned anew (deal.II's `weight` signal
// and repartition(), as at set-up), and everything a rank holds between two
// steps follows its cell: the automata as particles of the ParticleHandler,
// the pair states as particles of a second one, each at the place of one
// of the pair's automata (deal.II moves the particles of a cell with it).
// The new owners then build their ghosts and pair lists as at any rebuild;
// results do not depend on the partition beyond round-off.
//
// Checkpoints: a rank keeps the weights it gave at each rebalance. On
// resume, setup() builds the set-up partition on the same ranks, and
// replaying the weights in order rebuilds the checkpointed partition (p4est
// cuts by the weights alone), so the saved arrays fit it. On another number
// of ranks the weights are not replayed (redistribution.cc).

#include "record_bits.h"

#include <algorithm>
#include <deal.II/particles/particle_handler.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/system_figures.h>

namespace tribodyn
{
  namespace mca
  {
    bool
    AutomatonSystem::rebalance_due() const
    {
      const double threshold = prm.partition.rebalance_threshold;
      if (n_ranks == 1 || threshold == 0)
        return false;
      // Past the threshold, and grown by half of its margin since the last
      // partition: a partition that cannot do better (cells coarser than a
      // rank's share of the work) is not repeated at every rebuild.
      const double imbalance = work_imbalance();
      return imbalance > threshold
             && imbalance > partition_imbalance + 0.5 * (threshold - 1);
    }


    void
    AutomatonSystem::repartition_automata()
    {
      using Handler = dealii::Particles::ParticleHandler<3>;
      // Weights of the owned cells: the automata they hold now (the cost
      // model of the set-up partition).
      std::vector<unsigned int> count(cells.n_owned_cells(), 0);
      for (unsigned int k = 0; k < n_owned; ++k)
        ++count[cell_of[k]];
      std::vector<Decomposition::CellWeight> weights(cells.n_owned_cells());
      for (unsigned int c = 0; c < cells.n_owned_cells(); ++c)
        weights[c]
          = {cells.cell_key(c), cost_model::cost_per_automaton * count[c] + 1};
      std::sort(weights.begin(),
                weights.end(),
                [](const auto &a, const auto &b) { return a.key < b.key; });

      // A particle in owned cell c at x (the cells are boxes: the reference
      // point is the relative position).
      auto insert = [&](Handler            &handler,
                        const unsigned int  k,
                        const std::uint64_t particle_id,
                        const double       *props,
                        const unsigned int  n_props) {
        handler.insert_particle(x[k],
                                cells.reference_point(cell_of[k], x[k]),
                                particle_id,
                                cells.dealii_cell(cell_of[k]),
                                dealii::ArrayView<const double>(props,
                                                                n_props));
      };

      // The automata (all owned ones: after migrate() each is in an owned
      // cell, x wrapped into the box).
      particles->clear_particles();
      std::vector<double> props(automaton_fields.record_width());
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          automaton_fields.pack(k, props.data());
          insert(*particles, k, id[k], props.data(), props.size());
        }

      // The pair-state records of migrate(true), one copy at each owned
      // automaton of the pair (both automata may go to different ranks).
      const unsigned int width = 1 + pair_fields.width();
      Handler            carrier(cells.triangulation(), mapping, width);
      std::vector<std::pair<std::uint32_t, unsigned int>> by_id(n_owned);
      for (unsigned int k = 0; k < n_owned; ++k)
        by_id[k] = {id[k], k};
      std::sort(by_id.begin(), by_id.end());
      std::vector<double> record(width);
      std::uint64_t       n_records = 0;
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
            record[0] = records::bits_to_double(key);
            std::copy_n(kept_states.begin() + std::size_t(index) * (width - 1),
                        width - 1,
                        record.begin() + 1);
            insert(carrier, it->second, n_records++, record.data(), width);
          }
      std::vector<double>().swap(kept_states);
      std::vector<std::pair<std::uint64_t, std::uint32_t>>().swap(kept_keys);

      // New partition; the particles follow their cells.
      particles->prepare_for_coarsening_and_refinement();
      carrier.prepare_for_coarsening_and_refinement();
      cells.repartition(weights);
      particles->unpack_after_coarsening_and_refinement();
      carrier.unpack_after_coarsening_and_refinement();
      neighbours.reinit(comm, cells.neighbour_ranks());

      // Read them back.
      n_owned = particles->n_locally_owned_particles();
      n_local = n_owned;
      automaton_fields.resize(n_owned);
      unsigned int k = 0, n_bad = 0;
      for (const auto &particle : *particles)
        {
          unpack_automaton(k,
                           static_cast<std::uint32_t>(particle.get_id()),
                           particle.get_location(),
                           particle.get_properties().data());
          n_bad += cell_of[k] >= cells.n_owned_cells();
          ++k;
        }
      particles->clear_particles();
      kept_keys.reserve(carrier.n_locally_owned_particles());
      kept_states.reserve(std::size_t(carrier.n_locally_owned_particles())
                          * (width - 1));
      for (const auto &particle : carrier)
        {
          const auto r = particle.get_properties();
          kept_keys.emplace_back(records::double_to_bits(r[0]),
                                 kept_keys.size());
          kept_states.insert(kept_states.end(), r.begin() + 1, r.end());
        }
      std::sort(kept_keys.begin(), kept_keys.end());
      check_automata_arrived(n_bad, "the new partition");

      // Remembered for checkpoints (replay_rebalances()).
      rebalance_history.push_back(weights.size());
      for (const auto &w : weights)
        {
          rebalance_history.push_back(w.key);
          rebalance_history.push_back(w.weight);
        }
      ++rebalance_count;
      partition_imbalance = work_imbalance();
    }


    void
    AutomatonSystem::replay_rebalances()
    {
      std::size_t o = 0;
      while (o < rebalance_history.size())
        {
          const std::size_t n = rebalance_history[o++];
          AssertThrow(o + 2 * n <= rebalance_history.size(),
                      dealii::ExcInternalError());
          std::vector<Decomposition::CellWeight> weights(n);
          for (auto &w : weights)
            {
              w.key    = rebalance_history[o++];
              w.weight = static_cast<unsigned int>(rebalance_history[o++]);
            }
          cells.repartition(weights);
        }
      neighbours.reinit(comm, cells.neighbour_ranks());
    }
  } // namespace mca
} // namespace tribodyn
