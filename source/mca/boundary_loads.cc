// The boundary groups at work on the automata (BoundaryLoads): kinematic
// constraints (fixed, prescribed velocity), loads (rigid loading plates)
// and damping layers, with smooth ramps and switches; the half kick with
// its works; the group reductions reported to the observers.

#include <algorithm>
#include <array>
#include <cmath>
#include <tribodyn/mca/boundary_loads.h>
#include <tribodyn/mca/vector_algebra.h>
#include <type_traits>

namespace tribodyn
{
  namespace mca
  {
    BoundaryLoads::BoundaryLoads(const BoundaryParameters &parameters,
                                 const MPI_Comm            comm,
                                 AutomatonArrays          &automata,
                                 const SystemScalars      &scalars)
        : prm(parameters)
        , comm(comm)
        , automata(automata)
        , scalars(scalars)
    {
    }


    void
    BoundaryLoads::count_members()
    {
      wait_for_contact = false;
      damping_on       = prm.global_damping > 0;
      for (const auto &g : prm.groups)
        {
          wait_for_contact = wait_for_contact || g.switch_on_contact;
          damping_on = damping_on || g.type == BoundaryGroup::Type::damping;
        }

      // Group sizes are fixed: automata never change group.
      const unsigned int n_groups = prm.groups.size();
      group_size.assign(n_groups, 0);
      for (unsigned int k = 0; k < automata.n_owned; ++k)
        for (unsigned int gi = 0; gi < n_groups; ++gi)
          if (automata.groups[k] & (1u << gi))
            ++group_size[gi];
      dealii::Utilities::MPI::sum(group_size, comm, group_size);
      st.group_displacement.assign(n_groups, Vec3{{0, 0, 0}});
    }


    double
    BoundaryLoads::ramp(const double t) const
    {
      const double T = prm.ramp_time;
      if (T <= 0 || t >= T)
        return 1;
      if (t <= 0)
        return 0;
      const double s = t / T;
      return s * s * (3 - 2 * s);
    }


    Vec3
    BoundaryLoads::value(const BoundaryGroup &g, const double t) const
    {
      const bool   damping = g.type == BoundaryGroup::Type::damping;
      const double ts      = !g.switch_on_contact ? g.switch_time
                             : st.first_contact_time < 0
                               ? -1
                               : st.first_contact_time + g.switch_time;
      Vec3         out;
      if (ts < 0 || t <= ts)
        {
          for (unsigned int c = 0; c < 3; ++c)
            out[c] = g.value[c] * (damping ? 1 : ramp(t));
          return out;
        }
      // Blend from the value reached at the switch to the second value; a
      // component free after the switch ('*', NaN) is released at once.
      const double s  = ramp(t - ts);
      const double r0 = damping ? 1 : ramp(ts);
      for (unsigned int c = 0; c < 3; ++c)
        out[c] = std::isnan(g.second_value[c])
                   ? g.second_value[c]
                   : (1 - s) * r0 * g.value[c] + s * g.second_value[c];
      return out;
    }


    /**
     * The fixed and prescribed velocities at one time, prepared once and
     * applied automaton by automaton (apply_constraints(), and
     * kick_kick_drift() between its kicks): the kinetic energy a
     * constraint adds or removes is work of the loads (the loading
     * machine), recorded for the energy balance.
     */
    struct BoundaryLoads::Constraints
    {
      Constraints(const BoundaryLoads &loads, const double t)
          : loads(loads)
          , active(!loads.prm.groups.empty())
      {
        if (!active)
          return;
        values.resize(loads.prm.groups.size());
        for (unsigned int gi = 0; gi < values.size(); ++gi)
          values[gi] = loads.value(loads.prm.groups[gi], t);
      }

      /// Owned automaton @p k's constrained velocity components set.
      [[gnu::always_inline]] void
      apply(const unsigned int k)
      {
        AutomatonArrays &automata = loads.automata;
        if (automata.groups[k] == 0)
          return;
        const auto  &grp    = loads.prm.groups;
        const double before = dot(automata.v[k], automata.v[k]);
        bool         set    = false;
        for (unsigned int gi = 0; gi < grp.size(); ++gi)
          if (automata.groups[k] & (1u << gi))
            {
              if (grp[gi].type == BoundaryGroup::Type::fixed)
                {
                  automata.v[k] = {{0, 0, 0}};
                  set           = true;
                }
              else if (grp[gi].type == BoundaryGroup::Type::velocity)
                for (unsigned int c = 0; c < 3; ++c)
                  if (!std::isnan(values[gi][c]))
                    {
                      automata.v[k][c] = values[gi][c];
                      set              = true;
                    }
            }
        if (set)
          kick_work += 0.5 * loads.scalars.automaton_mass(automata, k)
                       * (dot(automata.v[k], automata.v[k]) - before);
      }

      /// The load work of the automata constrained so far into @p work.
      void
      book(WorkSums &work) const
      {
        if (active)
          work[load_work] += kick_work;
      }

      const BoundaryLoads &loads;
      const bool           active;
      std::vector<Vec3>    values;
      double               kick_work = 0;
    };


    void
    BoundaryLoads::apply_constraints(const double t, WorkSums &work)
    {
      Constraints constraints(*this, t);
      if (!constraints.active)
        return;
      for (unsigned int k = 0; k < automata.n_owned; ++k)
        constraints.apply(k);
      constraints.book(work);
    }


    Vec3
    BoundaryLoads::damping_force(const unsigned int       k,
                                 const std::vector<Vec3> &values) const
    {
      const auto  &grp  = prm.groups;
      const double mass = scalars.automaton_mass(automata, k);
      Vec3         fd{{0, 0, 0}};
      for (unsigned int c = 0; c < 3; ++c)
        fd[c] = -prm.global_damping * mass * automata.v[k][c];
      if (automata.groups[k] != 0)
        for (unsigned int gi = 0; gi < grp.size(); ++gi)
          if ((automata.groups[k] & (1u << gi))
              && grp[gi].type == BoundaryGroup::Type::damping)
            for (unsigned int c = 0; c < 3; ++c)
              fd[c] -= values[gi][c] * mass * automata.v[k][c];
      return fd;
    }


    /**
     * Velocity Verlet's half kick v += dt/2 F/m (and of the rotations) at
     * the time of the system, prepared once and given automaton by
     * automaton (half_kick(), and kick_kick_drift() twice), with its work.
     *
     * The kick changes the kinetic energy by exactly dt/2 F.(v_before +
     * v_after)/2: that is credited to the damping (st.f_damp), the applied
     * forces of the force groups and the pair forces and torques (the rest
     * of f), so that kinetic energy = pair + load - damped work holds to
     * round-off (energy test). A loading plate's redistribution of its
     * forces among its automata does no work (they share one velocity), so
     * it may be counted with the pair forces.
     *
     * A velocity component that a kinematic constraint resets right after
     * the kick stays at its prescribed value v_c: the forces do the work f
     * dt/2 v_c on it, and the kick's excess dt/2 f (v_after - v_c)/2 =
     * dt^2 f^2 / (8 m), which the constraint removes again, is the loading
     * machine's (credited to load_work, where the constraint books that
     * removal). Counting it as pair work moved dt^2 f^2 / (8 m) per
     * constrained component and half step from load to pair work
     * (measured: 75 % of the damped energy of the flat friction scene,
     * tests/mca/flat_friction_frictionless.prm).
     */
    struct BoundaryLoads::HalfKick
    {
      explicit HalfKick(const BoundaryLoads &loads)
          : loads(loads)
          , automata(loads.automata)
          , dt(loads.scalars.dt)
          , rotations(loads.scalars.rotations)
          , per_material(!loads.scalars.graded)
          , stale(loads.damping_stale())
      {
        const auto &grp = loads.prm.groups;
        for (unsigned int gi = 0; gi < grp.size(); ++gi)
          any_kinematic = any_kinematic
                          || grp[gi].type == BoundaryGroup::Type::fixed
                          || grp[gi].type == BoundaryGroup::Type::velocity;
        const double t = loads.scalars.current_time;
        if (any_kinematic)
          for (const auto &g : grp)
            kinematic.push_back(loads.value(g, t));
        // (without automata of several sizes, every automaton of a
        // material has its mass and moment of inertia: the factors
        // dt/2m and dt/2I of each material are computed at its first
        // automaton, the same divisions once instead of per automaton)
        a_of.assign(per_material ? loads.scalars.n_materials : 0, 0.);
        b_of.assign(a_of.size(), 0.);
        load.assign(grp.size(), Vec3{{0, 0, 0}});
        for (unsigned int gi = 0; gi < grp.size(); ++gi)
          if (grp[gi].type == BoundaryGroup::Type::force
              && loads.group_size[gi] > 0)
            {
              load[gi] = loads.value(grp[gi], t);
              for (unsigned int c = 0; c < 3; ++c)
                load[gi][c] /= loads.group_size[gi];
            }
        if (stale)
          for (const auto &g : grp)
            values.push_back(loads.value(g, t));
      }

      /// Bit c set: component c of automaton k is reset by a constraint.
      unsigned int
      constrained(const unsigned int k) const
      {
        const auto  &grp  = loads.prm.groups;
        unsigned int mask = 0;
        if (!any_kinematic || automata.groups[k] == 0)
          return mask;
        for (unsigned int gi = 0; gi < grp.size(); ++gi)
          if (automata.groups[k] & (1u << gi))
            {
              if (grp[gi].type == BoundaryGroup::Type::fixed)
                mask = 7;
              else if (grp[gi].type == BoundaryGroup::Type::velocity)
                for (unsigned int c = 0; c < 3; ++c)
                  if (!std::isnan(kinematic[gi][c]))
                    mask |= 1u << c;
            }
        return mask;
      }

      [[gnu::always_inline]] std::array<double, 2>
      factors(const unsigned int k)
      {
        const SystemScalars &scalars = loads.scalars;
        if (!per_material)
          return std::array<double, 2>{
            {0.5 * dt / scalars.automaton_mass(automata, k),
             rotations ? 0.5 * dt / scalars.automaton_inertia(automata, k)
                       : 0.}};
        const unsigned int m = automata.mat[k];
        if (a_of[m] == 0) [[unlikely]]
          {
            a_of[m] = 0.5 * dt / scalars.automaton_mass(automata, k);
            b_of[m] = rotations
                        ? 0.5 * dt / scalars.automaton_inertia(automata, k)
                        : 0.;
          }
        return std::array<double, 2>{{a_of[m], b_of[m]}};
      }

      /// The works of a half kick over dt/4, one partial sum per
      /// component and kind (independent chains of additions): pair
      /// forces and torques, loads, damping.
      struct Works
      {
        double wp[6] = {0, 0, 0, 0, 0, 0}, wl[3] = {0, 0, 0}, wd[3] = {0, 0, 0};
      };

      /// The kick of owned automaton @p k, its works added to @p w: a
      /// component moves at (vb + v)/2 over the half step, or at vb where a
      /// constraint resets it (see above; the kick's excess is then the
      /// loading machine's).
      [[gnu::always_inline]] void
      kick(const unsigned int k, Works &w)
      {
        double *const wp = w.wp, *const wl = w.wl, *const wd = w.wd;
        const auto  &grp = loads.prm.groups;
        const auto   ab  = factors(k);
        const double a   = ab[0];
        const Vec3   vb  = automata.v[k];
        // (an automaton no group acts on: all of its f is pair force)
        if (loads.untouched(k))
          for (unsigned int c = 0; c < 3; ++c)
            {
              automata.v[k][c] += a * automata.f[k][c];
              wp[c] += automata.f[k][c] * (vb[c] + automata.v[k][c]);
            }
        else
          {
            // after a rebuild st.f_damp is in the old order: recompute
            // it (from the velocity before the kick: an O(dt) error at
            // that step only)
            const Vec3 fd = !loads.damping_on ? Vec3{{0, 0, 0}}
                            : stale           ? loads.damping_force(k, values)
                                              : loads.st.f_damp[k];
            Vec3       fl{{0, 0, 0}};
            if (automata.groups[k] != 0)
              for (unsigned int gi = 0; gi < grp.size(); ++gi)
                if (automata.groups[k] & (1u << gi))
                  for (unsigned int c = 0; c < 3; ++c)
                    fl[c] += load[gi][c];
            const unsigned int mask = constrained(k);
            for (unsigned int c = 0; c < 3; ++c)
              {
                automata.v[k][c] += a * automata.f[k][c];
                const bool   fixed = mask & (1u << c);
                const double vm = fixed ? 2 * vb[c] : vb[c] + automata.v[k][c];
                wp[c] += (automata.f[k][c] - fd[c] - fl[c]) * vm;
                wd[c] -= fd[c] * vm;
                wl[c] += fl[c] * vm;
                if (fixed)
                  wl[c] += automata.f[k][c] * (automata.v[k][c] - vb[c]);
              }
          }
        if (rotations)
          {
            const double b = ab[1];
            for (unsigned int c = 0; c < 3; ++c)
              {
                const double wb = automata.w[k][c];
                automata.w[k][c] += b * automata.torque[k][c];
                wp[3 + c] += automata.torque[k][c] * (wb + automata.w[k][c]);
              }
          }
      }

      /// The works @p w of the automata kicked into @p work.
      void
      book(const Works &w, WorkSums &work) const
      {
        const double *const wp = w.wp, *const wl = w.wl, *const wd = w.wd;
        work[pair_work]
          += 0.25 * dt * ((wp[0] + wp[1] + wp[2]) + (wp[3] + wp[4] + wp[5]));
        work[load_work] += 0.25 * dt * (wl[0] + wl[1] + wl[2]);
        work[damped_work] += 0.25 * dt * (wd[0] + wd[1] + wd[2]);
      }

      const BoundaryLoads &loads;
      AutomatonArrays     &automata;
      const double         dt;
      const bool           rotations, per_material, stale;
      bool                 any_kinematic = false;
      std::vector<Vec3>    kinematic, load, values;
      std::vector<double>  a_of, b_of;
    };


    bool
    BoundaryLoads::damping_stale() const
    {
      return damping_on
             && (st.f_damp_rebuild != scalars.rebuild_count
                 || st.f_damp.size() != automata.n_owned);
    }


    void
    BoundaryLoads::half_kick(WorkSums &work)
    {
      HalfKick        kick(*this);
      HalfKick::Works w;
      for (unsigned int k = 0; k < automata.n_owned; ++k)
        kick.kick(k, w);
      kick.book(w, work);
    }


    KickDriftFigures
    BoundaryLoads::kick_kick_drift(WorkSums &work, const double speed_limit)
    {
      // The steps of velocity Verlet as they come (step(),
      // complete_step()): second half kick of step n at t_n, constraints
      // at t_n, first half kick of step n+1 (f unchanged, at t_n),
      // constraints at t_n + dt/2, drift. Each automaton goes through all
      // of them at once, in one pass over its data instead of three; each
      // kind of work keeps its own sums, added in the order of the steps,
      // so that every number is that of the separate passes, bit for bit.
      Assert(!damping_stale(), dealii::ExcInternalError());
      const double     t = scalars.current_time, dt = scalars.dt;
      HalfKick         second(*this), first(*this);
      Constraints      at_step(*this, t), at_half(*this, t + 0.5 * dt);
      HalfKick::Works  w2, w1;
      KickDriftFigures figures;
      const double     limit2 = speed_limit * speed_limit;
      // (automata of one size: the half size of every one)
      const double half_d    = 0.5 * scalars.d;
      const bool   free      = prm.global_damping == 0;
      const bool   rotations = scalars.rotations;
      const auto   pass      = [&](auto with_u, auto graded) {
        // (the sums local to the loop, so that they stay in registers: the
        // automata's stores cannot change them)
        HalfKick::Works s2, s1;
        unsigned int    unstable = 0;
        double          max_d2   = 0;
        for (unsigned int k = 0; k < automata.n_owned; ++k)
          {
            // the health of step n's velocities (count_unstable_automata())
            const auto health = [&]() {
              unstable
                += automata.too_fast(k,
                                     limit2,
                                     decltype(graded)::value
                                              ? 0.5
                                           * scalars.automaton_size(automata, k)
                                              : half_d);
            };
            if (free && automata.groups[k] == 0)
              {
                // (an automaton no group acts on: the common path of
                // HalfKick::kick() twice, with the same factors, and no
                // constraint)
                const auto ab = second.factors(k);
                Vec3      &v = automata.v[k], &w = automata.w[k];
                const Vec3 f         = automata.f[k];
                const auto free_kick = [&](HalfKick::Works &sums) {
                  for (unsigned int c = 0; c < 3; ++c)
                    {
                      const double vb = v[c];
                      v[c] += ab[0] * f[c];
                      sums.wp[c] += f[c] * (vb + v[c]);
                    }
                  if (rotations)
                    for (unsigned int c = 0; c < 3; ++c)
                      {
                        const double wb = w[c], tc = automata.torque[k][c];
                        w[c] += ab[1] * tc;
                        sums.wp[3 + c] += tc * (wb + w[c]);
                      }
                };
                free_kick(s2);
                health();
                free_kick(s1);
              }
            else
              {
                second.kick(k, s2);
                if (at_step.active)
                  at_step.apply(k);
                health();
                first.kick(k, s1);
                if (at_half.active)
                  at_half.apply(k);
              }
            // the drift (AutomatonSystem::step()) and the displacement
            // since the last rebuild (displacement_since_rebuild())
            const Vec3 dx = automata.drift(k, dt, with_u);
            max_d2 = std::max(max_d2, automata.displacement2_since_rebuild(k));
            book_displacement(k, dx);
          }
        w2                        = s2;
        w1                        = s1;
        figures.unstable          = unstable;
        figures.max_displacement2 = max_d2;
      };
      if (automata.u_stored)
        scalars.graded ? pass(std::true_type(), std::true_type())
                       : pass(std::true_type(), std::false_type());
      else
        scalars.graded ? pass(std::false_type(), std::true_type())
                       : pass(std::false_type(), std::false_type());
      second.book(w2, work);
      at_step.book(work);
      first.book(w1, work);
      at_half.book(work);
      return figures;
    }


    void
    BoundaryLoads::apply_forces(const double t)
    {
      // Adds external and damping forces to the pair forces f, which then
      // hold the total forces of the kicks; the pair-force reaction of each
      // group (what the observers report) is summed first, per rank.
      const auto               &grp = prm.groups;
      std::vector<Vec3>         values(grp.size());
      std::vector<unsigned int> plates;
      for (unsigned int gi = 0; gi < grp.size(); ++gi)
        {
          values[gi] = value(grp[gi], t);
          if (grp[gi].type == BoundaryGroup::Type::force)
            plates.push_back(gi);
        }
      st.group_reaction = local_sums(automata.f);
      // Scenes with damping keep its part of f in st.f_damp (energy
      // bookkeeping of the next half kicks); others hold no such array.
      if (damping_on)
        {
          st.f_damp.resize(automata.n_owned);
          st.f_damp_rebuild = scalars.rebuild_count;
        }
      for (unsigned int k = 0; k < automata.n_owned; ++k)
        {
          // (an automaton no group acts on has no damping force: zero)
          if (untouched(k))
            {
              if (damping_on)
                st.f_damp[k] = {{0, 0, 0}};
              continue;
            }
          if (damping_on)
            {
              st.f_damp[k] = damping_force(k, values);
              for (unsigned int c = 0; c < 3; ++c)
                automata.f[k][c] += st.f_damp[k][c];
            }
          if (automata.groups[k] == 0)
            continue;
          for (unsigned int gi = 0; gi < grp.size(); ++gi)
            if ((automata.groups[k] & (1u << gi))
                && grp[gi].type == BoundaryGroup::Type::force)
              for (unsigned int c = 0; c < 3; ++c)
                automata.f[k][c] += values[gi][c] / group_size[gi];
        }
      if (plates.empty())
        return;
      // A force group is a rigid loading plate: its automata share the
      // acceleration of the group's total force over its total mass. One
      // reduction for all plates.
      std::vector<double> sums(4 * plates.size(), 0.);
      for (unsigned int k = 0; k < automata.n_owned; ++k)
        if (automata.groups[k] != 0)
          for (unsigned int q = 0; q < plates.size(); ++q)
            if (automata.groups[k] & (1u << plates[q]))
              {
                for (unsigned int c = 0; c < 3; ++c)
                  sums[4 * q + c] += automata.f[k][c];
                sums[4 * q + 3] += scalars.automaton_mass(automata, k);
              }
      dealii::Utilities::MPI::sum(sums, comm, sums);
      for (unsigned int k = 0; k < automata.n_owned; ++k)
        if (automata.groups[k] != 0)
          for (unsigned int q = 0; q < plates.size(); ++q)
            if ((automata.groups[k] & (1u << plates[q])) && sums[4 * q + 3] > 0)
              for (unsigned int c = 0; c < 3; ++c)
                automata.f[k][c] = scalars.automaton_mass(automata, k)
                                   * sums[4 * q + c] / sums[4 * q + 3];
    }


    std::vector<Vec3>
    BoundaryLoads::local_sums(const std::vector<Vec3> &field) const
    {
      const unsigned int n_groups = prm.groups.size();
      std::vector<Vec3>  sums(n_groups, Vec3{{0, 0, 0}});
      for (unsigned int k = 0; k < automata.n_owned; ++k)
        if (automata.groups[k] != 0)
          for (unsigned int gi = 0; gi < n_groups; ++gi)
            if (automata.groups[k] & (1u << gi))
              for (unsigned int c = 0; c < 3; ++c)
                sums[gi][c] += field[k][c];
      return sums;
    }


    std::vector<Vec3>
    BoundaryLoads::global_sums(const std::vector<Vec3> &local) const
    {
      const unsigned int  n_groups = prm.groups.size();
      std::vector<double> sums(3 * n_groups, 0.);
      for (unsigned int gi = 0; gi < local.size(); ++gi)
        for (unsigned int c = 0; c < 3; ++c)
          sums[3 * gi + c] = local[gi][c];
      dealii::Utilities::MPI::sum(sums, comm, sums);
      std::vector<Vec3> out(n_groups);
      for (unsigned int gi = 0; gi < n_groups; ++gi)
        for (unsigned int c = 0; c < 3; ++c)
          out[gi][c] = sums[3 * gi + c];
      return out;
    }


    std::vector<Vec3>
    BoundaryLoads::reactions() const
    {
      // the pair-force reactions summed at the last step
      return global_sums(st.group_reaction);
    }


    std::vector<Vec3>
    BoundaryLoads::mean_displacements() const
    {
      std::vector<Vec3> out = global_sums(st.group_displacement);
      for (unsigned int gi = 0; gi < out.size(); ++gi)
        for (unsigned int c = 0; c < 3; ++c)
          out[gi][c] = group_size[gi] > 0 ? out[gi][c] / group_size[gi] : 0;
      return out;
    }
  } // namespace mca
} // namespace tribodyn
