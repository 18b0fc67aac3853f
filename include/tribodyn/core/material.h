#ifndef tribodyn_core_material_h
#define tribodyn_core_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <string>
#include <tribodyn/core/parameter_binding.h>

namespace tribodyn
{
  /**
   * An isotropic linear elastic phase: Young's modulus E (Pa), Poisson's
   * ratio nu and density rho (kg/m^3): a named material of the finite
   * elements' engines (core/phase_materials.h) when it is isotropic.
   */
  /// Largest accepted Young's modulus (Pa) and density (kg/m^3): beyond
  /// any real material (diamond 1.2 TPa, osmium 22600 kg/m^3); larger values
  /// are unit mistakes and make the critical time step vanish.
  constexpr double max_youngs_modulus = 1e13;
  constexpr double max_density        = 1e5;

  /// The accepted ranges of E, nu and rho, each with the hint its refusal
  /// gives: written once, for the bindings and for the check below.
  Interval
  youngs_modulus_range();
  Interval
  poisson_ratio_range();
  Interval
  density_range();

  /// Throw InputError naming `@p section/...` unless E > 0, -1 < nu < 0.5
  /// and rho > 0 (and E, rho below the limits above).
  void
  check_isotropic_elastic_constants(const std::string &section,
                                    const double       youngs_modulus,
                                    const double       poisson_ratio,
                                    const double       density);

  struct IsotropicElasticMaterial
  {
    double youngs_modulus = 30e9;
    double poisson_ratio  = 0.2;
    double density        = 1770.;

    /// Lamé's first parameter lambda = E nu / ((1 + nu)(1 - 2 nu)).
    double
    lambda() const;
    /// Shear modulus mu = G = E / (2 (1 + nu)).
    double
    mu() const;
    /// Bulk modulus K = E / (3 (1 - 2 nu)).
    double
    bulk_modulus() const;
    /// P-wave speed in plane strain, sqrt((lambda + 2 mu) / rho).
    double
    p_wave_speed() const;

    /**
     * Plane-strain stiffness in Voigt notation, order (xx, yy, xy) with the
     * engineering shear strain gamma_xy = 2 eps_xy:
     * [[lambda + 2mu, lambda, 0], [lambda, lambda + 2mu, 0], [0, 0, mu]].
     */
    dealii::Tensor<2, 3>
    plane_strain_voigt_stiffness() const;
  };
} // namespace tribodyn

#endif
