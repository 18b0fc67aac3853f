#ifndef tribodyn_homogenization_effective_properties_h
#define tribodyn_homogenization_effective_properties_h

#include <deal.II/base/tensor.h>
#include <tribodyn/core/elastic_phase.h>
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
    voigt_estimate(const std::vector<ElasticPhase> &phases,
                   const std::vector<double>       &fractions);

    /// Reuss estimate: uniform stress, S = sum_k f_k S_k.
    ApparentProperties
    reuss_estimate(const std::vector<ElasticPhase> &phases,
                   const std::vector<double>       &fractions);

    /**
     * Exact effective properties of a laminate (layers through the whole
     * volume) whose layers are normal to axis @p normal (0 = x, 1 = y):
     * the traction components (sigma_nn, sigma_nt) and the in-layer strain
     * eps_tt are uniform, the other components are piecewise constant.
     */
    ApparentProperties
    laminate_exact(const std::vector<ElasticPhase> &phases,
                   const std::vector<double>       &fractions,
                   const unsigned int               normal);

    /**
     * In-plane isotropic moduli of plane strain: the 2D bulk modulus kappa
     * (mean in-plane stress per unit in-plane dilatation, lambda + mu for
     * an isotropic phase) and the shear modulus mu. An isotropic plane
     * stiffness is [[kappa + mu, kappa - mu, 0], [kappa - mu, kappa + mu,
     * 0], [0, 0, mu]].
     */
    struct PlaneModuli
    {
      double kappa = 0;
      double mu    = 0;
    };

    /// kappa = lambda + mu and mu of an isotropic phase in plane strain.
    PlaneModuli
    plane_moduli(const IsotropicElasticMaterial &phase);

    /**
     * Isotropic projection of a plane stiffness: kappa = (C11 + C22 + 2
     * C12)/4, mu = ((C11 + C22 - 2 C12)/4 + C66)/2 (both exact for an
     * isotropic C).
     */
    PlaneModuli
    isotropic_projection(const VoigtMatrix &C);

    /// Relative distance |C - C_iso| / |C| (Frobenius norms of the Voigt
    /// matrices) of @p C from its isotropic projection.
    double
    anisotropy(const VoigtMatrix &C);

    /// Lower and upper bounds on kappa and mu.
    struct PlaneModuliBounds
    {
      PlaneModuli lower;
      PlaneModuli upper;
    };

    /**
     * Hashin-Shtrikman bounds on the plane-strain bulk modulus kappa and
     * the in-plane shear modulus mu of a statistically isotropic 2D
     * (in-plane) composite of isotropic phases, any number of them, in
     * Walpole's form (valid also when the phases are not well ordered):
     *   kappa_HS = [sum_k f_k / (kappa_k + mu_0)]^-1 - mu_0,
     *   mu_HS    = [sum_k f_k / (mu_k + z_0)]^-1 - z_0,
     *   z_0 = mu_0 kappa_0 / (kappa_0 + 2 mu_0),
     * with (kappa_0, mu_0) = (max kappa_k, max mu_k) for the upper bounds
     * and the minima for the lower ones (theory:
     * doc/theory/homogenization.md, "Bounds for N phases"). They bound the
     * effective constants of an in-plane isotropic microstructure only.
     */
    PlaneModuliBounds
    hashin_shtrikman_bounds(const std::vector<ElasticPhase> &phases,
                            const std::vector<double>       &fractions);

    /// Whether every phase is isotropic (the Hashin-Shtrikman bounds
    /// above need it).
    bool
    all_isotropic(const std::vector<ElasticPhase> &phases);

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
