// The pair law of the automata (seed eqs. 1-3, design §6): strain
// increments of the pairs, many-body mean-stress increments, pair stresses
// with the plastic correction, contact constraints of unbonded pairs,
// forces and torques; then bond breaking and formation.

#include <algorithm>
#include <cmath>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/plasticity.h>

namespace tribodyn
{
  namespace mca
  {
    void
    AutomatonSystem::evaluate_pairs(const double step_dt)
    {
      // Ghost kinematics: x, v, w from their owners (one message per
      // neighbour rank).
      if (neighbours.active() && n_local > 0)
        neighbours.update({{&x[0][0], 3}, {v[0].data(), 3}, {w[0].data(), 3}});
      // Neighbourhoods that changed at the last step (contacts, bonds).
      if (any_changed)
        update_neighbourhood_weights(false);
      const bool rot = rotations;
      if (rot && plastic_scene && bond_scene)
        pair_kernel<true, true, true>(step_dt);
      else if (rot && plastic_scene)
        pair_kernel<true, true, false>(step_dt);
      else if (rot && bond_scene)
        pair_kernel<true, false, true>(step_dt);
      else if (rot)
        pair_kernel<true, false, false>(step_dt);
      else if (plastic_scene && bond_scene)
        pair_kernel<false, true, true>(step_dt);
      else if (plastic_scene)
        pair_kernel<false, true, false>(step_dt);
      else if (bond_scene)
        pair_kernel<false, false, true>(step_dt);
      else
        pair_kernel<false, false, false>(step_dt);
    }


    template <bool rot, bool plastic, bool bonds>
    void
    AutomatonSystem::pair_kernel(const double step_dt)
    {
      const unsigned int n_pairs = pi.size();
      const double       mu      = prm.interaction.friction_coefficient;
      const double       inv_r0  = 1. / r0;
      if constexpr (plastic)
        sum_qs.assign(n_local, 0);
      dsm.assign(n_local, 0);
      // Contact and bond changes of this step mark both automata.
      auto mark = [&](const unsigned int p) {
        changed[pi[p]] = 1;
        changed[pj[p]] = 1;
        any_changed    = true;
      };

      // Pass A: geometry, tangential stresses, split of the normal
      // increment, volumetric strain increments of both sides.
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          const unsigned int i = pi[p], j = pj[p];
          const Vec3         dnew = pair_vector(p);
          // displacement increments of the step: dt v (the drift)
          Vec3 du, dold;
          for (unsigned int c = 0; c < 3; ++c)
            {
              du[c]   = step_dt * v[j][c] - step_dt * v[i][c];
              dold[c] = dnew[c] - du[c];
            }
          // (reciprocals multiplied: divisions are the dearest operations
          // of this loop)
          const double r = std::sqrt(dot(dnew, dnew)), inv_r = 1. / r;
          const double ro = std::sqrt(dot(dold, dold)), inv_ro = 1. / ro;
          Vec3         n, nm, sum, diff;
          for (unsigned int c = 0; c < 3; ++c)
            {
              n[c]    = dnew[c] * inv_r;
              nm[c]   = n[c] + dold[c] * inv_ro;
              sum[c]  = dnew[c] + dold[c];
              diff[c] = dnew[c] - dold[c];
            }
          const double inv_nmn = 1. / std::sqrt(dot(nm, nm));
          for (unsigned int c = 0; c < 3; ++c)
            nm[c] *= inv_nmn;
          double               dr_p = dot(diff, sum) / (r + ro), r_prev = ro;
          const SeriesSprings &k  = springs[mat[i] * n_materials + mat[j]];
          const double         ki = k.ki, kj = k.kj;

          if (!bonded[p])
            {
              if (r >= d)
                {
                  // separated: no interaction
                  if (in_contact[p])
                    mark(p);
                  in_contact[p] = 0;
                  sig_i[p] = sig_j[p] = 0;
                  tau.set(p, {{0, 0, 0}});
                  tau_scale_i[p] = tau_scale_j[p] = 1;
                  q_i[p]                          = r / 2;
                  continue;
                }
              if (!in_contact[p])
                {
                  // touching now: only the overlap counts, from r = d
                  in_contact[p] = 1;
                  mark(p);
                  q_i[p] = d / 2;
                  r_prev = d;
                  dr_p   = r - d;
                }
            }
          const double qi = q_i[p], qj = r_prev - qi;

          // Tangential: relative displacement of the contact points.
          if constexpr (rot)
            {
              Vec3 th;
              for (unsigned int c = 0; c < 3; ++c)
                th[c] = step_dt * (qi * w[i][c] + qj * w[j][c]);
              const Vec3 rc = cross(th, nm);
              for (unsigned int c = 0; c < 3; ++c)
                du[c] -= rc[c];
            }
          const double dun = dot(du, nm);
          for (unsigned int c = 0; c < 3; ++c)
            du[c] -= dun * nm[c];
          // rotate the stored shear stress into the new tangent plane,
          // keeping its magnitude (both sides are multiples of it)
          Vec3 t = tau[p];
          {
            const double t2 = dot(t, t);
            if (t2 > 0)
              {
                const double tn = dot(t, n);
                double       p2 = 0;
                for (unsigned int c = 0; c < 3; ++c)
                  {
                    t[c] -= tn * n[c];
                    p2 += t[c] * t[c];
                  }
                const double s = p2 > 1e-12 * t2 ? std::sqrt(t2 / p2) : 0.;
                for (unsigned int c = 0; c < 3; ++c)
                  t[c] *= s;
              }
          }
          {
            // series springs of the two halves: one shear stress
            // (kj tau_i + ki tau_j + ki kj du) / (ki + kj)
            const double inv = k.inv_sum;
            const double mix = kj * tau_scale_i[p] + ki * tau_scale_j[p];
            Vec3         tn;
            for (unsigned int c = 0; c < 3; ++c)
              tn[c] = (mix * t[c] + ki * kj * du[c]) * inv;
            tau.set(p, tn);
            tau_scale_i[p] = tau_scale_j[p] = 1;
          }
          // Normal split: equal elastic increments 2G de from both sides
          // (series springs), applied now; the many-body parts D dsm of the
          // two sides differ (added once dsm is known) and the force uses
          // the mean of the two sides.
          const double dqi = kj * dr_p * k.inv_sum;
          q_i[p]           = qi + dqi;
          sig_i[p] += ki * dqi;
          sig_j[p] += kj * (dr_p - dqi);
          const double qin = qi + dqi, qjn = r - qin;
          if (owned(i))
            {
              if constexpr (plastic)
                sum_qs[i] += qin * S;
              dsm[i] += beta_i[p] * dqi * inv_r0;
            }
          if (owned(j))
            {
              if constexpr (plastic)
                sum_qs[j] += qjn * S;
              dsm[j] += beta_j[p] * (dr_p - dqi) * inv_r0;
            }
        }

      // Mean-stress increment of each automaton: K times its volumetric
      // strain increment, the trace of the strain tensor fitted (least
      // squares) to its pairs' normal strains: dtheta = sum_j beta_ij
      // deps_ij (beta = 1/4 in a complete FCC neighbourhood).
      for (unsigned int k = 0; k < n_owned; ++k)
        dsm[k] *= mc[mat[k]].K;
      if (neighbours.active())
        neighbours.update(dsm.data(), 1);

      for (unsigned int k = 0; k < n_owned; ++k)
        {
          f[k]      = {{0, 0, 0}};
          torque[k] = {{0, 0, 0}};
        }
      // Many-body part of the elastic update of the side stresses.
      auto elastic_update = [&](const unsigned int p) {
        const unsigned int i = pi[p], j = pj[p];
        sig_i[p] += mc[mat[i]].D * dsm[i];
        sig_j[p] += mc[mat[j]].D * dsm[j];
      };

      // Pass B (plastic scenes): trial side stresses and trial tensors,
      // radial return per automaton.
      if constexpr (plastic)
        {
          trial.assign(n_local, Mat3{{0, 0, 0, 0, 0, 0, 0, 0, 0}});
          for (unsigned int p = 0; p < n_pairs; ++p)
            {
              if (!bonded[p] && !in_contact[p])
                continue;
              elastic_update(p);
              // automata of elastic regions need no trial stress
              if (!elastic(pi[p]) || !elastic(pj[p]))
                add_pair_stress(p, trial);
            }
          plast.assign(static_cast<std::size_t>(n_local) * 3, 0.);
          for (unsigned int k = 0; k < n_owned; ++k)
            {
              if (elastic(k))
                {
                  plast[3 * k + 1] = 1; // M = 1: no plastic correction
                  continue;
                }
              const auto  &m  = mc[mat[k]];
              const Sym3   s  = fabric_corrected(k, trial[k]);
              const double sm = (s[0] + s[1] + s[2]) / 3;
              const double q  = von_mises(s);
              double       M = 1, share = 0;
              if (m.m.is_plastic() && q > sigma_y[k])
                {
                  const double de = plastic_increment(m.m, m.G, eps_p[k], q);
                  const double sy_new = m.m.yield_stress_at(eps_p[k] + de);
                  M                   = sy_new / q;
                  const double work   = V * 0.5 * (sigma_y[k] + sy_new) * de;
                  eps_p[k] += de;
                  sigma_y[k] = sy_new;
                  plastic_work += work;
                  share = sum_qs[k] > 0 ? work / sum_qs[k] : 0;
                }
              plast[3 * k]     = sm;
              plast[3 * k + 1] = M;
              plast[3 * k + 2] = share;
            }
          if (neighbours.active())
            neighbours.update(plast.data(), 3);
        }

      // Pass C: plastic correction, contact constraints, forces, torques.
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          if (!bonded[p] && !in_contact[p])
            continue;
          const unsigned int i = pi[p], j = pj[p];
          double             r;
          const Vec3         n  = unit_normal(p, r);
          const double       qi = q_i[p], qj = r - qi;
          const Vec3         t  = tau[p];
          double             ai = tau_scale_i[p], aj = tau_scale_j[p];
          if constexpr (plastic)
            {
              const double smi = plast[3 * i], Mi = plast[3 * i + 1];
              const double smj = plast[3 * j], Mj = plast[3 * j + 1];
              if (Mi < 1)
                {
                  sig_i[p] = smi + Mi * (sig_i[p] - smi);
                  ai *= Mi;
                }
              if (Mj < 1)
                {
                  sig_j[p] = smj + Mj * (sig_j[p] - smj);
                  aj *= Mj;
                }
              // Plastic heat for bond formation: only heat generated while
              // the pair is unbonded counts (seed §2.1).
              if (!heat.empty() && !bonded[p])
                heat[p]
                  += qi * S * plast[3 * i + 2] + qj * S * plast[3 * j + 2];
            }
          else
            elastic_update(p);
          if (!bonded[p])
            {
              // no tension; Amontons-Coulomb on each side
              sig_i[p]                = std::min(sig_i[p], 0.);
              sig_j[p]                = std::min(sig_j[p], 0.);
              const SeriesSprings &k  = springs[mat[i] * n_materials + mat[j]];
              const double         ki = k.ki, kj = k.kj;
              const double         t_norm = std::sqrt(dot(t, t));
              for (const int side : {0, 1})
                {
                  double      &a     = side == 0 ? ai : aj;
                  const double limit = -mu * (side == 0 ? sig_i[p] : sig_j[p]);
                  const double tn    = std::abs(a) * t_norm;
                  if (tn > limit)
                    {
                      const double s = tn > 0 ? limit / tn : 0;
                      // work of the slip (tn - limit) / k_series of this
                      // side's half of the pair force, counted by the
                      // owner of that side
                      if (owned(side == 0 ? i : j))
                        friction_work += 0.5 * S * limit * (tn - limit)
                                         * (ki + kj) / (ki * kj);
                      a *= s;
                    }
                }
            }
          if (plastic || !bonded[p])
            {
              tau_scale_i[p] = ai;
              tau_scale_j[p] = aj;
            }
          const double sn = 0.5 * (sig_i[p] + sig_j[p]);
          const double am = 0.5 * S * (ai + aj);
          Vec3         ft, F;
          for (unsigned int c = 0; c < 3; ++c)
            {
              ft[c] = am * t[c];
              F[c]  = S * sn * n[c] + ft[c];
            }
          Vec3 nxf;
          if constexpr (rot)
            nxf = cross(n, ft);
          if (owned(i))
            {
              for (unsigned int c = 0; c < 3; ++c)
                f[i][c] += F[c];
              if constexpr (rot)
                for (unsigned int c = 0; c < 3; ++c)
                  torque[i][c] += qi * nxf[c];
            }
          if (owned(j))
            {
              for (unsigned int c = 0; c < 3; ++c)
                f[j][c] -= F[c];
              if constexpr (rot)
                for (unsigned int c = 0; c < 3; ++c)
                  torque[j][c] += qj * nxf[c];
            }
        }

      if constexpr (bonds)
        bond_switching<plastic>();
    }


    template <bool plastic>
    void
    AutomatonSystem::bond_switching()
    {
      // Bond switching (takes effect at the next step), from the automata's
      // stress tensors (eq. 4) exchanged with the neighbours.
      // member buffer: no allocation per step
      std::vector<double> &ex = bond_buffer;
      ex.assign(static_cast<std::size_t>(n_local) * 7, 0.);
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
            continue;
          const Sym3 s = automaton_stress(k);
          for (unsigned int c = 0; c < 6; ++c)
            ex[7 * k + c] = s[c];
        }
      if (neighbours.active())
        neighbours.update(ex.data(), 7);
      const double heat_fraction = prm.interaction.bond_formation_heat_fraction;
      const unsigned int n_pairs = pi.size();
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          const unsigned int i = pi[p], j = pj[p];
          if (elastic(i) && elastic(j))
            continue; // no bond switching inside elastic regions
          double       r;
          const Vec3   n  = unit_normal(p, r);
          const double sn = 0.5 * (sig_i[p] + sig_j[p]);
          const double am = 0.5 * (tau_scale_i[p] + tau_scale_j[p]);
          if (bonded[p] && prm.interaction.bond_breaking)
            {
              Sym3 s;
              for (unsigned int c = 0; c < 6; ++c)
                s[c] = 0.5 * (ex[7 * i + c] + ex[7 * j + c]);
              // replace the normal and shear parts by the pair's own
              const double sxx = s[0], syy = s[1], szz = s[2], syz = s[3],
                           sxz = s[4], sxy = s[5];
              Vec3         sn_vec{{sxx * n[0] + sxy * n[1] + sxz * n[2],
                                   sxy * n[0] + syy * n[1] + syz * n[2],
                                   sxz * n[0] + syz * n[1] + szz * n[2]}};
              const double snn = dot(sn_vec, n);
              Vec3         corr;
              for (unsigned int c = 0; c < 3; ++c)
                corr[c] = am * tau.component[c][p] - (sn_vec[c] - snn * n[c]);
              add_sym(s, sn - snn, n, n);
              add_sym(s, 1, n, corr);
              add_sym(s, 1, corr, n);
              const double limit
                = std::min(mc[mat[i]].sigma_b, mc[mat[j]].sigma_b);
              if (von_mises(s) >= limit)
                {
                  bonded[p]     = 0;
                  in_contact[p] = r < d;
                  if (!heat.empty())
                    heat[p] = 0;
                  changed[i] = changed[j] = 1;
                  any_changed             = true;
                }
            }
          else if (!bonded[p] && in_contact[p]
                   && prm.interaction.bond_formation)
            {
              const double sy = std::min(ex[7 * i + 6], ex[7 * j + 6]);
              const double Eb
                = std::min(mc[mat[i]].w_b, mc[mat[j]].w_b) * S * r;
              const double h = heat.empty() ? 0. : heat[p];
              if (sn <= -sy && h >= heat_fraction * Eb)
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
