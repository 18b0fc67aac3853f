// The pair kernel of an elastic bulk (AutomatonSystem::evaluate_pairs()
// hands its scenes here): every pair bonded, both automata of one material, the
// halves equally stiff (q_i = r/2), no plasticity and no bond law, so that
// no event can occur and the pairs store their sides' common normal stress
// only (PairArrays::sig_e; AutomatonSystem::allocate_side_states() decides
// it, collectively and for good, at each rebuild). What the branches of the
// general passes ask pair by pair (bonded? a shear factor? a stored moment
// arm? an event?) is known here for the whole scene, so a block's pair law
// runs in one branch-free loop that the compiler vectorizes; only the
// scattered sums into the automata stay pair by pair. The pair law is that
// of pair_pass_a() and pair_pass_c() term for term, but each pair's force
// is added in two parts: pass A adds what is known at its end, the common
// normal stress and the shear stress of the step's end, S sig_e n + S tau,
// and every torque; pass C only the sides' many-body part S (m_i + m_j)/2 n,
// once the many-body step has them. Equal in exact arithmetic; each
// automaton's sum takes the terms in another order (the order of the pairs
// in each pass, the same on any partition; doc/theory/mca.md §8.4,
// doc/performance.md "The elastic bulk's passes").
//
// The step's geometry (distances, normals, the turned shear stress, the
// contact points' slip) is written here again, term for term as in
// pair_pass_a(), not shared with it through inline helpers: such helpers
// change how the compiler fuses the general kernels' products into FMAs
// (measured: the plastic uniaxial_steel's series moved in its last bits),
// and the general kernels' results are to stay bit for bit.

#include "pair_blocks.h"
#include "pair_geometry_choice.h"
#include "pair_kinematics.h"

#include <algorithm>
#include <cmath>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/friction_laws.h>
#include <tribodyn/mca/moment_laws.h>
#include <tribodyn/mca/pair_law.h>
#include <type_traits>

namespace tribodyn
{
  namespace mca
  {
    void
    AutomatonSystem::evaluate_bulk_pairs(const double step_dt)
    {
      // (the caller, evaluate_pairs(), has updated the ghosts' kinematics
      // and the neighbourhood weights)
      with_chosen(
        [&](auto rot, const auto &pairs, auto &friction, auto &moment) {
          using Moment = std::decay_t<decltype(moment)>;
          if constexpr (decltype(rot)::value || !Moment::needs_rotations)
            bulk_pair_kernel<decltype(rot)::value>(step_dt,
                                                   pairs,
                                                   friction,
                                                   moment);
        },
        CompileTimeSwitch{rotations},
        pair_geometry_choice(),
        friction_laws,
        moment_laws);
    }


    template <bool rot, class Pairs, class Law, class Moment>
    void
    AutomatonSystem::bulk_pair_kernel(const double step_dt,
                                      const Pairs &geometry,
                                      Law &,
                                      Moment &moment)
    {
      // The step's buffers, as in pair_kernel() (no increments kept for
      // events, no normals kept for later passes: there are none).
      const unsigned int n_pairs = pi.size();
      const unsigned int n_ahead = prefetch_pairs(n_pairs, n_local);
      if constexpr (Law::stateful)
        pair_mu.resize(n_pairs);
      const PairStep step{step_dt, n_pairs, n_ahead, false, false};
      dsm.assign(n_local, 0);
      side_dq.assign(n_owned, 0);
      WorkSums dw{};
      // The pairs' forces and torques of the step, summed from zero: pass A
      // adds those it knows.
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          f[k]      = {{0, 0, 0}};
          torque[k] = {{0, 0, 0}};
        }
      pair_pass_a_bulk<rot>(step, dw, geometry, moment);
      // The many-body step (pair_kernel()): dsm holds each automaton's
      // many-body part m from here on.
      double mb_work = 0;
      many_body_step(0, n_owned, true, mb_work);
      dw[many_body_work] += mb_work;
      pair_pass_c_bulk<rot>(step, geometry, moment);
      for (unsigned int k = 0; k < n_works; ++k)
        work[k] += dw[k];
    }


    /**
     * The sums of the i side of a run of consecutive pairs of one owned
     * automaton i (the pairs run by i): its force, with @p torques its
     * torque, with @p many_body its volumetric strain increment, held in
     * registers and added to in the order of the pairs, as the arrays were
     * (the compiler cannot do it: it does not know that no j of the run is
     * i). take() stores the sums of the last run and loads those of i;
     * flush() stores them.
     */
    template <bool torques, bool many_body>
    struct ISideSums
    {
      static constexpr unsigned int none = static_cast<unsigned int>(-1);
      unsigned int                  a    = none;
      Vec3                          f{}, t{};
      double                        m = 0;
      void
      take(AutomatonArrays &arrays, const unsigned int i)
      {
        if (i == a)
          return;
        flush(arrays);
        if (!arrays.owned(i))
          return;
        a = i;
        f = arrays.f[i];
        if constexpr (torques)
          t = arrays.torque[i];
        if constexpr (many_body)
          m = arrays.dsm[i];
      }
      void
      flush(AutomatonArrays &arrays)
      {
        if (a == none)
          return;
        arrays.f[a] = f;
        if constexpr (torques)
          arrays.torque[a] = t;
        if constexpr (many_body)
          arrays.dsm[a] = m;
        a = none;
      }
    };


    template <bool rot, class Pairs, class Moment>
    void
    AutomatonSystem::pair_pass_a_bulk(const PairStep &step,
                                      WorkSums       &dw,
                                      const Pairs    &geometry,
                                      Moment         &moment)
    {
      const unsigned int     n_pairs = step.n_pairs, n_ahead = step.n_ahead;
      const double           step_dt = step.dt;
      constexpr unsigned int block   = NormalBlock::size;
      // a block's gathered kinematics and springs, then its increments
      alignas(64) double b_dnew[3][block], b_du[3][block], b_wi[3][block],
        b_wj[3][block], b_k[3][block], b_dq[2][block], b_t[3][block],
        b_tnew[3][block], b_sig[block];
      // the block's forces and torques as far as they are known in pass A
      alignas(64) double b_F[3][block], b_nxf[3][block], b_exf[3][block],
        b_q[2][block];
      // (the normals of the step, for a relative-rotation moment law)
      alignas(64) double b_n[3][block], b_nold[3][block], b_nm[3][block],
        b_K[3][block], b_f[block];
      unsigned int b_type[block];
      // (a scene of one material has one pair of springs)
      const bool one_material = n_materials == 1;
      for (unsigned int p0 = 0; p0 < n_pairs; p0 += block)
        {
          const unsigned int nb = std::min(block, n_pairs - p0);
          // The scattered loads of the block in one loop (pass A).
          for (unsigned int b = 0; b < nb; ++b)
            {
              const unsigned int p = p0 + b, i = pi[p], j = pj[p];
              const Vec3         dnew = pair_vector(p);
              for (unsigned int c = 0; c < 3; ++c)
                {
                  b_dnew[c][b] = dnew[c];
                  b_du[c][b]   = step_dt * (v[j][c] - v[i][c]);
                }
              if constexpr (rot)
                for (unsigned int c = 0; c < 3; ++c)
                  {
                    b_wi[c][b] = w[i][c];
                    b_wj[c][b] = w[j][c];
                  }
              for (unsigned int c = 0; c < 3; ++c)
                b_t[c][b] = tau.component[c][p];
              b_sig[b] = sig_e[p];
              const SeriesSprings &k
                = one_material ? springs[0]
                               : springs[mat[i] * n_materials + mat[j]];
              const double scale = geometry.stiffness_scale(p);
              b_k[0][b]          = k.ki * scale;
              b_k[1][b]          = k.kj * scale;
              b_k[2][b]          = k.inv_sum / scale;
              __builtin_prefetch(&dsm[j], 1);
              __builtin_prefetch(&f[j], 1);
              if constexpr (rot)
                __builtin_prefetch(&torque[j], 1);
              prefetch_streams<1>(p,
                                  n_ahead,
                                  sig_e,
                                  tau.component[0],
                                  tau.component[1],
                                  tau.component[2]);
              prefetch_streams<0>(p, n_ahead, beta_i, beta_j);
              if constexpr (rot)
                prefetch_ahead(pj.data(), p, n_ahead, x, v, w);
              else
                prefetch_ahead(pj.data(), p, n_ahead, x, v);
            }
          // The block's pair law, without a branch: distances, normals,
          // the shear stress turned into the new tangent plane and its
          // increment, the split of the normal increment (pass A).
          for (unsigned int b = 0; b < nb; ++b)
            {
              const unsigned int p  = p0 + b;
              const double       xn = b_dnew[0][b], yn = b_dnew[1][b],
                           zn          = b_dnew[2][b];
              const PairStepGeometry g = pair_step_geometry(
                xn, yn, zn, b_du[0][b], b_du[1][b], b_du[2][b]);
              const double r = g.r, ro = g.ro, inv_r = g.inv_r,
                           inv_ro = g.inv_ro, inv_nm = g.inv_nm;
              double     dr_p = g.dr;
              const Vec3 t    = turned_shear(
                b_t[0][b], b_t[1][b], b_t[2][b], xn, yn, zn, inv_r);
              Vec3 n, nm, du;
              for (unsigned int c = 0; c < 3; ++c)
                {
                  du[c] = b_du[c][b];
                  if constexpr (rot)
                    {
                      n[c]                 = b_dnew[c][b] * inv_r;
                      const double n_old_c = (b_dnew[c][b] - du[c]) * inv_ro;
                      nm[c]                = (n[c] + n_old_c) * inv_nm;
                      if constexpr (Moment::active)
                        {
                          b_n[c][b]    = n[c];
                          b_nold[c][b] = n_old_c;
                          b_nm[c][b]   = nm[c];
                        }
                    }
                  else
                    {
                      n[c]  = b_dnew[c][b] * inv_r;
                      nm[c] = (n[c] + (b_dnew[c][b] - du[c]) * inv_ro) * inv_nm;
                    }
                }
              // equally stiff halves: the moment arms are r/2
              const double qi = 0.5 * ro, qj = ro - qi;
              contact_point_slip<rot>(
                du, dr_p, nm, qi, qj, b_wi, b_wj, b, step_dt, geometry, p);
              // series springs, both shear factors 1
              const double ki = b_k[0][b], kj = b_k[1][b], inv = b_k[2][b];
              const double mix = kj * 1. + ki * 1.;
              for (unsigned int c = 0; c < 3; ++c)
                b_tnew[c][b] = (mix * t[c] + ki * kj * du[c]) * inv;
              // equal elastic increments of the two sides (sig_e)
              const double dqi = kj * dr_p * inv;
              b_dq[0][b]       = dqi;
              b_dq[1][b]       = dr_p - dqi;
              b_sig[b] += ki * dqi;
              // The pair's force but for the sides' many-body parts (pass
              // C adds S (m_i + m_j)/2 n): the common normal stress and the
              // tangential force, at the step's end; the torques of the
              // tangential force, all of them.
              const double Sp = geometry.area(p);
              const double am = 0.5 * Sp * (1. + 1.);
              Vec3         ft, F;
              for (unsigned int c = 0; c < 3; ++c)
                {
                  ft[c]     = am * b_tnew[c][b];
                  F[c]      = Sp * b_sig[b] * n[c] + ft[c];
                  b_F[c][b] = F[c];
                }
              if constexpr (rot)
                {
                  const Vec3 nxf = cross(n, ft);
                  for (unsigned int c = 0; c < 3; ++c)
                    b_nxf[c][b] = nxf[c];
                  b_q[0][b] = 0.5 * r;
                  b_q[1][b] = r - b_q[0][b];
                }
              if constexpr (rot && Pairs::offsets)
                {
                  const Vec3 exf = cross(geometry.offset(p), F);
                  for (unsigned int c = 0; c < 3; ++c)
                    b_exf[c][b] = exf[c];
                }
            }
          // The relative-rotation moment's trial update (pass A).
          if constexpr (rot && Moment::active)
            {
              for (unsigned int b = 0; b < nb; ++b)
                {
                  const unsigned int p = p0 + b;
                  b_type[b]            = mat[pi[p]] * n_materials + mat[pj[p]];
                  b_f[b]               = geometry.moment_scale(p);
                }
              moment.trial_block(p0,
                                 nb,
                                 b_type,
                                 b_f,
                                 b_nold,
                                 b_n,
                                 b_nm,
                                 b_wi,
                                 b_wj,
                                 step_dt,
                                 b_K);
              for (unsigned int b = 0; b < nb; ++b)
                moment.store_trial(p0 + b, b, b_K);
            }
          // The pair by pair part (the loops above read and write only the
          // block's arrays, which the compiler sees cannot alias): the
          // pair's new stresses; the forces and torques; the volumetric
          // strain increments of both sides, and the many-body work of the
          // sides of automata that are not uniform.
          // (The i side of consecutive pairs of one automaton i is summed
          // in registers, in the same order: the pairs run by i.)
          ISideSums<rot, true> si;
          AutomatonArrays     &arrays = *this;
          for (unsigned int b = 0; b < nb; ++b)
            {
              const unsigned int p = p0 + b, i = pi[p], j = pj[p];
              for (unsigned int c = 0; c < 3; ++c)
                tau.component[c][p] = b_tnew[c][b];
              sig_e[p] = b_sig[b];
              Vec3 K;
              if constexpr (Moment::active)
                K = moment.moment(p);
              si.take(arrays, i);
              const double Sp    = geometry.area(p);
              const double scale = geometry.inv_half_rest(p);
              // a side's volumetric strain increment into @p sum (its
              // automaton's), and the many-body work of the side of an
              // automaton that is not uniform
              const auto book_side = [&](const unsigned int a,
                                         const double       beta,
                                         const double       dq,
                                         double            &sum) {
                sum += beta * dq * scale;
                if (beta == 0 || mb_shape[a] == ManyBodyShape::general)
                  [[unlikely]]
                  {
                    side_dq[a] += Sp * dq;
                    dw[many_body_work] += Sp * dq * mb_offset[a];
                  }
              };
              if (si.a == i)
                {
                  for (unsigned int c = 0; c < 3; ++c)
                    si.f[c] += b_F[c][b];
                  if constexpr (rot)
                    for (unsigned int c = 0; c < 3; ++c)
                      si.t[c] += b_q[0][b] * b_nxf[c][b];
                  if constexpr (rot && Pairs::offsets)
                    for (unsigned int c = 0; c < 3; ++c)
                      si.t[c] += b_exf[c][b];
                  if constexpr (Moment::active)
                    for (unsigned int c = 0; c < 3; ++c)
                      si.t[c] += K[c];
                  book_side(i, beta_i[p], b_dq[0][b], si.m);
                }
              if (owned(j))
                {
                  for (unsigned int c = 0; c < 3; ++c)
                    f[j][c] -= b_F[c][b];
                  if constexpr (rot)
                    for (unsigned int c = 0; c < 3; ++c)
                      torque[j][c] += b_q[1][b] * b_nxf[c][b];
                  if constexpr (rot && Pairs::offsets)
                    for (unsigned int c = 0; c < 3; ++c)
                      torque[j][c] -= b_exf[c][b];
                  if constexpr (Moment::active)
                    for (unsigned int c = 0; c < 3; ++c)
                      torque[j][c] -= K[c];
                  book_side(j, beta_j[p], b_dq[1][b], dsm[j]);
                }
            }
          si.flush(arrays);
        }
    }


    template <bool rot, class Pairs, class Moment>
    void
    AutomatonSystem::pair_pass_c_bulk(const PairStep &step,
                                      const Pairs    &geometry,
                                      Moment &)
    {
      // Pass C of the bulk: what pass A could not add, the sides' many-body
      // parts m_i and m_j (many_body_step()) in the pair's normal force
      // S (m_i + m_j)/2 n, and their torques where the contact point is off
      // the line of centres.
      const unsigned int     n_pairs = step.n_pairs, n_ahead = step.n_ahead;
      constexpr unsigned int block = NormalBlock::size;
      alignas(64) double     b_m[2][block], b_F[3][block], b_exf[3][block];
      NormalBlock            nblock;
      auto                   pair_vector_of
        = [this](const unsigned int p) { return pair_vector(p); };
      for (unsigned int p0 = 0; p0 < n_pairs; p0 += block)
        {
          const unsigned int nb = std::min(block, n_pairs - p0);
          nblock.fill(p0, nb, pair_vector_of);
          for (unsigned int b = 0; b < nb; ++b)
            {
              const unsigned int i = pi[p0 + b], j = pj[p0 + b];
              b_m[0][b] = dsm[i];
              b_m[1][b] = dsm[j];
              __builtin_prefetch(&f[j], 1);
              if constexpr (rot && Pairs::offsets)
                __builtin_prefetch(&torque[j], 1);
              prefetch_ahead(pj.data(), p0 + b, n_ahead, x, dsm);
            }
          for (unsigned int b = 0; b < nb; ++b)
            {
              const unsigned int p  = p0 + b;
              const Vec3         n  = nblock.normal(b);
              const double       Sp = geometry.area(p);
              const double       sm = 0.5 * (b_m[0][b] + b_m[1][b]);
              Vec3               F;
              for (unsigned int c = 0; c < 3; ++c)
                {
                  F[c]      = Sp * sm * n[c];
                  b_F[c][b] = F[c];
                }
              if constexpr (rot && Pairs::offsets)
                {
                  const Vec3 exf = cross(geometry.offset(p), F);
                  for (unsigned int c = 0; c < 3; ++c)
                    b_exf[c][b] = exf[c];
                }
            }
          ISideSums<rot && Pairs::offsets, false> si;
          AutomatonArrays                        &arrays = *this;
          for (unsigned int b = 0; b < nb; ++b)
            {
              const unsigned int p = p0 + b, i = pi[p], j = pj[p];
              si.take(arrays, i);
              if (si.a == i)
                {
                  for (unsigned int c = 0; c < 3; ++c)
                    si.f[c] += b_F[c][b];
                  if constexpr (rot && Pairs::offsets)
                    for (unsigned int c = 0; c < 3; ++c)
                      si.t[c] += b_exf[c][b];
                }
              if (owned(j))
                {
                  for (unsigned int c = 0; c < 3; ++c)
                    f[j][c] -= b_F[c][b];
                  if constexpr (rot && Pairs::offsets)
                    for (unsigned int c = 0; c < 3; ++c)
                      torque[j][c] -= b_exf[c][b];
                }
            }
          si.flush(arrays);
        }
    }
  } // namespace mca
} // namespace tribodyn
