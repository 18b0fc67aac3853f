// Postprocessor "visualization": at the output times (`Output/Output
// interval`), the automata (`Output/Write particles`: particles.pvd) and a
// slab across the scene (`Output/Cross section`: cross_section.pvd, and the
// unbonded contacts in it, unbonded_pairs.pvd) as VTU files for ParaView,
// each indexed by its PVD file. One .vtu per rank and a .pvtu, through
// deal.II's VTU writer (DataOutBase::write_vtu: binary, zlib-compressed,
// base64; data as Float32). Each automaton is a patch of dimension 0 (a
// vertex), each pair of the contact network a patch of dimension 1 (a
// line), as deal.II's Particles::DataOut does for its particles.
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <cmath>
#include <cstdio>
#include <deal.II/base/data_out_base.h>
#include <sstream>
#include <tribodyn/core/output.h>
#include <tribodyn/mca/postprocessor.h>

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


      class Visualization : public Postprocessor
      {
      public:
        explicit Visualization(const PostprocessorInputs &in)
            : system(in.system)
            , prm(in.parameters)
            , rank(dealii::Utilities::MPI::this_mpi_process(in.comm))
            , n_ranks(dealii::Utilities::MPI::n_mpi_processes(in.comm))
            , directory(in.output_directory)
            , particles(join_path(directory, "particles.pvd"), in.root)
            , slab(join_path(directory, "cross_section.pvd"), in.root)
            , pairs(join_path(directory, "unbonded_pairs.pvd"), in.root)
        {
        }

        void
        write_output() override
        {
          const bool stress = prm.output.write_stress;
          if (prm.output.write_particles)
            particles.add(system.time(), write_particles("particles", stress));
          if (prm.output.cross_section)
            {
              const double th
                = prm.output.cross_section_thickness > 0
                    ? prm.output.cross_section_thickness
                    : 7 * prm.geometry.automaton_size / std::sqrt(2.);
              const double lo = prm.output.cross_section_position - th / 2,
                           hi = prm.output.cross_section_position + th / 2;
              const unsigned int axis = prm.output.cross_section_axis;
              slab.add(
                system.time(),
                write_particles("cross_section", stress, true, axis, lo, hi));
              pairs.add(system.time(),
                        write_unbonded_pairs("unbonded_pairs", axis, lo, hi));
            }
          ++output_number;
        }

        void
        save(boost::archive::binary_oarchive &ar) const override
        {
          ar << output_number;
          for (const PvdWriter *w : {&particles, &slab, &pairs})
            ar << w->entries();
        }

        void
        load(boost::archive::binary_iarchive &ar) override
        {
          ar >> output_number;
          for (PvdWriter *w : {&particles, &slab, &pairs})
            {
              std::vector<std::pair<double, std::string>> entries;
              ar >> entries;
              w->restore(entries);
            }
        }

        void
        resume_outputs() const override
        {
          for (const PvdWriter *w : {&particles, &slab, &pairs})
            w->write();
        }

      private:
        /// The file name NAME_NNNN of this output.
        std::string
        file_name(const std::string &base) const
        {
          char tag[32];
          std::snprintf(
            tag, sizeof(tag), "%s_%04u", base.c_str(), output_number);
          return tag;
        }

        /// Write BASE_NNNN.pvtu (+ .vtu per rank) of the owned automata;
        /// returns the pvtu name relative to the output directory. With
        /// @p slab, only the automata whose coordinate along @p axis lies
        /// within [lo, hi].
        std::string
        write_particles(const std::string &base,
                        const bool         with_stress,
                        const bool         slab = false,
                        const unsigned int axis = 0,
                        const double       lo   = 0,
                        const double       hi   = 0) const;

        /// Write the unbonded pairs in contact whose both automata lie in
        /// the slab [lo, hi] along @p axis as line cells (BASE_NNNN.pvtu +
        /// one .vtu per rank; the seed's Fig. 3a connects them by lines).
        std::string
        write_unbonded_pairs(const std::string &base,
                             const unsigned int axis,
                             const double       lo,
                             const double       hi) const;

        const AutomatonSystem &system;
        const Parameters      &prm;
        const unsigned int     rank, n_ranks;
        const std::string      directory;
        PvdWriter              particles, slab, pairs;
        /// the number of the next output (file names)
        unsigned int output_number = 0;
      };


      std::string
      Visualization::write_particles(const std::string &base,
                                     const bool         with_stress,
                                     const bool         slab,
                                     const unsigned int axis,
                                     const double       lo,
                                     const double       hi) const
      {
        const std::string name    = file_name(base);
        const auto        nbonded = system.bonded_neighbour_counts();
        const auto        nfree   = system.unbonded_contact_counts();
        const auto       &x       = system.positions();
        const auto       &v       = system.velocities();
        const auto       &u       = system.displacements();
        const auto       &w       = system.angular_velocities();
        // stresses are not stored: computed for this output only
        const std::vector<Sym3> stress
          = with_stress ? system.stresses() : std::vector<Sym3>();
        std::vector<unsigned int> selected;
        for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
          {
            if (slab)
              {
                const double y = system.decomposition().wrap(x[k])[axis];
                if (y < lo || y > hi)
                  continue;
              }
            selected.push_back(k);
          }
        // The fields (each once: name, components, value of automaton k).
        const bool with_elastic = !prm.interaction.elastic_regions.empty();
        const bool graded       = !prm.geometry.size_bands.empty();
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
        const unsigned int c_vm = with_stress ? fields.add("von_mises", 1) : 0;

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
            set(c_id, system.ids()[k]);
            set(c_rank, rank);
            set(c_mat, system.materials()[k]);
            set(c_body, system.body_index(k));
            set(c_nb, nbonded[k]);
            set(c_nu, nfree[k]);
            set(c_ep, system.plastic_strain(k));
            if (with_elastic)
              set(c_el, system.elastic(k));
            if (graded)
              set(c_size, system.automaton_size(k));
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
      Visualization::write_unbonded_pairs(const std::string &base,
                                          const unsigned int axis,
                                          const double       lo,
                                          const double       hi) const
      {
        const std::string name = file_name(base);
        // Each pair once, both ends in the slab.
        std::vector<AutomatonSystem::ContactLine> selected;
        for (const auto &line : system.unbonded_contact_lines())
          {
            const double yi = line.from[axis];
            const double yj = yi + line.along[axis];
            if (yi < lo || yi > hi || yj < lo || yj > hi)
              continue;
            selected.push_back(line);
          }
        // One line per pair, sigma at both vertices.
        Fields             fields;
        const unsigned int c_sigma = fields.add("sigma", 1);
        std::vector<dealii::DataOutBase::Patch<1, 3>> patches(selected.size());
        for (unsigned int n = 0; n < selected.size(); ++n)
          {
            const auto   &line  = selected[n];
            auto         &patch = patches[n];
            const Point3 &xi    = line.from;
            const Vec3   &dn    = line.along;
            patch.vertices[0]   = xi;
            patch.vertices[1]
              = Point3(xi[0] + dn[0], xi[1] + dn[1], xi[2] + dn[2]);
            patch.patch_index = n;
            patch.data.reinit(fields.names.size(), 2);
            patch.data(c_sigma, 0) = patch.data(c_sigma, 1)
              = static_cast<float>(line.sigma);
          }
        write_piece_and_index(directory, name, rank, n_ranks, patches, fields);
        return name + ".pvtu";
      }

      const bool visualization_registered = PostprocessorRegistry::add(
        {"visualization", 60, [](const PostprocessorInputs &in) {
           return std::make_unique<Visualization>(in);
         }});
    } // namespace
  }   // namespace mca
} // namespace tribodyn
