#ifndef tribodyn_core_elastic_phase_h
#define tribodyn_core_elastic_phase_h

#include <deal.II/base/tensor.h>
#include <optional>
#include <string>
#include <tribodyn/core/material.h>

namespace tribodyn
{
  /**
   * The five constants of a transversely isotropic linear elastic material
   * and the direction of its axis L (theory: doc/theory/homogenization.md,
   * "Transversely isotropic phases"). In the material axes (1 = L, 2 = T,
   * 3 = T', the plane (T, T') being the plane of isotropy) the normal part
   * of the compliance is
   *
   *   [[1/E_L, -nu_LT/E_L, -nu_LT/E_L],
   *    [-nu_LT/E_L, 1/E_T, -nu_TT/E_T],
   *    [-nu_LT/E_L, -nu_TT/E_T, 1/E_T]],
   *
   * the shear moduli are G_LT (planes containing L) and G_TT = E_T / (2 (1 +
   * nu_TT)) (the plane of isotropy).
   */
  struct TransverselyIsotropicConstants
  {
    double E_L   = 0; ///< Young's modulus along the axis (Pa)
    double E_T   = 0; ///< Young's modulus in the plane of isotropy (Pa)
    double nu_LT = 0; ///< -eps_T / eps_L under a uniaxial stress along L
    double nu_TT = 0; ///< Poisson's ratio in the plane of isotropy
    double G_LT  = 0; ///< shear modulus of planes containing L (Pa)
    /// Global direction of L: 0 = x, 1 = y (in the plane of the 2D
    /// problem), 2 = z (normal to it, e.g. the fibres of a cross-section).
    unsigned int axis = 0;

    /// Shear modulus of the plane of isotropy, E_T / (2 (1 + nu_TT)).
    double
    G_TT() const;

    /**
     * Plane-strain stiffness in Voigt notation (xx, yy, xy; engineering
     * shear) in the global axes, and in @p c_z the row sigma_zz = c_z . eps:
     * the normal compliance in global axes is condensed with eps_zz = 0;
     * the in-plane shear modulus is G_LT when L lies in the plane (x or y)
     * and G_TT when L = z. Throws InputError naming @p section unless the
     * 3D stiffness is positive definite (E_L, E_T, G_LT > 0 and a positive
     * definite normal compliance).
     */
    dealii::Tensor<2, 3>
    plane_strain_voigt_stiffness(dealii::Tensor<1, 3> &c_z,
                                 const std::string    &section) const;
  };


  /**
   * A linear elastic phase as the 2D plane-strain problems use it: its
   * stiffness C (Voigt, xx, yy, xy), the out-of-plane stress row c_z
   * (sigma_zz = c_z . eps) and its density; the isotropic constants when
   * the phase is isotropic (the Hashin-Shtrikman bounds need them).
   */
  struct ElasticPhase
  {
    dealii::Tensor<2, 3>                    C;
    dealii::Tensor<1, 3>                    c_z;
    double                                  density = 0;
    std::optional<IsotropicElasticMaterial> isotropic;
    /// The constants of a transversely isotropic phase.
    std::optional<TransverselyIsotropicConstants> transversely_isotropic;

    ElasticPhase() = default;
    /// An isotropic phase: C = [[lambda + 2 mu, lambda, 0], ...],
    /// c_z = (lambda, lambda, 0). (Implicit: an isotropic material is a
    /// phase.)
    ElasticPhase(const IsotropicElasticMaterial &material);
    /// A transversely isotropic phase; @p section names it in errors.
    ElasticPhase(const TransverselyIsotropicConstants &constants,
                 const double                          density,
                 const std::string                    &section);
  };
} // namespace tribodyn

#endif
