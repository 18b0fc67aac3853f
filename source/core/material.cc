#include <cmath>
#include <deal.II/base/patterns.h>
#include <limits>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/material.h>
#include <tuple>

namespace tribodyn
{
  Interval
  youngs_modulus_range()
  {
    return {0,
            max_youngs_modulus,
            true,
            false,
            "Young's modulus is in Pa and must be positive (the limit, 10 "
            "TPa, is eight times diamond's)."};
  }


  Interval
  poisson_ratio_range()
  {
    return {-1,
            0.5,
            true,
            true,
            "An isotropic elastic material needs -1 < nu < 0.5 to be "
            "stable."};
  }


  Interval
  density_range()
  {
    return {0,
            max_density,
            true,
            false,
            "The density is in kg/m^3 and must be positive (the limit is "
            "four times osmium's)."};
  }


  void
  check_isotropic_elastic_constants(const std::string &section,
                                    const double       youngs_modulus,
                                    const double       poisson_ratio,
                                    const double       density)
  {
    for (const auto &[name, value, range] :
         {std::tuple{"/Young modulus", youngs_modulus, youngs_modulus_range()},
          std::tuple{"/Poisson ratio", poisson_ratio, poisson_ratio_range()},
          std::tuple{"/Density", density, density_range()}})
      check_parameter_range(section + name,
                            value,
                            range.lower,
                            range.upper,
                            range.lower_open,
                            range.upper_open,
                            range.hint);
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
