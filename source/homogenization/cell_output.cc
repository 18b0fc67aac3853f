// Output of the cell problems: the displacement, stress and strain fields
// of each load case (VTU with a .pvd index) and the material map.
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
    using internal::CellIntegrals;
    using internal::for_each_owned_cell_integral;


    template <int dim>
    void
    CellProblem<dim>::write_fields(
      const BoundaryCondition              bc,
      const unsigned int                   load_case,
      const TrilinosWrappers::MPI::Vector &solution,
      const std::string                   &output_directory) const
    {
      TimerOutput::Scope scope(timer, "output");
      const bool         strain_driven = bc != BoundaryCondition::subc;
      const VoigtVector  macro_strain
        = strain_driven ? unit_load(load_case) : VoigtVector();

      // Total displacement u = E x + w (strain-driven) or u (SUBC).
      TrilinosWrappers::MPI::Vector total(locally_owned_dofs, mpi_communicator);
      if (strain_driven)
        VectorTools::interpolate(dof_handler,
                                 AffineDisplacement(macro_strain),
                                 total);
      TrilinosWrappers::MPI::Vector owned(locally_owned_dofs, mpi_communicator);
      owned = solution;
      total += owned;
      TrilinosWrappers::MPI::Vector total_ghosted(locally_owned_dofs,
                                                  locally_relevant_dofs,
                                                  mpi_communicator);
      total_ghosted = total;

      // Cell averages of stress and strain.
      const unsigned int           n_cells = triangulation.n_active_cells();
      std::array<Vector<float>, 9> cell_data;
      for (auto &v : cell_data)
        v.reinit(n_cells);
      for_each_owned_cell_integral(
        dof_handler,
        fe,
        parameters.fe_degree,
        phases,
        std::vector<const TrilinosWrappers::MPI::Vector *>{&solution},
        {macro_strain},
        [&](const auto &cell, unsigned int, const CellIntegrals &integrals) {
          const VoigtVector mean_eps   = integrals.strain / integrals.measure;
          const VoigtVector mean_sigma = integrals.stress / integrals.measure;
          const double      mean_szz = integrals.stress_zz / integrals.measure;
          const double      sxx = mean_sigma[0], syy = mean_sigma[1],
                       sxy       = mean_sigma[2];
          const double von_mises = std::sqrt(
            0.5
              * ((sxx - syy) * (sxx - syy) + (syy - mean_szz) * (syy - mean_szz)
                 + (mean_szz - sxx) * (mean_szz - sxx))
            + 3 * sxy * sxy);
          const unsigned int k = cell->active_cell_index();
          cell_data[0][k]      = sxx;
          cell_data[1][k]      = syy;
          cell_data[2][k]      = sxy;
          cell_data[3][k]      = mean_szz;
          cell_data[4][k]      = von_mises;
          cell_data[5][k]      = mean_eps[0];
          cell_data[6][k]      = mean_eps[1];
          cell_data[7][k]      = mean_eps[2];
          cell_data[8][k]      = cell->material_id();
        });

      DataOut<dim> data_out;
      data_out.attach_dof_handler(dof_handler);
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          2, DataComponentInterpretation::component_is_part_of_vector);
      data_out.add_data_vector(total_ghosted,
                               std::vector<std::string>(2, "displacement"),
                               DataOut<2>::type_dof_data,
                               interpretation);
      const char *names[9] = {"stress_xx",
                              "stress_yy",
                              "stress_xy",
                              "stress_zz",
                              "von_mises",
                              "strain_xx",
                              "strain_yy",
                              "strain_gamma_xy",
                              "material_id"};
      for (unsigned int i = 0; i < 9; ++i)
        data_out.add_data_vector(cell_data[i],
                                 names[i],
                                 DataOut<dim>::type_cell_data);
      data_out.build_patches();
      DataOutBase::VtkFlags flags;
      flags.time = load_case;
      // deal.II 9.4 defaults to the best (slowest) zlib compression, which
      // costs several times the solve here.
      flags.compression_level = DataOutBase::VtkFlags::best_speed;
      data_out.set_flags(flags);
      // One file per load case, written collectively with MPI I/O, and a
      // .pvd index of the three load cases (xx, yy, xy) as pseudo-times
      // 0, 1, 2.
      const std::string base          = "fields_" + to_string(bc);
      const char       *case_names[3] = {"xx", "yy", "xy"};
      data_out.write_vtu_in_parallel(
        join_path(output_directory,
                  base + "_" + case_names[load_case] + ".vtu"),
        mpi_communicator);
      if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
        {
          std::string pvd;
          pvd += "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
                 "version=\"0.1\" byte_order=\"LittleEndian\">\n"
                 "  <!-- load cases: 0 = xx, 1 = yy, 2 = xy -->\n"
                 "  <Collection>\n";
          for (unsigned int k = 0; k <= load_case; ++k)
            pvd += "    <DataSet timestep=\"" + std::to_string(k)
                   + "\" group=\"\" part=\"0\" file=\"" + base + "_"
                   + case_names[k] + ".vtu\"/>\n";
          pvd += "  </Collection>\n</VTKFile>\n";
          write_file_atomically(join_path(output_directory, base + ".pvd"),
                                pvd);
        }
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
      data_out.write_vtu_in_parallel(join_path(output_directory,
                                               "morphology.vtu"),
                                     mpi_communicator);
    }

    // The field output is that of plane strain (the 3D fields are still to
    // come, issue #51 item 6).
    template void
    CellProblem<2>::write_fields(const BoundaryCondition,
                                 const unsigned int,
                                 const TrilinosWrappers::MPI::Vector &,
                                 const std::string &) const;
    template void
    CellProblem<2>::write_material_map(const std::string &) const;
    template void
    CellProblem<3>::write_material_map(const std::string &) const;
  } // namespace homogenization
} // namespace tribodyn
