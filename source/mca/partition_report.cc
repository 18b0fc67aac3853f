// The partition of a scene over N ranks, computed on one process without
// building the mesh or the automata (tribodyn --partition-report N).

#include <algorithm>
#include <cmath>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>
#include <map>
#include <tribodyn/core/errors.h>
#include <tribodyn/mca/automaton_system.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      std::uint64_t
      interleave(const std::uint64_t i,
                 const std::uint64_t j,
                 const std::uint64_t k,
                 const unsigned int  level)
      {
        // p4est's Morton index within a tree: bit b of x, y, z at bits
        // 3b, 3b+1, 3b+2
        std::uint64_t m = 0;
        for (unsigned int b = 0; b < level; ++b)
          m |= ((i >> b) & 1) << (3 * b) | ((j >> b) & 1) << (3 * b + 1)
               | ((k >> b) & 1) << (3 * b + 2);
        return m;
      }
    } // namespace


    PartitionFigures
    AutomatonSystem::partition_report(const Parameters  &prm,
                                      const unsigned int n_ranks)
    {
      const auto  &g = prm.geometry;
      const double range
        = g.largest_pair_distance() * (1 + prm.interaction.skin);
      std::array<unsigned int, 3> trees;
      unsigned int                level;
      Decomposition::choose_grid(g, range, trees, level);
      std::array<unsigned int, 3> n;
      std::array<double, 3>       h;
      for (unsigned int c = 0; c < 3; ++c)
        {
          n[c] = trees[c] << level;
          h[c] = (g.domain_upper[c] - g.domain_lower[c]) / n[c];
        }
      const std::uint64_t n_cells = std::uint64_t(n[0]) * n[1] * n[2];
      if (n_cells > 2000000000ull)
        throw InputError("The scene has more than 2e9 cells of the "
                         "interaction range; the partition report does not "
                         "handle it.");

      // The order in which deal.II hands the trees to p4est (a few
      // thousand coarse cells at most: built here on this process).
      std::map<std::array<unsigned int, 3>, unsigned int> tree_of;
      {
        dealii::parallel::distributed::Triangulation<3> coarse(MPI_COMM_SELF);
        dealii::GridGenerator::subdivided_hyper_rectangle(
          coarse,
          std::vector<unsigned int>(trees.begin(), trees.end()),
          g.domain_lower,
          g.domain_upper);
        const auto &perm = coarse.get_coarse_cell_to_p4est_tree_permutation();
        for (const auto &cell : coarse.cell_iterators_on_level(0))
          {
            std::array<unsigned int, 3> t;
            for (unsigned int c = 0; c < 3; ++c)
              t[c] = static_cast<unsigned int>(
                (cell->center()[c] - g.domain_lower[c])
                / (h[c] * (1u << level)));
            tree_of[t] = perm[cell->index()];
          }
      }
      // (p4est's cells hold split^3 cells: Decomposition::cell_split())
      const unsigned int split = Decomposition::cell_split(
        trees, level, n_ranks, prm.partition.mesh_cells_per_rank);
      const unsigned int  mesh_level = Decomposition::mesh_level(level, split);
      const std::uint64_t per_tree   = std::uint64_t(1) << (3 * mesh_level);
      const std::uint64_t n_mesh_cells
        = n_cells / (std::uint64_t(split) * split * split);
      auto position =
        [&](const unsigned int i, const unsigned int j, const unsigned int k) {
          const std::array<unsigned int, 3> t{
            {i >> level, j >> level, k >> level}};
          const unsigned int mask = (1u << mesh_level) - 1;
          return tree_of.at(t) * per_tree
                 + interleave((i / split) & mask,
                              (j / split) & mask,
                              (k / split) & mask,
                              mesh_level);
        };
      // Automata per cell and the cells' size-level summaries (as
      // cell_level_summaries(): largest level, any near a change of size),
      // in one pass over the lattice.
      auto level_byte = [](const PackedAutomaton &a) {
        return static_cast<unsigned char>(
          a.level | (a.transitional ? transitional_flag : 0));
      };
      auto cell_of = [&](const Point3 &x) {
        std::array<unsigned int, 3> ijk;
        for (unsigned int c = 0; c < 3; ++c)
          ijk[c] = std::min<unsigned int>(
            n[c] - 1,
            static_cast<unsigned int>(
              std::max(0., std::floor((x[c] - g.domain_lower[c]) / h[c]))));
        return ijk;
      };
      auto linear =
        [&](const unsigned int i, const unsigned int j, const unsigned int k) {
          return (std::uint64_t(k) * n[1] + j) * n[0] + i;
        };
      std::vector<std::uint16_t>        count(n_cells, 0);
      std::vector<unsigned char>        summary(n_cells, 0);
      std::array<unsigned long long, 3> per_size = {{0, 0, 0}};
      Point3                            upper    = g.domain_upper;
      pack_box(g, g.domain_lower, upper, [&](const PackedAutomaton &a) {
        ++per_size[std::min<unsigned int>(a.level, 2)];
        const auto          ijk  = cell_of(a.position);
        const std::uint64_t cell = linear(ijk[0], ijk[1], ijk[2]);
        if (count[cell] < 65535)
          ++count[cell];
        const unsigned char b = level_byte(a);
        summary[cell]         = merge_level_summary(summary[cell], b);
      });

      // p4est's weighted partition (as AutomatonSystem::setup() asks for
      // it): the positions along the curve are dense (0 ... N_cells - 1),
      // and rank r owns the cells whose cumulative weight before them lies
      // in [W r / R, W (r + 1) / R), W the total weight.
      std::vector<std::uint32_t> owner_at(n_mesh_cells, 0);
      {
        std::vector<std::uint64_t> weight_at(n_mesh_cells, 0);
        for (unsigned int k = 0; k < n[2]; ++k)
          for (unsigned int j = 0; j < n[1]; ++j)
            for (unsigned int i = 0; i < n[0]; ++i)
              weight_at[position(i, j, k)]
                += cost_model::cost_per_automaton
                     * count[(std::uint64_t(k) * n[1] + j) * n[0] + i]
                   + 1;
        std::uint64_t total_weight = 0;
        for (const auto w : weight_at)
          total_weight += w;
        std::uint64_t before = 0;
        for (std::uint64_t pos = 0; pos < n_mesh_cells; ++pos)
          {
            owner_at[pos] = static_cast<std::uint32_t>(
              std::min<long double>(n_ranks - 1,
                                    std::floor(static_cast<long double>(before)
                                               * n_ranks / total_weight)));
            before += weight_at[pos];
          }
      }
      // owner of each cell by its structured index
      std::vector<std::uint32_t> owner(n_cells);
      for (unsigned int k = 0; k < n[2]; ++k)
        for (unsigned int j = 0; j < n[1]; ++j)
          for (unsigned int i = 0; i < n[0]; ++i)
            owner[linear(i, j, k)] = owner_at[position(i, j, k)];
      std::vector<std::uint32_t>().swap(owner_at);

      // The neighbour cells of cell (i, j, k) (index unwrapped, so that
      // its box is the image next to the cell, and wrapped).
      auto for_each_neighbour
        = [&](const std::array<unsigned int, 3> &ijk, const auto &f) {
            for (int oz = -1; oz <= 1; ++oz)
              for (int oy = -1; oy <= 1; ++oy)
                for (int ox = -1; ox <= 1; ++ox)
                  {
                    const int    off[3] = {ox, oy, oz};
                    int          v[3];
                    unsigned int nb[3];
                    bool         valid = true;
                    for (unsigned int c = 0; c < 3; ++c)
                      {
                        v[c] = static_cast<int>(ijk[c]) + off[c];
                        if ((v[c] < 0 || v[c] >= static_cast<int>(n[c]))
                            && !g.periodic[c])
                          valid = false;
                        nb[c] = (v[c] + n[c]) % n[c];
                      }
                    if (valid)
                      f(v, linear(nb[0], nb[1], nb[2]));
                  }
          };

      // Owned automata; cells with a neighbour of another rank, and the
      // automata a neighbour rank would receive were whole cells sent.
      std::vector<double>        owned(n_ranks, 0), ghosts(n_ranks, 0);
      std::vector<double>        whole_cells(n_ranks, 0);
      std::vector<unsigned char> boundary(n_cells, 0);
      unsigned long long         total = 0;
      std::vector<unsigned int>  seen;
      for (unsigned int k = 0; k < n[2]; ++k)
        for (unsigned int j = 0; j < n[1]; ++j)
          for (unsigned int i = 0; i < n[0]; ++i)
            {
              const std::uint64_t cell    = linear(i, j, k);
              const unsigned int  c_count = count[cell];
              if (c_count == 0)
                continue;
              total += c_count;
              const unsigned int o = owner[cell];
              owned[o] += c_count;
              seen.clear();
              for_each_neighbour({{i, j, k}},
                                 [&](const int *, const std::uint64_t nb) {
                                   const unsigned int r = owner[nb];
                                   if (r != o
                                       && std::find(seen.begin(), seen.end(), r)
                                            == seen.end())
                                     seen.push_back(r);
                                 });
              boundary[cell] = !seen.empty();
              for (const unsigned int r : seen)
                whole_cells[r] += c_count;
            }

      // The ghosts exchange_ghosts() sends: an automaton of a boundary
      // cell goes to each neighbour rank with a cell within its pair-list
      // range with that cell's largest size (second pass over the lattice).
      const bool   graded = !g.size_bands.empty();
      const auto   ranges = pair_list_ranges(prm);
      const double uniform_range
        = g.automaton_size * (1 + prm.interaction.skin);
      pack_box(g, g.domain_lower, upper, [&](const PackedAutomaton &a) {
        const auto          ijk  = cell_of(a.position);
        const std::uint64_t cell = linear(ijk[0], ijk[1], ijk[2]);
        if (!boundary[cell])
          return;
        const unsigned int o = owner[cell];
        seen.clear();
        for_each_neighbour(ijk, [&](const int *v, const std::uint64_t nb) {
          const unsigned int r = owner[nb];
          if (r == o || std::find(seen.begin(), seen.end(), r) != seen.end())
            return;
          const double reach
            = graded ? pair_list_range(ranges, level_byte(a), summary[nb])
                     : uniform_range;
          double dist2 = 0;
          for (unsigned int c = 0; c < 3; ++c)
            {
              const double lower = g.domain_lower[c] + v[c] * h[c];
              const double out   = std::max(
                {lower - a.position[c], a.position[c] - (lower + h[c]), 0.});
              dist2 += out * out;
            }
          if (dist2 < reach * reach * ghost_reach_margin)
            seen.push_back(r);
        });
        for (const unsigned int r : seen)
          ghosts[r] += 1;
      });

      PartitionFigures fig;
      fig.n_automata = total;
      fig.n_per_size = per_size;
      fig.n_ranks    = n_ranks;
      auto stats     = [&](const std::vector<double> &v,
                       double                    &lo,
                       double                    &mean,
                       double                    &hi) {
        lo   = *std::min_element(v.begin(), v.end());
        hi   = *std::max_element(v.begin(), v.end());
        mean = 0;
        for (const double a : v)
          mean += a;
        mean /= v.size();
      };
      stats(owned, fig.owned_min, fig.owned_mean, fig.owned_max);
      stats(ghosts, fig.ghosts_min, fig.ghosts_mean, fig.ghosts_max);
      double unused;
      stats(whole_cells, unused, fig.whole_cell_ghosts_mean, unused);
      const double moments = prm.interaction.relative_rotation_on()
                               ? cost_model::bytes_per_automaton_moments
                               : 0.;
      for (unsigned int r = 0; r < n_ranks; ++r)
        fig.bytes_per_rank_max = std::max(
          fig.bytes_per_rank_max,
          owned[r] * (cost_model::bytes_per_owned_automaton + moments)
            + ghosts[r] * (cost_model::bytes_per_ghost_automaton + moments));
      return fig;
    }
  } // namespace mca
} // namespace tribodyn
