// Postprocessor "Huet ordering" of 3D voxel volumes: C^SUBC <= C^periodic
// <= C^KUBC in the sense of positive semi-definite differences (Huet's
// partition theorem; to the solver's round-off), for each pair of the
// conditions solved: the smallest eigenvalue of each difference and
// whether it holds (summary.json: "huet"; a section of the screen table).
#include <iomanip>
#include <map>
#include <memory>
#include <tribodyn/homogenization/postprocessor.h>
#include <tribodyn/homogenization/volume_properties.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      class VolumeHuetOrdering : public Postprocessor<3>
      {
      public:
        void
        solved(const CellResult<3> &r, JsonValue &, std::ostream &) override
        {
          stiffness[r.boundary_condition] = r.properties.C;
        }

        void
        finish(JsonValue &summary, std::ostream &table) const override
        {
          JsonValue huet = JsonValue::object();
          table << "\nHuet's ordering (smallest eigenvalue of the "
                   "difference, GPa):\n";
          const std::pair<BoundaryCondition, BoundaryCondition> pairs[3]
            = {{BoundaryCondition::kubc, BoundaryCondition::subc},
               {BoundaryCondition::kubc, BoundaryCondition::periodic},
               {BoundaryCondition::periodic, BoundaryCondition::subc}};
          for (const auto &[upper, lower] : pairs)
            if (stiffness.count(upper) && stiffness.count(lower))
              {
                const VoigtMatrix6 &C_upper = stiffness.at(upper);
                const double e = min_eigenvalue6(C_upper - stiffness.at(lower));
                const bool   holds = e >= -1e-8 * C_upper.norm();
                const std::string key
                  = to_string(upper) + "_minus_" + to_string(lower);
                huet[key + "_min_eigenvalue"] = e;
                huet[key + "_holds"]          = holds;
                table << "  C^" << to_string(upper) << " - C^"
                      << to_string(lower) << ": " << std::scientific
                      << std::setprecision(3) << e / 1e9 << " ("
                      << (holds ? "holds" : "VIOLATED") << ")\n";
              }
          summary["huet"] = huet;
        }

      private:
        std::map<BoundaryCondition, VoigtMatrix6> stiffness;
      };

      const bool volume_huet_ordering_registered
        = PostprocessorRegistry<3>::add(
          {"Huet ordering",
           20,
           [](const PostprocessorInputs<3> &)
             -> std::unique_ptr<Postprocessor<3>> {
             return std::make_unique<VolumeHuetOrdering>();
           }});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
