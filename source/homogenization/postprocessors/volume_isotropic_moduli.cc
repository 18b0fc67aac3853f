// Postprocessor "isotropic moduli" of 3D voxel volumes: the isotropic
// projections (bulk k, shear mu) of each apparent stiffness with its
// anisotropy, beside the 3D Hashin-Shtrikman bounds (where every phase is
// isotropic; they bound a statistically isotropic volume): a section of
// the screen table; k, mu and anisotropy under each boundary condition and
// "bounds": "hashin_shtrikman" in summary.json (null otherwise).
#include "../moduli_table.h"

#include <memory>
#include <tribodyn/homogenization/postprocessor.h>
#include <tribodyn/homogenization/volume_properties.h>
#include <tuple>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      class VolumeIsotropicModuli : public Postprocessor<3>
      {
      public:
        explicit VolumeIsotropicModuli(const PostprocessorInputs<3> &in)
            : phases(in.phases)
            , fractions(in.fractions)
        {
        }

        void
        solved(const CellResult<3> &r, JsonValue &, std::ostream &) override
        {
          results.push_back(r);
        }

        void
        finish(JsonValue &summary, std::ostream &table) const override
        {
          bool                         isotropic = true;
          std::vector<IsotropicModuli> moduli;
          for (const auto &phase : phases)
            if (phase.isotropic)
              moduli.push_back(
                {phase.isotropic->bulk_modulus(), phase.isotropic->mu()});
            else
              isotropic = false;
          table << "\nIsotropic projections (GPa): k = (C11 + C22 + C33 + 2 "
                   "(C12 + C13 + C23))/9, mu = (C11 + C22 + C33 - C12 - C13 "
                   "- C23 + 3 (C44 + C55 + C66))/15\n"
                << std::left << std::setw(10) << "estimate" << std::right
                << std::setw(10) << "k" << std::setw(10) << "mu"
                << std::setw(12) << "anisotropy\n";
          internal::write_result_rows(
            table, summary, results, "k", [](const VoigtMatrix6 &C) {
              const IsotropicModuli m = isotropic_projection_3d(C);
              return std::tuple(m.k, m.mu, anisotropy_3d(C));
            });
          JsonValue hs; // null unless every phase is isotropic
          if (isotropic)
            {
              const auto [lower, upper]
                = hashin_shtrikman_bounds_3d(moduli, fractions);
              internal::write_moduli_row(table, "HS upper", upper.k, upper.mu);
              internal::write_moduli_row(table, "HS lower", lower.k, lower.mu);
              hs             = JsonValue::object();
              hs["k_lower"]  = lower.k;
              hs["k_upper"]  = upper.k;
              hs["mu_lower"] = lower.mu;
              hs["mu_upper"] = upper.mu;
            }
          summary["bounds"]["hashin_shtrikman"] = hs;
        }

      private:
        const std::vector<ElasticPhase> &phases;
        const std::vector<double>       &fractions;
        std::vector<CellResult<3>>       results;
      };

      const bool volume_isotropic_moduli_registered
        = PostprocessorRegistry<3>::add(
          {"isotropic moduli",
           30,
           [](const PostprocessorInputs<3> &in)
             -> std::unique_ptr<Postprocessor<3>> {
             return std::make_unique<VolumeIsotropicModuli>(in);
           }});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
