// FCC packing with regions (issue #4).
//
// A box of n^3 FCC cells holds exactly 4 n^3 automata, every automaton's
// nearest neighbours are at distance d (12 in the bulk); a spherical void
// removes the automata whose centres lie in it and a cylinder of any axis
// changes their material: the counts must equal the number of lattice
// sites inside the shapes (counted here with the shapes' own formulas,
// written again below, not Region::contains) and approach
// volume / V (V = d^3 / sqrt 2) within 5 %.

#include "mca_test_tools.h"

#include <map>

using namespace tribodyn_test;

namespace
{
  /// Every automaton of @p graded sits on the site of @p fine (sorted by
  /// id) with its id.
  bool
  on_fine_sites(const std::vector<PackedAutomaton> &graded,
                const std::vector<PackedAutomaton> &fine,
                const double                        d)
  {
    for (const auto &g : graded)
      {
        const auto site = std::lower_bound(fine.begin(),
                                           fine.end(),
                                           g.id,
                                           [](const auto &s, const auto id) {
                                             return s.id < id;
                                           });
        if (site == fine.end() || site->id != g.id
            || site->position.distance(g.position) >= 1e-12 * d)
          return false;
      }
    return true;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             d = 1e-3, a = d * std::sqrt(2.);
  const unsigned int                       n     = 12;
  Parameters                               p     = block_parameters(n, d, 0);
  const auto                               plain = pack_automata(p.geometry, 2);
  check(plain.size() == 4 * n * n * n,
        "FCC box of 12^3 cells holds 4 n^3 = " + std::to_string(4 * n * n * n)
          + " automata (" + std::to_string(plain.size()) + ")");
  // nearest-neighbour distance of an interior automaton
  const Point3 centre(n * a / 2, n * a / 2, n * a / 2);
  std::size_t  inner = 0;
  for (std::size_t k = 0; k < plain.size(); ++k)
    if (plain[k].position.distance(centre)
        < plain[inner].position.distance(centre))
      inner = k;
  unsigned int neighbours = 0;
  double       nearest    = 1e300;
  for (std::size_t k = 0; k < plain.size(); ++k)
    if (k != inner)
      {
        const double r = plain[k].position.distance(plain[inner].position);
        nearest        = std::min(nearest, r);
        if (r < d * (1 + 1e-9))
          ++neighbours;
      }
  check_relative(nearest, d, 1e-12, "nearest-neighbour distance = d");
  check(neighbours == 12, "12 neighbours at distance d in the bulk");

  const double R = 4.5 * d;
  Region       sphere;
  sphere.shape    = Region::Shape::sphere;
  sphere.a        = centre;
  sphere.radius   = R;
  sphere.material = -1;
  Region cylinder;
  cylinder.shape     = Region::Shape::cylinder;
  cylinder.a         = Point3(1 * a, 2 * a, 1.5 * a);
  cylinder.b         = Point3(10 * a, 9 * a, 10.5 * a);
  cylinder.radius    = 2.5 * d;
  cylinder.material  = 1;
  p.geometry.regions = {cylinder, sphere};
  const auto packed  = pack_automata(p.geometry, 2);
  // Membership from the shapes' definitions: |x - c| < R; a point whose
  // projection on the axis a + t (b - a) has t in [0, 1] and lies closer
  // than the radius to it. (No site lies within 1e-9 d of either surface:
  // the counts do not depend on < or <=.)
  const auto inside_sphere
    = [&](const Point3 &x) { return x.distance(centre) < R; };
  const auto inside_cylinder = [&](const Point3 &x) {
    const auto   axis = cylinder.b - cylinder.a;
    const auto   rel  = x - cylinder.a;
    const double t    = (rel * axis) / (axis * axis);
    return t >= 0 && t <= 1 && (rel - t * axis).norm() < cylinder.radius;
  };
  std::size_t in_sphere = 0, in_cylinder = 0, carbon = 0, near_surface = 0;
  for (const auto &q : plain)
    {
      const auto   axis = cylinder.b - cylinder.a;
      const auto   rel  = q.position - cylinder.a;
      const double t    = (rel * axis) / (axis * axis);
      near_surface
        += std::abs(q.position.distance(centre) - R) < 1e-9 * d
           || std::abs((rel - t * axis).norm() - cylinder.radius) < 1e-9 * d
           || std::min(std::abs(t), std::abs(t - 1)) * axis.norm() < 1e-9 * d;
      if (inside_sphere(q.position))
        ++in_sphere;
      else if (inside_cylinder(q.position))
        ++in_cylinder;
    }
  check(near_surface == 0, "no lattice site on a shape's surface");
  for (const auto &q : packed)
    carbon += q.material == 1;
  const double V = d * d * d / std::sqrt(2.);
  check(packed.size() == plain.size() - in_sphere,
        "the void removes the " + std::to_string(in_sphere)
          + " automata inside the sphere");
  check(carbon == in_cylinder,
        "the cylinder turns its " + std::to_string(in_cylinder)
          + " automata (outside the void) into carbon");
  check_relative(in_sphere * V,
                 4. / 3 * M_PI * R * R * R,
                 0.05,
                 "sphere: automata x V vs its volume");
  const double L       = cylinder.b.distance(cylinder.a);
  std::size_t  cyl_all = 0;
  for (const auto &q : plain)
    cyl_all += inside_cylinder(q.position);
  check_relative(cyl_all * V,
                 M_PI * 2.5 * d * 2.5 * d * L,
                 0.05,
                 "cylinder (oblique axis): automata x V vs its volume");

  // Graded packing (issue #18): a 16^3 block with z in [4a, 8a) at size
  // 2d and [8a, 16a) at 4d. A band of level L holds exactly the sites of
  // the FCC lattice of constant 2^L a with the common origin: 4 per cell of
  // that lattice, 4 (16 / 2^L)^2 (band height / 2^L a) of them; each is a
  // site of the fine lattice (same id, same position), and an interior one
  // has 12 neighbours of its size at 2^L d.
  {
    const unsigned int m    = 16;
    Parameters         q    = block_parameters(m, d, 0);
    const auto         fine = pack_automata(q.geometry, 2);
    q.geometry.size_bands
      = {{4 * a - 1e-3 * a, 8 * a - 1e-3 * a, 1}, {8 * a - 1e-3 * a, 1, 2}};
    q.geometry.fine_free_faces = false; // the bands' lattices to the faces
    const auto                 graded    = pack_automata(q.geometry, 2);
    std::array<std::size_t, 3> per_level = {{0, 0, 0}};
    for (const auto &g : graded)
      ++per_level[g.level];
    const bool fine_ids = on_fine_sites(graded, fine, d);
    check(per_level[0] == 4 * m * m * 4 && per_level[1] == 4 * 8 * 8 * 2
            && per_level[2] == 4 * 4 * 4 * 2,
          "graded block: " + std::to_string(per_level[0]) + " / "
            + std::to_string(per_level[1]) + " / "
            + std::to_string(per_level[2])
            + " automata of d / 2d / 4d (expected 4096 / 512 / 128)");
    check(fine_ids, "every graded automaton sits on the fine site of its id");
    for (const unsigned int level : {1u, 2u})
      {
        // the automaton of this level nearest to the middle of its band
        const double z_mid = level == 1 ? 6 * a : 12 * a;
        const Point3 mid(m * a / 2, m * a / 2, z_mid);
        std::size_t  best = graded.size();
        for (std::size_t k = 0; k < graded.size(); ++k)
          if (graded[k].level == level
              && (best == graded.size()
                  || graded[k].position.distance(mid)
                       < graded[best].position.distance(mid)))
            best = k;
        const double size    = (1u << level) * d;
        unsigned int equal   = 0;
        double       nearest = 1e300;
        for (std::size_t k = 0; k < graded.size(); ++k)
          if (k != best && graded[k].level == level)
            {
              const double r
                = graded[k].position.distance(graded[best].position);
              nearest = std::min(nearest, r);
              equal += r < size * (1 + 1e-9);
            }
        check_relative(nearest,
                       size,
                       1e-12,
                       "level " + std::to_string(level)
                         + ": nearest neighbour of its size at 2^L d");
        check(equal == 12,
              "level " + std::to_string(level) + ": 12 neighbours at 2^L d ("
                + std::to_string(equal) + ")");
      }
  }

  // The skin at free lateral faces (Geometry/Size at free faces = fine):
  // the same bands with free x and y faces keep the fine lattice's surface
  // (every fine site of the outermost layer of each lateral face, a/4 deep,
  // in the packing, of size d), no automaton of size 2^L d lies closer to a
  // lateral face than skin_depth(L) (a kept coarse cell, 2^L a / 2 in
  // radius, stays inside the body), and every automaton is on its fine site.
  {
    const unsigned int m    = 16;
    Parameters         q    = block_parameters(m, d, 0);
    const auto         fine = pack_automata(q.geometry, 2);
    q.geometry.size_bands
      = {{4 * a - 1e-3 * a, 8 * a - 1e-3 * a, 1}, {8 * a - 1e-3 * a, 1, 2}};
    const auto graded = pack_automata(q.geometry, 2);
    auto       depth  = [&](const Point3 &p) {
      return std::min(std::min(p[0], m * a - p[0]),
                      std::min(p[1], m * a - p[1]));
    };
    std::map<std::uint32_t, const PackedAutomaton *> by_id;
    std::array<std::size_t, 3>                       per_level = {{0, 0, 0}};
    for (const auto &g : graded)
      {
        by_id[g.id] = &g;
        ++per_level[g.level];
      }
    std::size_t surface = 0, kept = 0;
    for (const auto &f : fine)
      if (depth(f.position) < a / 2)
        {
          ++surface;
          const auto it = by_id.find(f.id);
          kept += it != by_id.end() && it->second->level == 0;
        }
    check(surface > 0 && kept == surface,
          "skin: " + std::to_string(kept) + " of the " + std::to_string(surface)
            + " fine sites of the lateral surface layers kept, of size d");
    double closest[3] = {1e300, 1e300, 1e300};
    for (const auto &g : graded)
      closest[g.level] = std::min(closest[g.level], depth(g.position));
    const bool on_sites = on_fine_sites(graded, fine, d);
    check(per_level[1] > 0 && per_level[2] > 0
            && closest[1] >= q.geometry.skin_depth(1) * (1 - 1e-12)
            && closest[2] >= q.geometry.skin_depth(2) * (1 - 1e-12),
          "skin: " + std::to_string(per_level[0]) + " / "
            + std::to_string(per_level[1]) + " / "
            + std::to_string(per_level[2])
            + " automata of d / 2d / 4d; the 2d and 4d ones at least "
            + std::to_string(closest[1] / a) + " a and "
            + std::to_string(closest[2] / a)
            + " a from a lateral face (skin depths a and 4a)");
    check(on_sites, "skin: every automaton sits on the fine site of its id");
  }
  return result();
}
