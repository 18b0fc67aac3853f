// Postprocessor "effective properties" of 3D voxel volumes: for each
// boundary condition solved, the apparent 6 x 6 stiffness and compliance,
// the twelve engineering constants, the CG iterations and times (per
// solve, per DoF and iteration) and the preconditioner; then the Voigt and
// Reuss estimates of the phases: a row of each in
// effective_properties.csv and in the screen table, an entry of each in
// summary.json (under the name of the boundary condition; "bounds":
// "voigt", "reuss").
#include <iomanip>
#include <memory>
#include <tribodyn/core/output.h>
#include <tribodyn/homogenization/postprocessor.h>
#include <tribodyn/homogenization/volume_homogenization_problem.h>
#include <tribodyn/homogenization/volume_properties.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      const char *const volume_constant_names[12] = {"E_x",
                                                     "E_y",
                                                     "E_z",
                                                     "nu_xy",
                                                     "nu_xz",
                                                     "nu_yx",
                                                     "nu_yz",
                                                     "nu_zx",
                                                     "nu_zy",
                                                     "G_yz",
                                                     "G_xz",
                                                     "G_xy"};

      std::vector<double>
      constant_values(const EngineeringConstants3D &c)
      {
        return {c.E_x,
                c.E_y,
                c.E_z,
                c.nu_xy,
                c.nu_xz,
                c.nu_yx,
                c.nu_yz,
                c.nu_zx,
                c.nu_zy,
                c.G_yz,
                c.G_xz,
                c.G_xy};
      }

      /// The CSV row: the twelve constants, then C_ij for i <= j.
      std::vector<double>
      volume_csv_values(const VolumeProperties &p)
      {
        std::vector<double> v = constant_values(p.constants);
        for (unsigned int i = 0; i < 6; ++i)
          for (unsigned int j = i; j < 6; ++j)
            v.push_back(p.C[i][j]);
        return v;
      }

      std::vector<std::string>
      csv_columns()
      {
        std::vector<std::string> columns = {"estimate"};
        for (const char *name : volume_constant_names)
          columns.push_back(name);
        for (unsigned int i = 0; i < 6; ++i)
          for (unsigned int j = i; j < 6; ++j)
            columns.push_back("C" + std::to_string(i + 1)
                              + std::to_string(j + 1));
        return columns;
      }

      void
      print_volume_row(std::ostream                 &out,
                       const std::string            &label,
                       const EngineeringConstants3D &c)
      {
        out << std::left << std::setw(10) << label << std::right << std::fixed
            << std::setprecision(3);
        for (const double E : {c.E_x, c.E_y, c.E_z, c.G_yz, c.G_xz, c.G_xy})
          out << std::setw(9) << E / 1e9;
        out << std::setprecision(4);
        for (const double nu : {c.nu_xy, c.nu_xz, c.nu_yz})
          out << std::setw(9) << nu;
        out << "\n";
      }


      class VolumeEffectiveProperties : public Postprocessor<3>
      {
      public:
        explicit VolumeEffectiveProperties(const PostprocessorInputs<3> &in)
            : in(in)
            , csv(join_path(in.output_directory, "effective_properties.csv"),
                  csv_columns(),
                  in.root)
        {
        }

        void
        started(std::ostream &table) override
        {
          table << "\nEffective properties (moduli in GPa), Voigt order xx, "
                   "yy, zz, yz, xz, xy:\n"
                << std::left << std::setw(10) << "estimate" << std::right;
          for (const char *name : {"E_x",
                                   "E_y",
                                   "E_z",
                                   "G_yz",
                                   "G_xz",
                                   "G_xy",
                                   "nu_xy",
                                   "nu_xz",
                                   "nu_yz"})
            table << std::setw(9) << name;
          table << "\n";
        }

        void
        solved(const CellResult<3> &r,
               JsonValue           &summary,
               std::ostream        &table) override
        {
          JsonValue j          = to_json(r.properties);
          JsonValue iterations = JsonValue::array();
          JsonValue cg_times   = JsonValue::array();
          JsonValue per_dof    = JsonValue::array();
          // time per DoF per CG iteration: of each solve (null when CG
          // took no iteration) and over the six
          const double n_dofs = in.n_dofs;
          for (const auto &lc : r.load_cases)
            {
              iterations.push_back(lc.cg_iterations);
              cg_times.push_back(lc.cg_time);
              per_dof.push_back(lc.cg_iterations > 0 ? JsonValue(
                                  lc.cg_time / (n_dofs * lc.cg_iterations))
                                                     : JsonValue());
            }
          j["cg_iterations"]                = iterations;
          j["cg_time_s"]                    = cg_times;
          j["time_per_dof_per_iteration_s"] = per_dof;
          j["mean_time_per_dof_per_iteration_s"]
            = r.cg_iterations() > 0
                ? JsonValue(r.cg_time() / (n_dofs * r.cg_iterations()))
                : JsonValue();
          j["wall_time_s"]    = r.wall_time;
          j["preconditioner"] = r.multigrid ? "multigrid" : "AMG";
          summary[to_string(r.boundary_condition)] = j;
          print_volume_row(table,
                           to_string(r.boundary_condition),
                           r.properties.constants);
          csv.add_row({to_string(r.boundary_condition)},
                      volume_csv_values(r.properties));
        }

        void
        finish(JsonValue &summary, std::ostream &table) const override
        {
          const VolumeProperties voigt
            = voigt_estimate_3d(in.stiffness, in.fractions);
          const VolumeProperties reuss
            = reuss_estimate_3d(in.stiffness, in.fractions);
          summary["bounds"]["voigt"] = to_json(voigt);
          summary["bounds"]["reuss"] = to_json(reuss);
          print_volume_row(table, "Voigt", voigt.constants);
          print_volume_row(table, "Reuss", reuss.constants);
          csv.add_row({"Voigt"}, volume_csv_values(voigt));
          csv.add_row({"Reuss"}, volume_csv_values(reuss));
          csv.flush(true);
        }

      private:
        const PostprocessorInputs<3> in;
        /// (rows are added at the end too: finish() completes the file)
        mutable CsvWriter csv;
      };

      const bool volume_effective_properties_registered
        = PostprocessorRegistry<3>::add(
          {"effective properties",
           10,
           [](const PostprocessorInputs<3> &in)
             -> std::unique_ptr<Postprocessor<3>> {
             return std::make_unique<VolumeEffectiveProperties>(in);
           }});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
