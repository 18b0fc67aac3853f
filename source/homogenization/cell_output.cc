// Output of the cell problems: the cell fields of a load case (the
// averages over each element of the stress, von Mises stress and strain,
// and the material id), written with the displacement as VTU with a .pvd
// index of the load cases, or cut along planes of elements (the slices of
// a 3D volume); and the material map.
#include "cell_integrals.h"

#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>
#include <string>
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/cell_problem.h>

namespace tribodyn
{
  namespace homogenization
  {
    using namespace dealii;
    using internal::AffineDisplacement;

    namespace
    {
      /// The Voigt components of @p dim dimensions: the names of the load
      /// cases and of the fields' components.
      template <int dim>
      const char *
      voigt_name(const unsigned int a)
      {
        static const char *const names2[3] = {"xx", "yy", "xy"};
        static const char *const names3[6]
          = {"xx", "yy", "zz", "yz", "xz", "xy"};
        return dim == 2 ? names2[a] : names3[a];
      }
    } // namespace


    template <int dim>
    std::vector<std::string>
    CellProblem<dim>::cell_field_names()
    {
      std::vector<std::string> names;
      for (unsigned int a = 0; a < n_voigt; ++a)
        names.push_back(std::string("stress_") + voigt_name<dim>(a));
      if (dim == 2)
        names.push_back("stress_zz");
      names.push_back("von_mises");
      for (unsigned int a = 0; a < n_voigt; ++a)
        names.push_back(std::string(a < dim ? "strain_" : "strain_gamma_")
                        + voigt_name<dim>(a));
      names.push_back("material_id");
      return names;
    }


    template <int dim>
    std::vector<Vector<float>>
    CellProblem<dim>::cell_fields(
      const BoundaryCondition                           bc,
      const unsigned int                                load_case,
      const LinearAlgebra::distributed::Vector<double> &field) const
    {
      const unsigned int         n_cells = triangulation.n_active_cells();
      std::vector<Vector<float>> values(cell_field_names().size(),
                                        Vector<float>(n_cells));
      for_each_element_integral(
        bc,
        {load_case},
        {&field},
        [&](const auto &cell, unsigned int, const ElementIntegrals &integrals) {
          const Voigt eps   = integrals.strain / integrals.measure;
          const Voigt sigma = integrals.stress / integrals.measure;
          // the normal stresses and the shears of the planes normal to x,
          // y, z (plane strain: sigma_zz, and the one shear xy)
          double normal[3], shear[3] = {0, 0, 0};
          for (unsigned int d = 0; d < dim; ++d)
            normal[d] = sigma[d];
          if constexpr (dim == 2)
            {
              normal[2] = integrals.stress_zz / integrals.measure;
              shear[2]  = sigma[2];
            }
          else
            for (unsigned int d = 0; d < 3; ++d)
              shear[d] = sigma[3 + d];
          const double       von_mises = von_mises_stress(normal, shear);
          const unsigned int k         = cell->active_cell_index();
          unsigned int       f         = 0;
          for (unsigned int a = 0; a < n_voigt; ++a)
            values[f++][k] = sigma[a];
          if (dim == 2)
            values[f++][k] = normal[2];
          values[f++][k] = von_mises;
          for (unsigned int a = 0; a < n_voigt; ++a)
            values[f++][k] = eps[a];
          values[f][k] = cell->material_id();
        });
      return values;
    }


    template <int dim>
    void
    CellProblem<dim>::write_fields(const LoadCaseFields<dim> &fields,
                                   const std::string &output_directory) const
    {
      const BoundaryCondition bc        = fields.bc;
      const unsigned int      load_case = fields.load_case;
      const auto             &field     = fields.field;
      const auto             &values    = fields.values;
      TimerOutput::Scope      scope(timer, "output");

      // Total displacement u = E x + w (strain-driven) or u (SUBC).
      LinearAlgebra::distributed::Vector<double> total(locally_owned_dofs,
                                                       locally_relevant_dofs,
                                                       mpi_communicator);
      if (bc != BoundaryCondition::subc)
        VectorTools::interpolate(dof_handler,
                                 AffineDisplacement<dim>(unit_load(load_case)),
                                 total);
      total += field;
      total.update_ghost_values();

      DataOut<dim> data_out;
      data_out.attach_dof_handler(dof_handler);
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          dim, DataComponentInterpretation::component_is_part_of_vector);
      data_out.add_data_vector(total,
                               std::vector<std::string>(dim, "displacement"),
                               DataOut<dim>::type_dof_data,
                               interpretation);
      const std::vector<std::string> names = cell_field_names();
      for (unsigned int f = 0; f < names.size(); ++f)
        data_out.add_data_vector(values[f],
                                 names[f],
                                 DataOut<dim>::type_cell_data);
      data_out.build_patches();
      DataOutBase::VtkFlags flags;
      flags.time = load_case;
      // deal.II 9.4 defaults to the best (slowest) zlib compression, which
      // costs several times the solve here.
      flags.compression_level = DataOutBase::VtkFlags::best_speed;
      data_out.set_flags(flags);

      // The file of load case k: in 2D one file for all ranks
      // (write_vtu_file()), named by the load case; in 3D (volumes of 10^6 to
      // 10^8 voxels) one piece per rank and its .pvtu record, numbered by the
      // load case (deal.II's convention: fields_<BC>_<k>.<rank>.vtu).
      const std::string base = "fields_" + to_string(bc);
      const auto        file = [&](const unsigned int k) {
        return dim == 2 ? base + "_" + voigt_name<dim>(k) + ".vtu"
                               : base + "_" + std::to_string(k) + ".pvtu";
      };
      if constexpr (dim == 2)
        write_vtu_file(data_out,
                       join_path(output_directory, file(load_case)),
                       mpi_communicator);
      else
        data_out.write_vtu_with_pvtu_record(
          output_directory + "/", base, load_case, mpi_communicator, 1);
      // The .pvd index of the load cases as pseudo-times 0, 1, ...
      if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
        {
          std::string cases;
          for (unsigned int k = 0; k < n_voigt; ++k)
            cases += (k > 0 ? ", " : "") + std::to_string(k) + " = "
                     + voigt_name<dim>(k);
          std::string pvd;
          pvd += "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
                 "version=\"0.1\" byte_order=\"LittleEndian\">\n"
                 "  <!-- load cases: "
                 + cases + " -->\n  <Collection>\n";
          for (unsigned int k = 0; k <= load_case; ++k)
            pvd += "    <DataSet timestep=\"" + std::to_string(k)
                   + "\" group=\"\" part=\"0\" file=\"" + file(k) + "\"/>\n";
          pvd += "  </Collection>\n</VTKFile>\n";
          write_file_atomically(join_path(output_directory, base + ".pvd"),
                                pvd);
        }
    }


    template <int dim>
    FieldSlice
    CellProblem<dim>::slice(const SlicePlane                 &plane,
                            const std::vector<Vector<float>> &values) const
    {
      FieldSlice s;
      s.plane                         = plane;
      s.names                         = cell_field_names();
      const auto                    h = element_size();
      std::array<unsigned int, dim> n_elements;
      for (unsigned int d = 0; d < dim; ++d)
        n_elements[d] = static_cast<unsigned int>(
          std::lround(Traits::extent(geometry, d) / h[d]));
      for (unsigned int d = 0, a = 0; d < dim; ++d)
        if (d != plane.axis && a < 2)
          {
            s.axes[a] = d;
            s.n[a]    = n_elements[d];
            ++a;
          }
      if (dim == 2)
        s.n[1] = 1;
      s.values.assign(s.names.size(),
                      std::vector<double>(std::size_t(s.n[0]) * s.n[1], 0.));
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const Point<dim> centre = cell->center();
            const auto       index  = [&](const unsigned int d) {
              return static_cast<unsigned int>(std::floor(centre[d] / h[d]));
            };
            if (index(plane.axis) != plane.index)
              continue;
            const std::size_t at
              = index(s.axes[0])
                + (dim == 3 ? std::size_t(s.n[0]) * index(s.axes[1]) : 0);
            for (unsigned int f = 0; f < s.names.size(); ++f)
              s.values[f][at] = values[f][cell->active_cell_index()];
          }
      // each element is owned by one rank, zero on the others
      for (auto &v : s.values)
        Utilities::MPI::sum(v, mpi_communicator, v);
      return s;
    }


    template <int dim>
    void
    CellProblem<dim>::write_material_map(
      const std::string &output_directory) const
    {
      TimerOutput::Scope scope(timer, "output");
      Vector<float>      ids(triangulation.n_active_cells());
      Vector<float>      ranks(triangulation.n_active_cells());
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            ids[cell->active_cell_index()]   = cell->material_id();
            ranks[cell->active_cell_index()] = cell->subdomain_id();
          }
      DataOut<dim> data_out;
      data_out.attach_triangulation(triangulation);
      data_out.add_data_vector(ids,
                               "material_id",
                               DataOut<dim>::type_cell_data);
      data_out.add_data_vector(ranks, "mpi_rank", DataOut<dim>::type_cell_data);
      data_out.build_patches();
      DataOutBase::VtkFlags flags;
      flags.compression_level = DataOutBase::VtkFlags::best_speed;
      data_out.set_flags(flags);
      write_vtu_file(data_out,
                     join_path(output_directory, "morphology.vtu"),
                     mpi_communicator);
    }

#define TRIBODYN_INSTANTIATE(dim)                                           \
  template std::vector<std::string>   CellProblem<dim>::cell_field_names(); \
  template std::vector<Vector<float>> CellProblem<dim>::cell_fields(        \
    const BoundaryCondition,                                                \
    const unsigned int,                                                     \
    const LinearAlgebra::distributed::Vector<double> &) const;              \
  template void CellProblem<dim>::write_fields(const LoadCaseFields<dim> &, \
                                               const std::string &) const;  \
  template FieldSlice CellProblem<dim>::slice(                              \
    const SlicePlane &, const std::vector<Vector<float>> &) const;          \
  template void CellProblem<dim>::write_material_map(const std::string &) const;
    TRIBODYN_INSTANTIATE(2)
    TRIBODYN_INSTANTIATE(3)
#undef TRIBODYN_INSTANTIATE
  } // namespace homogenization
} // namespace tribodyn
