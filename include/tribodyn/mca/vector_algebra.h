#ifndef tribodyn_mca_vector_algebra_h
#define tribodyn_mca_vector_algebra_h

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    using Vec3 = std::array<double, 3>;
    using Sym3 = std::array<double, 6>; ///< xx yy zz yz xz xy
    using Mat3 = std::array<double, 9>; ///< row major

    // Small inline kernels of the pair loops: plain arrays so that the
    // compiler keeps them in registers (no Tensor temporaries).

    inline double
    dot(const Vec3 &a, const Vec3 &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    inline Vec3
    negated(const Vec3 &a)
    {
      return {{-a[0], -a[1], -a[2]}};
    }

    inline Vec3
    cross(const Vec3 &a, const Vec3 &b)
    {
      return {{a[1] * b[2] - a[2] * b[1],
               a[2] * b[0] - a[0] * b[2],
               a[0] * b[1] - a[1] * b[0]}};
    }

    /// Add c * (n (x) t) to the full tensor m.
    inline void
    add_outer(Mat3 &m, const double c, const Vec3 &n, const Vec3 &t)
    {
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          m[3 * a + b] += c * n[a] * t[b];
    }

    /**
     * An array of 3-vectors stored as three arrays of components
     * (structure of arrays): streamed by the pair loops, and remapped one
     * component at a time at a pair-list rebuild, so that no second copy
     * of the whole array is ever needed.
     */
    struct VectorArray
    {
      std::array<std::vector<double>, 3> component;

      Vec3
      operator[](const std::size_t p) const
      {
        return {{component[0][p], component[1][p], component[2][p]}};
      }
      void
      set(const std::size_t p, const Vec3 &t)
      {
        for (unsigned int c = 0; c < 3; ++c)
          component[c][p] = t[c];
      }
      std::size_t
      size() const
      {
        return component[0].size();
      }
      /// Resize to @p n vectors of zeros.
      void
      assign(const std::size_t n)
      {
        for (auto &a : component)
          a.assign(n, 0.);
      }
      std::size_t
      memory_consumption() const
      {
        return 3 * component[0].capacity() * sizeof(double);
      }
    };

    /// Von Mises equivalent stress sqrt(3 J2).
    inline double
    von_mises(const Sym3 &s)
    {
      const double m = (s[0] + s[1] + s[2]) / 3;
      const double a = s[0] - m, b = s[1] - m, c = s[2] - m;
      const double j2 = 0.5 * (a * a + b * b + c * c) + s[3] * s[3]
                        + s[4] * s[4] + s[5] * s[5];
      return std::sqrt(3 * j2);
    }
  } // namespace mca
} // namespace tribodyn

#endif
