// Voronoi cells of automata of several sizes (issue #18): the volumes and
// contact areas a graded packing needs, checked against exact identities.
//
// 1. Uniform FCC (periodic box): every cell is the rhombic dodecahedron,
//    V = d³/√2 and 12 faces of area S = d²/(2√2) (doc/theory/mca.md §1),
//    to 1e-12 relative (round-off of a few dozen clips).
// 2. A graded periodic box, bands of automata of size d, 2d and 4d on FCC
//    lattices aligned so that coarse sites are fine sites (transitions
//    d -> 2d -> 4d and, across the periodic face, 4d -> d):
//    - the cells tile the box: Σ V_i = box volume (mass is conserved);
//    - every cell is closed by its neighbours' faces (no face of the
//      bounding cell is left) and Σ_j S_ij n_ij = 0 (a homogeneous stress
//      puts no net force on any automaton, transition automata included);
//    - S_ij = S_ji (Newton's third law of the pair forces);
//    - Σ_pairs S_ij r_ij ⊗ n_ij = V_box I (the virial of a homogeneous
//      stress, i.e. the effective stiffness, is exact across transitions).
//    Tolerance 1e-12 relative: identities of exact geometry, checked in
//    double precision (measured errors ~1e-15).
//    It also prints the largest distance of face-sharing neighbours per
//    pair of sizes (the pair-list ranges a graded scene needs).

#include "../test_utilities.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tribodyn/mca/voronoi_cell.h>

using namespace tribodyn_test;
using tribodyn::mca::Vec3;
using tribodyn::mca::VoronoiCell;

namespace
{
  struct Site
  {
    Vec3         x;
    unsigned int level; ///< size 2^level d
  };

  /// Sites of the FCC lattice of automaton size 2^level d (lattice
  /// constant 2^level d √2, origin 0) in the box [0, L) with z in [z0, z1).
  void
  add_lattice(std::vector<Site> &sites,
              const double       d,
              const unsigned int level,
              const double       L[3],
              const double       z0,
              const double       z1)
  {
    const double half = (1u << level) * d * std::sqrt(2.) / 2;
    const int    n[3] = {int(std::lround(L[0] / half)),
                         int(std::lround(L[1] / half)),
                         int(std::lround(L[2] / half))};
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i)
          if ((i + j + k) % 2 == 0 && k * half >= z0 - 1e-9 * d
              && k * half < z1 - 1e-9 * d)
            sites.push_back({{{i * half, j * half, k * half}}, level});
  }

  /// The Voronoi cells of all sites (periodic box), as (neighbour, area,
  /// pair vector) per site, and the volumes.
  struct Tessellation
  {
    std::vector<double>                                     volume;
    std::vector<std::vector<std::tuple<int, double, Vec3>>> faces;
    std::vector<double>                                     bound_area;
  };

  Tessellation
  tessellate(const std::vector<Site> &sites, const double d, const double L[3])
  {
    Tessellation t;
    for (const Site &s : sites)
      {
        // All other sites (nearest periodic image), nearest first.
        std::vector<std::pair<double, int>> order;
        std::vector<Vec3>                   r(sites.size());
        for (std::size_t j = 0; j < sites.size(); ++j)
          {
            if (&sites[j] == &s)
              continue;
            for (unsigned int c = 0; c < 3; ++c)
              {
                r[j][c] = sites[j].x[c] - s.x[c];
                r[j][c] -= L[c] * std::round(r[j][c] / L[c]);
              }
            order.emplace_back(std::sqrt(tribodyn::mca::dot(r[j], r[j])), j);
          }
        std::sort(order.begin(), order.end());
        // Bounding cell: the rhombic dodecahedron of a size 8 d (larger
        // than any cell of the box).
        VoronoiCell cell(8 * d);
        for (const auto &[distance, j] : order)
          {
            if (distance > 2 * cell.radius())
              break;
            cell.clip_by_neighbour(r[j], j);
          }
        t.volume.push_back(cell.volume());
        t.faces.emplace_back();
        t.bound_area.push_back(0);
        for (const auto &[tag, area] : cell.face_areas())
          if (tag < 0)
            t.bound_area.back() += area;
          else
            t.faces.back().emplace_back(tag, area, r[tag]);
      }
    return t;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             d = 1e-8, a = d * std::sqrt(2.);

  // 1. Uniform FCC, 4 x 4 x 4 cells, periodic.
  {
    const double      L[3] = {4 * a, 4 * a, 4 * a};
    std::vector<Site> sites;
    add_lattice(sites, d, 0, L, 0, L[2]);
    const Tessellation t       = tessellate(sites, d, L);
    double             worst_v = 0, worst_s = 0;
    bool               twelve = true;
    for (std::size_t i = 0; i < sites.size(); ++i)
      {
        worst_v
          = std::max(worst_v,
                     std::abs(t.volume[i] / (d * d * d / std::sqrt(2.)) - 1));
        twelve = twelve && t.faces[i].size() == 12 && t.bound_area[i] == 0;
        for (const auto &[j, area, r] : t.faces[i])
          worst_s
            = std::max(worst_s,
                       std::abs(area / (d * d / (2 * std::sqrt(2.))) - 1));
      }
    check(twelve,
          "uniform FCC: every cell has 12 neighbour faces and no free face ("
            + std::to_string(sites.size()) + " automata)");
    check_relative(
      worst_v, 0, 1e-12, "uniform FCC: largest |V/(d^3/sqrt 2) - 1|", 1);
    check_relative(
      worst_s, 0, 1e-12, "uniform FCC: largest |S/(d^2/(2 sqrt 2)) - 1|", 1);

    // A bounding cell that is already the Voronoi cell (the rhombic
    // dodecahedron of size d): the 12 neighbours' planes coincide with its
    // faces, which must pass to the neighbours (no free face left).
    VoronoiCell cell(d);
    int         tag = 0;
    for (const Vec3 &n : {Vec3{{1, 1, 0}},
                          Vec3{{1, -1, 0}},
                          Vec3{{-1, 1, 0}},
                          Vec3{{-1, -1, 0}},
                          Vec3{{1, 0, 1}},
                          Vec3{{1, 0, -1}},
                          Vec3{{-1, 0, 1}},
                          Vec3{{-1, 0, -1}},
                          Vec3{{0, 1, 1}},
                          Vec3{{0, 1, -1}},
                          Vec3{{0, -1, 1}},
                          Vec3{{0, -1, -1}}})
      cell.clip_by_neighbour({{n[0] * a / 2, n[1] * a / 2, n[2] * a / 2}},
                             tag++);
    const auto faces = cell.face_areas();
    check(faces.size() == 12 && faces.front().first == 0,
          "rhombic dodecahedron clipped by its 12 neighbours: 12 faces, all "
          "of neighbours ("
            + std::to_string(faces.size()) + " faces, first tag "
            + std::to_string(faces.front().first) + ")");
  }

  // 2. Graded: d in [0, 2a), 2d in [2a, 4a), 4d in [4a, 8a); 8a x 8a
  // across, periodic.
  {
    const double      L[3] = {8 * a, 8 * a, 8 * a};
    std::vector<Site> sites;
    add_lattice(sites, d, 0, L, 0, 2 * a);
    add_lattice(sites, d, 1, L, 2 * a, 4 * a);
    add_lattice(sites, d, 2, L, 4 * a, 8 * a);
    std::array<unsigned int, 3> per_level = {{0, 0, 0}};
    for (const Site &s : sites)
      ++per_level[s.level];
    std::cout << "graded box: " << per_level[0] << " automata of d, "
              << per_level[1] << " of 2d, " << per_level[2] << " of 4d"
              << std::endl;
    const Tessellation t = tessellate(sites, d, L);

    double total = 0, free_area = 0, worst_closure = 0, worst_symmetry = 0;
    double virial[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    std::map<std::pair<unsigned int, unsigned int>, double> farthest;
    for (std::size_t i = 0; i < sites.size(); ++i)
      {
        total += t.volume[i];
        free_area += t.bound_area[i];
        Vec3 closure = {{0, 0, 0}};
        for (const auto &[j, area, r] : t.faces[i])
          {
            const double length = std::sqrt(tribodyn::mca::dot(r, r));
            for (unsigned int c = 0; c < 3; ++c)
              {
                closure[c] += area * r[c] / length;
                for (unsigned int e = 0; e < 3; ++e)
                  virial[c][e] += 0.5 * area * r[c] * r[e] / length;
              }
            double back = 0;
            for (const auto &[k, area_k, r_k] : t.faces[j])
              if (k == int(i))
                back = area_k;
            worst_symmetry
              = std::max(worst_symmetry, std::abs(area - back) / (d * d));
            auto key      = std::minmax(sites[i].level, sites[j].level);
            farthest[key] = std::max(farthest[key], length / d);
          }
        worst_closure
          = std::max(worst_closure,
                     std::sqrt(tribodyn::mca::dot(closure, closure)) / (d * d));
      }
    const double box = L[0] * L[1] * L[2];
    check_relative(total,
                   box,
                   1e-12,
                   "graded: sum of the cell volumes = box volume");
    check_relative(
      free_area,
      0,
      1e-12,
      "graded: area of bounding-cell faces left (every cell closed by "
      "neighbours), in d^2",
      d * d);
    check_relative(
      worst_closure, 0, 1e-12, "graded: largest |sum_j S_ij n_ij| / d^2", 1);
    check_relative(
      worst_symmetry, 0, 1e-12, "graded: largest |S_ij - S_ji| / d^2", 1);
    double worst_virial = 0;
    for (unsigned int c = 0; c < 3; ++c)
      for (unsigned int e = 0; e < 3; ++e)
        worst_virial
          = std::max(worst_virial, std::abs(virial[c][e] / box - (c == e)));
    check_relative(worst_virial,
                   0,
                   1e-12,
                   "graded: largest |sum_pairs S r n / V_box - I|",
                   1);
    for (const auto &[levels, r] : farthest)
      std::cout << "sizes " << (1u << levels.first) << "d-"
                << (1u << levels.second)
                << "d: farthest face-sharing neighbour at " << r << " d"
                << std::endl;
  }
  return result();
}
