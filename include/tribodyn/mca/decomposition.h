#ifndef tribodyn_mca_decomposition_h
#define tribodyn_mca_decomposition_h

#include <array>
#include <cstdint>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <functional>
#include <initializer_list>
#include <tribodyn/mca/parameters.h>
#include <unordered_map>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    /**
     * The 3D domain decomposition of the automata engine.
     *
     * The simulation box is a parallel::distributed::Triangulation<3>
     * (p4est) of cells at least one interaction range wide, with periodic
     * faces in the periodic directions. A rank owns the cells p4est's
     * partition gives it (cuts in x, y and z) and the automata in them.
     *
     * The cells form a structured grid: cell (i, j, k) of
     * n_cells[0] x n_cells[1] x n_cells[2]. A deal.II cell holds
     * split^3 of them (cell_split()): where the ranks hold many cells, the
     * mesh, whose cells cost deal.II ~280 bytes each in 3D, has 8 times
     * fewer cells than the search grid, while the neighbour search and the
     * ghost layer keep cells of the interaction range. The partition's
     * grain is the deal.II cell; of a ghost deal.II cell, only the cells
     * next to an owned one are local. Every automaton within the
     * interaction range of an automaton in cell C lies in C or in one of its
     * 26 neighbours, possibly across a periodic face (then seen through an
     * image shift of one period). This class lists, for each owned cell,
     * those neighbours with their shift, and the ranks that own them: the
     * neighbour ranks, the only ones a rank ever talks to. deal.II 9.4's
     * ghost cells include the cells across periodic faces (p4est's ghost
     * layer follows the periodic connectivity), but its particle ghost
     * exchange does not; this is the periodic-aware neighbour map that
     * deal.II 9.5 builds from coinciding vertices.
     *
     * Nothing here has the size of the global mesh: the local cells are the
     * owned cells and their neighbour (ghost) cells.
     */
    class Decomposition
    {
    public:
      using CellIterator =
        typename dealii::parallel::distributed::Triangulation<
          3>::active_cell_iterator;

      /// A neighbour of an owned cell: local cell index and image shift code
      /// (shift_vector(code) is added to the neighbour's coordinates).
      struct Neighbour
      {
        unsigned int  cell;
        unsigned char shift;
      };

      /// Shift code of no shift.
      static constexpr unsigned char no_shift = 13;

      static constexpr unsigned int invalid = static_cast<unsigned int>(-1);

      /// Cells of @p interaction_range; deal.II cells of 2 x 2 x 2 of them
      /// where each rank keeps at least @p mesh_cells_per_rank (0: never;
      /// cell_split()).
      /// The automata are stored in the order @p order (curve_index()).
      Decomposition(const GeometryParameters &geometry,
                    const double              interaction_range,
                    const unsigned int        mesh_cells_per_rank,
                    const PartitionParameters::AutomatonOrder order,
                    const MPI_Comm                            comm);

      /// Choose the cell grid for the box and the interaction range: the
      /// coarse mesh of nearly cubic p4est trees, refined to cells of at
      /// least the range. Static so that the partition report can use it
      /// without building the mesh.
      static void
      choose_grid(const GeometryParameters    &geometry,
                  const double                 interaction_range,
                  std::array<unsigned int, 3> &trees,
                  unsigned int                &level);
      /// The most levels the mesh is coarser than the cells (split 4).
      static constexpr unsigned int max_split_levels = 2;

      /// Cells per deal.II cell and direction for the grid of @p trees
      /// refined @p level times (choose_grid()) on @p n_ranks ranks: 4 (the
      /// mesh refined twice less) or 2 (once less) where that still leaves
      /// at least @p mesh_cells_per_rank (Partition/Mesh cells per rank;
      /// 0: never) deal.II cells a rank, so that the partition's grain
      /// stays a small part of a rank's work (the cells of a graded scene
      /// weigh up to 64 times more than others: the seed's graded scene on
      /// 256 ranks with the mesh split has a work imbalance of 1.12, 1.02
      /// not), else 1. A deal.II cell costs ~280 bytes in 3D: a cell per
      /// search cell is ~130 bytes per automaton of a uniform scene, a
      /// split of 2 one eighth of it, a split of 4 one 64th.
      static unsigned int
      cell_split(const std::array<unsigned int, 3> &trees,
                 const unsigned int                 level,
                 const unsigned int                 n_ranks,
                 const unsigned int                 mesh_cells_per_rank);

      /// The refinement level of the deal.II mesh whose cells hold
      /// @p split^3 cells of the grid refined @p level times.
      static unsigned int
      mesh_level(const unsigned int level, const unsigned int split);

      /**
       * The work held by the cell of structured index @p ijk, the box
       * [@p lower, @p upper) (in units of p4est weights: the set-up counts
       * the automata the packing puts there, and an empty cell costs a
       * little for its bins).
       */
      using CellCost
        = std::function<unsigned int(const std::array<unsigned int, 3> &ijk,
                                     const Point3                      &lower,
                                     const Point3                      &upper)>;

      /// Build the mesh, partition it and the cell tables. With a @p cost
      /// and several ranks, p4est's partition is weighted by it (deal.II's
      /// `weight` signal and repartition()): each rank holds about the same
      /// work instead of the same number of cells.
      void
      setup(const CellCost &cost = {});

      /// Weight of a cell for the partition: its key (cell_key()) and
      /// p4est weight.
      struct CellWeight
      {
        std::uint64_t key;
        unsigned int  weight;
      };
      /// Partition the mesh anew by the given weights of this rank's owned
      /// cells (sorted by key; deal.II's repartition()) and rebuild the
      /// cell tables. Particles of ParticleHandlers on the mesh prepared
      /// for it (prepare_for_coarsening_and_refinement()) follow their
      /// cells.
      void
      repartition(const std::vector<CellWeight> &weights);

      /// Global key of local cell @p c (the same on every rank).
      std::uint64_t
      cell_key(const unsigned int c) const;

      /// The box [@p lower, @p upper) of the cell of structured index
      /// @p ijk (the last cell of a direction ends at the box's upper side).
      void
      cell_box(const std::array<unsigned int, 3> &ijk,
               Point3                            &lower,
               Point3                            &upper) const;

      const dealii::parallel::distributed::Triangulation<3> &
      triangulation() const
      {
        return tria;
      }

      /// Bytes of the background mesh (deal.II's cells of all levels; not
      /// p4est's own quadrants) and of the cell tables.
      std::size_t
      memory_consumption() const;

      unsigned int
      n_owned_cells() const
      {
        return n_owned;
      }
      unsigned int
      n_local_cells() const
      {
        return cell_index.size();
      }
      const std::array<unsigned int, 3> &
      cells_per_direction() const
      {
        return n_cells;
      }
      const std::array<double, 3> &
      cell_size() const
      {
        return h;
      }
      /// Cells per deal.II cell in each direction (1, 2 or 4: cell_split()).
      unsigned int
      cells_per_mesh_cell() const
      {
        return split;
      }

      /// Structured index (i, j, k) of local cell @p c.
      const std::array<unsigned int, 3> &
      cell_coordinates(const unsigned int c) const
      {
        return cell_index[c];
      }
      /// Rank owning local cell @p c.
      unsigned int
      owner(const unsigned int c) const
      {
        return mesh_cells[mesh_cell_of[c]]->subdomain_id();
      }
      /// The deal.II cell holding local cell @p c.
      CellIterator
      dealii_cell(const unsigned int c) const
      {
        return mesh_cells[mesh_cell_of[c]];
      }
      /// Reference coordinates of @p x in the deal.II cell of local cell
      /// @p c (the cells are boxes), clamped to the unit cell.
      dealii::Point<3>
      reference_point(const unsigned int c, const Point3 &x) const;
      /// Place of an automaton at @p x in local cell @p c in the
      /// automata's order (Partition/Automaton order), the same on every
      /// partition: its cell's along a Morton curve of the global cell
      /// grid, or in slabs: by layers of the cells' slabs across the
      /// longest direction without periodic faces (layers_per_slab a slab),
      /// then by the rows and columns of the cells, the longer direction
      /// first. An automaton's partners then lie within about one
      /// interaction range of layers of it in the order (the pair kernel's
      /// pipeline, PairList::chunk_for_pipeline()).
      std::uint64_t
      curve_index(const unsigned int c, const Point3 &x) const;
      /// Layers of a slab of cells in the slab order (curve_index()).
      static constexpr unsigned int layers_per_slab = 8;

      /// Structured cell of a point (wrapped into the box in periodic
      /// directions); false if outside the box in a non-periodic direction.
      bool
      structured_cell(const Point3 &p, std::array<unsigned int, 3> &ijk) const;
      /// Local cell containing @p p (invalid if not a local cell).
      unsigned int
      local_cell(const Point3 &p) const;
      /// Local cell with structured index @p ijk (invalid if not local).
      unsigned int
      local_cell(const std::array<unsigned int, 3> &ijk) const;

      /// @p p moved into the box in the periodic directions.
      Point3
      wrap(const Point3 &p) const;

      /// Call @p f(Neighbour) for each neighbour of owned cell @p c, itself
      /// included (shift none). Computed when asked (pair-list rebuilds
      /// only): stored lists would cost ~230 bytes per cell, ~100 per
      /// automaton.
      template <typename F>
      void
      for_each_neighbour(const unsigned int c, const F &f) const
      {
        for (unsigned int o = 0; o < 27; ++o)
          {
            Neighbour nb;
            if (neighbour(c, o, nb))
              f(nb);
          }
      }
      /// Image shift vector of a shift code.
      const std::array<double, 3> &
      shift_vector(const unsigned char code) const
      {
        return shifts[code];
      }
      static unsigned char
      opposite_shift(const unsigned char code)
      {
        return 26 - code;
      }

      /// Ranks owning a neighbour cell of an owned cell (this rank
      /// excluded), ascending.
      const std::vector<unsigned int> &
      neighbour_ranks() const
      {
        return ranks;
      }
      /// Owned cells that neighbour a cell of neighbour_ranks()[n]: their
      /// automata are ghosts on that rank. Ascending local cell index.
      const std::vector<unsigned int> &
      cells_sent_to(const unsigned int n) const
      {
        return send_cells[n];
      }
      /// Index in neighbour_ranks() of @p rank (invalid if none).
      unsigned int
      neighbour_index(const unsigned int rank) const;

      const std::array<bool, 3> &
      periodic() const
      {
        return periodic_;
      }
      const std::array<double, 3> &
      period() const
      {
        return period_;
      }

    private:
      /// The tables of the local cells, their owners and the neighbour
      /// ranks, from the mesh's current partition.
      void
      build_cell_tables();
      /// p4est's partition weighted by @p weight of each locally owned cell
      /// (by structured index): the `weight` signal and repartition().
      void
      repartition_by(
        const std::function<unsigned int(const std::array<unsigned int, 3> &)>
          &weight);

      /// Neighbour @p o (offset code, 0...26 like the shift codes) of owned
      /// cell @p c; false where a non-periodic side has none.
      bool
      neighbour(const unsigned int c,
                const unsigned int o,
                Neighbour         &nb) const;
      /// Structured index of the neighbour @p o of cell @p ijk (wrapped
      /// across periodic faces) and its shift code; false where a
      /// non-periodic side has none.
      bool
      neighbour_index(const std::array<unsigned int, 3> &ijk,
                      const unsigned int                 o,
                      std::array<unsigned int, 3>       &nb,
                      unsigned char                     &shift) const;
      /// Structured index of the first (lowest) cell of deal.II cell
      /// @p cell.
      std::array<unsigned int, 3>
      first_cell_of(const CellIterator &cell) const;

      std::uint64_t
      key(const std::array<unsigned int, 3> &ijk) const
      {
        return (static_cast<std::uint64_t>(ijk[2]) * n_cells[1] + ijk[1])
                 * n_cells[0]
               + ijk[0];
      }

      const GeometryParameters                 &geometry;
      const double                              range;
      const unsigned int                        mesh_cells_per_rank;
      const PartitionParameters::AutomatonOrder order;
      /// The directions of the slab order, slowest first (curve_index()).
      std::array<unsigned int, 3> slab_axes{{2, 1, 0}};
      MPI_Comm                    comm;
      unsigned int                rank;

      dealii::parallel::distributed::Triangulation<3> tria;
      std::array<unsigned int, 3>                     n_cells{{0, 0, 0}};
      unsigned int                                    split = 1;
      std::array<double, 3>                           h{{0, 0, 0}};
      std::array<bool, 3>                             periodic_{{0, 0, 0}};
      std::array<double, 3>                           period_{{0, 0, 0}};
      std::array<std::array<double, 3>, 27>           shifts;

      unsigned int                             n_owned = 0;
      std::vector<std::array<unsigned int, 3>> cell_index;
      /// The owned and ghost deal.II cells, and the one of each local cell
      /// (an index into them: split^3 local cells share one).
      std::vector<CellIterator> mesh_cells;
      std::vector<unsigned int> mesh_cell_of;
      /// The local cells' indices in the order of their keys (key() of
      /// cell_index): 4 bytes a cell (a hash map costs ~50)
      std::vector<unsigned int>              local_by_key;
      std::vector<unsigned int>              ranks;
      std::vector<std::vector<unsigned int>> send_cells;
    };


    /**
     * Point-to-point exchange with the neighbour ranks of a Decomposition.
     * After set-up, update() copies a fixed number of doubles per automaton
     * from the owned automata in the send lists to the ghost copies on the
     * neighbours (the receiving rank's ghosts of neighbour n are the
     * contiguous block recv_offset[n] ... recv_offset[n+1] after the owned
     * automata). exchange() sends variable-length messages once.
     */
    class NeighbourExchange
    {
    public:
      void
      reinit(const MPI_Comm comm, const std::vector<unsigned int> &ranks);

      /// Send @p out[n] to ranks[n] and return what each neighbour sent.
      template <typename T>
      std::vector<std::vector<T>>
      exchange(const std::vector<std::vector<T>> &out, const int tag) const;

      /// Per-step ghost update set-up: send_indices[n] are the local indices
      /// of the owned automata whose copies neighbour n holds, in its order;
      /// ghost block n starts at ghost_offset[n].
      void
      set_ghost_lists(std::vector<std::vector<unsigned int>> send_indices,
                      std::vector<unsigned int>              ghost_offset);

      /// One per-automaton field of a ghost update: @p width doubles per
      /// local automaton at @p data (stride @p width).
      struct Field
      {
        double      *data;
        unsigned int width;
      };

      /// Copy the given fields from owners to ghosts, all in one message
      /// per neighbour (no array of all local automata is packed: only the
      /// automata sent are gathered).
      void
      update(std::initializer_list<Field> fields) const;

      /// The same for one field.
      void
      update(double *data, const unsigned int width) const
      {
        update({Field{data, width}});
      }

      bool
      active() const
      {
        return !ranks.empty();
      }
      /// The lists given to set_ghost_lists() (checkpoints).
      const std::vector<std::vector<unsigned int>> &
      ghost_send_indices() const
      {
        return send_indices;
      }
      const std::vector<unsigned int> &
      ghost_offsets() const
      {
        return ghost_offset;
      }
      const std::vector<unsigned int> &
      neighbour_ranks() const
      {
        return ranks;
      }

    private:
      MPI_Comm                                 comm = MPI_COMM_SELF;
      std::vector<unsigned int>                ranks;
      std::vector<std::vector<unsigned int>>   send_indices;
      std::vector<unsigned int>                ghost_offset;
      mutable std::vector<std::vector<double>> send_buffers, recv_buffers;
      mutable std::vector<MPI_Request>         requests;
    };
  } // namespace mca
} // namespace tribodyn

#endif
