// Particle output: one .vtu per rank and a .pvtu, optionally restricted to
// a slab (cross-sections of the seed's Figs. 3-4).

#include <cstdio>
#include <iomanip>
#include <sstream>
#include <tribodyn/core/output.h>
#include <tribodyn/mca/automaton_system.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      /// End the points of a .vtu piece, write its cells (@p n_cells of
      /// @p vertices consecutive points each, VTK cell type @p vtk_type:
      /// 1 vertex, 3 line) and close the piece and the file.
      void
      write_cells_and_close(std::ostream     &o,
                            const std::size_t n_cells,
                            const unsigned    vertices,
                            const unsigned    vtk_type)
      {
        o << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" "
             "Name=\"connectivity\" format=\"ascii\">\n";
        for (std::size_t k = 0; k < n_cells; ++k)
          for (unsigned int v = 0; v < vertices; ++v)
            o << vertices * k + v << (v + 1 < vertices ? " " : "\n");
        o << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
             "format=\"ascii\">\n";
        for (std::size_t k = 0; k < n_cells; ++k)
          o << vertices * (k + 1) << "\n";
        o << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
             "format=\"ascii\">\n";
        for (std::size_t k = 0; k < n_cells; ++k)
          o << vtk_type << "\n";
        o << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</"
             "VTKFile>\n";
      }

      /// Write this rank's piece @p piece as NAME.RANK.vtu and, on rank 0,
      /// the index NAME.pvtu of all ranks' pieces with the data arrays
      /// declared in @p data_declarations (a PPointData or PCellData
      /// element); both atomically.
      void
      write_piece_and_index(const std::string &directory,
                            const std::string &name,
                            const unsigned int rank,
                            const unsigned int n_ranks,
                            const std::string &piece,
                            const std::string &data_declarations)
      {
        write_file_atomically(
          join_path(directory, name + "." + std::to_string(rank) + ".vtu"),
          piece);
        if (rank != 0)
          return;
        std::ostringstream pv;
        pv << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" "
              "version=\"0.1\" byte_order=\"LittleEndian\">\n"
              "<PUnstructuredGrid GhostLevel=\"0\">\n"
           << data_declarations
           << "<PPoints><PDataArray type=\"Float64\" "
              "NumberOfComponents=\"3\"/></PPoints>\n";
        for (unsigned int r = 0; r < n_ranks; ++r)
          pv << "<Piece Source=\"" << name << "." << r << ".vtu\"/>\n";
        pv << "</PUnstructuredGrid>\n</VTKFile>\n";
        write_file_atomically(join_path(directory, name + ".pvtu"), pv.str());
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
      std::ostringstream o;
      o << std::setprecision(8);
      o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
           "version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
        << "<Piece NumberOfPoints=\"" << selected.size()
        << "\" NumberOfCells=\"" << selected.size() << "\">\n";
      o << "<PointData Scalars=\"material\">\n";
      auto scalar = [&](const std::string &field, const auto &value) {
        o << "<DataArray type=\"Float64\" Name=\"" << field
          << "\" format=\"ascii\">\n";
        for (const unsigned int k : selected)
          o << value(k) << "\n";
        o << "</DataArray>\n";
      };
      auto vector = [&](const std::string &field, const auto &value) {
        o << "<DataArray type=\"Float64\" Name=\"" << field
          << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const unsigned int k : selected)
          {
            const Vec3 a = value(k);
            o << a[0] << " " << a[1] << " " << a[2] << "\n";
          }
        o << "</DataArray>\n";
      };
      scalar("id", [&](unsigned k) { return static_cast<double>(id[k]); });
      scalar("rank", [&](unsigned) { return static_cast<double>(rank); });
      scalar("material", [&](unsigned k) { return double(mat[k]); });
      scalar("body", [&](unsigned k) { return double(body_index(k)); });
      scalar("bonded_neighbours",
             [&](unsigned k) { return double(nbonded[k]); });
      scalar("unbonded_contacts", [&](unsigned k) { return double(nfree[k]); });
      scalar("plastic_strain", [&](unsigned k) { return eps_p[k]; });
      const bool with_elastic = !prm.interaction.elastic_regions.empty();
      if (with_elastic)
        scalar("elastic", [&](unsigned k) { return double(elastic(k)); });
      // graded scenes: the size 2^L d of each automaton (ParaView's glyph
      // scale)
      if (graded)
        scalar("size", [&](unsigned k) { return automaton_size(k); });
      vector("velocity", [&](unsigned k) { return v[k]; });
      vector("displacement", [&](unsigned k) { return u[k]; });
      vector("angular_velocity", [&](unsigned k) { return w[k]; });
      if (with_stress)
        {
          o << "<DataArray type=\"Float64\" Name=\"stress\" "
               "NumberOfComponents=\"9\" format=\"ascii\">\n";
          for (const unsigned int k : selected)
            {
              const Sym3 &s = stress[k];
              o << s[0] << " " << s[5] << " " << s[4] << " " << s[5] << " "
                << s[1] << " " << s[3] << " " << s[4] << " " << s[3] << " "
                << s[2] << "\n";
            }
          o << "</DataArray>\n";
          scalar("pressure", [&](unsigned k) {
            return -(stress[k][0] + stress[k][1] + stress[k][2]) / 3;
          });
          scalar("von_mises", [&](unsigned k) { return von_mises(stress[k]); });
        }
      o << "</PointData>\n<Points>\n<DataArray type=\"Float64\" "
           "NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const unsigned int k : selected)
        o << x[k][0] << " " << x[k][1] << " " << x[k][2] << "\n";
      write_cells_and_close(o, selected.size(), 1, 1);
      std::ostringstream pv;
      pv << "<PPointData Scalars=\"material\">\n";
      for (const char *s : {"id",
                            "rank",
                            "material",
                            "body",
                            "bonded_neighbours",
                            "unbonded_contacts",
                            "plastic_strain"})
        pv << "<PDataArray type=\"Float64\" Name=\"" << s << "\"/>\n";
      if (with_elastic)
        pv << "<PDataArray type=\"Float64\" Name=\"elastic\"/>\n";
      if (graded)
        pv << "<PDataArray type=\"Float64\" Name=\"size\"/>\n";
      for (const char *s : {"velocity", "displacement", "angular_velocity"})
        pv << "<PDataArray type=\"Float64\" Name=\"" << s
           << "\" NumberOfComponents=\"3\"/>\n";
      if (with_stress)
        pv << "<PDataArray type=\"Float64\" Name=\"stress\" "
              "NumberOfComponents=\"9\"/>\n<PDataArray type=\"Float64\" "
              "Name=\"pressure\"/>\n<PDataArray type=\"Float64\" "
              "Name=\"von_mises\"/>\n";
      pv << "</PPointData>\n";
      write_piece_and_index(directory, name, rank, n_ranks, o.str(), pv.str());
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
      std::ostringstream o;
      o << std::setprecision(8);
      o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
           "version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
        << "<Piece NumberOfPoints=\"" << 2 * selected.size()
        << "\" NumberOfCells=\"" << selected.size() << "\">\n";
      o << "<CellData Scalars=\"sigma\">\n<DataArray type=\"Float64\" "
           "Name=\"sigma\" format=\"ascii\">\n";
      for (const unsigned int p : selected)
        o << 0.5 * (sig_i[p] + sig_j[p]) << "\n";
      o << "</DataArray>\n</CellData>\n<Points>\n<DataArray type=\"Float64\" "
           "NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const unsigned int p : selected)
        {
          const Point3 xi = cells.wrap(x[pi[p]]);
          const Vec3   dn = pair_vector(p);
          o << xi[0] << " " << xi[1] << " " << xi[2] << "\n"
            << xi[0] + dn[0] << " " << xi[1] + dn[1] << " " << xi[2] + dn[2]
            << "\n";
        }
      write_cells_and_close(o, selected.size(), 2, 3);
      write_piece_and_index(directory,
                            name,
                            rank,
                            n_ranks,
                            o.str(),
                            "<PCellData Scalars=\"sigma\">\n<PDataArray "
                            "type=\"Float64\" Name=\"sigma\"/>\n"
                            "</PCellData>\n");
      return name + ".pvtu";
    }
  } // namespace mca
} // namespace tribodyn
