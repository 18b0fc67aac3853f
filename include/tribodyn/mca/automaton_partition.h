// The partition of the automata over the ranks and their ghost copies: one
// part of AutomatonSystem (issue #52 item 1), with one job — who holds
// which automaton (design §6; doc/theory/mca.md §1).
#ifndef tribodyn_mca_automaton_partition_h
#define tribodyn_mca_automaton_partition_h

#include <cstdint>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/particles/particle_handler.h>
#include <memory>
#include <string>
#include <tribodyn/mca/automaton_arrays.h>
#include <tribodyn/mca/decomposition.h>
#include <tribodyn/mca/parameters.h>
#include <tribodyn/mca/system_scalars.h>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    /**
     * Who holds which automaton. The automata of a rank are those in the
     * cells it owns in a parallel::distributed background mesh
     * (Decomposition); ghost copies of the automata of neighbour cells
     * owned by other ranks come from those ranks only (NeighbourExchange).
     * At a pair-list rebuild the automata that entered a cell of another
     * rank migrate there (deal.II's ParticleHandler, point to point across
     * periodic faces), the owned automata are ordered by their places
     * (Partition/Automaton order: the global order key of the pair list)
     * and the ghosts are received anew; when the ranks' work drifted
     * apart the cells are weighted by the automata they hold and
     * partitioned anew.
     *
     * A part of AutomatonSystem in the way of BoundaryLoads: it reads and
     * writes the automata (AutomatonArrays: their records, positions,
     * cells, order keys and counts), reads the scene's pair-list ranges and
     * automaton count (SystemScalars), and owns the mesh, the exchange with
     * the neighbour ranks and the history of its partitions (State). It
     * knows nothing of pairs: what must travel with an automaton besides
     * its own fields (the states of its pairs) is given to it as records
     * attached to owned automata, or sent by the caller to the ranks that
     * plan_migration() names.
     */
    class AutomatonPartition
    {
    public:
      AutomatonPartition(const Parameters    &parameters,
                         const MPI_Comm       comm,
                         AutomatonArrays     &automata,
                         const SystemScalars &scalars);

      /// What the part carries from one step to the next (checkpointed,
      /// in this order): the rebalances so far, the imbalance right after
      /// the last partition, and the weights this rank gave at each
      /// rebalance ((number of cells, then key and weight per cell) per
      /// rebalance), replayed on a resume.
      struct State
      {
        unsigned int               rebalance_count     = 0;
        double                     partition_imbalance = 1;
        std::vector<std::uint64_t> rebalance_history;
      };
      State &
      state()
      {
        return partition_state;
      }
      const State &
      state() const
      {
        return partition_state;
      }

      /// The cells of the mesh and their owners, neighbours and shifts.
      const Decomposition &
      cells() const
      {
        return decomposition;
      }
      /// Point-to-point messages to the neighbour ranks and the per-step
      /// update of the ghosts from their owners.
      const NeighbourExchange &
      neighbours() const
      {
        return exchange;
      }

      /// Set up the mesh partitioned by @p cost of each cell
      /// (Decomposition::setup()), the neighbour ranks and the particle
      /// handler for migrations (the automata's record width).
      void
      setup(const Decomposition::CellCost &cost);

      /// Where each owned automaton goes at a migration: its cell after
      /// wrapping into the box and that cell's owner.
      struct Migration
      {
        std::vector<unsigned int>  destination, new_cell;
        std::vector<unsigned char> crossed; ///< crossed a periodic face
      };
      /// Collective: the migration of the automata now (throws, naming
      /// the box, if an automaton left it through a non-periodic side).
      Migration
      plan_migration() const;
      /// Collective: wrap the owned automata into the box, send those of
      /// @p plan that go to another rank and take in those that come.
      void
      migrate(const Migration &plan);
      /// Collective: whether the partition is due to be weighted anew
      /// (Partition/Rebalance threshold passed, and grown by half of its
      /// margin since the last partition).
      bool
      rebalance_due() const;
      /// Collective: partition the cells anew, weighted by the automata
      /// they hold now; every owned automaton follows its cell, and so do
      /// the @p records of @p width doubles, each attached to owned
      /// automaton @p attached_to (a copy per entry). Returns the records
      /// that this rank holds afterwards (in no particular order).
      std::vector<double>
      repartition(const std::vector<unsigned int> &attached_to,
                  const std::vector<double>       &records,
                  const unsigned int               width);
      /// Repartition by the weights this rank gave at each earlier
      /// rebalance, in order: the partition of a checkpointed run, rebuilt
      /// on resume (same ranks, same weights, same p4est partition).
      void
      replay_rebalances();
      /// Collective: the largest number of owned automata of a rank over
      /// the mean (1: perfectly balanced work).
      double
      work_imbalance() const;

      /// Sort the owned automata by their places in the automata's order
      /// (Decomposition::curve_index(): their cell's along the curve, or
      /// the layer of their cell's slab), then by id, and set their order
      /// keys (the place << 16 | rank among the automata of that place).
      void
      order_owned_automata();
      /// Collective: receive the ghosts from the neighbour ranks (the
      /// automata within pair-list range of this rank's cells; the ranges
      /// of SystemScalars now) after the owned automata.
      void
      exchange_ghosts();
      /// Collective: the ghosts' x, v, w from their owners.
      void
      update_ghost_kinematics() const;
      /// The ghost lists of a checkpoint (NeighbourExchange).
      void
      restore_ghost_lists(std::vector<std::vector<unsigned int>> send,
                          std::vector<unsigned int>              offsets);

      /// Automaton @p k from its id, its position and its migration record
      /// (automaton_fields.pack(): the carried fields); finds its local
      /// cell.
      void
      unpack_automaton(const unsigned int  k,
                       const std::uint32_t the_id,
                       const Point3       &location,
                       const double       *props);
      /// Collective: throws if automata were lost in @p move (the global
      /// count differs, or @p n_misplaced arrived outside the owned cells).
      void
      check_automata_arrived(const unsigned int n_misplaced,
                             const std::string &move) const;

      /// Bytes of the mesh and the cell tables.
      std::size_t
      memory_consumption() const
      {
        return decomposition.memory_consumption();
      }

    private:
      /// Size-level summary of each local cell (largest level, and
      /// transitional_flag if any automaton is near a change of size): the
      /// owned cells' from their automata, the neighbours' received.
      std::vector<unsigned char>
      cell_level_summaries() const;

      const Parameters    &prm;
      MPI_Comm             comm;
      unsigned int         n_ranks, rank;
      AutomatonArrays     &automata;
      const SystemScalars &scalars;

      Decomposition                                          decomposition;
      NeighbourExchange                                      exchange;
      dealii::MappingQ1<3>                                   mapping;
      std::unique_ptr<dealii::Particles::ParticleHandler<3>> particles;
      State                                                  partition_state;
    };
  } // namespace mca
} // namespace tribodyn

#endif
