// Pair-list rebuilds: migration of automata between ranks, ghosts from the
// neighbour ranks, and the pair states carried over.

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
          // (rebalance.cc): the migration then carries every pair state
          const bool rebalance = rebalance_due();
          migrate(rebalance);
          if (rebalance)
            repartition_automata();
        }
      order_owned_automata();
      exchange_ghosts();
      x_at_rebuild.resize(n_owned);
      for (unsigned int k = 0; k < n_owned; ++k)
        for (unsigned int c = 0; c < 3; ++c)
          x_at_rebuild[k][c] = static_cast<float>(x[k][c]);
      build_pair_list();
      // the order keys are needed again at the next rebuild only
      std::vector<std::uint64_t>().swap(order);
      restore_pair_states(initial);
      changed.assign(n_local, 1);
      mb_mu.assign(n_local, 0);
      update_neighbourhood_weights(true);
      // (the weights anew: the change of the many-body energy is booked)
      work[switching_work] += mb_energy_before - many_body_energy();
      ++rebuild_count;
    }


    void
    AutomatonSystem::unpack_automaton(const unsigned int  k,
                                      const std::uint32_t the_id,
                                      const Point3       &location,
                                      const double       *props)
    {
      id[k]      = the_id;
      x[k]       = location;
      cell_of[k] = cells.local_cell(x[k]);
      automaton_fields.unpack(k, props);
    }


    void
    AutomatonSystem::check_automata_arrived(const unsigned int n_misplaced,
                                            const std::string &move) const
    {
      const unsigned long long n_now
        = dealii::Utilities::MPI::sum<unsigned long long>(n_owned, comm);
      throw_collectively(comm,
                         n_misplaced > 0 || n_now != n_global,
                         "Internal error: " + move
                           + " lost or misplaced automata ("
                           + std::to_string(n_now) + " of "
                           + std::to_string(n_global) + ").");
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

      // Wrap into the box; find who owns the new cell.
      std::vector<unsigned int>  destination(n_owned, rank);
      std::vector<unsigned int>  new_cell(n_owned, Decomposition::invalid);
      std::vector<unsigned char> crossed(n_owned, 0);
      unsigned int               n_lost = 0;
      std::ostringstream         lost;
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          const Point3       p = cells.wrap(x[k]);
          const unsigned int c = cells.local_cell(p);
          if (c == Decomposition::invalid)
            {
              if (n_lost++ < 3)
                lost << " automaton " << id[k] << " at (" << x[k] << ")";
              continue;
            }
          // x itself is wrapped once the pair states are packed (they use
          // the pair vectors, whose image shifts refer to unwrapped x)
          crossed[k]     = !(p == x[k]);
          new_cell[k]    = c;
          destination[k] = cells.owner(c);
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

      // Pair states of the pairs of departing automata go to their new
      // owners (neighbour ranks).
      const auto                      &nb_ranks = cells.neighbour_ranks();
      std::vector<std::vector<double>> out_pairs(nb_ranks.size());
      // A record: the key (raw 64-bit word), then the state in id order.
      for (unsigned int p = 0; p < n_old; ++p)
        for (const unsigned int k : {pi[p], pj[p]})
          if (k < n_owned && destination[k] != rank)
            {
              auto &buf = out_pairs[cells.neighbour_index(destination[k])];
              const std::size_t start = buf.size();
              buf.resize(start + width);
              buf[start] = bits_to_double(pair_key(id[pi[p]], id[pj[p]]));
              pair_fields.pack(p,
                               id[pi[p]] > id[pj[p]],
                               pair_distance(p),
                               buf.data() + start + 1);
            }
      auto in_pairs = neighbours.exchange(out_pairs, 81);
      for (unsigned int k = 0; k < n_owned; ++k)
        if (new_cell[k] != Decomposition::invalid)
          x[k] = cells.wrap(x[k]);

      // The departing automata travel as particles of deal.II's
      // ParticleHandler: inserted in the (owned) cell they were in and
      // sorted into the cell, and rank, that now contains them. deal.II
      // 9.4's search for the new cell does not follow periodic faces (it
      // loses such particles, as its ghost exchange ignores them), so the
      // automata that crossed a periodic face go to their new owner point
      // to point, with the same record.
      particles->clear_particles();
      const unsigned int n_props = automaton_fields.record_width();
      Assert(particles->n_properties_per_particle() == n_props,
             dealii::ExcInternalError());
      std::vector<double>              props(n_props);
      std::vector<std::vector<double>> out_automata(nb_ranks.size());
      for (unsigned int k = 0; k < n_owned; ++k)
        if (destination[k] != rank)
          {
            automaton_fields.pack(k, props.data());
            if (crossed[k])
              {
                auto &buf = out_automata[cells.neighbour_index(destination[k])];
                buf.push_back(id[k]);
                buf.insert(buf.end(), x[k].begin_raw(), x[k].end_raw());
                buf.insert(buf.end(), props.begin(), props.end());
                continue;
              }
            const auto cell = cells.dealii_cell(cell_of[k]);
            particles->insert_particle(
              x[k],
              mapping.transform_real_to_unit_cell(cell, x[k]),
              id[k],
              cell,
              dealii::ArrayView<const double>(props.data(), props.size()));
          }
      particles->sort_particles_into_subdomains_and_cells();
      const auto in_automata = neighbours.exchange(out_automata, 83);

      // Keep the automata that stay, append the arrivals.
      unsigned int kept = 0;
      for (unsigned int k = 0; k < n_owned; ++k)
        if (destination[k] == rank)
          {
            cell_of[k] = new_cell[k];
            if (kept != k)
              automaton_fields.move(k, kept);
            ++kept;
          }
      const unsigned int record    = 4 + n_props;
      unsigned int       n_arrived = particles->n_locally_owned_particles();
      for (const auto &buf : in_automata)
        n_arrived += buf.size() / record;
      n_owned = kept + n_arrived;
      automaton_fields.resize(n_owned);
      unsigned int k = kept, n_bad = 0;
      auto         arrive = [&](const std::uint32_t the_id,
                        const Point3       &location,
                        const double       *props) {
        unpack_automaton(k, the_id, location, props);
        n_bad += cell_of[k] >= cells.n_owned_cells();
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

      // Received pair states by key, for the restore.
      kept_states.clear();
      kept_keys.clear();
      in_pairs.push_back(std::move(own_records));
      for (const auto &buf : in_pairs)
        for (std::size_t o = 0; o + width <= buf.size(); o += width)
          {
            kept_keys.emplace_back(double_to_bits(buf[o]), kept_keys.size());
            kept_states.insert(kept_states.end(),
                               buf.begin() + o + 1,
                               buf.begin() + o + width);
          }
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
    AutomatonSystem::order_owned_automata()
    {
      // Along the curve of the cells, then by id: a global order, the same
      // on any partition.
      std::vector<std::uint64_t> cell_curve(n_owned);
      for (unsigned int k = 0; k < n_owned; ++k)
        cell_curve[k] = cells.curve_index(cell_of[k]);
      std::vector<unsigned int> perm(n_owned);
      std::iota(perm.begin(), perm.end(), 0u);
      std::sort(perm.begin(), perm.end(), [&](unsigned a, unsigned b) {
        return cell_curve[a] != cell_curve[b] ? cell_curve[a] < cell_curve[b]
                                              : id[a] < id[b];
      });
      automaton_fields.permute(perm);
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
    AutomatonSystem::cell_level_summaries() const
    {
      // each owned cell's largest size level and whether any of its
      // automata is near a change of size (the byte of size_level)
      std::vector<unsigned char> summary(cells.n_local_cells(), 0);
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          auto &s = summary[cell_of[k]];
          s       = std::max<unsigned char>(s & ~transitional_flag,
                                      size_level[k] & ~transitional_flag)
              | ((s | size_level[k]) & transitional_flag);
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
      const auto in = neighbours.exchange(out, 85);
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
    AutomatonSystem::exchange_ghosts()
    {
      // The automata of the owned cells next to a neighbour rank's cells,
      // in the owned order, go to that rank, but only those within their
      // pair-list range of one of its cells there: the range of the
      // automaton's size with the largest size of that cell (uniform
      // scenes: the one range). A cell is as wide as the longest pair of
      // the scene (1.12 · 4d with automata of 4d); without this choice the
      // fine automata next to another rank would all be sent, a layer 4.5
      // times thicker than their pairs reach (doc/performance.md).
      const unsigned int n_nb        = cells.neighbour_ranks().size();
      const unsigned int ghost_width = automaton_fields.ghost_width();
      std::vector<std::vector<double>>       out(n_nb);
      std::vector<std::vector<unsigned int>> send_indices(n_nb);
      std::vector<unsigned int> first_of_cell(cells.n_owned_cells() + 1, 0);
      for (unsigned int k = 0; k < n_owned; ++k)
        ++first_of_cell[cell_of[k] + 1];
      // owned automata are ordered along the curve, as the owned cells are
      std::partial_sum(first_of_cell.begin(),
                       first_of_cell.end(),
                       first_of_cell.begin());
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
            for (unsigned int k = first_of_cell[c]; k < first_of_cell[c + 1];
                 ++k)
              {
                bool needed = false;
                for (const auto &t : targets)
                  {
                    const double reach = graded ? pair_list_range(graded_range,
                                                                  size_level[k],
                                                                  t.summary)
                                                : range;
                    double       dist2 = 0;
                    for (unsigned int e = 0; e < 3; ++e)
                      {
                        const double out_of_box = std::max(
                          {t.lower[e] - x[k][e], x[k][e] - t.upper[e], 0.});
                        dist2 += out_of_box * out_of_box;
                      }
                    if (dist2 < reach * reach * ghost_reach_margin)
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
                automaton_fields.pack_ghost(k, buf.data() + start);
              }
          }
      const auto                in = neighbours.exchange(out, 82);
      std::vector<unsigned int> offsets(n_nb + 1, n_owned);
      for (unsigned int n = 0; n < n_nb; ++n)
        offsets[n + 1] = offsets[n] + in[n].size() / ghost_width;
      n_local = offsets[n_nb];
      automaton_fields.resize(n_local);
      order.resize(n_local);
      unsigned int n_bad = 0;
      for (unsigned int n = 0; n < n_nb; ++n)
        for (unsigned int g = 0, k = offsets[n]; k < offsets[n + 1]; ++g, ++k)
          {
            automaton_fields.unpack_ghost(k,
                                          in[n].data()
                                            + std::size_t(g) * ghost_width);
            cell_of[k] = cells.local_cell(x[k]);
            if (cell_of[k] == Decomposition::invalid)
              ++n_bad;
            v[k] = w[k] = {{0, 0, 0}};
          }
      throw_collectively(comm,
                         n_bad > 0,
                         "Internal error: a ghost automaton lies outside the "
                         "ghost cells of the receiving rank.");
      neighbours.set_ghost_lists(std::move(send_indices), std::move(offsets));
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
      // The sides' many-body offsets from then on too, once the new pairs
      // are in place (the old ones are not at the first call): each side
      // the common offset of its automaton, the ghosts' as their owners
      // sent it.
      if (check_pairs && shear_factors && !mb_stored)
        {
          Assert(mb_offset.size() >= n_local, dealii::ExcInternalError());
          mb_i.resize(n_pairs);
          mb_j.resize(n_pairs);
          for (unsigned int p = 0; p < n_pairs; ++p)
            {
              mb_i[p] = mb_offset[pi[p]];
              mb_j[p] = mb_offset[pj[p]];
            }
          std::vector<double>().swap(mb_offset);
          mb_stored = true;
        }
    }
  } // namespace mca
} // namespace tribodyn
