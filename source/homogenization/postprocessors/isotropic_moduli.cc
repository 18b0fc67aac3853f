// Postprocessor "isotropic moduli" of 2D homogenization: the in-plane
// isotropic projections (2D bulk kappa, shear mu) of each apparent
// stiffness with its anisotropy, beside the Hashin-Shtrikman bounds (where
// every phase is isotropic) and the projections of the Voigt and Reuss
// estimates: a section of the screen table; kappa, mu and anisotropy under
// each boundary condition and "bounds": "hashin_shtrikman" in
// summary.json (null with a transversely isotropic phase).
#include "../moduli_table.h"

#include <memory>
#include <tribodyn/homogenization/effective_properties.h>
#include <tribodyn/homogenization/postprocessor.h>
#include <tuple>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      class InPlaneIsotropicModuli : public Postprocessor<2>
      {
      public:
        explicit InPlaneIsotropicModuli(const PostprocessorInputs<2> &in)
            : phases(in.phases)
            , fractions(in.fractions)
        {
        }

        void
        solved(const CellProblemResult &r, JsonValue &, std::ostream &) override
        {
          results.push_back(r);
        }

        void
        finish(JsonValue &summary, std::ostream &table) const override
        {
          // The Hashin-Shtrikman bounds need isotropic phases; with a
          // transversely isotropic one they are not computed (null in
          // summary.json).
          const bool              isotropic = all_isotropic(phases);
          const PlaneModuliBounds hs
            = isotropic ? hashin_shtrikman_bounds(phases, fractions)
                        : PlaneModuliBounds{};
          const PlaneModuli voigt
            = isotropic_projection(voigt_estimate(phases, fractions).C);
          const PlaneModuli reuss
            = isotropic_projection(reuss_estimate(phases, fractions).C);
          JsonValue j; // null
          if (isotropic)
            {
              j                = JsonValue::object();
              j["kappa_lower"] = hs.lower.kappa;
              j["kappa_upper"] = hs.upper.kappa;
              j["mu_lower"]    = hs.lower.mu;
              j["mu_upper"]    = hs.upper.mu;
            }
          summary["bounds"]["hashin_shtrikman"] = j;

          table
            << "\nIn-plane isotropic moduli (GPa): 2D bulk kappa = (C11 + C22 "
               "+ 2 C12)/4, shear mu = ((C11 + C22 - 2 C12)/4 + C66)/2;\n"
            << (isotropic ? "Hashin-Shtrikman bounds apply to an in-plane "
                            "isotropic microstructure (see anisotropy):\n"
                          : "no Hashin-Shtrikman bounds: a phase is "
                            "transversely isotropic.\n")
            << std::left << std::setw(10) << "estimate" << std::right
            << std::setw(10) << "kappa" << std::setw(10) << "mu"
            << std::setw(12) << "anisotropy"
            << "\n";
          const auto row = [&](const std::string &label, const PlaneModuli &m) {
            internal::write_moduli_row(table, label, m.kappa, m.mu);
          };
          internal::write_result_rows(
            table, summary, results, "kappa", [](const VoigtMatrix &C) {
              const PlaneModuli m = isotropic_projection(C);
              return std::tuple(m.kappa, m.mu, anisotropy(C));
            });
          if (isotropic)
            {
              row("HS upper", hs.upper);
              row("HS lower", hs.lower);
            }
          row("Voigt", voigt);
          row("Reuss", reuss);
        }

      private:
        const std::vector<ElasticPhase> &phases;
        const std::vector<double>       &fractions;
        std::vector<CellProblemResult>   results;
      };

      const bool isotropic_moduli_registered = PostprocessorRegistry<2>::add(
        {"isotropic moduli",
         30,
         [](const PostprocessorInputs<2> &in)
           -> std::unique_ptr<Postprocessor<2>> {
           return std::make_unique<InPlaneIsotropicModuli>(in);
         }});
    } // namespace
  }   // namespace homogenization
} // namespace tribodyn
