// Postprocessor "Huet ordering" of 2D homogenization: where both KUBC and
// SUBC were solved, the smallest eigenvalue of the symmetric part of
// C^KUBC - C^SUBC, which Huet's partition theorem makes >= 0
// (summary.json: kubc_minus_subc_min_eigenvalue; a line of the screen
// table saying whether it holds).
#include <iomanip>
#include <memory>
#include <optional>
#include <tribodyn/homogenization/effective_properties.h>
#include <tribodyn/homogenization/postprocessor.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      class HuetOrdering : public Postprocessor<2>
      {
      public:
        void
        solved(const CellProblemResult &r, JsonValue &, std::ostream &) override
        {
          if (r.boundary_condition == BoundaryCondition::kubc)
            kubc = r.properties.C;
          if (r.boundary_condition == BoundaryCondition::subc)
            subc = r.properties.C;
        }

        void
        finish(JsonValue &summary, std::ostream &table) const override
        {
          if (!kubc || !subc)
            return;
          const double min_eigenvalue
            = min_eigenvalue_of_symmetric_part(*kubc - *subc);
          summary["kubc_minus_subc_min_eigenvalue"] = min_eigenvalue;
          table << "Huet ordering C^KUBC - C^SUBC >= 0: smallest eigenvalue "
                << std::scientific << std::setprecision(3)
                << min_eigenvalue / 1e9 << " GPa ("
                << (min_eigenvalue >= -1e-8 * kubc->norm() ? "holds"
                                                           : "VIOLATED")
                << ")\n";
        }

      private:
        std::optional<VoigtMatrix> kubc, subc;
      };

      const bool huet_ordering_registered = PostprocessorRegistry<2>::add(
        {"Huet ordering",
         20,
         [](const PostprocessorInputs<2> &)
           -> std::unique_ptr<Postprocessor<2>> {
           return std::make_unique<HuetOrdering>();
         }});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
