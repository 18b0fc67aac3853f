// Elastic phases of the 2D plane-strain problems: isotropic and
// transversely isotropic with the axis along x, y or z.
#include <tribodyn/core/elastic_phase.h>
#include <tribodyn/core/errors.h>

namespace tribodyn
{
  double
  TransverselyIsotropicConstants::G_TT() const
  {
    return E_T / (2 * (1 + nu_TT));
  }


  dealii::Tensor<2, 3>
  TransverselyIsotropicConstants::plane_strain_voigt_stiffness(
    dealii::Tensor<1, 3> &c_z,
    const std::string    &section) const
  {
    check_parameter(E_L > 0 && E_T > 0 && G_LT > 0,
                    section,
                    "the moduli E_L, E_T and G_LT of a transversely "
                    "isotropic material must be positive.");
    // Normal part of the 3D compliance in the material axes (L, T, T').
    const double M[3][3] = {{1. / E_L, -nu_LT / E_L, -nu_LT / E_L},
                            {-nu_LT / E_L, 1. / E_T, -nu_TT / E_T},
                            {-nu_LT / E_L, -nu_TT / E_T, 1. / E_T}};
    // Material axis of each global axis (x, y, z): L on 'axis', T and T'
    // on the other two, in order.
    static constexpr unsigned int material_of_global[3][3]
      = {{0, 1, 2}, {1, 0, 2}, {1, 2, 0}};
    const unsigned int *m = material_of_global[axis];
    double              S[3][3];
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        S[i][j] = M[m[i]][m[j]];
    // Plane strain: eps_zz = 0 gives sigma_zz = -(S31 s_xx + S32 s_yy)/S33,
    // so the in-plane compliance is S_ij - S_i3 S_3j / S33.
    const double a   = S[0][0] - S[0][2] * S[2][0] / S[2][2];
    const double b   = S[0][1] - S[0][2] * S[2][1] / S[2][2];
    const double d   = S[1][1] - S[1][2] * S[2][1] / S[2][2];
    const double det = a * d - b * b;
    // S33 > 0 and a positive definite condensed block: the normal
    // compliance is positive definite.
    check_parameter(det > 0 && a > 0,
                    section,
                    "the constants (E_L, E_T, nu_LT, nu_TT, G_LT) do not "
                    "give a positive definite stiffness: they need |nu_TT| "
                    "< 1 and 1 - nu_TT - 2 nu_LT^2 E_T / E_L > 0.");
    dealii::Tensor<2, 3> C;
    C[0][0] = d / det;
    C[0][1] = C[1][0] = -b / det;
    C[1][1]           = a / det;
    C[2][2]           = axis == 2 ? G_TT() : G_LT;
    for (unsigned int j = 0; j < 2; ++j)
      c_z[j] = -(S[2][0] * C[0][j] + S[2][1] * C[1][j]) / S[2][2];
    c_z[2] = 0;
    return C;
  }


  ElasticPhase::ElasticPhase(const IsotropicElasticMaterial &material)
      : C(material.plane_strain_voigt_stiffness())
      , density(material.density)
      , isotropic(material)
  {
    c_z[0] = c_z[1] = material.lambda();
  }


  ElasticPhase::ElasticPhase(const TransverselyIsotropicConstants &constants,
                             const double                          density,
                             const std::string                    &section)
      : density(density)
      , transversely_isotropic(constants)
  {
    C = constants.plane_strain_voigt_stiffness(c_z, section);
  }
} // namespace tribodyn
