#ifndef tribodyn_homogenization_effective_properties_h
#define tribodyn_homogenization_effective_properties_h

#include <deal.II/base/tensor.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/material.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    /// A 3x3 matrix in plane Voigt notation, order (xx, yy, xy), strains
    /// with the engineering shear gamma_xy = 2 eps_xy.
    using VoigtMatrix = dealii::Tensor<2, 3>;
    /// A plane Voigt vector, same order.
    using VoigtVector = dealii::Tensor<1, 3>;

    /**
     * The five constants of a transversely isotropic material whose axis L
     * is x and whose isotropy plane is (T = y, T' = z): Young's moduli E_L,
     * E_T (Pa), Poisson ratios nu_LT = -eps_T/eps_L under uniaxial stress
     * along L and nu_TT = -eps_T'/eps_T under uniaxial stress along T, and
     * the shear modulus G_LT (Pa).
     */
    struct EngineeringConstants
    {
      double E_L   = 0;
      double E_T   = 0;
      double nu_LT = 0;
      double nu_TT = 0;
      double G_LT  = 0;
    };

    /**
     * Apparent (or estimated) plane-strain properties of a volume: the
     * in-plane stiffness C (<sigma> = C <eps>), its inverse S, the
     * out-of-plane row c_z (<sigma_zz> = c_z . <eps>, nonzero in plane
     * strain) and the engineering constants derived from both.
     */
    struct ApparentProperties
    {
      VoigtMatrix          C;
      VoigtMatrix          S;
      VoigtVector          c_z;
      EngineeringConstants constants;
    };

    /**
     * Complete the plane-strain data to a 3D transversely isotropic
     * stiffness and extract the engineering constants (theory in
     * doc/theory/homogenization.md): in the axes (1 = x = L, 2 = y = T,
     * 3 = z = T') C11 = C[0][0], C12 = (C[0][1] + C[1][0])/2, C22 =
     * C[1][1], C13 = c_z[0], C23 = c_z[1], C33 = C22 (isotropy of the
     * T-T' plane), G_LT = C[2][2]; E and nu come from the inverse of the
     * 3x3 normal block.
     */
    ApparentProperties
    properties_from_stiffness(const VoigtMatrix &C, const VoigtVector &c_z);

    /// Voigt estimate: uniform strain, C = sum_k f_k C_k.
    ApparentProperties
    voigt_estimate(const std::vector<IsotropicElasticMaterial> &phases,
                   const std::vector<double>                   &fractions);

    /// Reuss estimate: uniform stress, S = sum_k f_k S_k.
    ApparentProperties
    reuss_estimate(const std::vector<IsotropicElasticMaterial> &phases,
                   const std::vector<double>                   &fractions);

    /**
     * Exact effective properties of a laminate (layers through the whole
     * volume) whose layers are normal to axis @p normal (0 = x, 1 = y):
     * the traction components (sigma_nn, sigma_nt) and the in-layer strain
     * eps_tt are uniform, the other components are piecewise constant.
     */
    ApparentProperties
    laminate_exact(const std::vector<IsotropicElasticMaterial> &phases,
                   const std::vector<double>                   &fractions,
                   const unsigned int                           normal);

    /// Smallest eigenvalue of the symmetric part of @p A.
    double
    min_eigenvalue_of_symmetric_part(const VoigtMatrix &A);

    /// JSON object with C, S, c_z and the five constants.
    JsonValue
    to_json(const ApparentProperties &properties);

    /// Row-major nested arrays of a 3x3 matrix.
    JsonValue
    matrix_to_json(const VoigtMatrix &A);
  } // namespace homogenization
} // namespace tribodyn

#endif
