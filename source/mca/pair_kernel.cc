// The pair law of the automata (seed eqs. 1-3, design §6): strain
// increments of the pairs, many-body mean-stress increments, pair stresses
// with the plastic correction, contact constraints of unbonded pairs (the
// friction law, include/tribodyn/mca/friction_law.h), the relative-rotation
// moment (moment_laws.h), forces and torques; then bond breaking and
// formation (bond_switching.h, under the criteria of bond_laws.h). The
// kernel is compiled per combination of these policies, chosen once in
// evaluate_pairs() (include/tribodyn/mca/pair_law.h).

#include "bond_switching.h"
#include "pair_blocks.h"
#include "pair_energy.h"
#include "pair_events.h"
#include "pair_geometry.h"
#include "pair_geometry_choice.h"
#include "pair_kinematics.h"
#include "pair_stress.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <tribodyn/mca/automaton_system.h>
#include <tribodyn/mca/pair_law.h>
#include <tribodyn/mca/plasticity.h>
#include <type_traits>

namespace tribodyn
{
  namespace mca
  {
    void
    AutomatonSystem::evaluate_pairs(const double step_dt)
    {
      partition.update_ghost_kinematics();
      // Neighbourhoods that changed at the last step (contacts, bonds).
      if (any_changed)
        update_neighbourhood_weights(false);
      // The kernel for the scene's combination of the pair law's policies
      // (pair_law.h), chosen once here: no per-pair flags in its loops.
      // Adding a law to a family adds its kernels here through the
      // family's list; nothing to change in this function.
      // An elastic bulk (every pair bonded, of one material, equally stiff
      // halves, no plasticity and no bond law: no event can occur) has a
      // kernel of its own (pair_kernel_bulk.cc).
      if (!mb_stored && !q_stored)
        {
          Assert(!plastic_scene && !bond_scene, dealii::ExcInternalError());
          evaluate_bulk_pairs(step_dt);
          return;
        }
      const auto geometry = pair_geometry_choice();
      with_chosen(
        [&](auto        rot,
            auto        plastic,
            const auto &pairs,
            auto       &friction,
            auto       &moment,
            const auto &breaking,
            const auto &formation) {
          using Moment         = std::decay_t<decltype(moment)>;
          using Breaking       = std::decay_t<decltype(breaking)>;
          using Formation      = std::decay_t<decltype(formation)>;
          constexpr bool bonds = Breaking::active || Formation::active;
          // (a moment law that needs rotations is refused without them
          // at set-up: no kernel for that combination)
          if constexpr (decltype(rot)::value || !Moment::needs_rotations)
            {
              pair_kernel<decltype(rot)::value,
                          decltype(plastic)::value,
                          bonds>(step_dt, pairs, friction, moment);
              if constexpr (bonds)
                bond_switching<decltype(plastic)::value>(breaking, formation);
            }
        },
        CompileTimeSwitch{rotations},
        CompileTimeSwitch{plastic_scene},
        geometry,
        friction_laws,
        moment_laws,
        breaking_laws,
        formation_laws);
    }


    template <bool rot,
              bool plastic,
              bool bonds,
              class Pairs,
              class Law,
              class Moment>
    void
    AutomatonSystem::pair_kernel(const double step_dt,
                                 const Pairs &geometry,
                                 Law         &law,
                                 Moment      &moment)
    {
      // The step's buffers.
      const unsigned int n_pairs = pi.size();
      // (the pair count, or 0 in scenes that fit in a core's caches)
      const unsigned int n_ahead = prefetch_pairs(n_pairs, n_local);
      if constexpr (Law::stateful)
        pair_mu.resize(n_pairs);
      // this step's increments of the pairs that can release energy in
      // pass C (pair_events()): none in an elastic bulk of one material, all
      // bonded, where the array stays empty (scans of a byte per pair and
      // per automaton)
      if (plastic || std::find(bonded.begin(), bonded.end(), 0) != bonded.end()
          || std::adjacent_find(mat.begin(), mat.end(), std::not_equal_to<>())
               != mat.end())
        pair_dr.resize(2 * static_cast<std::size_t>(n_pairs));
      // Plastic and bond kernels evaluate the pairs' normals up to three
      // times more (passes B, C and bond switching): pass A keeps them
      // where that is cheaper (keep_pair_normals(); empty otherwise).
      const bool keep_normals
        = (plastic || bonds) && keep_pair_normals(n_pairs);
      step_normals.resize(keep_normals ? 4 * static_cast<std::size_t>(n_pairs)
                                       : 0);
      const PairStep step{
        step_dt, n_pairs, n_ahead, keep_normals, plastic && bonds};
      // The automata's sums of the step: volumetric increments, forces and
      // torques; the trial tensors, the automata with an unbonded contact,
      // whose final tensor pass C of a bond kernel sums anew, and the
      // returns. They start from zero chunk by chunk (clear_sums below).
      dsm.resize(n_local);
      side_dq.resize(n_owned);
      if constexpr (plastic || bonds)
        trial.resize(n_local);
      if constexpr (plastic)
        {
          if (step.anew_tensors)
            stress_anew.resize(n_local);
          plast.resize(static_cast<std::size_t>(n_local) * 2);
          // (bond scenes: each stress s for bond switching, which needs
          // the final one, this one where pass C does not sum the tensor
          // anew)
          if (bond_scene)
            bond_buffer.resize(static_cast<std::size_t>(n_local) * 7);
        }
      const auto clear_sums
        = [&](const unsigned int k_begin, const unsigned int k_end) {
            std::fill(dsm.begin() + k_begin, dsm.begin() + k_end, 0.);
            if constexpr (plastic || bonds)
              std::fill(trial.begin() + k_begin,
                        trial.begin() + k_end,
                        Mat3{{0, 0, 0, 0, 0, 0, 0, 0, 0}});
            if constexpr (plastic)
              {
                if (step.anew_tensors)
                  std::fill(stress_anew.begin() + k_begin,
                            stress_anew.begin() + k_end,
                            0);
                std::fill(plast.begin() + 2 * std::size_t(k_begin),
                          plast.begin() + 2 * std::size_t(k_end),
                          0.);
              }
            for (unsigned int k = k_begin; k < std::min(k_end, n_owned); ++k)
              {
                side_dq[k] = 0;
                f[k]       = {{0, 0, 0}};
                torque[k]  = {{0, 0, 0}};
              }
          };
      clear_sums(n_owned, n_local); // (the ghosts')
      // The works of this step's events (added to work at its end), among
      // them the many-body work (doc/theory/mca.md §8.4): that of the
      // many-body parts of the side stresses over the step, minus the
      // change of the automata's kappa G^2. Pass C's apart, as it runs
      // beside pass A.
      WorkSums dw{}, dw_c{};
      double   mb_work = 0;
      bool     events  = false;

      // The passes as a pipeline over chunks of the pair list
      // (PairList::chunk_for_pipeline()): each automaton's sums in pass A
      // are complete once pass A has done its chunk, so pass B can follow
      // chunk_lag chunks behind it and pass C as far behind pass B; the
      // pairs between the fronts stay in the cache, where three passes over
      // the whole list would each read it from memory. Every pass still
      // visits the pairs in their order, so each automaton's sums are the
      // same as pass by pass, bit for bit. Where a ghost takes part (its
      // values come from the neighbour ranks once every owned automaton is
      // done) the list is one chunk: the passes one after the other.
      // (the chunks are set with the list, index_by_automaton(), and
      // after a checkpoint's lists are read back)
      Assert(n_chunks() > 0 && chunk_pair.back() == n_pairs
               && chunk_automaton.back() == n_owned,
             dealii::ExcInternalError());
      const bool pipelined = this->pipelined();
      // chunk c: pairs pair_at[c] ... pair_at[c + 1], owned automata
      // automaton_at[c] ... automaton_at[c + 1]; one chunk of all of them
      // where the passes run one after the other
      const unsigned int all_pairs[2]    = {0, n_pairs},
                         all_automata[2] = {0, n_owned};
      const unsigned int *pair_at = pipelined ? chunk_pair.data() : all_pairs;
      const unsigned int *automaton_at
        = pipelined ? chunk_automaton.data() : all_automata;
      const unsigned int n_chunks = pipelined ? this->n_chunks() : 1;
      const unsigned int lag      = pipelined ? chunk_lag : 0;
      // The owned automata's sums start from zero just ahead of pass A,
      // which adds to automata up to lag chunks ahead of its own (the
      // passes after it add to no automaton beyond): each sum's lines are
      // then in the cache when it starts, rather than swept out of it by
      // one clearing of all of them before the passes.
      unsigned int cleared = 0;
      for (unsigned int t = 0; t < n_chunks + 2 * lag; ++t)
        {
          for (; cleared < n_chunks && cleared <= t + lag; ++cleared)
            clear_sums(automaton_at[cleared], automaton_at[cleared + 1]);
          if (t < n_chunks)
            {
              pair_pass_a<rot, plastic>(
                step, pair_at[t], pair_at[t + 1], dw, geometry, law, moment);
              // Mean-stress increment of each automaton: K times its
              // volumetric strain increment, the trace of the strain tensor
              // fitted (least squares) to its pairs' normal strains: dtheta
              // = sum_j beta_ij deps_ij (beta = 1/4 in a complete FCC
              // neighbourhood). With it, in the same pass over the owned
              // automata, the many-body work of the step and their new mu
              // (pair_energy.cc); the ghosts' mu from their owners'
              // increments.
              many_body_step(automaton_at[t],
                             automaton_at[t + 1],
                             t + 1 == n_chunks,
                             mb_work);
            }
          // (where the pairs store their common part only, dsm holds each
          // automaton's many-body part m from here on: PairArrays::sig_e)
          if constexpr (plastic)
            if (t >= lag && t - lag < n_chunks)
              {
                const unsigned int c = t - lag;
                pair_pass_b(step, pair_at[c], pair_at[c + 1]);
                radial_returns(automaton_at[c],
                               automaton_at[c + 1],
                               c + 1 == n_chunks);
                if constexpr (bonds)
                  final_tensors_anew(automaton_at[c], automaton_at[c + 1]);
              }
          if (t >= 2 * lag && t - 2 * lag < n_chunks)
            {
              const unsigned int c = t - 2 * lag;
              if (pair_pass_c<rot, plastic, bonds>(step,
                                                   pair_at[c],
                                                   pair_at[c + 1],
                                                   dw_c,
                                                   geometry,
                                                   law,
                                                   moment))
                events = true;
            }
        }
      Assert(mb_stored || !plastic, dealii::ExcInternalError());
      dw[many_body_work] += mb_work;

      for (unsigned int k = 0; k < n_works; ++k)
        work[k] += dw[k] + dw_c[k];
      // the uniform automata whose shape an event ended (lambda = 0)
      if (plastic || events)
        sync_many_body_shapes();
    }


    template <bool rot, bool plastic, class Pairs, class Law, class Moment>
    void
    AutomatonSystem::pair_pass_a(const PairStep    &step,
                                 const unsigned int p_begin,
                                 const unsigned int p_end,
                                 WorkSums          &dw,
                                 const Pairs       &geometry,
                                 Law               &law,
                                 Moment            &moment)
    {
      const unsigned int n_pairs = step.n_pairs, n_ahead = step.n_ahead;
      const bool         keep_normals = step.keep_normals;
      const double       step_dt      = step.dt;
      // (the shear factors: all 1 and not stored until the scene can have
      // an event, allocate_side_states(); plastic kernels always store
      // them and read them as before)
      const bool factors = plastic || shear_factors;
      // Contact and bond changes of this step mark both automata.
      auto mark = [&](const unsigned int p) {
        changed[pi[p]] = 1;
        changed[pj[p]] = 1;
        any_changed    = true;
      };

      // Pass A: geometry, tangential stresses, split of the normal
      // increment, volumetric strain increments of both sides. The pairs
      // go in blocks: the square roots and divisions of a block (the
      // dearest operations of the pass) run in one branch-free loop that
      // the compiler vectorizes; the branchy pair law then reads them.
      constexpr unsigned int block = NormalBlock::size;
      alignas(64) double     b_dnew[3][block], b_du[3][block];
      alignas(64) double     b_r[block], b_ro[block], b_inv_r[block],
        b_inv_ro[block], b_inv_nm[block], b_dr[block], b_t[3][block],
        b_wi[3][block], b_wj[3][block], b_n[3][block], b_nold[3][block];
      // (a relative-rotation moment law's trial moments of the block, from
      // the mid-step normals; the pairs' materials and size factors)
      alignas(64) double b_nm[3][block], b_K[3][block], b_f[block];
      unsigned int       b_type[block];
      for (unsigned int p0 = p_begin; p0 < p_end; p0 += block)
        {
          const unsigned int nb = std::min(block, p_end - p0);
          for (unsigned int b = 0; b < nb; ++b)
            {
              const unsigned int p = p0 + b, i = pi[p], j = pj[p];
              const Vec3         dnew = pair_vector(p);
              // relative displacement of the step, dt (v_j - v_i): the
              // drift moved each automaton by dt v; one product of the
              // difference keeps a rigid motion exactly rigid (also with
              // FMA contraction)
              for (unsigned int c = 0; c < 3; ++c)
                {
                  b_dnew[c][b] = dnew[c];
                  b_du[c][b]   = step_dt * (v[j][c] - v[i][c]);
                }
              // (the scattered loads of the block in one loop, where the
              // processor overlaps their cache misses)
              if constexpr (rot)
                for (unsigned int c = 0; c < 3; ++c)
                  {
                    b_wi[c][b] = w[i][c];
                    b_wj[c][b] = w[j][c];
                  }
              if constexpr (Moment::active)
                {
                  b_type[b] = mat[i] * n_materials + mat[j];
                  b_f[b]    = geometry.moment_scale(p);
                }
              __builtin_prefetch(&dsm[j], 1);
              // (and those of the block after next, and the pair arrays
              // further on: pair_blocks.h)
              prefetch_streams<1>(p,
                                  n_ahead,
                                  sig_i,
                                  sig_j,
                                  sig_e,
                                  q_i,
                                  tau.component[0],
                                  tau.component[1],
                                  tau.component[2]);
              if (factors)
                prefetch_streams<0>(p, n_ahead, tau_scale_i, tau_scale_j);
              prefetch_streams<0>(p, n_ahead, beta_i, beta_j);
              if constexpr (rot)
                prefetch_ahead(pj.data(), p, n_ahead, x, v, w);
              else
                prefetch_ahead(pj.data(), p, n_ahead, x, v);
            }
          for (unsigned int b = 0; b < nb; ++b)
            {
              const double xn = b_dnew[0][b], yn = b_dnew[1][b],
                           zn          = b_dnew[2][b];
              const PairStepGeometry g = pair_step_geometry(
                xn, yn, zn, b_du[0][b], b_du[1][b], b_du[2][b]);
              b_r[b]       = g.r;
              b_ro[b]      = g.ro;
              b_inv_r[b]   = g.inv_r;
              b_inv_ro[b]  = g.inv_ro;
              b_inv_nm[b]  = g.inv_nm;
              b_dr[b]      = g.dr;
              const Vec3 t = turned_shear(tau.component[0][p0 + b],
                                          tau.component[1][p0 + b],
                                          tau.component[2][p0 + b],
                                          xn,
                                          yn,
                                          zn,
                                          g.inv_r);
              for (unsigned int c = 0; c < 3; ++c)
                b_t[c][b] = t[c];
            }
          // Kernels with rotations: the normals n and n_old of the step
          // (the moment law turns with them), each rounded on its own, and
          // the mid-step normal from them. (The kernels without rotations
          // contract one product into the sum instead: both as before the
          // moment laws became policies, bit for bit.)
          if constexpr (rot)
            for (unsigned int b = 0; b < nb; ++b)
              for (unsigned int c = 0; c < 3; ++c)
                {
                  b_n[c][b]    = b_dnew[c][b] * b_inv_r[b];
                  b_nold[c][b] = (b_dnew[c][b] - b_du[c][b]) * b_inv_ro[b];
                }
          // The relative-rotation moment's trial update of the block
          // (moment_laws.h), in one vectorized loop; the pairs that stay in
          // contact keep it below, and pass C limits it and adds its
          // torques.
          if constexpr (Moment::active)
            {
              for (unsigned int b = 0; b < nb; ++b)
                for (unsigned int c = 0; c < 3; ++c)
                  b_nm[c][b] = (b_n[c][b] + b_nold[c][b]) * b_inv_nm[b];
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
            }
          for (unsigned int b = 0; b < nb; ++b)
            {
              const unsigned int p = p0 + b, i = pi[p], j = pj[p];
              const double       r = b_r[b], ro = b_ro[b];
              Vec3               n, nm, du;
              for (unsigned int c = 0; c < 3; ++c)
                {
                  du[c] = b_du[c][b];
                  if constexpr (rot)
                    {
                      n[c]  = b_n[c][b];
                      nm[c] = (n[c] + b_nold[c][b]) * b_inv_nm[b];
                    }
                  else
                    {
                      n[c]  = b_dnew[c][b] * b_inv_r[b];
                      nm[c] = (n[c] + (b_dnew[c][b] - du[c]) * b_inv_ro[b])
                              * b_inv_nm[b];
                    }
                }
              if (keep_normals)
                NormalBlock::keep_normal(step_normals, n_pairs, p, r, n);
              double               dr_p = b_dr[b], r_prev = ro;
              const SeriesSprings &k = springs[mat[i] * n_materials + mat[j]];
              const double         scale   = geometry.stiffness_scale(p);
              const double         ki      = k.ki * scale;
              const double         kj      = k.kj * scale;
              const double         inv_sum = k.inv_sum / scale;

              if (!bonded[p])
                {
                  const double touch = geometry.contact_distance(p);
                  // (an unbonded pair: its scene stores the sides)
                  Assert(mb_stored, dealii::ExcInternalError());
                  if (r >= touch)
                    {
                      // separated: no interaction; the energy of a contact
                      // that opens (or of a bond broken beyond the contact
                      // distance at the last step) is released
                      if (in_contact[p] || sig_i[p] != 0 || sig_j[p] != 0
                          || b_t[0][b] != 0 || b_t[1][b] != 0 || b_t[2][b] != 0)
                        {
                          release_opening(p, b_dr[b]);
                          if constexpr (Moment::active)
                            if (owned(i))
                              {
                                Vec3 n_new;
                                for (unsigned int c = 0; c < 3; ++c)
                                  n_new[c] = b_dnew[c][b] * b_inv_r[b];
                                dw[switching_work]
                                  += moment.energy(p,
                                                   mat[i] * n_materials
                                                     + mat[j],
                                                   n_new,
                                                   geometry.moment_scale(p));
                              }
                        }
                      if (in_contact[p])
                        mark(p);
                      in_contact[p] = 0;
                      sig_i[p] = sig_j[p] = 0;
                      tau.set(p, {{0, 0, 0}});
                      if (factors
                          && (tau_scale_i[p] != 1 || tau_scale_j[p] != 1))
                        tau_scale_i[p] = tau_scale_j[p] = 1;
                      if (q_stored)
                        q_i[p] = r / 2;
                      if constexpr (Moment::active)
                        moment.separate(p);
                      continue;
                    }
                  if (!in_contact[p])
                    {
                      // touching now: only the overlap counts, from r = d
                      in_contact[p] = 1;
                      mark(p);
                      law.start_contact(p);
                      // many-body parts from zero (a pair that holds no
                      // stress); its sides are not weighted yet (the
                      // weights follow at the next step), so no uniform
                      // automaton changes
                      Assert(beta_i[p] == 0 && beta_j[p] == 0,
                             dealii::ExcInternalError());
                      // (an unbonded pair: its scene stores the offsets)
                      Assert(mb_stored, dealii::ExcInternalError());
                      if (sig_i[p] == 0 && sig_j[p] == 0)
                        {
                          mb_i[p] = -mc[mat[i]].D * mb_mu[i];
                          mb_j[p] = -mc[mat[j]].D * mb_mu[j];
                        }
                      if (q_stored)
                        q_i[p] = touch / 2;
                      r_prev = touch;
                      dr_p   = r - touch;
                    }
                }
              const double qi = moment_arm(p, r_prev, 0), qj = r_prev - qi;

              // Relative-rotation moment K_ij: the pair keeps its trial
              // moment (above).
              if constexpr (Moment::active)
                moment.store_trial(p, b, b_K);

              // Tangential: relative displacement of the contact points
              // (graded: the contact point is the face centroid, off the
              // line of centres; the work of the torques e x F below).
              contact_point_slip<rot>(
                du, dr_p, nm, qi, qj, b_wi, b_wj, b, step_dt, geometry, p);
              // a rate-dependent friction law: the contact's state over
              // the step at its slip rate, the relative tangential speed
              // of the contact points
              if constexpr (Law::stateful)
                if (!bonded[p])
                  pair_mu[p]
                    = law.advance(p, std::sqrt(dot(du, du)) / step_dt, step_dt);
              const Vec3   t{{b_t[0][b], b_t[1][b], b_t[2][b]}};
              const double Sp = geometry.area(p);
              {
                // series springs of the two halves: one shear stress
                // (kj tau_i + ki tau_j + ki kj du) / (ki + kj)
                const double inv = inv_sum;
                const double ai  = factors ? tau_scale_i[p] : 1.,
                             aj  = factors ? tau_scale_j[p] : 1.;
                const double mix = kj * ai + ki * aj;
                Vec3         tn;
                for (unsigned int c = 0; c < 3; ++c)
                  tn[c] = (mix * t[c] + ki * kj * du[c]) * inv;
                tau.set(p, tn);
                // (both factors 1 after pass A: passes B and C assume it;
                // a line of factors already 1 is not written again)
                if (ai != 1 || aj != 1)
                  tau_scale_i[p] = tau_scale_j[p] = 1;
                // sides of other shear stresses (a limit or a return at
                // the last step) made equal: the energy lost, half on each
                // side, is plastic work of a bond, friction work of a
                // contact
                if (ai != aj) [[unlikely]]
                  {
                    const double lost
                      = 0.5
                        * pair_energy::shear_mixing(Sp, inv, ai, aj, dot(t, t));
                    // (constant indices keep dw in registers)
                    if (bonded[p])
                      dw[plastic_work] += (owned(i) + owned(j)) * lost;
                    else
                      {
                        dw[friction_work] += (owned(i) + owned(j)) * lost;
                        dw[friction_work_law] += (owned(i) + owned(j)) * lost;
                      }
                  }
                // this step's increments, for the releases of pass C
                if (plastic || !bonded[p] || mat[i] != mat[j]) [[unlikely]]
                  {
                    pair_dr[2 * p]     = dr_p;
                    pair_dr[2 * p + 1] = dot(tn, du);
                  }
              }
              // Normal split: equal elastic increments 2G de from both sides
              // (series springs), applied now; the many-body parts D dsm of the
              // two sides differ (added once dsm is known) and the force uses
              // the mean of the two sides.
              const double dqi = kj * dr_p * inv_sum;
              if (q_stored)
                q_i[p] = qi + dqi;
              if (plastic || mb_stored)
                {
                  sig_i[p] += ki * dqi;
                  sig_j[p] += kj * (dr_p - dqi);
                }
              else
                // (equal halves of a bonded pair of one material: the two
                // sides' elastic increments are the same, ki = kj and dqi
                // = dr / 2 but for round-off; PairArrays::sig_e)
                sig_e[p] += ki * dqi;
              // (and the many-body work of the sides' parts m = D mu + c:
              // that of their offsets c here, S c dq; that of D mu from the
              // sums S dq of each automaton; none of the weighted sides of
              // a uniform automaton, update_many_body_state())
              const auto book_side = [&](const unsigned int         a,
                                         const std::vector<double> &beta_s,
                                         const double               dq,
                                         const std::vector<double> &mb_s,
                                         const unsigned int         mb_k) {
                if (!owned(a))
                  return;
                const double beta = beta_s[p];
                dsm[a] += beta * dq * geometry.inv_half_rest(p);
                if (beta == 0 || mb_shape[a] == ManyBodyShape::general)
                  [[unlikely]]
                  {
                    side_dq[a] += Sp * dq;
                    dw[many_body_work] += Sp * dq * mb_s[mb_k];
                  }
              };
              // (the sides' offsets: the pair's own, which plastic scenes
              // always store, or their automata's while the pairs store
              // none)
              const bool own = plastic || mb_stored;
              book_side(i, beta_i, dqi, own ? mb_i : mb_offset, own ? p : i);
              book_side(
                j, beta_j, dr_p - dqi, own ? mb_j : mb_offset, own ? p : j);
            }
        }
    }


    void
    AutomatonSystem::pair_pass_b(const PairStep    &step,
                                 const unsigned int p_begin,
                                 const unsigned int p_end)
    {
      // Pass B (plastic scenes): trial side stresses and trial tensors.
      const unsigned int     n_pairs = step.n_pairs, n_ahead = step.n_ahead;
      constexpr unsigned int block = NormalBlock::size;
      NormalBlock            nblock;
      auto                   pair_vector_of
        = [this](const unsigned int p) { return pair_vector(p); };
      // (the tensors and flags start from zero: pair_kernel())
      // The trial tensor T^a += (q S / V_a) n (x) (sigma n + tau) of seed
      // eq. (4) for each owned side outside elastic regions (which need
      // no trial stress); both shear factors are 1 after pass A. The i
      // side of consecutive pairs of one automaton is summed in registers,
      // from its tensor as the run starts and in the pairs' order: the
      // same sums as term by term (no pair of the run adds to i as its j).
      Mat3               ti{};
      constexpr unsigned none  = static_cast<unsigned int>(-1);
      unsigned int       ti_of = none, run_of = none;
      for (unsigned int p0 = p_begin; p0 < p_end; p0 += block)
        {
          const unsigned int nb = std::min(block, p_end - p0);
          nblock.fill(p0, nb, step_normals, n_pairs, pair_vector_of);
          for (unsigned int b = 0; b < nb; ++b)
            {
              const unsigned int p = p0 + b;
              prefetch_ahead(pj.data(), p, n_ahead, x, dsm);
              if (!bonded[p] && !in_contact[p])
                continue;
              const unsigned int i = pi[p], j = pj[p];
              Assert(tau_scale_i[p] == 1 && tau_scale_j[p] == 1,
                     dealii::ExcInternalError());
              if (step.anew_tensors && !bonded[p])
                stress_anew[i] = stress_anew[j] = 1;
              // many-body part of the elastic update of the side stresses
              sig_i[p] += mc[mat[i]].D * dsm[i];
              sig_j[p] += mc[mat[j]].D * dsm[j];
              const Vec3   n = nblock.normal(b);
              const double r = nblock.r[b];
              if (i != run_of)
                {
                  if (ti_of != none)
                    trial[ti_of] = ti;
                  run_of = i;
                  ti_of  = owned(i) && !elastic(i) ? i : none;
                  if (ti_of != none)
                    ti = trial[i];
                }
              if (ti_of != none)
                add_side_stress(ti, p, 0, i, sig_i[p], 1., r, n);
              if (owned(j) && !elastic(j))
                add_side_stress(trial[j], p, 1, j, sig_j[p], 1., r, n);
            }
        }
      if (ti_of != none)
        trial[ti_of] = ti;
    }


    namespace
    {
      /// The dissipation V sigma_y,mid d eps_p of the flow rule of an
      /// automaton of stress @p s (mean stress @p sm), over the share of it
      /// its sides hold.
      double
      flow_rule_work(const Sym3  &inverse_fabric,
                     const Sym3  &s,
                     const double sm,
                     const double volume,
                     const double sy_old,
                     const double sy_new,
                     const double de)
      {
        const Sym3 dev{{s[0] - sm, s[1] - sm, s[2] - sm, s[3], s[4], s[5]}};
        return volume * 0.5 * (sy_old + sy_new) * de
               * sides_energy_share(inverse_fabric, dev);
      }
    } // namespace


    void
    AutomatonSystem::radial_returns(const unsigned int k_begin,
                                    const unsigned int k_end,
                                    const bool         last)
    {
      // The radial return of each owned automaton from its trial tensor
      // (pass B): the mean stress sigma_m and the factor M of its sides.
      // (the plastic work is what the sides release, pass C; plast and
      // the bond scenes' stresses sized by pair_kernel())
      for (unsigned int k = k_begin; k < k_end; ++k)
        {
          if (elastic(k))
            {
              plast[2 * k + 1] = 1; // M = 1: no plastic correction
              continue;
            }
          const auto  &m  = mc[mat[k]];
          const Sym3   s  = fabric_corrected(k, trial[k]);
          const double sm = (s[0] + s[1] + s[2]) / 3;
          const double q  = von_mises(s);
          double       M  = 1;
          if (m.m.is_plastic() && q > sigma_y[k])
            {
              const double de     = plastic_increment(m.m, m.G, eps_p[k], q);
              const double sy_new = m.m.yield_stress_at(eps_p[k] + de);
              M = sy_new / q * verification::radial_return_factor;
              // the dissipation of the flow rule, apart from what the
              // sides release (the physical balance, §8.4)
              work[plastic_work_flow_rule]
                += flow_rule_work(fabric_inverse[k],
                                  s,
                                  sm,
                                  automaton_volume(*this, k),
                                  sigma_y[k],
                                  sy_new,
                                  de);
              eps_p[k] += de;
              sigma_y[k] = sy_new;
            }
          plast[2 * k]     = sm;
          plast[2 * k + 1] = M;
          if (bond_scene)
            std::copy_n(s.begin(), 6, &bond_buffer[7 * k]);
        }
      // (the ghosts' from their owners, once every owned one is done)
      if (last && partition.neighbours().active())
        partition.neighbours().update(plast.data(), 2);
    }


    void
    AutomatonSystem::final_tensors_anew(const unsigned int k_begin,
                                        const unsigned int k_end)
    {
      // A plastic bond kernel's pass C sums anew only the final tensors
      // of the automata whose sides it can change: a side changes in pass C
      // only by its automaton's plastic return (M < 1) or the constraints
      // of an unbonded contact (pair_events()); every other automaton's
      // final tensor is pass B's trial one, the same terms of the same
      // stresses in the same order, bit for bit (and an elastic region's,
      // which pass B skips, is summed as before).
      for (unsigned int k = k_begin; k < k_end; ++k)
        if (stress_anew[k] || plast[2 * k + 1] < 1 || elastic(k))
          {
            stress_anew[k] = 1;
            trial[k]       = Mat3{{0, 0, 0, 0, 0, 0, 0, 0, 0}};
          }
    }


    template <bool rot,
              bool plastic,
              bool bonds,
              class Pairs,
              class Law,
              class Moment>
    bool
    AutomatonSystem::pair_pass_c(const PairStep    &step,
                                 const unsigned int p_begin,
                                 const unsigned int p_end,
                                 WorkSums          &dw,
                                 const Pairs       &geometry,
                                 Law               &law,
                                 Moment            &moment)
    {
      const unsigned int     n_pairs = step.n_pairs, n_ahead = step.n_ahead;
      constexpr unsigned int block = NormalBlock::size;
      alignas(64) double     b_dsm_i[block], b_dsm_j[block];
      // radius of the circular contact face of area S (moment limits)
      const double face_radius = std::sqrt(S / M_PI);
      // (an elastic kernel's events in a call of their own: an elastic
      // bulk has none, and its hot loop keeps its registers)
      bool       events_out_of_line_called = false;
      const auto events_out_of_line
        = [&](const unsigned int p, const Vec3 &t, double &ai, double &aj)
          __attribute__((noinline))
      {
        events_out_of_line_called = true;
        pair_events<plastic>(p, geometry, law, t, ai, aj, dw);
      };
      NormalBlock nblock;
      auto        pair_vector_of
        = [this](const unsigned int p) { return pair_vector(p); };

      // Pass C: plastic correction, contact constraints, forces, torques;
      // in bond scenes also the final stress tensors (T of eq. 4) of the
      // owned automata, which the bond criteria need (those a plastic
      // kernel sums anew: final_tensors_anew(); an elastic kernel's all,
      // from zero: pair_kernel()).
      // (blocks as in pass A: normals of a block in one vectorized loop).
      for (unsigned int p0 = p_begin; p0 < p_end; p0 += block)
        {
          const unsigned int nb = std::min(block, p_end - p0);
          nblock.fill(p0, nb, step_normals, n_pairs, pair_vector_of);
          for (unsigned int b = 0; b < nb; ++b)
            {
              // scattered loads of the block together (see pass A)
              const unsigned int i = pi[p0 + b], j = pj[p0 + b];
              if constexpr (!plastic)
                {
                  // D dsm, or the sides' many-body parts m where the pairs
                  // store their common part only (see above)
                  b_dsm_i[b] = mb_stored ? mc[mat[i]].D * dsm[i] : dsm[i];
                  b_dsm_j[b] = mb_stored ? mc[mat[j]].D * dsm[j] : dsm[j];
                }
              __builtin_prefetch(&f[j], 1);
              if constexpr (rot)
                __builtin_prefetch(&torque[j], 1);
              prefetch_ahead(pj.data(), p0 + b, n_ahead, x, dsm);
            }
          for (unsigned int b = 0; b < nb; ++b)
            {
              const unsigned int p = p0 + b;
              if (!bonded[p] && !in_contact[p])
                continue;
              const unsigned int i = pi[p], j = pj[p];
              const double       r  = nblock.r[b];
              const Vec3         n  = nblock.normal(b);
              const double       qi = moment_arm(p, r, 0), qj = r - qi;
              const double       Sp = geometry.area(p);
              const Vec3         t  = tau[p];
              // (pass A set both shear factors to 1)
              double ai = 1, aj = 1;
              if constexpr (!plastic)
                if (mb_stored)
                  {
                    // many-body part of the elastic update (gathered above)
                    sig_i[p] += b_dsm_i[b];
                    sig_j[p] += b_dsm_j[b];
                  }
              // The events of the step (pair_events.h); an elastic kernel
              // calls them for the pairs that can have some (an elastic
              // bulk has none: bonded pairs of one material).
              if constexpr (plastic)
                pair_events<plastic>(p, geometry, law, t, ai, aj, dw);
              else if (!bonded[p] || mat[i] != mat[j])
                events_out_of_line(p, t, ai, aj);
              if (ai != 1 || aj != 1)
                {
                  Assert(shear_factors, dealii::ExcInternalError());
                  tau_scale_i[p] = ai;
                  tau_scale_j[p] = aj;
                }
              // (where the pairs store their common part only, the mean
              // of the sides sig_e + m_i and sig_e + m_j: no event above,
              // bonded pairs of one material)
              const double sn = plastic || mb_stored
                                  ? 0.5 * (sig_i[p] + sig_j[p])
                                  : sig_e[p] + 0.5 * (b_dsm_i[b] + b_dsm_j[b]);
              const double am = 0.5 * Sp * (ai + aj);
              Vec3         ft, F;
              for (unsigned int c = 0; c < 3; ++c)
                {
                  ft[c] = am * t[c];
                  F[c]  = Sp * sn * n[c] + ft[c];
                }
              Vec3 nxf, exf;
              if constexpr (rot)
                nxf = cross(n, ft);
              if constexpr (rot && Pairs::offsets)
                exf = cross(geometry.offset(p), F);
              if (owned(i))
                {
                  for (unsigned int c = 0; c < 3; ++c)
                    f[i][c] += F[c];
                  if constexpr (rot)
                    for (unsigned int c = 0; c < 3; ++c)
                      torque[i][c] += qi * nxf[c];
                  if constexpr (rot && Pairs::offsets)
                    for (unsigned int c = 0; c < 3; ++c)
                      torque[i][c] += exf[c];
                }
              if (owned(j))
                {
                  for (unsigned int c = 0; c < 3; ++c)
                    f[j][c] -= F[c];
                  if constexpr (rot)
                    for (unsigned int c = 0; c < 3; ++c)
                      torque[j][c] += qj * nxf[c];
                  if constexpr (rot && Pairs::offsets)
                    for (unsigned int c = 0; c < 3; ++c)
                      torque[j][c] -= exf[c];
                }
              // Relative-rotation moment K_ij: an unbonded contact's limit
              // from its final normal stress (the slip work is friction
              // work, counted by side i's owner), and its torques.
              if constexpr (Moment::active)
                {
                  Vec3 K;
                  if (bonded[p])
                    K = moment.moment(p);
                  else
                    {
                      // (the face of a pair of other size: its own radius)
                      double radius = face_radius;
                      if constexpr (Pairs::offsets)
                        radius = std::sqrt(geometry.area(p) / M_PI);
                      const double slip_work
                        = moment.limit_unbonded(p,
                                                mat[i] * n_materials + mat[j],
                                                n,
                                                -Sp * sn,
                                                friction_coefficient(law, p),
                                                radius,
                                                geometry.moment_scale(p),
                                                K);
                      if (owned(i))
                        {
                          dw[friction_work] += slip_work;
                          dw[friction_work_law] += slip_work;
                        }
                    }
                  if (owned(i))
                    for (unsigned int c = 0; c < 3; ++c)
                      torque[i][c] += K[c];
                  if (owned(j))
                    for (unsigned int c = 0; c < 3; ++c)
                      torque[j][c] -= K[c];
                }
              // the final stress tensors, for the bond criteria
              if constexpr (bonds)
                add_pair_stress(p,
                                n,
                                r,
                                trial,
                                false,
                                plastic ? stress_anew.data() : nullptr);
            }
        }
      return events_out_of_line_called;
    }


  } // namespace mca
} // namespace tribodyn
