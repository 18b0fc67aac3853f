#ifndef tribodyn_homogenization_volume_properties_h
#define tribodyn_homogenization_volume_properties_h

#include <deal.II/base/tensor.h>
#include <tribodyn/core/elastic_phase.h>
#include <tribodyn/core/json.h>
#include <vector>

namespace tribodyn
{
  namespace homogenization
  {
    /// A 6x6 matrix in 3D Voigt notation, order (xx, yy, zz, yz, xz, xy),
    /// strains with the engineering shears gamma_ij = 2 eps_ij.
    using VoigtMatrix6 = dealii::Tensor<2, 6>;
    /// A 3D Voigt vector, same order.
    using VoigtVector6 = dealii::Tensor<1, 6>;

    /**
     * The engineering constants of a 3D compliance S: Young's moduli E_i =
     * 1 / S_ii (i = x, y, z), Poisson ratios nu_ij = -S_ji / S_ii (the
     * contraction along j under a uniaxial stress along i), shear moduli
     * G_yz = 1 / S_44, G_xz = 1 / S_55, G_xy = 1 / S_66. Exact for an
     * orthotropic material in the axes x, y, z; for another symmetry they
     * are the apparent constants of uniaxial and simple-shear stress tests.
     */
    struct EngineeringConstants3D
    {
      double E_x = 0, E_y = 0, E_z = 0;
      double nu_xy = 0, nu_xz = 0, nu_yx = 0, nu_yz = 0, nu_zx = 0, nu_zy = 0;
      double G_yz = 0, G_xz = 0, G_xy = 0;
    };

    /// Apparent (or estimated) 3D properties: C, S = C^-1 and the
    /// engineering constants of S.
    struct VolumeProperties
    {
      VoigtMatrix6           C;
      VoigtMatrix6           S;
      EngineeringConstants3D constants;
    };

    /// Inverse of a 6x6 matrix (Gauss-Jordan with partial pivoting).
    VoigtMatrix6
    invert6(const VoigtMatrix6 &A);

    /// Smallest eigenvalue of the symmetric part of @p A (Jacobi).
    double
    min_eigenvalue6(const VoigtMatrix6 &A);

    /// The properties of the stiffness @p C.
    VolumeProperties
    volume_properties_from_stiffness(const VoigtMatrix6 &C);
    /// The properties of the compliance @p S.
    VolumeProperties
    volume_properties_from_compliance(const VoigtMatrix6 &S);

    /**
     * The 3D stiffness of a phase: isotropic, lambda + 2 mu and lambda in
     * the normal block, mu on the shears; transversely isotropic, the
     * inverse of its compliance in the global axes (axis L along x, y or
     * z; plane of isotropy with G_TT = E_T / (2 (1 + nu_TT))).
     */
    VoigtMatrix6
    stiffness_3d(const ElasticPhase &phase);

    /// Voigt estimate C = sum_k f_k C_k and Reuss S = sum_k f_k S_k.
    VolumeProperties
    voigt_estimate_3d(const std::vector<VoigtMatrix6> &stiffness,
                      const std::vector<double>       &fractions);
    VolumeProperties
    reuss_estimate_3d(const std::vector<VoigtMatrix6> &stiffness,
                      const std::vector<double>       &fractions);

    /// Bulk and shear moduli (3D).
    struct IsotropicModuli
    {
      double k  = 0;
      double mu = 0;
    };

    /**
     * Isotropic projection of a 3D stiffness: k = (C11 + C22 + C33 + 2
     * (C12 + C13 + C23)) / 9, mu = (C11 + C22 + C33 - C12 - C13 - C23 + 3
     * (C44 + C55 + C66)) / 15 (both exact for an isotropic C).
     */
    IsotropicModuli
    isotropic_projection_3d(const VoigtMatrix6 &C);

    /// |C - C_iso| / |C| (Frobenius norms of the Voigt matrices): the
    /// anisotropy of @p C.
    double
    anisotropy_3d(const VoigtMatrix6 &C);

    /**
     * Hashin-Shtrikman bounds on the bulk and shear moduli of a
     * statistically isotropic 3D composite of isotropic phases, in
     * Walpole's form:
     *   k_HS  = [sum_k f_k / (k_k + 4/3 mu_0)]^-1 - 4/3 mu_0,
     *   mu_HS = [sum_k f_k / (mu_k + z_0)]^-1 - z_0,
     *   z_0   = mu_0 / 6 (9 k_0 + 8 mu_0) / (k_0 + 2 mu_0),
     * (k_0, mu_0) = the largest phase moduli for the upper bounds, the
     * smallest for the lower ones.
     */
    std::pair<IsotropicModuli, IsotropicModuli>
    hashin_shtrikman_bounds_3d(const std::vector<IsotropicModuli> &phases,
                               const std::vector<double>          &fractions);

    /// JSON object with C, S and the engineering constants.
    JsonValue
    to_json(const VolumeProperties &properties);
    /// Row-major nested arrays of a 6x6 matrix.
    JsonValue
    matrix6_to_json(const VoigtMatrix6 &A);
  } // namespace homogenization
} // namespace tribodyn

#endif
