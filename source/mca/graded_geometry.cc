// Automata of several sizes (issue #18, doc/theory/mca.md §9): the volumes
// of the automata near a change of size and the areas and rest lengths of
// their pairs, from their Voronoi cells at set-up; the pair geometry of new
// pairs; the pairs that can never interact dropped from the list.

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/packing.h>
#include <tribodyn/mca/voronoi_cell.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      /// Largest number of faces of a Voronoi cell near a change of size
      /// (a uniform cell has 12; measured up to ~20 across transitions).
      constexpr unsigned int max_faces = 64;
      /// Faces smaller than this times S that join automata beyond the
      /// pair-list range are dropped (slivers of round-off in the box).
      constexpr double sliver = 1e-3;
    } // namespace


    double
    AutomatonSystem::new_pair_area(const unsigned int p) const
    {
      const unsigned int i = pi[p], j = pj[p];
      // near a change of size only the Voronoi faces of the set-up
      // interact (a pair found later is inert)
      if (transitional(i) || transitional(j))
        return 0;
      // elsewhere both automata have one size (automata of different sizes
      // away from a change of size are farther apart than any range)
      const unsigned int level = size_level[i] & ~transitional_flag;
      return S * (1u << (2 * level));
    }


    double
    AutomatonSystem::new_pair_half_rest(const unsigned int p) const
    {
      const unsigned int i = pi[p], j = pj[p];
      if (transitional(i) || transitional(j))
        return 0;
      return r0 * (1u << (size_level[i] & ~transitional_flag));
    }


    void
    AutomatonSystem::setup_graded_geometry()
    {
      const auto          &g     = prm.geometry;
      const Decomposition &cells = partition.cells();
      // The Voronoi cell of each owned automaton near a change of size,
      // from the sites of the packing around it (pack_box: the geometry
      // alone, the same bits on any partition). It is clipped from its
      // bounding cell, the rhombic dodecahedron of twice the largest
      // adjacent size (at most 2^(L+2) d: sizes change by a factor 2), so
      // every site that can cut it lies within twice that cell's radius:
      // the candidates, farther than the pair list, which needs to hold
      // only the pairs that share a face (their distance is checked below
      // against the pair-list range).
      struct Face
      {
        std::uint32_t id;
        double        area;
        Vec3          offset; ///< centroid off the line of centres
      };
      std::vector<std::vector<Face>>               faces(n_local);
      unsigned int                                 n_crowded     = 0;
      double                                       farthest_face = 0;
      std::vector<PackedAutomaton>                 sites;
      std::vector<unsigned char>                   site_shift;
      std::vector<std::uint32_t>                   real_ids;
      std::size_t                                  n_real = 0;
      std::vector<std::pair<double, unsigned int>> by_distance;
      std::vector<std::vector<unsigned int>> in_cell(cells.n_owned_cells());
      for (unsigned int k = 0; k < n_owned; ++k)
        if (transitional(k))
          in_cell[cell_of[k]].push_back(k);
      for (unsigned int c = 0; c < in_cell.size(); ++c)
        {
          if (in_cell[c].empty())
            continue;
          unsigned int top = 0;
          for (const unsigned int k : in_cell[c])
            top = std::max(top,
                           static_cast<unsigned int>(size_level[k]
                                                     & ~transitional_flag));
          const double reach = 2 * VoronoiCell(4 * (1u << top) * d).radius();
          // the sites of the cell's box widened by the reach, with their
          // periodic images (the widened box clipped to the domain, for
          // each image shift of one period)
          Point3 lower, upper;
          cells.cell_box(cells.cell_coordinates(c), lower, upper);
          sites.clear();
          site_shift.clear();
          n_real = 0;
          for (const bool continued : {false, true})
            for (int sx = -1; sx <= 1; ++sx)
              for (int sy = -1; sy <= 1; ++sy)
                for (int sz = -1; sz <= 1; ++sz)
                  {
                    const int s[3] = {sx, sy, sz};
                    Point3    shift, lo, hi;
                    bool      empty = false;
                    for (unsigned int e = 0; e < 3; ++e)
                      {
                        const double period
                          = g.domain_upper[e] - g.domain_lower[e];
                        if (s[e] != 0 && !g.periodic[e])
                          empty = true;
                        shift[e] = s[e] * period;
                        lo[e]    = lower[e] - reach - shift[e];
                        hi[e]    = upper[e] + reach - shift[e];
                        if (!continued || g.periodic[e])
                          {
                            lo[e] = std::max(lo[e], g.domain_lower[e]);
                            hi[e] = std::min(hi[e], g.domain_upper[e]);
                          }
                        empty = empty || lo[e] >= hi[e];
                      }
                    if (empty)
                      continue;
                    // the continued lattice adds the sites where the
                    // packing has none (vacuum): they bound the cells
                    // of the automata on a free surface, and have no face
                    // that interacts
                    if (continued)
                      {
                        real_ids.clear();
                        for (std::size_t q = 0; q < n_real; ++q)
                          if (site_shift[q]
                              == (sx + 1) * 9 + (sy + 1) * 3 + sz + 1)
                            real_ids.push_back(sites[q].id);
                        std::sort(real_ids.begin(), real_ids.end());
                      }
                    pack_box(
                      g,
                      lo,
                      hi,
                      [&](const PackedAutomaton &a) {
                        if (continued
                            && std::binary_search(real_ids.begin(),
                                                  real_ids.end(),
                                                  a.id))
                          return;
                        PackedAutomaton b = a;
                        for (unsigned int e = 0; e < 3; ++e)
                          b.position[e] += shift[e];
                        if (continued)
                          b.id = outside_lattice;
                        sites.push_back(b);
                      },
                      continued);
                    site_shift.resize(sites.size(),
                                      (sx + 1) * 9 + (sy + 1) * 3 + sz + 1);
                    if (!continued)
                      n_real = sites.size();
                  }

          for (const unsigned int k : in_cell[c])
            {
              const double own      = automaton_size(k);
              const double complete = 2 * VoronoiCell(4 * own).radius();
              by_distance.clear();
              double bound = own;
              for (unsigned int a = 0; a < sites.size(); ++a)
                {
                  Vec3 r;
                  for (unsigned int e = 0; e < 3; ++e)
                    r[e] = sites[a].position[e] - x[k][e];
                  const double distance = std::sqrt(dot(r, r));
                  if (distance >= complete || distance < 1e-6 * own)
                    continue;
                  by_distance.emplace_back(distance, a);
                  // an adjacent automaton of another size (d-2d faces lie
                  // at 1.49 (d_i + d_j)/2 at most)
                  const double size = d * (1u << sites[a].level);
                  if (distance < 0.8 * (own + size))
                    bound = std::max(bound, size);
                }
              // (ties in the order of the sites: the same on any partition)
              std::sort(by_distance.begin(), by_distance.end());
              // the bounding cell: the rhombic dodecahedron of twice the
              // largest adjacent size. Near a change of size, cells reach
              // into the sites of the fine lattice that a coarse one leaves
              // empty: the cell of a fine automaton below a 2d layer extends
              // to 1.18 d, beyond the 2d dodecahedron around it (test
              // mca_hooke_graded fails with that bound). On a free surface
              // the sites of the continued lattice close it.
              VoronoiCell cell(2 * bound);
              for (const auto &[distance, a] : by_distance)
                {
                  if (distance > 2 * cell.radius())
                    break;
                  Vec3 r;
                  for (unsigned int e = 0; e < 3; ++e)
                    r[e] = sites[a].position[e] - x[k][e];
                  cell.clip_by_neighbour(r, static_cast<int>(a));
                }
              volume[k]        = cell.volume();
              const auto areas = cell.face_geometry();
              // a cell still bounded by its dodecahedron (tag -1) is open
              // where even the continued lattice has no sites (the gap
              // under a lifted upper body): there it can share faces with
              // automata farther apart than in the bulk, faces across the
              // vacuum that the uniform lattice does not have either: they
              // are dropped
              const bool open = !areas.empty() && areas.front().tag < 0
                                && areas.front().area > 1e-6 * S;
              for (const auto &[tag, area, centroid] : areas)
                if (tag >= 0)
                  {
                    const PackedAutomaton &other = sites[tag];
                    if (other.id == outside_lattice)
                      continue; // vacuum
                    Vec3 r;
                    for (unsigned int e = 0; e < 3; ++e)
                      r[e] = other.position[e] - x[k][e];
                    const double apart
                      = std::sqrt(dot(r, r))
                        / std::max(own, d * (1u << other.level));
                    // beyond the range: faces across the vacuum of an
                    // open cell, and slivers at the four-fold vertices of
                    // the FCC cell (two second neighbours a = sqrt(2) d
                    // apart touch there; a period that holds a whole number
                    // of cells only to 1e-6, as the check of the box
                    // allows, opens faces of ~5e-6 S between them)
                    if (apart > g.transition_face_factor()
                        && (open || area < sliver * S))
                      continue;
                    // the centroid's offset from the line of centres
                    const double along = dot(centroid, r) / dot(r, r);
                    Vec3         offset;
                    for (unsigned int e = 0; e < 3; ++e)
                      offset[e] = centroid[e] - along * r[e];
                    faces[k].push_back({other.id, area, offset});
                    if (area > 1e-6 * S)
                      farthest_face = std::max(farthest_face, apart);
                  }
              n_crowded += faces[k].size() > max_faces;
            }
        }
      // A face farther than the pair-list range would be missed.
      farthest_face = dealii::Utilities::MPI::max(farthest_face, comm);
      throw_collectively(
        comm,
        farthest_face > g.transition_face_factor(),
        "Internal error: a Voronoi face near a change of size joins automata "
          + format_number(farthest_face)
          + " times the larger size apart, beyond the pair-list range "
            "(GeometryParameters::transition_face_factor(); Geometry/Size "
            "bands: report this scene).");
      throw_collectively(
        comm,
        n_crowded > 0,
        "Internal error: " + std::to_string(n_crowded)
          + " Voronoi cell(s) near a change of size have more than "
          + std::to_string(max_faces)
          + " faces (Geometry/Size bands: report this scene).");

      // The faces of the ghosts from their owners: one record per ghost,
      // in the order of the ghost blocks (its number of faces, then id,
      // area and offset of each).
      const auto &send = partition.neighbours().ghost_send_indices();
      std::vector<std::vector<double>> out(send.size());
      for (unsigned int n = 0; n < send.size(); ++n)
        for (const unsigned int k : send[n])
          {
            out[n].push_back(faces[k].size());
            for (const Face &f : faces[k])
              {
                out[n].push_back(f.id);
                out[n].push_back(f.area);
                for (unsigned int e = 0; e < 3; ++e)
                  out[n].push_back(f.offset[e]);
              }
          }
      if (partition.neighbours().active())
        {
          const auto  in      = partition.neighbours().exchange(out, 84);
          const auto &offsets = partition.neighbours().ghost_offsets();
          for (unsigned int n = 0; n < in.size(); ++n)
            {
              std::size_t o = 0;
              for (unsigned int g = offsets[n]; g < offsets[n + 1]; ++g)
                {
                  const unsigned int count
                    = static_cast<unsigned int>(in[n][o++]);
                  for (unsigned int c = 0; c < count; ++c, o += 5)
                    faces[g].push_back(
                      {static_cast<std::uint32_t>(in[n][o]),
                       in[n][o + 1],
                       {{in[n][o + 2], in[n][o + 3], in[n][o + 4]}}});
                }
            }
        }

      // The face of automaton k towards automaton @p other (pair p): its
      // Voronoi face, or for an automaton away from a change of size the
      // face of its uniform cell (centred on the line of centres).
      const auto face_towards = [&](const unsigned int k,
                                    const unsigned int other,
                                    const unsigned int p) {
        if (transitional(k))
          {
            for (const Face &f : faces[k])
              if (f.id == id[other])
                return f;
            return Face{id[other], 0., {{0, 0, 0}}};
          }
        const double size = automaton_size(k);
        return Face{id[other],
                    std::abs(pair_distance(p) - size) < 1e-6 * size
                      ? S * (size / d) * (size / d)
                      : 0.,
                    {{0, 0, 0}}};
      };
      // Each pair's area is the mean of its two faces (equal up to
      // round-off), computed from the same bits on every rank: partition-
      // independent, and S_ij = S_ji exactly.
      const double       face_floor = 1e-6 * S;
      const unsigned int n_pairs    = pi.size();
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          const unsigned int i = pi[p], j = pj[p];
          if (!transitional(i) && !transitional(j))
            continue;
          const Face   from_i = face_towards(i, j, p);
          const Face   from_j = face_towards(j, i, p);
          const double area   = 0.5 * (from_i.area + from_j.area);
          const bool   face   = area > face_floor;
          // the offset of the centroid, the same point seen from both
          // sides (weighted by the faces: one may be missing)
          for (unsigned int c = 0; c < 3; ++c)
            face_offset.component[c][p] = face
                                            ? (from_i.area * from_i.offset[c]
                                               + from_j.area * from_j.offset[c])
                                                / (from_i.area + from_j.area)
                                            : 0.;
          pair_area[p]      = face ? area : 0.;
          pair_half_rest[p] = face ? 0.5 * pair_distance(p) : 0.;
          bonded[p]         = face && body_index(i) == body_index(j);
          in_contact[p]     = face;
        }
    }


    void
    AutomatonSystem::drop_inert_pairs()
    {
      // Near a change of size: pairs without a face, and unbonded ones
      // beyond their contact range (with the skin), never interact.
      const unsigned int         n_pairs = pi.size();
      const double               reach   = 1 + prm.interaction.skin;
      std::vector<unsigned char> keep(n_pairs, 1);
      unsigned int               n_kept = 0;
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          if ((transitional(pi[p]) || transitional(pj[p])) && !bonded[p]
              && (pair_area[p] == 0
                  || pair_distance(p) >= 2 * pair_half_rest[p] * reach))
            keep[p] = 0;
          n_kept += keep[p];
        }
      if (n_kept == n_pairs)
        return;
      PairList::compact(keep);
      pair_fields.compact(keep);
    }
  } // namespace mca
} // namespace tribodyn
