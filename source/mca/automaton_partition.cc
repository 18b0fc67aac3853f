// The partition of the automata over the ranks and their ghost copies
// (automaton_partition.h): migration at a pair-list rebuild, the order of
// the owned automata, the ghosts, and the partition weighted anew.
//
// Rebalancing. At set-up p4est cuts its curve so that the ranks hold equal
// work (the cells weighted by the automata the packing puts there,
// AutomatonSystem::setup()). The automata then move: the upper body of a
// friction scene slides over the lower one, a body compresses, and the work
// of the ranks drifts apart. At a pair-list rebuild where the imbalance
// (largest rank's automata over the mean) has passed Partition/Rebalance
// threshold, the cells are weighted by the automata they hold now and
// partitioned anew (deal.II's `weight` signal and repartition(), as at
// set-up), and everything a rank holds between two steps follows its cell:
// the automata as particles of the ParticleHandler, the records attached to
// them (the pair states) as particles of a second one, each at the place of
// its automaton (deal.II moves the particles of a cell with it). The new
// owners then build their ghosts and pair lists as at any rebuild; results
// do not depend on the partition beyond round-off.
//
// Checkpoints: a rank keeps the weights it gave at each rebalance. On
// resume, setup() builds the set-up partition on the same ranks, and
// replaying the weights in order rebuilds the checkpointed partition (p4est
// cuts by the weights alone), so the saved arrays fit it. On another number
// of ranks the weights are not replayed (redistribution.cc).

#include <algorithm>
#include <numeric>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/mca/automaton_partition.h>
#include <tribodyn/mca/system_figures.h>

namespace tribodyn
{
  namespace mca
  {
    AutomatonPartition::AutomatonPartition(const Parameters    &parameters,
                                           const MPI_Comm       communicator,
                                           AutomatonArrays     &the_automata,
                                           const SystemScalars &the_scalars)
        : prm(parameters)
        , comm(communicator)
        , n_ranks(dealii::Utilities::MPI::n_mpi_processes(communicator))
        , rank(dealii::Utilities::MPI::this_mpi_process(communicator))
        , automata(the_automata)
        , scalars(the_scalars)
        , decomposition(parameters.geometry,
                        parameters.geometry.largest_pair_distance()
                          * (1 + parameters.interaction.skin),
                        parameters.partition.mesh_cells_per_rank,
                        parameters.partition.automaton_order,
                        communicator)
    {
    }


    void
    AutomatonPartition::setup(const Decomposition::CellCost &cost)
    {
      decomposition.setup(cost);
      exchange.reinit(comm, decomposition.neighbour_ranks());
      // The particle handler carries the automata that change rank at a
      // rebuild (their state in the particle properties); it is empty
      // between rebuilds.
      particles = std::make_unique<dealii::Particles::ParticleHandler<3>>(
        decomposition.triangulation(),
        mapping,
        automata.automaton_fields.record_width());
    }


    void
    AutomatonPartition::unpack_automaton(const unsigned int  k,
                                         const std::uint32_t the_id,
                                         const Point3       &location,
                                         const double       *props)
    {
      automata.id[k]      = the_id;
      automata.x[k]       = location;
      automata.cell_of[k] = decomposition.local_cell(automata.x[k]);
      automata.automaton_fields.unpack(k, props);
    }


    void
    AutomatonPartition::check_automata_arrived(const unsigned int n_misplaced,
                                               const std::string &move) const
    {
      const unsigned long long n_now
        = dealii::Utilities::MPI::sum<unsigned long long>(automata.n_owned,
                                                          comm);
      throw_collectively(comm,
                         n_misplaced > 0 || n_now != scalars.n_global,
                         "Internal error: " + move
                           + " lost or misplaced automata ("
                           + std::to_string(n_now) + " of "
                           + std::to_string(scalars.n_global) + ").");
    }


    AutomatonPartition::Migration
    AutomatonPartition::plan_migration() const
    {
      const unsigned int n_owned = automata.n_owned;
      const auto        &x       = automata.x;
      // Wrap into the box; find who owns the new cell.
      Migration plan;
      plan.destination.assign(n_owned, rank);
      plan.new_cell.assign(n_owned, Decomposition::invalid);
      plan.crossed.assign(n_owned, 0);
      unsigned int       n_lost = 0;
      std::ostringstream lost;
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          const Point3       p = decomposition.wrap(x[k]);
          const unsigned int c = decomposition.local_cell(p);
          if (c == Decomposition::invalid)
            {
              if (n_lost++ < 3)
                lost << " automaton " << automata.id[k] << " at (" << x[k]
                     << ")";
              continue;
            }
          // x itself is wrapped by migrate(), after the caller has used the
          // pair vectors, whose image shifts refer to unwrapped x
          plan.crossed[k]     = !(p == x[k]);
          plan.new_cell[k]    = c;
          plan.destination[k] = decomposition.owner(c);
        }
      throw_collectively(
        comm,
        n_lost > 0,
        std::to_string(n_lost)
          + " automata left the simulation box (Geometry/Domain lower and "
            "upper) through a non-periodic side, e.g."
          + lost.str()
          + ". Enlarge the box to leave room for the motion, or hold the "
            "bodies with boundary groups.");
      return plan;
    }


    void
    AutomatonPartition::migrate(const Migration &plan)
    {
      const unsigned int n_owned = automata.n_owned;
      auto              &x       = automata.x;
      auto              &fields  = automata.automaton_fields;
      for (unsigned int k = 0; k < n_owned; ++k)
        if (plan.new_cell[k] != Decomposition::invalid)
          x[k] = decomposition.wrap(x[k]);

      // The departing automata travel as particles of deal.II's
      // ParticleHandler: inserted in the (owned) cell they were in and
      // sorted into the cell, and rank, that now contains them. deal.II
      // 9.4's search for the new cell does not follow periodic faces (it
      // loses such particles, as its ghost exchange ignores them), so the
      // automata that crossed a periodic face go to their new owner point
      // to point, with the same record.
      particles->clear_particles();
      const unsigned int n_props = fields.record_width();
      Assert(particles->n_properties_per_particle() == n_props,
             dealii::ExcInternalError());
      std::vector<double>              props(n_props);
      std::vector<std::vector<double>> out_automata(
        decomposition.neighbour_ranks().size());
      for (unsigned int k = 0; k < n_owned; ++k)
        if (plan.destination[k] != rank)
          {
            fields.pack(k, props.data());
            if (plan.crossed[k])
              {
                auto &buf = out_automata[decomposition.neighbour_index(
                  plan.destination[k])];
                buf.push_back(automata.id[k]);
                buf.insert(buf.end(), x[k].begin_raw(), x[k].end_raw());
                buf.insert(buf.end(), props.begin(), props.end());
                continue;
              }
            const auto cell = decomposition.dealii_cell(automata.cell_of[k]);
            particles->insert_particle(
              x[k],
              mapping.transform_real_to_unit_cell(cell, x[k]),
              automata.id[k],
              cell,
              dealii::ArrayView<const double>(props.data(), props.size()));
          }
      particles->sort_particles_into_subdomains_and_cells();
      const auto in_automata = exchange.exchange(out_automata, 83);

      // Keep the automata that stay, append the arrivals.
      unsigned int kept = 0;
      for (unsigned int k = 0; k < n_owned; ++k)
        if (plan.destination[k] == rank)
          {
            automata.cell_of[k] = plan.new_cell[k];
            if (kept != k)
              fields.move(k, kept);
            ++kept;
          }
      const unsigned int record    = 4 + n_props;
      unsigned int       n_arrived = particles->n_locally_owned_particles();
      for (const auto &buf : in_automata)
        n_arrived += buf.size() / record;
      automata.n_owned = kept + n_arrived;
      fields.resize(automata.n_owned);
      unsigned int k = kept, n_bad = 0;
      auto         arrive = [&](const std::uint32_t the_id,
                        const Point3       &location,
                        const double       *record_props) {
        unpack_automaton(k, the_id, location, record_props);
        n_bad += automata.cell_of[k] >= decomposition.n_owned_cells();
        ++k;
      };
      for (const auto &particle : *particles)
        arrive(particle.get_id(),
               particle.get_location(),
               particle.get_properties().data());
      for (const auto &buf : in_automata)
        for (std::size_t o = 0; o + record <= buf.size(); o += record)
          arrive(static_cast<std::uint32_t>(buf[o]),
                 Point3(buf[o + 1], buf[o + 2], buf[o + 3]),
                 buf.data() + o + 4);
      particles->clear_particles();
      check_automata_arrived(n_bad, "the migration of automata between ranks");
    }


    void
    AutomatonPartition::order_owned_automata()
    {
      const unsigned int n_owned = automata.n_owned;
      const auto        &id      = automata.id;
      const auto        &cell_of = automata.cell_of;
      auto              &order   = automata.order;
      const auto        &cells   = decomposition;
      auto              &fields  = automata.automaton_fields;
      // By their places in the automata's order (the curve of the cells,
      // or the layers of the slabs: Decomposition::curve_index()), then by
      // id: a global order, the same on any partition.
      std::vector<std::uint64_t> cell_curve(n_owned);
      for (unsigned int k = 0; k < n_owned; ++k)
        cell_curve[k] = cells.curve_index(cell_of[k], automata.x[k]);
      std::vector<unsigned int> perm(n_owned);
      std::iota(perm.begin(), perm.end(), 0u);
      std::sort(perm.begin(), perm.end(), [&](unsigned a, unsigned b) {
        return cell_curve[a] != cell_curve[b] ? cell_curve[a] < cell_curve[b]
                                              : id[a] < id[b];
      });
      fields.permute(perm);
      {
        const auto copy = cell_curve;
        for (unsigned int k = 0; k < n_owned; ++k)
          cell_curve[k] = copy[perm[k]];
      }
      order.resize(n_owned);
      for (unsigned int k = 0, rank_in_cell = 0; k < n_owned; ++k)
        {
          rank_in_cell = (k > 0 && cell_curve[k] == cell_curve[k - 1])
                           ? rank_in_cell + 1
                           : 0;
          order[k]     = cell_curve[k] << 16 | rank_in_cell;
        }
    }


    std::vector<unsigned char>
    AutomatonPartition::cell_level_summaries() const
    {
      const unsigned int n_owned    = automata.n_owned;
      const auto        &cell_of    = automata.cell_of;
      const auto        &size_level = automata.size_level;
      const auto        &cells      = decomposition;
      // each owned cell's largest size level and whether any of its
      // automata is near a change of size (the byte of size_level)
      std::vector<unsigned char> summary(cells.n_local_cells(), 0);
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          auto &s = summary[cell_of[k]];
          s       = AutomatonArrays::merge_level_summary(s, size_level[k]);
        }
      // and those of the neighbours' cells next to the owned ones
      const unsigned int               n_nb = cells.neighbour_ranks().size();
      std::vector<std::vector<double>> out(n_nb);
      for (unsigned int n = 0; n < n_nb; ++n)
        for (const unsigned int c : cells.cells_sent_to(n))
          {
            for (const unsigned int i : cells.cell_coordinates(c))
              out[n].push_back(i);
            out[n].push_back(summary[c]);
          }
      const auto in = exchange.exchange(out, 85);
      for (unsigned int n = 0; n < n_nb; ++n)
        for (std::size_t r = 0; r + 3 < in[n].size(); r += 4)
          {
            const std::array<unsigned int, 3> ijk{
              {static_cast<unsigned int>(in[n][r]),
               static_cast<unsigned int>(in[n][r + 1]),
               static_cast<unsigned int>(in[n][r + 2])}};
            const unsigned int c = cells.local_cell(ijk);
            AssertThrow(c != Decomposition::invalid,
                        dealii::ExcInternalError());
            summary[c] = static_cast<unsigned char>(in[n][r + 3]);
          }
      return summary;
    }


    void
    AutomatonPartition::exchange_ghosts()
    {
      const unsigned int n_owned    = automata.n_owned;
      auto              &x          = automata.x;
      auto              &v          = automata.v;
      auto              &w          = automata.w;
      auto              &cell_of    = automata.cell_of;
      auto              &order      = automata.order;
      const auto        &size_level = automata.size_level;
      auto              &fields     = automata.automaton_fields;
      const auto        &cells      = decomposition;
      const bool         graded     = scalars.graded;
      const double       range      = scalars.range;
      // The automata of the owned cells next to a neighbour rank's cells,
      // in the owned order, go to that rank, but only those within their
      // pair-list range of one of its cells there: the range of the
      // automaton's size with the largest size of that cell (uniform
      // scenes: the one range). A cell is as wide as the longest pair of
      // the scene (1.12 · 4d with automata of 4d); without this choice the
      // fine automata next to another rank would all be sent, a layer 4.5
      // times thicker than their pairs reach (doc/performance.md).
      const unsigned int               n_nb = cells.neighbour_ranks().size();
      const unsigned int               ghost_width = fields.ghost_width();
      std::vector<std::vector<double>> out(n_nb);
      std::vector<std::vector<unsigned int>> send_indices(n_nb);
      // the owned automata of each owned cell, in the owned order (the
      // cells' own order need not be theirs: Partition/Automaton order)
      std::vector<unsigned int> first_of_cell(cells.n_owned_cells() + 1, 0);
      for (unsigned int k = 0; k < n_owned; ++k)
        ++first_of_cell[cell_of[k] + 1];
      std::partial_sum(first_of_cell.begin(),
                       first_of_cell.end(),
                       first_of_cell.begin());
      std::vector<unsigned int> in_cell(n_owned);
      {
        std::vector<unsigned int> fill(first_of_cell.begin(),
                                       first_of_cell.end() - 1);
        for (unsigned int k = 0; k < n_owned; ++k)
          in_cell[fill[cell_of[k]]++] = k;
      }
      const std::vector<unsigned char> summary
        = graded ? cell_level_summaries() : std::vector<unsigned char>();
      struct Reachable // a neighbour rank's cell, as seen from the owned one
      {
        Point3        lower, upper;
        unsigned char summary;
      };
      std::vector<Reachable> targets;
      for (unsigned int n = 0; n < n_nb; ++n)
        for (const unsigned int c : cells.cells_sent_to(n))
          {
            targets.clear();
            cells.for_each_neighbour(
              c, [&](const Decomposition::Neighbour &nb) {
                if (cells.owner(nb.cell) != cells.neighbour_ranks()[n])
                  return;
                Reachable t;
                cells.cell_box(cells.cell_coordinates(nb.cell),
                               t.lower,
                               t.upper);
                const auto &s = cells.shift_vector(nb.shift);
                for (unsigned int e = 0; e < 3; ++e)
                  {
                    t.lower[e] += s[e];
                    t.upper[e] += s[e];
                  }
                t.summary = graded ? summary[nb.cell] : 0;
                targets.push_back(t);
              });
            for (unsigned int m = first_of_cell[c]; m < first_of_cell[c + 1];
                 ++m)
              {
                const unsigned int k      = in_cell[m];
                bool               needed = false;
                for (const auto &t : targets)
                  {
                    const double reach
                      = graded ? AutomatonArrays::pair_list_range(
                          scalars.graded_range, size_level[k], t.summary)
                               : range;
                    double dist2 = 0;
                    for (unsigned int e = 0; e < 3; ++e)
                      {
                        const double out_of_box = std::max(
                          {t.lower[e] - x[k][e], x[k][e] - t.upper[e], 0.});
                        dist2 += out_of_box * out_of_box;
                      }
                    if (dist2
                        < reach * reach * AutomatonArrays::ghost_reach_margin)
                      {
                        needed = true;
                        break;
                      }
                  }
                if (!needed)
                  continue;
                send_indices[n].push_back(k);
                auto             &buf   = out[n];
                const std::size_t start = buf.size();
                buf.resize(start + ghost_width);
                fields.pack_ghost(k, buf.data() + start);
              }
          }
      const auto                in = exchange.exchange(out, 82);
      std::vector<unsigned int> offsets(n_nb + 1, n_owned);
      for (unsigned int n = 0; n < n_nb; ++n)
        offsets[n + 1] = offsets[n] + in[n].size() / ghost_width;
      automata.n_local = offsets[n_nb];
      fields.resize(automata.n_local);
      order.resize(automata.n_local);
      unsigned int n_bad = 0;
      for (unsigned int n = 0; n < n_nb; ++n)
        for (unsigned int g = 0, k = offsets[n]; k < offsets[n + 1]; ++g, ++k)
          {
            fields.unpack_ghost(k, in[n].data() + std::size_t(g) * ghost_width);
            cell_of[k] = cells.local_cell(x[k]);
            if (cell_of[k] == Decomposition::invalid)
              ++n_bad;
            v[k] = w[k] = {{0, 0, 0}};
          }
      throw_collectively(comm,
                         n_bad > 0,
                         "Internal error: a ghost automaton lies outside the "
                         "ghost cells of the receiving rank.");
      exchange.set_ghost_lists(std::move(send_indices), std::move(offsets));
    }


    void
    AutomatonPartition::update_ghost_kinematics() const
    {
      // one message per neighbour rank; a rank that owns no automata still
      // takes part, with empty messages, or its neighbours would wait for it
      const auto flat = [](auto &a) { return a.empty() ? nullptr : &a[0][0]; };
      if (exchange.active())
        exchange.update({{flat(automata.x), 3},
                         {flat(automata.v), 3},
                         {flat(automata.w), 3}});
    }


    void
    AutomatonPartition::restore_ghost_lists(
      std::vector<std::vector<unsigned int>> send,
      std::vector<unsigned int>              offsets)
    {
      exchange.set_ghost_lists(std::move(send), std::move(offsets));
    }


    double
    AutomatonPartition::work_imbalance() const
    {
      const double largest
        = dealii::Utilities::MPI::max(double(automata.n_owned), comm);
      return largest * n_ranks / std::max(1., double(scalars.n_global));
    }


    bool
    AutomatonPartition::rebalance_due() const
    {
      const double threshold = prm.partition.rebalance_threshold;
      if (n_ranks == 1 || threshold == 0)
        return false;
      // Past the threshold, and grown by half of its margin since the last
      // partition: a partition that cannot do better (cells coarser than a
      // rank's share of the work) is not repeated at every rebuild.
      const double imbalance = work_imbalance();
      return imbalance > threshold
             && imbalance
                  > partition_state.partition_imbalance + 0.5 * (threshold - 1);
    }


    std::vector<double>
    AutomatonPartition::repartition(
      const std::vector<unsigned int> &attached_to,
      const std::vector<double>       &records,
      const unsigned int               width)
    {
      using Handler              = dealii::Particles::ParticleHandler<3>;
      const unsigned int n_owned = automata.n_owned;
      const auto        &x       = automata.x;
      const auto        &cell_of = automata.cell_of;
      auto              &fields  = automata.automaton_fields;
      // Weights of the owned cells: the automata they hold now (the cost
      // model of the set-up partition).
      std::vector<unsigned int> count(decomposition.n_owned_cells(), 0);
      for (unsigned int k = 0; k < n_owned; ++k)
        ++count[cell_of[k]];
      std::vector<Decomposition::CellWeight> weights(
        decomposition.n_owned_cells());
      for (unsigned int c = 0; c < decomposition.n_owned_cells(); ++c)
        weights[c] = {decomposition.cell_key(c),
                      cost_model::cost_per_automaton * count[c] + 1};
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
                                decomposition.reference_point(cell_of[k], x[k]),
                                particle_id,
                                decomposition.dealii_cell(cell_of[k]),
                                dealii::ArrayView<const double>(props,
                                                                n_props));
      };

      // The automata (all owned ones: after migrate() each is in an owned
      // cell, x wrapped into the box).
      particles->clear_particles();
      std::vector<double> props(fields.record_width());
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          fields.pack(k, props.data());
          insert(*particles, k, automata.id[k], props.data(), props.size());
        }

      // The records, each at its owned automaton.
      Handler carrier(decomposition.triangulation(), mapping, width);
      for (std::size_t r = 0; r < attached_to.size(); ++r)
        insert(carrier, attached_to[r], r, records.data() + r * width, width);

      // New partition; the particles follow their cells.
      particles->prepare_for_coarsening_and_refinement();
      carrier.prepare_for_coarsening_and_refinement();
      decomposition.repartition(weights);
      particles->unpack_after_coarsening_and_refinement();
      carrier.unpack_after_coarsening_and_refinement();
      exchange.reinit(comm, decomposition.neighbour_ranks());

      // Read them back.
      automata.n_owned = particles->n_locally_owned_particles();
      automata.n_local = automata.n_owned;
      fields.resize(automata.n_owned);
      unsigned int k = 0, n_bad = 0;
      for (const auto &particle : *particles)
        {
          unpack_automaton(k,
                           static_cast<std::uint32_t>(particle.get_id()),
                           particle.get_location(),
                           particle.get_properties().data());
          n_bad += automata.cell_of[k] >= decomposition.n_owned_cells();
          ++k;
        }
      particles->clear_particles();
      std::vector<double> received;
      received.reserve(std::size_t(carrier.n_locally_owned_particles())
                       * width);
      for (const auto &particle : carrier)
        {
          const auto r = particle.get_properties();
          received.insert(received.end(), r.begin(), r.end());
        }
      check_automata_arrived(n_bad, "the new partition");

      // Remembered for checkpoints (replay_rebalances()).
      auto &history = partition_state.rebalance_history;
      history.push_back(weights.size());
      for (const auto &w : weights)
        {
          history.push_back(w.key);
          history.push_back(w.weight);
        }
      ++partition_state.rebalance_count;
      partition_state.partition_imbalance = work_imbalance();
      return received;
    }


    void
    AutomatonPartition::replay_rebalances()
    {
      const auto &history = partition_state.rebalance_history;
      std::size_t o       = 0;
      while (o < history.size())
        {
          const std::size_t n = history[o++];
          AssertThrow(o + 2 * n <= history.size(), dealii::ExcInternalError());
          std::vector<Decomposition::CellWeight> weights(n);
          for (auto &w : weights)
            {
              w.key    = history[o++];
              w.weight = static_cast<unsigned int>(history[o++]);
            }
          decomposition.repartition(weights);
        }
      exchange.reinit(comm, decomposition.neighbour_ranks());
    }
  } // namespace mca
} // namespace tribodyn
