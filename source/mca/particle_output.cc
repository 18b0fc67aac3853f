// Particle output: one .vtu per rank and a .pvtu, optionally restricted to
// a slab (cross-sections of the seed's Figs. 3-4), through deal.II's VTU
// writer (DataOutBase::write_vtu: binary, zlib-compressed, base64; data as
// Float32). Each automaton is a patch of dimension 0 (a vertex), each pair
// of the contact network a patch of dimension 1 (a line), as deal.II's
// Particles::DataOut does for its particles.

#include <cstdio>
#include <deal.II/base/data_out_base.h>
#include <sstream>
#include <tribodyn/core/output.h>
#include <tribodyn/mca/automaton_system.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      using VectorRanges = std::vector<std::tuple<
        unsigned int,
        unsigned int,
        std::string,
        dealii::DataComponentInterpretation::DataComponentInterpretation>>;

      /// The fields of a piece, listed once: each field's name and number
      /// of components (1, 3 or 9) with its columns in the patches' data.
      struct Fields
      {
        std::vector<std::string> names;
        VectorRanges             vector_ranges;

        /// Declare a field of @p n components; returns its first column.
        unsigned int
        add(const std::string &name, const unsigned int n)
        {
          const unsigned int first = names.size();
          for (unsigned int c = 0; c < n; ++c)
            names.push_back(n == 1 ? name : name + "_" + std::to_string(c));
          if (n > 1)
            vector_ranges.emplace_back(first,
                                       first + n - 1,
                                       name,
                                       n == 3
                                         ? dealii::DataComponentInterpretation::
                                           component_is_part_of_vector
                                         : dealii::DataComponentInterpretation::
                                           component_is_part_of_tensor);
          return first;
        }
      };

      /// Write this rank's patches as NAME.RANK.vtu and, on rank 0, the
      /// index NAME.pvtu of all ranks' pieces; both atomically.
      template <int dim>
      void
      write_piece_and_index(
        const std::string                                     &directory,
        const std::string                                     &name,
        const unsigned int                                     rank,
        const unsigned int                                     n_ranks,
        const std::vector<dealii::DataOutBase::Patch<dim, 3>> &patches,
        const Fields                                          &fields)
      {
        dealii::DataOutBase::VtkFlags flags;
        flags.compression_level
          = dealii::DataOutBase::VtkFlags::ZlibCompressionLevel::best_speed;
        std::ostringstream piece;
        dealii::DataOutBase::write_vtu(
          patches, fields.names, fields.vector_ranges, flags, piece);
        write_file_atomically(
          join_path(directory, name + "." + std::to_string(rank) + ".vtu"),
          piece.str());
        if (rank != 0)
          return;
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < n_ranks; ++r)
          pieces.push_back(name + "." + std::to_string(r) + ".vtu");
        std::ostringstream index;
        dealii::DataOutBase::write_pvtu_record(
          index, pieces, fields.names, fields.vector_ranges, flags);
        write_file_atomically(join_path(directory, name + ".pvtu"),
                              index.str());
      }
    } // namespace


    std::string
    AutomatonSystem::write_particles(const std::string &directory,
                                     const std::string &base,
                                     const unsigned int number,
                                     const bool         with_stress,
                                     const bool         slab,
                                     const unsigned int axis,
                                     const double       slab_lo,
                                     const double       slab_hi) const
    {
      char tag[32];
      std::snprintf(tag, sizeof(tag), "%s_%04u", base.c_str(), number);
      const std::string name    = tag;
      const auto        nbonded = bonded_neighbour_counts();
      const auto        nfree   = unbonded_contact_counts();
      // stresses are not stored: computed for this output only
      const std::vector<Sym3> stress
        = with_stress ? stresses() : std::vector<Sym3>();
      std::vector<unsigned int> selected;
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          if (slab)
            {
              const double y = cells.wrap(x[k])[axis];
              if (y < slab_lo || y > slab_hi)
                continue;
            }
          selected.push_back(k);
        }
      // The fields (each once: name, components, value of automaton k).
      const bool with_elastic = !prm.interaction.elastic_regions.empty();
      Fields     fields;
      const unsigned int c_id   = fields.add("id", 1);
      const unsigned int c_rank = fields.add("rank", 1);
      const unsigned int c_mat  = fields.add("material", 1);
      const unsigned int c_body = fields.add("body", 1);
      const unsigned int c_nb   = fields.add("bonded_neighbours", 1);
      const unsigned int c_nu   = fields.add("unbonded_contacts", 1);
      const unsigned int c_ep   = fields.add("plastic_strain", 1);
      const unsigned int c_el   = with_elastic ? fields.add("elastic", 1) : 0;
      // graded scenes: the size 2^L d of each automaton (ParaView's glyph
      // scale)
      const unsigned int c_size = graded ? fields.add("size", 1) : 0;
      const unsigned int c_v    = fields.add("velocity", 3);
      const unsigned int c_u    = fields.add("displacement", 3);
      const unsigned int c_w    = fields.add("angular_velocity", 3);
      const unsigned int c_s    = with_stress ? fields.add("stress", 9) : 0;
      const unsigned int c_p    = with_stress ? fields.add("pressure", 1) : 0;
      const unsigned int c_vm   = with_stress ? fields.add("von_mises", 1) : 0;

      std::vector<dealii::DataOutBase::Patch<0, 3>> patches(selected.size());
      for (unsigned int n = 0; n < selected.size(); ++n)
        {
          const unsigned int k     = selected[n];
          auto              &patch = patches[n];
          patch.vertices[0]        = x[k];
          patch.patch_index        = n;
          patch.data.reinit(fields.names.size(), 1);
          auto set = [&](const unsigned int c, const double value) {
            patch.data(c, 0) = static_cast<float>(value);
          };
          set(c_id, id[k]);
          set(c_rank, rank);
          set(c_mat, mat[k]);
          set(c_body, body_index(k));
          set(c_nb, nbonded[k]);
          set(c_nu, nfree[k]);
          set(c_ep, eps_p[k]);
          if (with_elastic)
            set(c_el, elastic(k));
          if (graded)
            set(c_size, automaton_size(k));
          for (unsigned int e = 0; e < 3; ++e)
            {
              set(c_v + e, v[k][e]);
              set(c_u + e, u[k][e]);
              set(c_w + e, w[k][e]);
            }
          if (with_stress)
            {
              // Sym3 (xx, yy, zz, yz, xz, xy) as a full 3x3 tensor
              const Sym3        &t    = stress[k];
              const unsigned int m[9] = {0, 5, 4, 5, 1, 3, 4, 3, 2};
              for (unsigned int e = 0; e < 9; ++e)
                set(c_s + e, t[m[e]]);
              set(c_p, -(t[0] + t[1] + t[2]) / 3);
              set(c_vm, von_mises(t));
            }
        }
      write_piece_and_index(directory, name, rank, n_ranks, patches, fields);
      return name + ".pvtu";
    }

    std::string
    AutomatonSystem::write_unbonded_pairs(const std::string &directory,
                                          const std::string &base,
                                          const unsigned int number,
                                          const unsigned int axis,
                                          const double       slab_lo,
                                          const double       slab_hi) const
    {
      char tag[32];
      std::snprintf(tag, sizeof(tag), "%s_%04u", base.c_str(), number);
      const std::string name = tag;
      // Each pair once (by the owner of i), both ends in the slab; the line
      // goes from x_i to x_i + (x_j - x_i + image shift), so that pairs
      // across a periodic face are short lines, not box-long ones.
      std::vector<unsigned int> selected;
      for (unsigned int p = 0; p < pi.size(); ++p)
        {
          if (bonded[p] || !in_contact[p] || !owned(pi[p]))
            continue;
          const double yi = cells.wrap(x[pi[p]])[axis];
          const double yj = yi + pair_vector(p)[axis];
          if (yi < slab_lo || yi > slab_hi || yj < slab_lo || yj > slab_hi)
            continue;
          selected.push_back(p);
        }
      // One line per pair, sigma (mean of both ends') at both vertices.
      Fields             fields;
      const unsigned int c_sigma = fields.add("sigma", 1);
      std::vector<dealii::DataOutBase::Patch<1, 3>> patches(selected.size());
      for (unsigned int n = 0; n < selected.size(); ++n)
        {
          const unsigned int p     = selected[n];
          auto              &patch = patches[n];
          const Point3       xi    = cells.wrap(x[pi[p]]);
          const Vec3         dn    = pair_vector(p);
          patch.vertices[0]        = xi;
          patch.vertices[1]
            = Point3(xi[0] + dn[0], xi[1] + dn[1], xi[2] + dn[2]);
          patch.patch_index = n;
          patch.data.reinit(fields.names.size(), 2);
          patch.data(c_sigma, 0) = patch.data(c_sigma, 1)
            = static_cast<float>(0.5 * (sig_i[p] + sig_j[p]));
        }
      write_piece_and_index(directory, name, rank, n_ranks, patches, fields);
      return name + ".pvtu";
    }
  } // namespace mca
} // namespace tribodyn
