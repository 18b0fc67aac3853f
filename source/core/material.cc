#include <cmath>
#include <deal.II/base/patterns.h>
#include <limits>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/material.h>

namespace tribodyn
{
  void
  IsotropicElasticMaterial::declare_parameters(
    dealii::ParameterHandler &prm,
    const double              default_youngs_modulus,
    const double              default_poisson_ratio,
    const double              default_density)
  {
    prm.declare_entry("Young modulus",
                      format_number(default_youngs_modulus),
                      dealii::Patterns::Double(),
                      "Young's modulus E in Pa; must be > 0.");
    prm.declare_entry("Poisson ratio",
                      format_number(default_poisson_ratio),
                      dealii::Patterns::Double(),
                      "Poisson's ratio nu; must lie in (-1, 0.5).");
    prm.declare_entry("Density",
                      format_number(default_density),
                      dealii::Patterns::Double(),
                      "Mass density rho in kg/m^3; must be > 0.");
  }


  void
  check_isotropic_elastic_constants(const std::string &section,
                                    const double       youngs_modulus,
                                    const double       poisson_ratio,
                                    const double       density)
  {
    check_parameter_range(section + "/Young modulus",
                          youngs_modulus,
                          0,
                          max_youngs_modulus,
                          true,
                          false,
                          "Young's modulus is in Pa and must be positive "
                          "(the limit, 10 TPa, is eight times diamond's).");
    check_parameter_range(section + "/Poisson ratio",
                          poisson_ratio,
                          -1,
                          0.5,
                          true,
                          true,
                          "An isotropic elastic material needs "
                          "-1 < nu < 0.5 to be stable.");
    check_parameter_range(section + "/Density",
                          density,
                          0,
                          max_density,
                          true,
                          false,
                          "The density is in kg/m^3 and must be positive "
                          "(the limit is four times osmium's).");
  }


  void
  IsotropicElasticMaterial::parse_parameters(dealii::ParameterHandler &prm,
                                             const std::string        &section)
  {
    youngs_modulus = prm.get_double("Young modulus");
    poisson_ratio  = prm.get_double("Poisson ratio");
    density        = prm.get_double("Density");
    check_isotropic_elastic_constants(section,
                                      youngs_modulus,
                                      poisson_ratio,
                                      density);
  }


  double
  IsotropicElasticMaterial::lambda() const
  {
    return youngs_modulus * poisson_ratio
           / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
  }


  double
  IsotropicElasticMaterial::mu() const
  {
    return youngs_modulus / (2 * (1 + poisson_ratio));
  }


  double
  IsotropicElasticMaterial::bulk_modulus() const
  {
    return youngs_modulus / (3 * (1 - 2 * poisson_ratio));
  }


  double
  IsotropicElasticMaterial::p_wave_speed() const
  {
    return std::sqrt((lambda() + 2 * mu()) / density);
  }


  dealii::Tensor<2, 3>
  IsotropicElasticMaterial::plane_strain_voigt_stiffness() const
  {
    dealii::Tensor<2, 3> C;
    C[0][0] = C[1][1] = lambda() + 2 * mu();
    C[0][1] = C[1][0] = lambda();
    C[2][2]           = mu();
    return C;
  }
} // namespace tribodyn
