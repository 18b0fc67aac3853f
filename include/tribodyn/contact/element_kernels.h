#ifndef tribodyn_contact_element_kernels_h
#define tribodyn_contact_element_kernels_h

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tribodyn
{
  namespace contact
  {
    /// dst += K src, cell by cell, from the 8 x 8 element matrices (one per
    /// material; @p single: one material, hoisted out of the loop).
    template <bool single>
    inline void
    apply_element_stiffness(const std::vector<unsigned int>  &cell_dofs,
                            const std::vector<unsigned char> &cell_material,
                            const std::vector<std::array<double, 64>> &Ke,
                            const double *__restrict src,
                            double *__restrict dst)
    {
      const std::size_t n_cells = cell_material.size();
      const double     *K0      = Ke[0].data();
      for (std::size_t c = 0; c < n_cells; ++c)
        {
          const unsigned int *idx = &cell_dofs[8 * c];
          const double       *K   = single ? K0 : Ke[cell_material[c]].data();
          double              we[8];
          for (unsigned int j = 0; j < 8; ++j)
            we[j] = src[idx[j]];
          for (unsigned int i = 0; i < 8; ++i)
            {
              double s = 0;
              for (unsigned int j = 0; j < 8; ++j)
                s += K[8 * i + j] * we[j];
              dst[idx[i]] += s;
            }
        }
    }


    /// Von Mises stress of (sigma_xx, sigma_yy, sigma_xy, sigma_zz).
    inline double
    von_mises(const std::array<double, 4> &s)
    {
      const double a = s[0] - s[1], b = s[1] - s[3], c = s[3] - s[0];
      return std::sqrt(0.5 * (a * a + b * b + c * c) + 3. * s[2] * s[2]);
    }
  } // namespace contact
} // namespace tribodyn

#endif
