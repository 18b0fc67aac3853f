#include <algorithm>
#include <cmath>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <limits>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/mca/decomposition.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      /// Spread the lowest 21 bits of @p v to every third bit.
      std::uint64_t
      spread_bits(std::uint64_t v)
      {
        v &= 0x1fffff;
        v = (v | v << 32) & 0x1f00000000ffffULL;
        v = (v | v << 16) & 0x1f0000ff0000ffULL;
        v = (v | v << 8) & 0x100f00f00f00f00fULL;
        v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
        v = (v | v << 2) & 0x1249249249249249ULL;
        return v;
      }

      /// Structured index of cell @p b (0 ... split^3 - 1, x fastest) of
      /// the deal.II cell whose first cell is @p first.
      std::array<unsigned int, 3>
      cell_in_mesh_cell(const std::array<unsigned int, 3> &first,
                        const unsigned int                 split,
                        const unsigned int                 b)
      {
        return {{first[0] + b % split,
                 first[1] + b / split % split,
                 first[2] + b / (split * split)}};
      }
    } // namespace


    Decomposition::Decomposition(
      const GeometryParameters                 &geometry,
      const double                              interaction_range,
      const unsigned int                        mesh_cells_per_rank,
      const PartitionParameters::AutomatonOrder order,
      const MPI_Comm                            communicator)
        : geometry(geometry)
        , range(interaction_range)
        , mesh_cells_per_rank(mesh_cells_per_rank)
        , order(order)
        , comm(communicator)
        , rank(dealii::Utilities::MPI::this_mpi_process(communicator))
        , tria(communicator)
    {
      periodic_ = geometry.periodic;
      for (unsigned int c = 0; c < 3; ++c)
        period_[c] = geometry.domain_upper[c] - geometry.domain_lower[c];
      for (int sz = -1; sz <= 1; ++sz)
        for (int sy = -1; sy <= 1; ++sy)
          for (int sx = -1; sx <= 1; ++sx)
            shifts[(sx + 1) + 3 * (sy + 1) + 9 * (sz + 1)]
              = {{sx * period_[0], sy * period_[1], sz * period_[2]}};
    }


    void
    Decomposition::choose_grid(const GeometryParameters    &g,
                               const double                 r,
                               std::array<unsigned int, 3> &trees,
                               unsigned int                &level)
    {
      // Cells must be at least the interaction range wide in every
      // direction (then all partners of an automaton lie in the 27 cells
      // around it) and should be as close to it as possible (the search
      // volume and the ghost layer grow with the cell size). The coarse mesh
      // (the p4est trees) is replicated on every rank, so it stays small,
      // and the fewer the trees the better the partition: deal.II orders the
      // trees for p4est hierarchically (SparsityTools::reorder_hierarchical),
      // so with many trees the ranks' borders follow that ordering and are
      // jagged, while within a tree p4est's Morton curve cuts along cell
      // planes. (The 10^6-automaton cube: 9^3 trees of 8^3 cells gave 0.111
      // ghosts per owned automaton on 2 ranks, one tree of 64^3 slightly
      // wider cells 0.032.) Hence: the grid with the fewest trees whose
      // widest cell is within 15 % of the best achievable with at most 4096
      // trees.
      std::array<double, 3>       L;
      std::array<unsigned int, 3> n_max;
      for (unsigned int c = 0; c < 3; ++c)
        {
          L[c]     = g.domain_upper[c] - g.domain_lower[c];
          n_max[c] = std::max(1u, static_cast<unsigned int>(L[c] / r));
        }
      const unsigned int  n_min = *std::min_element(n_max.begin(), n_max.end());
      std::vector<double> width;
      for (unsigned int l = 0; (1u << l) <= n_min && l < 20; ++l)
        {
          double w = 0, prod = 1;
          for (unsigned int c = 0; c < 3; ++c)
            {
              const unsigned int t = n_max[c] >> l;
              prod *= t;
              w = std::max(w, L[c] / (t << l));
            }
          width.push_back(prod <= 4096 ? w
                                       : std::numeric_limits<double>::max());
        }
      const double best = *std::min_element(width.begin(), width.end());
      level             = 0;
      for (unsigned int l = 0; l < width.size(); ++l)
        if (width[l] <= 1.15 * best)
          level = l;
      for (unsigned int c = 0; c < 3; ++c)
        trees[c] = n_max[c] >> level;
    }


    unsigned int
    Decomposition::cell_split(const std::array<unsigned int, 3> &trees,
                              const unsigned int                 level,
                              const unsigned int                 n_ranks,
                              const unsigned int mesh_cells_per_rank)
    {
      // Each level coarser divides the deal.II cells by 8; at most
      // max_split_levels of them, while every rank keeps its share.
      if (mesh_cells_per_rank == 0)
        return 1;
      const double trees_total = double(trees[0]) * trees[1] * trees[2];
      unsigned int coarser     = 0;
      while (coarser < max_split_levels && coarser < level
             && trees_total * std::pow(8., level - coarser - 1)
                  >= double(mesh_cells_per_rank) * n_ranks)
        ++coarser;
      return 1u << coarser;
    }


    unsigned int
    Decomposition::mesh_level(const unsigned int level,
                              const unsigned int split)
    {
      unsigned int coarser = 0;
      while ((1u << coarser) < split)
        ++coarser;
      return level - coarser;
    }


    void
    Decomposition::setup(const CellCost &cost)
    {
      const auto &g = geometry;
      for (unsigned int c = 0; c < 3; ++c)
        if (periodic_[c] && period_[c] <= 2 * range)
          throw InputError(
            std::string("The periodic length in ") + "xyz"[c] + " ("
            + format_number(period_[c])
            + " m) must exceed twice the interaction range (automaton size "
              "times 1 + Interaction/Skin, with Geometry/Size bands 1.12 "
              "times the largest size: "
            + format_number(range)
            + " m). Widen the box in that direction or use smaller sizes.");
      std::array<unsigned int, 3> trees;
      unsigned int                level;
      choose_grid(g, range, trees, level);
      dealii::GridGenerator::subdivided_hyper_rectangle(
        tria,
        std::vector<unsigned int>(trees.begin(), trees.end()),
        g.domain_lower,
        g.domain_upper,
        true);
      std::vector<dealii::GridTools::PeriodicFacePair<
        dealii::parallel::distributed::Triangulation<3>::cell_iterator>>
        faces;
      for (unsigned int c = 0; c < 3; ++c)
        if (periodic_[c])
          dealii::GridTools::collect_periodic_faces(
            tria, 2 * c, 2 * c + 1, c, faces);
      if (!faces.empty())
        tria.add_periodicity(faces);
      // (the mesh one or two levels coarser than the cells where it can be)
      split = cell_split(trees,
                         level,
                         dealii::Utilities::MPI::n_mpi_processes(comm),
                         mesh_cells_per_rank);
      if (mesh_level(level, split) > 0)
        tria.refine_global(mesh_level(level, split));
      for (unsigned int c = 0; c < 3; ++c)
        {
          n_cells[c] = trees[c] << level;
          h[c]       = period_[c] / n_cells[c];
        }
      // The slab order's directions: slowest the one with the most cells
      // among those without periodic faces (of all three where every one
      // has them), whose neighbours across it are then a layer of cells
      // away in the order (across a periodic one, the last layer's would
      // lie beside the first's); then the longer of the other two.
      const auto more_cells
        = [this](const unsigned int a, const unsigned int b) {
            return n_cells[a] != n_cells[b] ? n_cells[a] > n_cells[b] : a > b;
          };
      slab_axes = {{2, 1, 0}};
      std::sort(slab_axes.begin(),
                slab_axes.end(),
                [&](const unsigned int a, const unsigned int b) {
                  return periodic_[a] != periodic_[b] ? !periodic_[a]
                                                      : more_cells(a, b);
                });
      if (more_cells(slab_axes[2], slab_axes[1]))
        std::swap(slab_axes[1], slab_axes[2]);

      // Weighted partition: p4est cuts its space-filling curve so that the
      // ranks' sums of the cells' weights are equal (rather than their
      // numbers of cells).
      if (cost && dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
        repartition_by([&](const std::array<unsigned int, 3> &ijk) {
          Point3 lower, upper;
          cell_box(ijk, lower, upper);
          return cost(ijk, lower, upper);
        });
      build_cell_tables();
    }


    void
    Decomposition::repartition_by(
      const std::function<unsigned int(const std::array<unsigned int, 3> &)>
        &weight)
    {
      // deal.II's `weight` signal asks for the locally owned deal.II
      // cells' weights: the sums of their cells' (by structured index
      // here); deal.II's ParticleHandlers attached to the mesh carry their
      // particles to the new owners.
      using Tria      = dealii::parallel::distributed::Triangulation<3>;
      const auto slot = tria.signals.weight.connect(
        [&](const Tria::cell_iterator &cell, const Tria::CellStatus) {
          const auto   first = first_cell_of(cell);
          unsigned int sum   = 0;
          for (unsigned int b = 0; b < split * split * split; ++b)
            sum += weight(cell_in_mesh_cell(first, split, b));
          return sum;
        });
      tria.repartition();
      slot.disconnect();
    }


    void
    Decomposition::repartition(const std::vector<CellWeight> &weights)
    {
      // p4est cuts its curve anew by these weights (the locally owned
      // cells' own, looked up by key).
      repartition_by([&](const std::array<unsigned int, 3> &ijk) {
        const std::uint64_t k = key(ijk);
        const auto          it
          = std::lower_bound(weights.begin(),
                             weights.end(),
                             k,
                             [](const CellWeight &w, const std::uint64_t v) {
                               return w.key < v;
                             });
        AssertThrow(it != weights.end() && it->key == k,
                    dealii::ExcInternalError());
        return it->weight;
      });
      build_cell_tables();
    }


    std::size_t
    Decomposition::memory_consumption() const
    {
      return tria.memory_consumption()
             + cell_index.capacity() * sizeof(cell_index[0])
             + mesh_cells.capacity() * sizeof(mesh_cells[0])
             + mesh_cell_of.capacity() * sizeof(mesh_cell_of[0])
             + local_by_key.capacity() * sizeof(local_by_key[0]);
    }


    std::uint64_t
    Decomposition::cell_key(const unsigned int c) const
    {
      return key(cell_index[c]);
    }


    std::array<unsigned int, 3>
    Decomposition::first_cell_of(const CellIterator &cell) const
    {
      std::array<unsigned int, 3> ijk;
      const bool                  inside = structured_cell(cell->center(), ijk);
      AssertThrow(inside, dealii::ExcInternalError());
      // (the centre of a split cell is the corner its cells share)
      for (unsigned int c = 0; c < 3; ++c)
        ijk[c] -= ijk[c] % split;
      return ijk;
    }


    dealii::Point<3>
    Decomposition::reference_point(const unsigned int c, const Point3 &x) const
    {
      const CellIterator     cell  = dealii_cell(c);
      const dealii::Point<3> lower = cell->vertex(0), upper = cell->vertex(7);
      dealii::Point<3>       reference;
      for (unsigned int e = 0; e < 3; ++e)
        reference[e]
          = std::clamp((x[e] - lower[e]) / (upper[e] - lower[e]), 0., 1.);
      return reference;
    }


    void
    Decomposition::build_cell_tables()
    {
      // Local cells: the owned ones (along the space-filling curve, for
      // locality of the automata numbered after them), then the ghosts:
      // the cells of ghost deal.II cells next to an owned cell.
      struct Entry
      {
        std::uint64_t               z;
        std::array<unsigned int, 3> ijk;
        unsigned int                mesh_cell;
      };
      std::vector<Entry> owned, candidates, ghost;
      const unsigned int per_cell = split * split * split;
      mesh_cells.clear();
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          {
            const auto         first = first_cell_of(cell);
            const unsigned int m     = mesh_cells.size();
            mesh_cells.push_back(cell);
            for (unsigned int b = 0; b < per_cell; ++b)
              {
                const auto          ijk = cell_in_mesh_cell(first, split, b);
                const std::uint64_t z   = spread_bits(ijk[0])
                                        | spread_bits(ijk[1]) << 1
                                        | spread_bits(ijk[2]) << 2;
                (cell->is_locally_owned() ? owned : candidates)
                  .push_back({z, ijk, m});
              }
          }
      mesh_cells.shrink_to_fit();
      std::vector<std::uint64_t> owned_keys;
      owned_keys.reserve(owned.size());
      for (const Entry &e : owned)
        owned_keys.push_back(key(e.ijk));
      std::sort(owned_keys.begin(), owned_keys.end());
      for (const Entry &e : candidates)
        for (unsigned int o = 0; o < 27; ++o)
          {
            std::array<unsigned int, 3> nb;
            unsigned char               shift;
            if (o != no_shift && neighbour_index(e.ijk, o, nb, shift)
                && std::binary_search(owned_keys.begin(),
                                      owned_keys.end(),
                                      key(nb)))
              {
                ghost.push_back(e);
                break;
              }
          }
      std::vector<std::uint64_t>().swap(owned_keys);
      std::vector<Entry>().swap(candidates);
      auto by_curve = [](const Entry &a, const Entry &b) { return a.z < b.z; };
      std::sort(owned.begin(), owned.end(), by_curve);
      std::sort(ghost.begin(), ghost.end(), by_curve);
      n_owned = owned.size();
      cell_index.clear();
      mesh_cell_of.clear();
      local_by_key.clear();
      const std::size_t n_local = owned.size() + ghost.size();
      cell_index.reserve(n_local);
      mesh_cell_of.reserve(n_local);
      local_by_key.reserve(n_local);
      for (const auto *list : {&owned, &ghost})
        for (const Entry &entry : *list)
          {
            local_by_key.push_back(cell_index.size());
            cell_index.push_back(entry.ijk);
            mesh_cell_of.push_back(entry.mesh_cell);
          }
      std::sort(local_by_key.begin(),
                local_by_key.end(),
                [this](const unsigned int a, const unsigned int b) {
                  return key(cell_index[a]) < key(cell_index[b]);
                });

      // Ranks owning neighbours of the owned cells (periodic images
      // included), and the owned cells each of them needs as ghosts.
      std::vector<std::vector<unsigned int>> cells_for_rank;
      ranks.clear();
      for (unsigned int c = 0; c < n_owned; ++c)
        for_each_neighbour(c, [&](const Neighbour &nb) {
          const unsigned int r = owner(nb.cell);
          if (r == rank)
            return;
          auto it = std::lower_bound(ranks.begin(), ranks.end(), r);
          const unsigned int n = it - ranks.begin();
          if (it == ranks.end() || *it != r)
            {
              ranks.insert(it, r);
              cells_for_rank.insert(cells_for_rank.begin() + n,
                                    std::vector<unsigned int>());
            }
          if (cells_for_rank[n].empty() || cells_for_rank[n].back() != c)
            cells_for_rank[n].push_back(c);
        });
      send_cells = std::move(cells_for_rank);
    }


    void
    Decomposition::cell_box(const std::array<unsigned int, 3> &ijk,
                            Point3                            &lower,
                            Point3                            &upper) const
    {
      for (unsigned int e = 0; e < 3; ++e)
        {
          lower[e] = geometry.domain_lower[e] + ijk[e] * h[e];
          upper[e] = ijk[e] + 1 == n_cells[e] ? geometry.domain_upper[e]
                                              : lower[e] + h[e];
        }
    }


    bool
    Decomposition::neighbour_index(const std::array<unsigned int, 3> &ijk,
                                   const unsigned int                 o,
                                   std::array<unsigned int, 3>       &nb,
                                   unsigned char &shift) const
    {
      const int offset[3] = {static_cast<int>(o % 3) - 1,
                             static_cast<int>(o / 3 % 3) - 1,
                             static_cast<int>(o / 9) - 1};
      int       s[3]      = {0, 0, 0};
      for (unsigned int d = 0; d < 3; ++d)
        {
          int v = static_cast<int>(ijk[d]) + offset[d];
          if (v < 0 || v >= static_cast<int>(n_cells[d]))
            {
              if (!periodic_[d])
                return false;
              s[d] = v < 0 ? -1 : 1;
              v -= s[d] * static_cast<int>(n_cells[d]);
            }
          nb[d] = v;
        }
      shift = (s[0] + 1) + 3 * (s[1] + 1) + 9 * (s[2] + 1);
      return true;
    }


    bool
    Decomposition::neighbour(const unsigned int c,
                             const unsigned int o,
                             Neighbour         &nb) const
    {
      std::array<unsigned int, 3> ijk;
      if (!neighbour_index(cell_index[c], o, ijk, nb.shift))
        return false;
      nb.cell = local_cell(ijk);
      if (nb.cell == invalid)
        throw RunError("Internal error: a neighbour cell of an owned cell is "
                       "not in this rank's ghost layer (periodic connectivity "
                       "of the p4est mesh).");
      return true;
    }


    std::uint64_t
    Decomposition::curve_index(const unsigned int c, const Point3 &x) const
    {
      const auto &ijk = cell_index[c];
      if (order == PartitionParameters::AutomatonOrder::curve)
        return spread_bits(ijk[0]) | spread_bits(ijk[1]) << 1
               | spread_bits(ijk[2]) << 2;
      // the layer of the cell's slab that holds x (clamped: a periodic
      // slowest direction's automata may sit just outside their cell)
      const auto [a, b, e] = slab_axes;
      const double below   = x[a] - (geometry.domain_lower[a] + ijk[a] * h[a]);
      const int    in_cell = std::clamp(static_cast<int>(std::floor(
                                       below / h[a] * layers_per_slab)),
                                     0,
                                     static_cast<int>(layers_per_slab) - 1);
      const std::uint64_t layer
        = static_cast<std::uint64_t>(ijk[a]) * layers_per_slab + in_cell;
      return (layer * n_cells[b] + ijk[b]) * n_cells[e] + ijk[e];
    }


    bool
    Decomposition::structured_cell(const Point3                &p,
                                   std::array<unsigned int, 3> &ijk) const
    {
      for (unsigned int c = 0; c < 3; ++c)
        {
          double y = p[c] - geometry.domain_lower[c];
          if (periodic_[c])
            y -= period_[c] * std::floor(y / period_[c]);
          else if (y < 0 || y >= period_[c])
            return false;
          const long i = static_cast<long>(std::floor(y / h[c]));
          ijk[c]       = static_cast<unsigned int>(
            std::min<long>(n_cells[c] - 1, std::max<long>(0, i)));
        }
      return true;
    }


    unsigned int
    Decomposition::local_cell(const std::array<unsigned int, 3> &ijk) const
    {
      const std::uint64_t k = key(ijk);
      const auto          it
        = std::lower_bound(local_by_key.begin(),
                           local_by_key.end(),
                           k,
                           [this](const unsigned int c, const std::uint64_t v) {
                             return key(cell_index[c]) < v;
                           });
      return it == local_by_key.end() || key(cell_index[*it]) != k ? invalid
                                                                   : *it;
    }


    unsigned int
    Decomposition::local_cell(const Point3 &p) const
    {
      std::array<unsigned int, 3> ijk;
      if (!structured_cell(p, ijk))
        return invalid;
      return local_cell(ijk);
    }


    Point3
    Decomposition::wrap(const Point3 &p) const
    {
      Point3 q = p;
      for (unsigned int c = 0; c < 3; ++c)
        if (periodic_[c])
          {
            const double lo = geometry.domain_lower[c];
            q[c] -= period_[c] * std::floor((q[c] - lo) / period_[c]);
            // round-off can leave q exactly at the upper end
            if (q[c] >= lo + period_[c])
              q[c] = lo;
          }
      return q;
    }


    unsigned int
    Decomposition::neighbour_index(const unsigned int r) const
    {
      const auto it = std::lower_bound(ranks.begin(), ranks.end(), r);
      return (it == ranks.end() || *it != r)
               ? invalid
               : static_cast<unsigned int>(it - ranks.begin());
    }


    // ------------------------------------------------------------------
    void
    NeighbourExchange::reinit(const MPI_Comm                   communicator,
                              const std::vector<unsigned int> &neighbours)
    {
      comm  = communicator;
      ranks = neighbours;
      send_indices.clear();
      ghost_offset.assign(1, 0);
      send_buffers.resize(ranks.size());
      recv_buffers.resize(ranks.size());
      requests.resize(2 * ranks.size());
    }


    template <typename T>
    std::vector<std::vector<T>>
    NeighbourExchange::exchange(const std::vector<std::vector<T>> &out,
                                const int                          tag) const
    {
      std::vector<std::vector<T>> in(ranks.size());
      std::vector<MPI_Request>    sends(ranks.size());
      for (unsigned int n = 0; n < ranks.size(); ++n)
        MPI_Isend(out[n].data(),
                  out[n].size() * sizeof(T),
                  MPI_BYTE,
                  ranks[n],
                  tag,
                  comm,
                  &sends[n]);
      for (unsigned int n = 0; n < ranks.size(); ++n)
        {
          MPI_Status status;
          MPI_Probe(ranks[n], tag, comm, &status);
          int bytes = 0;
          MPI_Get_count(&status, MPI_BYTE, &bytes);
          in[n].resize(bytes / sizeof(T));
          MPI_Recv(in[n].data(),
                   bytes,
                   MPI_BYTE,
                   ranks[n],
                   tag,
                   comm,
                   MPI_STATUS_IGNORE);
        }
      MPI_Waitall(sends.size(), sends.data(), MPI_STATUSES_IGNORE);
      return in;
    }

    template std::vector<std::vector<double>>
    NeighbourExchange::exchange(const std::vector<std::vector<double>> &,
                                const int) const;


    void
    NeighbourExchange::set_ghost_lists(
      std::vector<std::vector<unsigned int>> indices,
      std::vector<unsigned int>              offsets)
    {
      send_indices = std::move(indices);
      ghost_offset = std::move(offsets);
    }


    void
    NeighbourExchange::update(std::initializer_list<Field> fields) const
    {
      const unsigned int n_nb = ranks.size();
      if (n_nb == 0)
        return;
      unsigned int width = 0;
      for (const Field &field : fields)
        width += field.width;
      for (unsigned int n = 0; n < n_nb; ++n)
        {
          recv_buffers[n].resize((ghost_offset[n + 1] - ghost_offset[n])
                                 * width);
          MPI_Irecv(recv_buffers[n].data(),
                    recv_buffers[n].size(),
                    MPI_DOUBLE,
                    ranks[n],
                    78,
                    comm,
                    &requests[n]);
        }
      for (unsigned int n = 0; n < n_nb; ++n)
        {
          auto &buf = send_buffers[n];
          buf.resize(send_indices[n].size() * width);
          double *out = buf.data();
          for (const unsigned int k : send_indices[n])
            for (const Field &field : fields)
              out = std::copy(field.data + std::size_t(k) * field.width,
                              field.data + std::size_t(k + 1) * field.width,
                              out);
          MPI_Isend(buf.data(),
                    buf.size(),
                    MPI_DOUBLE,
                    ranks[n],
                    78,
                    comm,
                    &requests[n_nb + n]);
        }
      MPI_Waitall(2 * n_nb, requests.data(), MPI_STATUSES_IGNORE);
      for (unsigned int n = 0; n < n_nb; ++n)
        {
          const double *in = recv_buffers[n].data();
          for (unsigned int k = ghost_offset[n]; k < ghost_offset[n + 1]; ++k)
            for (const Field &field : fields)
              {
                std::copy(in,
                          in + field.width,
                          field.data + std::size_t(k) * field.width);
                in += field.width;
              }
        }
    }
  } // namespace mca
} // namespace tribodyn
