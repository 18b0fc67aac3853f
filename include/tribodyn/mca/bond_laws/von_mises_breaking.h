// Bond breaking by the von Mises criterion on the pair's stress state
// (seed 000 Sec. 2.1, doc/theory/mca.md Sec. 5): on with Interaction/Bond
// breaking. The state of a bonded pair is the mean of the stress tensors
// of its two automata (eq. 4, exchanged with the neighbours) with its
// normal and shear parts replaced by the pair's own; the bond breaks when
// its von Mises stress reaches the smaller Bond breaking stress of the two
// materials. A policy of the pair kernel (pair_law.h), called per bonded
// pair by AutomatonSystem::bond_switching().
#ifndef tribodyn_mca_bond_laws_von_mises_breaking_h
#define tribodyn_mca_bond_laws_von_mises_breaking_h

#include <algorithm>
#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <tribodyn/mca/pair_fields.h>
#include <tribodyn/mca/vector_algebra.h>

namespace tribodyn
{
  namespace mca
  {
    /// 3 J2, the square of the von Mises stress: the bond criterion
    /// compares it with the squared strength (no square root per pair).
    inline double
    von_mises_squared(const Sym3 &s)
    {
      const double m = (s[0] + s[1] + s[2]) / 3;
      const double a = s[0] - m, b = s[1] - m, c = s[2] - m;
      return 1.5 * (a * a + b * b + c * c)
             + 3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
    }

    class VonMisesBondBreaking
    {
    public:
      static constexpr const char *name   = "von Mises";
      static constexpr bool        active = true;

      struct Parameters
      {
        bool on = false;

        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          prm.declare_entry("Bond breaking",
                            "false",
                            dealii::Patterns::Bool(),
                            "Bonded pairs break when the von Mises stress of "
                            "the pair reaches the Bond breaking stress.");
        }
        void
        parse_parameters(dealii::ParameterHandler &prm)
        {
          on = prm.get_bool("Bond breaking");
        }
        bool
        chosen() const
        {
          return on;
        }
      };

      explicit VonMisesBondBreaking(const Parameters &)
      {
      }
      void
      register_pair_fields(PairFieldTable &, const std::function<bool()> &)
      {
      }

      /// Does the bond of a pair break? @p s_i, @p s_j: the stress tensors
      /// of its automata (xx, yy, zz, yz, xz, xy); @p n its unit normal,
      /// @p sn its normal stress, @p am times @p tau its shear stress;
      /// @p limit_i, @p limit_j the materials' bond breaking stresses.
      static bool
      breaks(const double *s_i,
             const double *s_j,
             const Vec3   &n,
             const double  sn,
             const double  am,
             const Vec3   &tau,
             const double  limit_i,
             const double  limit_j)
      {
        Sym3 s;
        for (unsigned int c = 0; c < 6; ++c)
          s[c] = 0.5 * (s_i[c] + s_j[c]);
        // replace the normal and shear parts by the pair's own
        const double sxx = s[0], syy = s[1], szz = s[2], syz = s[3], sxz = s[4],
                     sxy = s[5];
        Vec3         sn_vec{{sxx * n[0] + sxy * n[1] + sxz * n[2],
                             sxy * n[0] + syy * n[1] + syz * n[2],
                             sxz * n[0] + syz * n[1] + szz * n[2]}};
        const double snn = dot(sn_vec, n);
        Vec3         corr;
        for (unsigned int c = 0; c < 3; ++c)
          corr[c] = am * tau[c] - (sn_vec[c] - snn * n[c]);
        add_sym(s, sn - snn, n, n);
        add_sym(s, 1, n, corr);
        add_sym(s, 1, corr, n);
        const double limit = std::min(limit_i, limit_j);
        return von_mises_squared(s) >= limit * limit;
      }
    };
  } // namespace mca
} // namespace tribodyn

#endif
