// The boundary groups at work on the automata: one part of AutomatonSystem
// (issue #52 item 1), with one job — what the loading machine does.
#ifndef tribodyn_mca_boundary_loads_h
#define tribodyn_mca_boundary_loads_h

#include <deal.II/base/mpi.h>
#include <tribodyn/mca/automaton_arrays.h>
#include <tribodyn/mca/parameters.h>
#include <tribodyn/mca/system_figures.h>
#include <tribodyn/mca/system_scalars.h>
#include <tribodyn/mca/vector_algebra.h>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    /// What BoundaryLoads::kick_kick_drift() sees of the automata on its
    /// way (owned automata of this rank).
    struct KickDriftFigures
    {
      /// Automata whose velocity or rotation speed at the end of the step
      /// (after its second half kick) is not finite or above the limit
      /// (AutomatonSystem::count_unstable_automata()).
      unsigned int unstable = 0;
      /// Squared largest displacement since the last rebuild after the
      /// drift (AutomatonSystem::displacement_since_rebuild()).
      double max_displacement2 = 0;
    };


    /**
     * The groups of 'Boundary conditions' acting on the automata:
     * kinematic constraints (fixed, prescribed velocity), loads (a force
     * group is a rigid loading plate), damping (global and damping groups),
     * each with its smooth ramp and its switch (at a time, or at the first
     * contact of the bodies); the velocity-Verlet half kick with the work
     * that the pair forces, the loads and the damping do over it (the
     * energy balance, doc/theory/mca.md §8); and what the observers read:
     * each group's pair-force reaction and mean displacement.
     *
     * A part of AutomatonSystem in the way of ASPECT's SimulatorAccess: it
     * reads the automata (AutomatonArrays: membership, masses, velocities,
     * forces) and the run's scalars (SystemScalars: the time, the step,
     * the materials) of its system, writes the automata's velocities and
     * forces, and owns its own state (State): the groups' sizes and
     * reactions, the contact time and the damping forces.
     */
    class BoundaryLoads
    {
    public:
      BoundaryLoads(const BoundaryParameters &parameters,
                    const MPI_Comm            comm,
                    AutomatonArrays          &automata,
                    const SystemScalars      &scalars);

      /// What the part carries from one step to the next: checkpointed (in
      /// this order; the damping forces with the automata, an automaton
      /// field) and moved by a restart on another number of ranks.
      struct State
      {
        /// Time at which the bodies first touched; -1 before.
        double first_contact_time = -1;
        /// The rebuild at which f_damp was computed (it is in that
        /// rebuild's order of the automata).
        unsigned int f_damp_rebuild = 0;
        /// Pair-force reaction of each group on this rank (sum of f over
        /// the group's owned automata before the loads are added).
        std::vector<Vec3> group_reaction;
        /// Displacement of each group on this rank: the sum of the drifts
        /// of the group's automata while this rank owned them (their mean
        /// displacement is the sum over the ranks over the group's size;
        /// no automaton needs to store its own).
        std::vector<Vec3> group_displacement;
        /// Damping part of f of each owned automaton (for the damped
        /// work), valid while f_damp_rebuild is the system's rebuild
        /// count; empty without damping.
        std::vector<Vec3> f_damp;
      };
      State &
      state()
      {
        return st;
      }
      const State &
      state() const
      {
        return st;
      }

      /// At set-up, after the automata are packed (collective): the
      /// groups' sizes (automata never change group) and whether any
      /// group waits for the contact or damps.
      void
      count_members();

      /// Whether a group switches when the bodies first touch and they have
      /// not yet (the system then looks for the first contact).
      bool
      waits_for_contact() const
      {
        return wait_for_contact && st.first_contact_time < 0;
      }
      void
      set_contact_time(const double t)
      {
        st.first_contact_time = t;
      }
      double
      contact_time() const
      {
        return st.first_contact_time;
      }
      /// Global damping or a damping group (State::f_damp is used).
      bool
      damping() const
      {
        return damping_on;
      }

      /// Velocity-Verlet half kick v += dt/2 F/m (and of the rotations),
      /// booking its work as pair, load and damped work in @p work.
      void
      half_kick(WorkSums &work);
      /// The fixed and prescribed velocities at time @p t; the kinetic
      /// energy they add or remove is load work.
      void
      apply_constraints(const double t, WorkSums &work);
      /// Whether kick_kick_drift() may run: not right after a rebuild of a
      /// scene with damping, whose damping forces half_kick() then
      /// recomputes from each kick's velocities.
      bool
      may_kick_kick_drift() const
      {
        return !damping_stale();
      }
      /**
       * The leapfrog form of velocity Verlet: the second half kick of the
       * step just done and its constraints (at the system's time t), the
       * first half kick of the next step (with the same forces) and its
       * constraints (at t + dt/2), and that step's drift x += dt v (with
       * the automata's displacements u where stored, and their groups'),
       * in one pass over the automata: the same numbers as half_kick(),
       * apply_constraints(), half_kick(), apply_constraints() and the drift
       * one after the other, bit for bit, each automaton's data read once
       * instead of three times. On its way it counts the automata whose
       * speed at the end of the step exceeds @p speed_limit and measures
       * the displacements since the last rebuild after the drift.
       */
      KickDriftFigures
      kick_kick_drift(WorkSums &work, const double speed_limit);
      /// The groups' reactions (the pair forces f, summed per rank), then
      /// the loads and damping at time @p t added to f, which then holds
      /// the forces of the next kicks; a loading plate's automata share
      /// its acceleration (collective).
      void
      apply_forces(const double t);

      /// Number of automata in each group, global (counted at set-up).
      const std::vector<unsigned long long> &
      sizes() const
      {
        return group_size;
      }
      /// Reaction (sum of pair forces) on each group at the last step,
      /// global.
      std::vector<Vec3>
      reactions() const;
      /// Mean displacement of each group's automata, global.
      std::vector<Vec3>
      mean_displacements() const;
      /// Owned automaton @p k moved by @p dx (the drift): its groups'
      /// displacements move with it.
      void
      book_displacement(const unsigned int k, const Vec3 &dx)
      {
        if (st.group_displacement.empty())
          return;
        const std::uint32_t in = automata.groups[k];
        if (in == 0)
          return;
        for (unsigned int gi = 0; gi < st.group_displacement.size(); ++gi)
          if (in & (1u << gi))
            for (unsigned int c = 0; c < 3; ++c)
              st.group_displacement[gi][c] += dx[c];
      }

    private:
      /// A half kick and the constraints at one time, prepared once and
      /// applied automaton by automaton (boundary_loads.cc).
      struct HalfKick;
      struct Constraints;
      /// Is State::f_damp in another order than the automata's (a rebuild
      /// since apply_forces())?
      bool
      damping_stale() const;
      /// The smooth (C1) ramp of velocities and forces at time @p t.
      double
      ramp(const double t) const;
      /// The value of group @p g at time @p t (its ramp and switch).
      Vec3
      value(const BoundaryGroup &g, const double t) const;
      /// Is owned automaton @p k free of every group's action: in no group
      /// and without global damping (no damping, load or constraint; its
      /// f is all pair force)?
      bool
      untouched(const unsigned int k) const
      {
        return prm.global_damping == 0 && automata.groups[k] == 0;
      }
      /// Damping force -c m v of owned automaton @p k (@p values: value()
      /// of every group).
      Vec3
      damping_force(const unsigned int       k,
                    const std::vector<Vec3> &values) const;
      /// Sum of @p field (per local automaton) over the owned automata of
      /// each group on this rank; the sum over ranks of such sums.
      std::vector<Vec3>
      local_sums(const std::vector<Vec3> &field) const;
      std::vector<Vec3>
      global_sums(const std::vector<Vec3> &local) const;

      const BoundaryParameters &prm;
      MPI_Comm                  comm;
      AutomatonArrays          &automata;
      const SystemScalars      &scalars;

      std::vector<unsigned long long> group_size;
      bool                            wait_for_contact = false;
      bool                            damping_on       = false;
      State                           st;
    };
  } // namespace mca
} // namespace tribodyn

#endif
