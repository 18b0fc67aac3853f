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

      /// What may_break() needs of an automaton's stress tensor, in single
      /// precision: the norm of its deviator (rounded up) and its mean
      /// stress (computed from the tensors bond switching exchanges).
      static constexpr unsigned int screen_size = 2;

      /// The screen's figures @p f of the stress tensor @p s (xx, yy, zz,
      /// yz, xz, xy): |dev s| rounded up (float's relative rounding is
      /// below 1e-7) and tr s / 3.
      static void
      screen_figures(const double *s, float *f)
      {
        const double m  = (s[0] + s[1] + s[2]) / 3;
        const double d0 = s[0] - m, d1 = s[1] - m, d2 = s[2] - m;
        const double norm
          = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2
                      + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
        f[0] = static_cast<float>(norm * (1 + 1e-6));
        f[1] = static_cast<float>(m);
      }

      /// Can the bond of a pair break? A screen from the figures @p f_i,
      /// @p f_j of its automata's tensors (screen_figures()): false only
      /// where breaks() is false. For any scalar c, 3 J2(s') = 3/2 |dev
      /// s'|^2 <= 3/2 |s' - c I|^2, and with P = I - n n, s' - c I = P (s -
      /// c I) P + (sn + 2 c_n - c) n n + am (n (P tau) + (P tau) n), three
      /// orthogonal parts (pair_von_mises_squared()). With c the mean of
      /// the automata's mean stresses, s - c I is the mean of their
      /// deviators: |P (s - c I) P| <= a = (|dev s_i| + |dev s_j|) / 2,
      /// (sn + 2 c_n - c)^2 <= 2 (sn - c)^2 + 8 am^2 |tau|^2 and 2 am^2
      /// |P tau|^2 <= 2 am^2 |tau|^2: 3 J2 <= 3/2 (a^2 + 2 (sn - c)^2 + 10
      /// am^2 |tau|^2). A pressure common to the pair and its automata (a
      /// contact's) drops out, where a bound from the tensors' full norms
      /// kept it. Margins: the means' single precision (1e-6 of their
      /// magnitudes added to |sn - c|), and 1e-9 of 2 bound + 9 c^2 >= 3/2
      /// |s'|^2 for the rounding of the bound and of the criterion's own
      /// evaluation (3.1e-14 of |s'|^2, tests/mca/bond_breaking.cc).
      static bool
      may_break(const float *f_i,
                const float *f_j,
                const double sn,
                const double am,
                const Vec3  &tau,
                const double limit_i,
                const double limit_j)
      {
        const double a = 0.5 * (double(f_i[0]) + f_j[0]);
        const double c = 0.5 * (double(f_i[1]) + f_j[1]);
        const double e
          = std::abs(sn - c) + 1e-6 * (std::abs(f_i[1]) + std::abs(f_j[1]));
        const double bound
          = 1.5 * (a * a + 2 * e * e + 10 * am * am * dot(tau, tau));
        const double limit = std::min(limit_i, limit_j);
        return bound + 1e-9 * (2 * bound + 9 * c * c) >= limit * limit;
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
