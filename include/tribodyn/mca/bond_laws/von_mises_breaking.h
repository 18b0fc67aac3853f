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
#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <tribodyn/core/law_selection.h>
#include <tribodyn/mca/pair_fields.h>
#include <tribodyn/mca/vector_algebra.h>

namespace tribodyn
{
  namespace mca
  {
    class VonMisesBondBreaking
    {
    public:
      static constexpr const char *name   = "von Mises";
      static constexpr bool        active = true;

      struct Parameters : BoundLawParameters<Parameters>
      {
        bool on = false;

        ParameterBinding
        binding()
        {
          ParameterBinding e("", "Interaction");
          e.add("Bond breaking",
                on,
                "Bonded pairs break when the von Mises stress of the pair "
                "reaches the Bond breaking stress.");
          return e;
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

      /// 3 J2 of the pair's stress state: the mean @p s of the stress
      /// tensors of its automata (xx, yy, zz, yz, xz, xy) with the traction
      /// on its face (unit normal @p n) replaced by the pair's own, normal
      /// @p sn and shear @p am times @p tau: s' = s + a n n + n c + c n with
      /// a = sn - n.s.n and c = am tau - (s n - (n.s.n) n). Without
      /// building s': with P = I - n n, s' = P s P + (sn + 2 c_n) n n +
      /// am (n (P tau) + (P tau) n), c_n = am tau.n, three orthogonal parts,
      /// so |s'|^2 = |s|^2 - 2 |s n|^2 + (n.s.n)^2 + (sn + 2 c_n)^2 + 2 am^2
      /// |P tau|^2 and tr s' = tr s - n.s.n + sn + 2 c_n (half the
      /// operations; the same value to round-off, tests/mca/bond_breaking.cc).
      static double
      pair_von_mises_squared(const Sym3  &s,
                             const Vec3  &n,
                             const double sn,
                             const double am,
                             const Vec3  &tau)
      {
        const Vec3   s_n{{s[0] * n[0] + s[5] * n[1] + s[4] * n[2],
                          s[5] * n[0] + s[1] * n[1] + s[3] * n[2],
                          s[4] * n[0] + s[3] * n[1] + s[2] * n[2]}};
        const double snn = dot(s_n, n), tn = dot(tau, n);
        const double s_nn_new = sn + 2 * am * tn;
        const double s2       = s[0] * s[0] + s[1] * s[1] + s[2] * s[2]
                          + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
        const double norm2 = s2 - 2 * dot(s_n, s_n) + snn * snn
                             + s_nn_new * s_nn_new
                             + 2 * am * am * (dot(tau, tau) - tn * tn);
        const double trace = s[0] + s[1] + s[2] - snn + s_nn_new;
        return 1.5 * (norm2 - trace * trace / 3);
      }

      /// Can the bond of a pair break? A screen that needs only the
      /// Frobenius norms @p norm_i, @p norm_j of its automata's tensors
      /// (xx, yy, zz and twice the shear components squared): false only
      /// where breaks() is false. 3 J2(s') <= 3/2 |s'|^2, and of the three
      /// orthogonal parts of s' (pair_von_mises_squared()) |P s P| <= |s|
      /// <= (norm_i + norm_j) / 2, (sn + 2 c_n)^2 <= 2 sn^2 + 8 am^2
      /// |tau|^2, 2 am^2 |P tau|^2 <= 2 am^2 |tau|^2. The margin 1e-9
      /// covers the rounding of the bound and of the criterion's own
      /// evaluation (3.1e-14 of |s'|^2, tests/mca/bond_breaking.cc); norms
      /// kept in single precision must be rounded up.
      /// The norm may_break() screens by: the Frobenius norm of the
      /// stress tensor @p s (xx, yy, zz, yz, xz, xy).
      static double
      screen_norm(const double *s)
      {
        return std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]
                         + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
      }

      static bool
      may_break(const double norm_i,
                const double norm_j,
                const double sn,
                const double am,
                const Vec3  &tau,
                const double limit_i,
                const double limit_j)
      {
        const double a = 0.5 * (norm_i + norm_j);
        const double bound
          = 1.5 * (a * a + 2 * sn * sn + 10 * am * am * dot(tau, tau));
        const double limit = std::min(limit_i, limit_j);
        return bound * (1 + 1e-9) >= limit * limit;
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
        const double limit = std::min(limit_i, limit_j);
        return pair_von_mises_squared(s, n, sn, am, tau) >= limit * limit;
      }
    };
  } // namespace mca
} // namespace tribodyn

#endif
