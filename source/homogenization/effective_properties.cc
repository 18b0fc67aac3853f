#include <algorithm>
#include <deal.II/base/symmetric_tensor.h>
#include <limits>
#include <stdexcept>
#include <tribodyn/homogenization/effective_properties.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      /// The (n, n) block A and the (n, t) column b of a Voigt stiffness,
      /// for the index sets n = (n0, n1) and t.
      std::pair<dealii::Tensor<2, 2>, dealii::Tensor<1, 2>>
      split_blocks(const VoigtMatrix &C,
                   const unsigned int n0,
                   const unsigned int n1,
                   const unsigned int t)
      {
        dealii::Tensor<2, 2> A;
        A[0][0] = C[n0][n0];
        A[0][1] = C[n0][n1];
        A[1][0] = C[n1][n0];
        A[1][1] = C[n1][n1];
        return {A, dealii::Tensor<1, 2>({C[n0][t], C[n1][t]})};
      }
    } // namespace


    ApparentProperties
    properties_from_stiffness(const VoigtMatrix &C, const VoigtVector &c_z)
    {
      ApparentProperties result;
      result.C   = C;
      result.S   = dealii::invert(C);
      result.c_z = c_z;

      const double         C12 = 0.5 * (C[0][1] + C[1][0]);
      dealii::Tensor<2, 3> normal_block;
      normal_block[0][0] = C[0][0];
      normal_block[1][1] = C[1][1];
      normal_block[2][2] = C[1][1]; // C33 = C22
      normal_block[0][1] = normal_block[1][0] = C12;
      normal_block[0][2] = normal_block[2][0] = c_z[0];
      normal_block[1][2] = normal_block[2][1] = c_z[1];
      const dealii::Tensor<2, 3> compliance   = dealii::invert(normal_block);

      result.constants.E_L   = 1. / compliance[0][0];
      result.constants.E_T   = 1. / compliance[1][1];
      result.constants.nu_LT = -compliance[1][0] / compliance[0][0];
      result.constants.nu_TT = -compliance[2][1] / compliance[1][1];
      result.constants.G_LT  = C[2][2];
      return result;
    }


    ApparentProperties
    voigt_estimate(const std::vector<ElasticPhase> &phases,
                   const std::vector<double>       &fractions)
    {
      VoigtMatrix C;
      VoigtVector c_z;
      for (unsigned int k = 0; k < phases.size(); ++k)
        {
          C += fractions[k] * phases[k].C;
          c_z += fractions[k] * phases[k].c_z;
        }
      return properties_from_stiffness(C, c_z);
    }


    ApparentProperties
    reuss_estimate(const std::vector<ElasticPhase> &phases,
                   const std::vector<double>       &fractions)
    {
      VoigtMatrix S;
      for (unsigned int k = 0; k < phases.size(); ++k)
        S += fractions[k] * dealii::invert(phases[k].C);
      const VoigtMatrix C = dealii::invert(S);
      // Uniform stress sigma = C <eps>; sigma_zz^k = c_z^k . (S_k sigma).
      VoigtVector c_z;
      for (unsigned int k = 0; k < phases.size(); ++k)
        c_z += fractions[k] * (phases[k].c_z * dealii::invert(phases[k].C) * C);
      return properties_from_stiffness(C, c_z);
    }


    ApparentProperties
    laminate_exact(const std::vector<ElasticPhase> &phases,
                   const std::vector<double>       &fractions,
                   const unsigned int               normal)
    {
      if (normal > 1)
        throw std::logic_error("laminate_exact: normal must be 0 or 1");
      // Voigt indices of the continuous traction components (n) and of the
      // continuous in-layer strain (t).
      const unsigned int n0 = normal, n1 = 2, t = 1 - normal;

      // For a unit mean strain e_j: eps_t = <eps>_t in every layer, and the
      // uniform traction s = (sigma_n0, sigma_n1) solves
      // <A_k^{-1}> s = <eps_n> + <A_k^{-1} b_k> eps_t with A_k the (n, n)
      // block and b_k the (n, t) column of C_k.
      VoigtMatrix C_eff;
      VoigtVector c_z;
      for (unsigned int j = 0; j < 3; ++j)
        {
          VoigtVector mean_strain;
          mean_strain[j] = 1;
          dealii::Tensor<2, 2> mean_A_inverse;
          dealii::Tensor<1, 2> mean_A_inverse_b;
          for (unsigned int k = 0; k < phases.size(); ++k)
            {
              const auto [A, b] = split_blocks(phases[k].C, n0, n1, t);
              const dealii::Tensor<2, 2> A_inverse = dealii::invert(A);
              mean_A_inverse += fractions[k] * A_inverse;
              mean_A_inverse_b += fractions[k] * (A_inverse * b);
            }
          const dealii::Tensor<1, 2> mean_eps_n(
            {mean_strain[n0], mean_strain[n1]});
          const dealii::Tensor<1, 2> traction
            = dealii::invert(mean_A_inverse)
              * (mean_eps_n + mean_A_inverse_b * mean_strain[t]);

          for (unsigned int k = 0; k < phases.size(); ++k)
            {
              const VoigtMatrix Ck = phases[k].C;
              const auto [A, b]    = split_blocks(Ck, n0, n1, t);
              const dealii::Tensor<1, 2> eps_n
                = dealii::invert(A) * (traction - b * mean_strain[t]);
              VoigtVector eps_k;
              eps_k[n0]                 = eps_n[0];
              eps_k[n1]                 = eps_n[1];
              eps_k[t]                  = mean_strain[t];
              const VoigtVector sigma_k = Ck * eps_k;
              for (unsigned int i = 0; i < 3; ++i)
                C_eff[i][j] += fractions[k] * sigma_k[i];
              c_z[j] += fractions[k] * (phases[k].c_z * eps_k);
            }
        }
      return properties_from_stiffness(C_eff, c_z);
    }


    PlaneModuli
    plane_moduli(const IsotropicElasticMaterial &phase)
    {
      return {phase.lambda() + phase.mu(), phase.mu()};
    }


    PlaneModuli
    isotropic_projection(const VoigtMatrix &C)
    {
      const double c12 = 0.5 * (C[0][1] + C[1][0]);
      return {0.25 * (C[0][0] + C[1][1] + 2 * c12),
              0.5 * (0.25 * (C[0][0] + C[1][1] - 2 * c12) + C[2][2])};
    }


    double
    anisotropy(const VoigtMatrix &C)
    {
      const PlaneModuli m = isotropic_projection(C);
      VoigtMatrix       iso;
      iso[0][0] = iso[1][1] = m.kappa + m.mu;
      iso[0][1] = iso[1][0] = m.kappa - m.mu;
      iso[2][2]             = m.mu;
      return (C - iso).norm() / C.norm();
    }


    bool
    all_isotropic(const std::vector<ElasticPhase> &phases)
    {
      return std::all_of(phases.begin(),
                         phases.end(),
                         [](const ElasticPhase &p) { return !!p.isotropic; });
    }


    PlaneModuliBounds
    hashin_shtrikman_bounds(const std::vector<ElasticPhase> &phases,
                            const std::vector<double>       &fractions)
    {
      if (!all_isotropic(phases))
        throw std::logic_error("hashin_shtrikman_bounds: a phase is not "
                               "isotropic");
      // The comparison material of each bound: the stiffest (upper) or the
      // softest (lower) kappa and mu of the phases, taken separately.
      PlaneModuli largest{0, 0};
      PlaneModuli smallest{std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::max()};
      for (const auto &phase : phases)
        {
          const PlaneModuli m = plane_moduli(*phase.isotropic);
          largest.kappa       = std::max(largest.kappa, m.kappa);
          largest.mu          = std::max(largest.mu, m.mu);
          smallest.kappa      = std::min(smallest.kappa, m.kappa);
          smallest.mu         = std::min(smallest.mu, m.mu);
        }
      const auto bound = [&](const PlaneModuli &reference) {
        const double z = reference.mu * reference.kappa
                         / (reference.kappa + 2 * reference.mu);
        double sum_kappa = 0, sum_mu = 0;
        for (unsigned int k = 0; k < phases.size(); ++k)
          {
            const PlaneModuli m = plane_moduli(*phases[k].isotropic);
            sum_kappa += fractions[k] / (m.kappa + reference.mu);
            sum_mu += fractions[k] / (m.mu + z);
          }
        return PlaneModuli{1. / sum_kappa - reference.mu, 1. / sum_mu - z};
      };
      return {bound(smallest), bound(largest)};
    }


    double
    min_eigenvalue_of_symmetric_part(const VoigtMatrix &A)
    {
      dealii::SymmetricTensor<2, 3> sym;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          sym[i][j] = 0.5 * (A[i][j] + A[j][i]);
      const auto eigenvalues = dealii::eigenvalues(sym);
      return eigenvalues[2]; // sorted in descending order
    }


    JsonValue
    matrix_to_json(const VoigtMatrix &A)
    {
      JsonValue rows = JsonValue::array();
      for (unsigned int i = 0; i < 3; ++i)
        rows.push_back(json_array({A[i][0], A[i][1], A[i][2]}));
      return rows;
    }


    JsonValue
    to_json(const ApparentProperties &p)
    {
      JsonValue j = JsonValue::object();
      j["C"]      = matrix_to_json(p.C);
      j["S"]      = matrix_to_json(p.S);
      j["c_z"]    = json_array({p.c_z[0], p.c_z[1], p.c_z[2]});
      j["E_L"]    = p.constants.E_L;
      j["E_T"]    = p.constants.E_T;
      j["nu_LT"]  = p.constants.nu_LT;
      j["nu_TT"]  = p.constants.nu_TT;
      j["G_LT"]   = p.constants.G_LT;
      return j;
    }
  } // namespace homogenization
} // namespace tribodyn
