// The table of isotropic projections that the 2D and the 3D homogenization
// problems print and write to summary.json: one row per boundary
// condition, then the bounds and estimates. Private to the homogenization
// sources.
#ifndef tribodyn_source_homogenization_moduli_table_h
#define tribodyn_source_homogenization_moduli_table_h

#include <iomanip>
#include <ostream>
#include <string>
#include <tribodyn/core/json.h>
#include <tribodyn/homogenization/cell_problem.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    namespace internal
    {
      /// A row "label  bulk  mu  [anisotropy]" (moduli in GPa); the
      /// anisotropy only when it is not negative (estimates and bounds
      /// have none).
      inline void
      write_moduli_row(std::ostream      &table,
                       const std::string &label,
                       const double       bulk,
                       const double       mu,
                       const double       anisotropy = -1)
      {
        table << std::left << std::setw(10) << label << std::right << std::fixed
              << std::setprecision(3) << std::setw(10) << bulk / 1e9
              << std::setw(10) << mu / 1e9;
        if (anisotropy >= 0)
          table << std::setw(12) << std::setprecision(4) << anisotropy;
        table << "\n";
      }


      /// The rows of the cell problems' @p results, and their entries
      /// @p bulk_key, "mu" and "anisotropy" in @p summary (under the name
      /// of the boundary condition). @p project gives the bulk modulus,
      /// the shear modulus and the anisotropy of an apparent stiffness.
      template <int dim, typename Projection>
      void
      write_result_rows(std::ostream                       &table,
                        JsonValue                          &summary,
                        const std::vector<CellResult<dim>> &results,
                        const std::string                  &bulk_key,
                        const Projection                   &project)
      {
        for (const auto &r : results)
          {
            const auto [bulk, mu, anisotropy] = project(r.properties.C);
            write_moduli_row(
              table, to_string(r.boundary_condition), bulk, mu, anisotropy);
            auto &entry         = summary[to_string(r.boundary_condition)];
            entry[bulk_key]     = bulk;
            entry["mu"]         = mu;
            entry["anisotropy"] = anisotropy;
          }
      }
    } // namespace internal
  }   // namespace homogenization
} // namespace tribodyn

#endif
