// Bond switching of the automata (seed 000 Sec. 2.1; doc/theory/mca.md
// Sec. 5) under the chosen criteria (include/tribodyn/mca/bond_laws.h):
// bonded pairs break (von Mises: at the bond breaking stress), unbonded
// contacts bond (plastic heat: in compression at the yield stress once
// their plastic heat reaches a fraction of the bond energy). Called at the
// end of the pair kernel of bond scenes, in its translation unit
// (pair_kernel.cc, which chooses the criteria); acts from the next step.
#ifndef tribodyn_mca_bond_switching_h
#define tribodyn_mca_bond_switching_h

#include <algorithm>
#include <cmath>
#include <tribodyn/mca/automaton_system.h>
#include <type_traits>
#include <utility>

namespace tribodyn
{
  namespace mca
  {
    /// Does bond breaking criterion @p B screen its pairs (may_break())?
    template <class B, class = void>
    struct has_breaking_screen : std::false_type
    {
    };
    template <class B>
    struct has_breaking_screen<
      B,
      std::void_t<decltype(B::screen_figures(nullptr, nullptr)),
                  decltype(B::may_break(nullptr,
                                        nullptr,
                                        0.,
                                        0.,
                                        std::declval<const Vec3 &>(),
                                        0.,
                                        0.))>> : std::true_type
    {
    };


    template <bool plastic, class Breaking, class Formation>
    void
    AutomatonSystem::bond_switching([[maybe_unused]] const Breaking  &breaking,
                                    [[maybe_unused]] const Formation &formation)
    {
      // Bond switching (takes effect at the next step), from the automata's
      // stress tensors (eq. 4) exchanged with the neighbours.
      // member buffer: no allocation per step. A plastic kernel's radial
      // returns left in it the stress sym(B^-1 T) of each owned
      // automaton's trial tensor, outside elastic regions: the final one
      // where pass C did not sum the tensor anew (stress_anew).
      std::vector<double> &ex = bond_buffer;
      if constexpr (!plastic)
        ex.assign(static_cast<std::size_t>(n_local) * 7, 0.);
      Assert(ex.size() == static_cast<std::size_t>(n_local) * 7,
             dealii::ExcInternalError());
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          ex[7 * k + 6] = plastic_scene ? sigma_y[k] : mc[mat[k]].yield0;
          // an automaton of an elastic region with only elastic partners
          // takes part in no bond check: its stress is not needed
          bool needed = !elastic(k);
          if (!needed)
            for_each_pair_of(
              k, [&](const unsigned int p, const unsigned int side) {
                needed = needed || !elastic(side ? pi[p] : pj[p]);
              });
          if (!needed)
            {
              if constexpr (plastic)
                std::fill_n(&ex[7 * k], 6, 0.);
              continue;
            }
          if constexpr (plastic)
            if (!stress_anew[k])
              continue;
          const Sym3 s = fabric_corrected(k, trial[k]);
          for (unsigned int c = 0; c < 6; ++c)
            ex[7 * k + c] = s[c];
        }
      if (partition.neighbours().active())
        partition.neighbours().update(ex.data(), 7);
      // A breaking criterion that screens its pairs by figures of their
      // automata's tensors (may_break(): never false where it breaks)
      // skips the full criterion for most pairs of a bulk far below it.
      constexpr bool screened    = has_breaking_screen<Breaking>::value;
      unsigned int   screen_size = 0;
      if constexpr (screened)
        {
          screen_size = Breaking::screen_size;
          stress_screen.resize(std::size_t(screen_size) * n_local);
          for (unsigned int k = 0; k < n_local; ++k)
            Breaking::screen_figures(&ex[7 * k],
                                     &stress_screen[screen_size * k]);
        }
      const unsigned int n_pairs = pi.size();
      // The distance and normal of a pair, as pass A kept them or anew
      // (the same bits as NormalBlock): asked for only by the pairs that
      // pass the screen or are in contact, most bonded pairs of a bulk far
      // below the criterion need neither.
      const auto geometry_of = [&](const unsigned int p) {
        if (!step_normals.empty())
          {
            Vec3 n;
            for (unsigned int c = 0; c < 3; ++c)
              n[c] = step_normals[(c + 1) * std::size_t(n_pairs) + p];
            return std::make_pair(step_normals[p], n);
          }
        const Vec3   dn = pair_vector(p);
        const double r
          = std::sqrt(dn[0] * dn[0] + dn[1] * dn[1] + dn[2] * dn[2]);
        const double inv_r = 1. / r;
        return std::make_pair(
          r, Vec3{{dn[0] * inv_r, dn[1] * inv_r, dn[2] * inv_r}});
      };
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          const unsigned int i = pi[p], j = pj[p];
          if (elastic(i) && elastic(j))
            continue; // no bond switching inside elastic regions
          if (!bonded[p] && !in_contact[p])
            continue;
          const double sn = 0.5 * (sig_i[p] + sig_j[p]);
          const double am = 0.5 * (shear_factor(p, 0) + shear_factor(p, 1));
          if (bonded[p])
            {
              if constexpr (Breaking::active)
                if constexpr (screened)
                  if (!breaking.may_break(&stress_screen[screen_size * i],
                                          &stress_screen[screen_size * j],
                                          sn,
                                          am,
                                          tau[p],
                                          mc[mat[i]].sigma_b,
                                          mc[mat[j]].sigma_b))
                    continue;
              if constexpr (Breaking::active)
                if (const auto [r, n] = geometry_of(p);
                    breaking.breaks(&ex[7 * i],
                                    &ex[7 * j],
                                    n,
                                    sn,
                                    am,
                                    tau[p],
                                    mc[mat[i]].sigma_b,
                                    mc[mat[j]].sigma_b))
                  {
                    bonded[p]     = 0;
                    in_contact[p] = r < (graded ? 2 * pair_half_rest[p] : d);
                    // a new contact for the friction law
                    friction_laws.with_selected(
                      [p](auto &law) { law.start_contact(p); });
                    if (!heat.empty())
                      heat[p] = 0;
                    changed[i] = changed[j] = 1;
                    any_changed             = true;
                  }
            }
          else
            {
              if constexpr (Formation::active)
                if (const double r = geometry_of(p).first;
                    formation.forms(sn,
                                    ex[7 * i + 6],
                                    ex[7 * j + 6],
                                    heat.empty() ? 0. : heat[p],
                                    mc[mat[i]].w_b,
                                    mc[mat[j]].w_b,
                                    area_of(p),
                                    r))
                  {
                    bonded[p] = 1;
                    if (!heat.empty())
                      heat[p] = 0;
                    changed[i] = changed[j] = 1;
                    any_changed             = true;
                  }
            }
        }
    }
  } // namespace mca
} // namespace tribodyn

#endif
