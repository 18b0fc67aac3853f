// 3D effective properties (issue #51): engineering constants of a 6x6
// compliance, the phases' 3D stiffness, Voigt/Reuss and Hashin-Shtrikman
// bounds (theory: doc/theory/homogenization.md, "3D voxel volumes").
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tribodyn/homogenization/volume_properties.h>

namespace tribodyn
{
  namespace homogenization
  {
    VoigtMatrix6
    invert6(const VoigtMatrix6 &A)
    {
      double a[6][12];
      for (unsigned int i = 0; i < 6; ++i)
        for (unsigned int j = 0; j < 6; ++j)
          {
            a[i][j]     = A[i][j];
            a[i][6 + j] = i == j ? 1. : 0.;
          }
      for (unsigned int c = 0; c < 6; ++c)
        {
          unsigned int pivot = c;
          for (unsigned int r = c + 1; r < 6; ++r)
            if (std::fabs(a[r][c]) > std::fabs(a[pivot][c]))
              pivot = r;
          if (a[pivot][c] == 0.)
            throw std::runtime_error("invert6: singular matrix");
          for (unsigned int j = 0; j < 12; ++j)
            std::swap(a[c][j], a[pivot][j]);
          const double d = a[c][c];
          for (unsigned int j = 0; j < 12; ++j)
            a[c][j] /= d;
          for (unsigned int r = 0; r < 6; ++r)
            if (r != c && a[r][c] != 0.)
              {
                const double factor = a[r][c];
                for (unsigned int j = 0; j < 12; ++j)
                  a[r][j] -= factor * a[c][j];
              }
        }
      VoigtMatrix6 inverse;
      for (unsigned int i = 0; i < 6; ++i)
        for (unsigned int j = 0; j < 6; ++j)
          inverse[i][j] = a[i][6 + j];
      return inverse;
    }


    double
    min_eigenvalue6(const VoigtMatrix6 &A)
    {
      // Cyclic Jacobi rotations on the symmetric part until the
      // off-diagonal entries vanish to round-off.
      double a[6][6];
      for (unsigned int i = 0; i < 6; ++i)
        for (unsigned int j = 0; j < 6; ++j)
          a[i][j] = 0.5 * (A[i][j] + A[j][i]);
      for (unsigned int sweep = 0; sweep < 100; ++sweep)
        {
          double off = 0, diagonal = 0;
          for (unsigned int i = 0; i < 6; ++i)
            {
              diagonal += a[i][i] * a[i][i];
              for (unsigned int j = i + 1; j < 6; ++j)
                off += a[i][j] * a[i][j];
            }
          if (off <= 1e-30 * diagonal || off == 0.)
            break;
          for (unsigned int p = 0; p < 6; ++p)
            for (unsigned int q = p + 1; q < 6; ++q)
              {
                if (a[p][q] == 0.)
                  continue;
                const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
                const double t
                  = (theta >= 0 ? 1. : -1.)
                    / (std::fabs(theta) + std::sqrt(theta * theta + 1));
                const double c = 1 / std::sqrt(t * t + 1), s = t * c;
                for (unsigned int k = 0; k < 6; ++k)
                  {
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                  }
                for (unsigned int k = 0; k < 6; ++k)
                  {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                  }
              }
        }
      double smallest = a[0][0];
      for (unsigned int i = 1; i < 6; ++i)
        smallest = std::min(smallest, a[i][i]);
      return smallest;
    }


    VolumeProperties
    volume_properties_from_compliance(const VoigtMatrix6 &S)
    {
      VolumeProperties p;
      p.S     = S;
      p.C     = invert6(S);
      auto &c = p.constants;
      c.E_x   = 1 / S[0][0];
      c.E_y   = 1 / S[1][1];
      c.E_z   = 1 / S[2][2];
      c.nu_xy = -S[1][0] / S[0][0];
      c.nu_xz = -S[2][0] / S[0][0];
      c.nu_yx = -S[0][1] / S[1][1];
      c.nu_yz = -S[2][1] / S[1][1];
      c.nu_zx = -S[0][2] / S[2][2];
      c.nu_zy = -S[1][2] / S[2][2];
      c.G_yz  = 1 / S[3][3];
      c.G_xz  = 1 / S[4][4];
      c.G_xy  = 1 / S[5][5];
      return p;
    }


    VolumeProperties
    volume_properties_from_stiffness(const VoigtMatrix6 &C)
    {
      VolumeProperties p = volume_properties_from_compliance(invert6(C));
      p.C                = C;
      return p;
    }


    VoigtMatrix6
    stiffness_3d(const ElasticPhase &phase)
    {
      VoigtMatrix6 C;
      if (phase.isotropic)
        {
          const double lambda = phase.isotropic->lambda();
          const double mu     = phase.isotropic->mu();
          for (unsigned int i = 0; i < 3; ++i)
            {
              for (unsigned int j = 0; j < 3; ++j)
                C[i][j] = lambda;
              C[i][i] += 2 * mu;
              C[3 + i][3 + i] = mu;
            }
          return C;
        }
      // Transversely isotropic: the compliance in the global axes, L along
      // axis a; the shear of the plane normal to a (Voigt index 3 + a) is
      // that of the plane of isotropy.
      const auto        &t = *phase.transversely_isotropic;
      const unsigned int a = t.axis;
      VoigtMatrix6       S;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          {
            if (i == a && j == a)
              S[i][j] = 1 / t.E_L;
            else if (i == a || j == a)
              S[i][j] = -t.nu_LT / t.E_L;
            else if (i == j)
              S[i][j] = 1 / t.E_T;
            else
              S[i][j] = -t.nu_TT / t.E_T;
          }
      for (unsigned int i = 0; i < 3; ++i)
        S[3 + i][3 + i] = i == a ? 1 / t.G_TT() : 1 / t.G_LT;
      return invert6(S);
    }


    VolumeProperties
    voigt_estimate_3d(const std::vector<VoigtMatrix6> &stiffness,
                      const std::vector<double>       &fractions)
    {
      VoigtMatrix6 C;
      for (unsigned int k = 0; k < stiffness.size(); ++k)
        C += fractions[k] * stiffness[k];
      return volume_properties_from_stiffness(C);
    }


    VolumeProperties
    reuss_estimate_3d(const std::vector<VoigtMatrix6> &stiffness,
                      const std::vector<double>       &fractions)
    {
      VoigtMatrix6 S;
      for (unsigned int k = 0; k < stiffness.size(); ++k)
        if (fractions[k] > 0)
          S += fractions[k] * invert6(stiffness[k]);
      return volume_properties_from_compliance(S);
    }


    IsotropicModuli
    isotropic_projection_3d(const VoigtMatrix6 &C)
    {
      const double normal = C[0][0] + C[1][1] + C[2][2];
      const double cross  = C[0][1] + C[0][2] + C[1][2];
      const double shear  = C[3][3] + C[4][4] + C[5][5];
      return {(normal + 2 * cross) / 9, (normal - cross + 3 * shear) / 15};
    }


    double
    anisotropy_3d(const VoigtMatrix6 &C)
    {
      const IsotropicModuli m      = isotropic_projection_3d(C);
      const double          lambda = m.k - 2. / 3. * m.mu;
      VoigtMatrix6          iso;
      for (unsigned int i = 0; i < 3; ++i)
        {
          for (unsigned int j = 0; j < 3; ++j)
            iso[i][j] = lambda;
          iso[i][i] += 2 * m.mu;
          iso[3 + i][3 + i] = m.mu;
        }
      return (C - iso).norm() / C.norm();
    }


    std::pair<IsotropicModuli, IsotropicModuli>
    hashin_shtrikman_bounds_3d(const std::vector<IsotropicModuli> &phases,
                               const std::vector<double>          &fractions)
    {
      const auto bound = [&](const double k0, const double mu0) {
        const double z0 = mu0 / 6 * (9 * k0 + 8 * mu0) / (k0 + 2 * mu0);
        double       sk = 0, smu = 0;
        for (unsigned int i = 0; i < phases.size(); ++i)
          {
            sk += fractions[i] / (phases[i].k + 4. / 3. * mu0);
            smu += fractions[i] / (phases[i].mu + z0);
          }
        return IsotropicModuli{1 / sk - 4. / 3. * mu0, 1 / smu - z0};
      };
      double k_min = phases[0].k, k_max = phases[0].k;
      double mu_min = phases[0].mu, mu_max = phases[0].mu;
      for (unsigned int i = 0; i < phases.size(); ++i)
        if (fractions[i] > 0)
          {
            k_min  = std::min(k_min, phases[i].k);
            k_max  = std::max(k_max, phases[i].k);
            mu_min = std::min(mu_min, phases[i].mu);
            mu_max = std::max(mu_max, phases[i].mu);
          }
      return {bound(k_min, mu_min), bound(k_max, mu_max)};
    }


    JsonValue
    matrix6_to_json(const VoigtMatrix6 &A)
    {
      JsonValue rows = JsonValue::array();
      for (unsigned int i = 0; i < 6; ++i)
        rows.push_back(
          json_array({A[i][0], A[i][1], A[i][2], A[i][3], A[i][4], A[i][5]}));
      return rows;
    }


    JsonValue
    to_json(const VolumeProperties &p)
    {
      JsonValue j   = JsonValue::object();
      j["C"]        = matrix6_to_json(p.C);
      j["S"]        = matrix6_to_json(p.S);
      const auto &c = p.constants;
      j["E_x"]      = c.E_x;
      j["E_y"]      = c.E_y;
      j["E_z"]      = c.E_z;
      j["nu_xy"]    = c.nu_xy;
      j["nu_xz"]    = c.nu_xz;
      j["nu_yx"]    = c.nu_yx;
      j["nu_yz"]    = c.nu_yz;
      j["nu_zx"]    = c.nu_zx;
      j["nu_zy"]    = c.nu_zy;
      j["G_yz"]     = c.G_yz;
      j["G_xz"]     = c.G_xz;
      j["G_xy"]     = c.G_xy;
      return j;
    }
  } // namespace homogenization
} // namespace tribodyn
