#ifndef tribodyn_mca_automaton_system_h
#define tribodyn_mca_automaton_system_h

#include <algorithm>
#include <array>
#include <cstdint>
#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <functional>
#include <memory>
#include <tribodyn/core/archive_fwd.h>
#include <tribodyn/mca/automaton_arrays.h>
#include <tribodyn/mca/automaton_partition.h>
#include <tribodyn/mca/bond_laws.h>
#include <tribodyn/mca/boundary_loads.h>
#include <tribodyn/mca/decomposition.h>
#include <tribodyn/mca/moment_laws.h>
#include <tribodyn/mca/packing.h>
#include <tribodyn/mca/pair_arrays.h>
#include <tribodyn/mca/pair_fields.h>
#include <tribodyn/mca/pair_list.h>
#include <tribodyn/mca/parameters.h>
#include <tribodyn/mca/system_figures.h>
#include <tribodyn/mca/system_scalars.h>
#include <tribodyn/mca/vector_algebra.h>
#include <vector>

namespace tribodyn
{
  namespace mca
  {

    /**
     * The automata and their pairs.
     *
     * Decomposition (the part AutomatonPartition): the automata of a rank
     * are those in the cells it owns in a parallel::distributed background
     * mesh (see Decomposition); each rank packs only the lattice sites of
     * its own cells. Ghost copies of the automata of neighbour cells owned
     * by other ranks are received from those ranks only, with their
     * owners' (raw) coordinates; the periodic image shift of a pair is
     * cached in the pair list, so the pair kernel never searches for a
     * minimum image.
     *
     * Between two pair-list rebuilds (when an automaton moved more than
     * skin/2) the state lives in flat arrays indexed by a local automaton
     * index: owned automata first (along the space-filling curve of their
     * cells), then ghosts (the base AutomatonArrays, automaton_arrays.h),
     * and in flat arrays indexed by pair: the pair list (the base
     * PairList, pair_list.h: which automata, the image shift, the pairs of
     * each automaton) and the pairs' state (the base PairArrays,
     * pair_arrays.h, with the table of the persistent pair fields); the
     * scene's constants and counters are the base SystemScalars
     * (system_scalars.h). At a
     * rebuild, automata that entered a cell of another rank migrate through
     * deal.II's ParticleHandler (sort_particles_into_subdomains_and_cells), and
     * the states of their pairs follow them point to point.
     *
     * Results do not depend on the partition: the pairs are ordered by a
     * global key (an automaton's place in the automata's order,
     * Partition/Automaton order, then its id), so every
     * automaton sums its pair forces in the same order on any number of
     * ranks.
     *
     * A time step (velocity Verlet): half kick, drift, ghost update, pair
     * kernel (compiled per combination of the pair law's policies,
     * include/tribodyn/mca/pair_law.h), boundary conditions, half kick.
     */
    class AutomatonSystem : private AutomatonArrays,
                            private PairList,
                            private PairArrays,
                            private SystemScalars
    {
    public:
      AutomatonSystem(const Parameters &parameters, const MPI_Comm comm);

      /// Pack, distribute, build the pair list (initial bonds: pairs of
      /// the same body at contact distance).
      void
      setup();

      /// Time step: the given one, or courant * critical_time_step().
      double
      time_step() const
      {
        return dt;
      }
      /// Sound-crossing time of the smallest automaton, d_min / c_p,max.
      double
      critical_time_step() const
      {
        return critical_dt;
      }
      /// The largest Courant factor dt c_p,max / d_min this scene allows:
      /// TimeParameters::max_courant, less where an automaton's springs
      /// are stiffer than in the uniform lattice (a change of size).
      double
      courant_limit() const
      {
        return courant_max;
      }
      double
      time() const
      {
        return current_time;
      }
      unsigned long
      step_number() const
      {
        return n_steps_done;
      }

      /**
       * One velocity-Verlet step. With @p may_defer (and a speed limit
       * given to defer_second_kicks()), the step may leave its second half
       * kick and its constraints pending: the next step() gives them
       * together with its own first half kick and drift, in one pass over
       * the automata (BoundaryLoads::kick_kick_drift(): the same numbers,
       * bit for bit). Until then the automata's velocities are those
       * before that kick, and whoever reads the automata between the steps
       * calls complete_step() first.
       */
      void
      step(const bool may_defer = false);
      /// Give the last step's pending second half kick, if any (step()):
      /// the automata then hold the state at the step's end.
      void
      complete_step();
      bool
      step_complete() const
      {
        return !second_kick_pending;
      }
      /// Let step() defer its second half kicks; @p speed_limit (m/s): that
      /// of count_unstable_automata(), which the deferred kicks apply to
      /// the velocities at each step's end on their way.
      void
      defer_second_kicks(const double speed_limit);
      /// The owned automata found unstable (count_unstable_automata() with
      /// @p limit) since the last call: those the deferred kicks counted,
      /// and those of the current state if its step is complete. Each
      /// step's end is counted once, the step after it where its kick was
      /// deferred.
      unsigned int
      take_unstable_count(const double limit);

      /// Squared largest displacement (m^2) of the owned automata since the
      /// last pair-list rebuild: local to the rank. step() rebuilds the
      /// pair list when the ranks' largest exceeds (skin d / 2)^2.
      double
      displacement_since_rebuild() const;
      /// The ranks' largest displacement_since_rebuild(), agreed by the
      /// caller in a reduction of its own (the driver's health check after
      /// each step): the next step() uses it instead of a reduction of its
      /// own, one synchronisation of the ranks less per step.
      void
      set_agreed_displacement_since_rebuild(const double max_displacement2);

      // ---- stability and checkpoints (source/mca/stability.cc,
      // source/mca/checkpoint.cc)
      /// Owned automata whose velocity or rotation speed |w| d/2 is not
      /// finite or above @p limit (m/s).
      unsigned int
      count_unstable_automata(const double limit) const;
      /// Collective: throw RunError naming the worst automaton of all
      /// ranks (id, position, material, groups, speed) and the likely cause.
      [[noreturn]] void
      report_instability(const double limit) const;
      /// The whole state between two steps (the arrays listed once in
      /// source/mca/checkpoint.cc); load_state() after setup(), on the same
      /// number of ranks, restores it exactly.
      void
      save_state(boost::archive::binary_oarchive &archive) const;
      void
      load_state(boost::archive::binary_iarchive &archive);
      /// Restart on another number of ranks (source/mca/redistribution.cc):
      /// after setup(), absorb_state() takes each state of a checkpointed
      /// rank this rank read (any number), then redistribute_absorbed()
      /// (collective) sends the automata and pair states to their owners in
      /// this run's partition and builds the pair list there.
      void
      absorb_state(boost::archive::binary_iarchive &archive);
      void
      redistribute_absorbed();

      /// Rebuild the pair list now (migration, ghosts, pair states carried
      /// over), as step() does when an automaton moved more than skin/2.
      void
      rebuild_pair_list()
      {
        rebuild(false);
      }

      SystemEnergies
      energies() const;

      /// The boundary groups at work (reactions, mean displacements, sizes:
      /// boundary_loads.h).
      const BoundaryLoads &
      boundary_loads() const
      {
        return loads;
      }

      unsigned long long
      n_global_automata() const
      {
        return n_global;
      }
      using AutomatonArrays::n_ghost_automata;
      using AutomatonArrays::n_owned_automata;
      unsigned long long
      n_global_pairs() const;
      unsigned int
      n_rebuilds() const
      {
        return rebuild_count;
      }
      /// The pair kernel's pipeline on this rank for the pair list now
      /// (PairList::chunk_for_pipeline()): its chunks and how many chunks
      /// each pass trails the one before; 1 and 0 where the passes run one
      /// after the other (a rank with neighbour ranks; an elastic bulk's
      /// kernel, pair_kernel_bulk.cc, which has no pass B).
      unsigned int
      pipeline_chunks() const
      {
        return pipelined() ? n_chunks() : 1;
      }
      unsigned int
      pipeline_lag() const
      {
        return pipelined() ? chunk_lag : 0;
      }
      /// Bonded pairs that left the pair-list range (and so were dropped),
      /// global count since the start.
      unsigned long long
      n_dropped_bonds() const;
      /// Time at which the two bodies first touched (an unbonded pair in
      /// contact), when a boundary group switches on contact; -1 before.
      double
      contact_time() const
      {
        return loads.contact_time();
      }
      /// The contacting parts (Geometry/Inclusions) at set-up, global:
      /// their automata and those turned into the inclusion material, and
      /// the same as volumes in automata of d (an automaton of 2^L d counts
      /// 8^L: in a graded part the inclusions' share of the volume is not
      /// their share of the automata). Voids are removed: in neither.
      struct PartCounts
      {
        unsigned long long automata = 0, inclusions = 0;
        unsigned long long volume = 0, inclusion_volume = 0;
      };
      const PartCounts &
      contacting_part_counts() const
      {
        return part_counts;
      }
      /// Bytes held by this rank's automata and pair arrays and its
      /// background mesh.
      std::size_t
      memory_consumption() const;
      /// The same, array by array (name, bytes), in a fixed order: the
      /// automaton fields, the pair fields, the pair list and the per-step
      /// pair buffers, the mesh.
      std::vector<std::pair<std::string, std::size_t>>
      memory_by_part() const;
      const Decomposition &
      decomposition() const
      {
        return partition.cells();
      }

      // ---- access for analyses and tests (owned automata: index < n_owned)
      // (read access to the automata's arrays: automaton_arrays.h)
      using AutomatonArrays::angular_velocities;
      using AutomatonArrays::body_index;
      using AutomatonArrays::displacements;
      using AutomatonArrays::elastic;
      using AutomatonArrays::forces;
      using AutomatonArrays::ids;
      using AutomatonArrays::materials;
      using AutomatonArrays::plastic_strain;
      using AutomatonArrays::positions;
      using AutomatonArrays::size_levels;
      using AutomatonArrays::torques;
      using AutomatonArrays::velocities;
      /// Stress tensors of the owned automata (seed eq. 4, with the fabric
      /// correction), computed now from the pair stresses: not stored, so
      /// that an elastic scene keeps no tensor per automaton.
      std::vector<Sym3>
      stresses() const;
      /// The same for owned automaton @p k.
      Sym3
      automaton_stress(const unsigned int k) const;
      /// Tests: the stress tensors of the owned automata that the bond
      /// criteria of the last step read (bond scenes; zero where no bond
      /// check needed one), as the pair kernel summed them.
      std::vector<Sym3>
      bond_criterion_stresses() const;
      /// Twisting and bending stiffnesses (N m / rad) of the relative-
      /// rotation moment of a pair of materials @p mi, @p mj (0 when off).
      std::pair<double, double>
      rotation_stiffnesses(const unsigned int mi, const unsigned int mj) const;
      /// Number of bonded pairs of each local automaton (owned: complete).
      std::vector<unsigned int>
      bonded_neighbour_counts() const;
      /// Number of unbonded pairs in contact of each local automaton
      /// (owned: complete): the quasi-fluid layer indicator.
      std::vector<unsigned int>
      unbonded_contact_counts() const;

      /// An unbonded pair in contact as a line: from x_i (wrapped into
      /// the box) to x_i + (x_j - x_i + image shift), so that pairs across
      /// a periodic face are short lines, not box-long ones; sigma: the
      /// mean normal stress of its two sides.
      struct ContactLine
      {
        Point3 from;
        Vec3   along;
        double sigma;
      };
      /// The unbonded pairs in contact, each once (by the owner of its i).
      std::vector<ContactLine>
      unbonded_contact_lines() const;
      /// Size 2^L d of local automaton @p k.
      double
      automaton_size(const unsigned int k) const
      {
        return SystemScalars::automaton_size(*this, k);
      }
      /// Volume of owned automaton @p k (its Voronoi cell's near a change
      /// of size).
      double
      volume_of(const unsigned int k) const
      {
        return automaton_volume(*this, k);
      }

      /// Set velocity and angular velocity of every local automaton from a
      /// function of the position (tests, initial conditions).
      template <typename F>
      void
      set_velocities(const F &f)
      {
        for (unsigned int k = 0; k < x.size(); ++k)
          f(x[k], v[k], w[k]);
      }

      /**
       * Tests: move every local automaton (owned and ghost) by
       * @p displacement(x) with angular increment @p rotation(x) over a
       * pseudo-step of length @p pseudo_dt, then evaluate the pair kernel
       * (no integration). Affine fields give homogeneous states.
       */
      template <typename F>
      void
      impose_motion(const F &motion, const double pseudo_dt)
      {
        for (unsigned int k = 0; k < x.size(); ++k)
          {
            Vec3 du, dtheta;
            motion(x[k], du, dtheta);
            for (unsigned int c = 0; c < 3; ++c)
              {
                x[k][c] += du[c];
                if (u_stored)
                  u[k][c] += du[c];
                w[k][c] = dtheta[c] / pseudo_dt;
                v[k][c] = du[c] / pseudo_dt;
              }
            if (k < n_owned)
              loads.book_displacement(k, du);
          }
        evaluate_pairs(pseudo_dt);
      }

      // ---- pair access (tests)
      using PairView = mca::PairView;
      std::vector<PairView>
      pair_views() const;

      /// Tests: plastic heat of every pair set to @p value.
      void
      set_pair_heat(const double value);

      const Parameters &
      parameters() const
      {
        return prm;
      }

      /**
       * The partition of @p prm's scene over @p n_ranks ranks as p4est
       * would cut it (equal numbers of cells along the space-filling curve
       * of the trees), computed on this process without building the mesh
       * or the automata: counts of owned and ghost automata per rank and
       * the memory estimate. Cost: one pass over the lattice sites.
       */
      static PartitionFigures
      partition_report(const Parameters &prm, const unsigned int n_ranks);

      /// Collective: the largest number of owned automata of a rank over
      /// the mean (1: perfectly balanced work).
      double
      work_imbalance() const
      {
        return partition.work_imbalance();
      }
      /// Times the partition was weighted anew during the run.
      unsigned int
      n_rebalances() const
      {
        return partition.state().rebalance_count;
      }

    private:
      /// The largest Courant factor for which every automaton's highest
      /// frequency estimate (its springs against fixed neighbours, the
      /// relative-rotation moments included) stays below that of an
      /// automaton in the uniform lattice at TimeParameters::max_courant
      /// (source/mca/stability.cc), over the materials @p used anywhere
      /// (by material: 1 or 0, the same on every rank). Collective; needs
      /// the pair list.
      double
      stiffest_courant_limit(const std::vector<unsigned int> &used) const;
      // --- set-up and rebuild (automaton_system.cc, rebuild.cc)
      void
      pack_owned_cells();
      void
      rebuild(const bool initial);
      /// The automata's migration at a rebuild (the partition's
      /// migrate()) with the states of their pairs: those of the pairs of
      /// departing automata go to their new owners; the received ones and
      /// this rank's old pairs become the records of restore_pair_states().
      /// With @p all_pair_states, the states of all this rank's pairs
      /// become records too (kept_keys, kept_states) for
      /// repartition_automata().
      void
      migrate(const bool all_pair_states = false);
      /// The partition weighted anew (AutomatonPartition::repartition()),
      /// the pair-state records of migrate(true) following their automata.
      void
      repartition_automata();
      /// The pair list of the automata now (PairList::build(), with this
      /// scene's ranges).
      void
      build_pair_list()
      {
        PairList::build(partition.cells(),
                        *this,
                        range,
                        graded ? &graded_range : nullptr);
      }
      /// Restore the pair states kept over a rebuild.
      void
      restore_pair_states(const bool initial);
      /// Store the pairs' own side states — shear factors (all 1 until
      /// then) and, once the new pairs are in place (@p check_pairs), the
      /// sides' many-body offsets (their automata's until then) — once any
      /// rank has them or a pair that can have an event: a plastic or bond
      /// scene, an unbonded pair, a pair of two materials (collective;
      /// @p n_pairs: the size of the pair arrays now).
      void
      allocate_side_states(const std::size_t n_pairs, const bool check_pairs);

      // --- dynamics (pair_kernel.cc)
      void
      evaluate_pairs(const double step);
      /// The pair kernel for one combination of the pair-law policies
      /// (include/tribodyn/mca/pair_law.h), chosen in evaluate_pairs().
      /// Compiled as a function of its own (no inlining into the
      /// dispatch, no interprocedural clones: `noipa`), as when each
      /// kernel had a single caller: its rounding (which products fuse
      /// into FMAs) then does not depend on the combination that calls it.
      template <bool rotations,
                bool plastic,
                bool bonds,
                class Pairs,
                class FrictionLaw,
                class MomentLaw>
      [[gnu::noipa]] void
      pair_kernel(const double step,
                  const Pairs &geometry,
                  FrictionLaw &law,
                  MomentLaw   &moment);
      /// Do the pair kernel's passes run as a pipeline over the chunks of
      /// the pair list (pair_kernel())? On a rank without neighbour ranks,
      /// whose values then need no exchange between the passes, and not in
      /// an elastic bulk's kernel (pair_kernel_bulk.cc).
      bool
      pipelined() const
      {
        return !partition.neighbours().active() && (mb_stored || q_stored);
      }
      /// What the passes of one step of the pair kernel share; each adds
      /// the works of its events to the step's sums (WorkSums).
      struct PairStep
      {
        double       dt;
        unsigned int n_pairs;
        /// prefetch distance (0 in scenes that fit in a core's caches)
        unsigned int n_ahead;
        /// pass A keeps r and n of every pair for the later passes
        bool keep_normals;
        /// pass C of a plastic bond kernel sums the final tensors anew only
        /// where pass B's trial ones are not final (stress_anew)
        bool anew_tensors;
      };
      // The passes are functions of their own in the source and one body in
      // the binary (always_inline into pair_kernel): the rounding of the
      // kernel (which products fuse into FMAs) stays that of one function.
      /// Pass A: geometry, tangential stresses, split of the normal
      /// increment, volumetric strain increments of both sides.
      template <bool rotations,
                bool plastic,
                class Pairs,
                class FrictionLaw,
                class MomentLaw>
      [[gnu::always_inline]] inline void
      pair_pass_a(const PairStep    &step,
                  const unsigned int p_begin,
                  const unsigned int p_end,
                  WorkSums          &works,
                  const Pairs       &geometry,
                  FrictionLaw       &law,
                  MomentLaw         &moment);
      /// Pass B (plastic kernels): trial side stresses and tensors.
      [[gnu::always_inline]] inline void
      pair_pass_b(const PairStep    &step,
                  const unsigned int p_begin,
                  const unsigned int p_end);
      /// The radial return of each owned automaton k_begin ... k_end
      /// (plastic kernels); the ghosts' from their owners after the @p last
      /// chunk.
      [[gnu::always_inline]] inline void
      radial_returns(const unsigned int k_begin,
                     const unsigned int k_end,
                     const bool         last);
      /// Plastic bond kernels: the final tensors pass C sums anew, from zero.
      [[gnu::always_inline]] inline void
      final_tensors_anew(const unsigned int k_begin, const unsigned int k_end);
      /// Pass C: plastic correction, contact constraints, forces and
      /// torques; in bond scenes the final stress tensors. Whether an
      /// elastic kernel ran events (its uniform automata's shapes to sync).
      template <bool rotations,
                bool plastic,
                bool bonds,
                class Pairs,
                class FrictionLaw,
                class MomentLaw>
      [[gnu::always_inline]] inline bool
      pair_pass_c(const PairStep    &step,
                  const unsigned int p_begin,
                  const unsigned int p_end,
                  WorkSums          &works,
                  const Pairs       &geometry,
                  FrictionLaw       &law,
                  MomentLaw         &moment);
      /// The pair geometry of the scene as a choice for with_chosen()
      /// (source/mca/pair_geometry_choice.h).
      auto
      pair_geometry_choice() const;
      /// The kernel of an elastic bulk (source/mca/pair_kernel_bulk.cc):
      /// every pair bonded, of one material, equally stiff halves, no
      /// plasticity and no bond law, so that no event can occur (the pairs
      /// store their sides' common normal stress only, PairArrays::sig_e).
      /// Its own translation unit: the other kernels' code, and so their
      /// rounding, stay as they were.
      void
      evaluate_bulk_pairs(const double step);
      template <bool rotations, class Pairs, class FrictionLaw, class MomentLaw>
      void
      bulk_pair_kernel(const double step,
                       const Pairs &geometry,
                       FrictionLaw &law,
                       MomentLaw   &moment);
      /// Its passes A and C: each block's pair law in one branch-free loop
      /// the compiler vectorizes; only the scattered sums of the automata
      /// pair by pair.
      template <bool rotations, class Pairs, class MomentLaw>
      [[gnu::always_inline]] inline void
      pair_pass_a_bulk(const PairStep &step,
                       WorkSums       &works,
                       const Pairs    &geometry,
                       MomentLaw      &moment);
      template <bool rotations, class Pairs, class MomentLaw>
      [[gnu::always_inline]] inline void
      pair_pass_c_bulk(const PairStep &step,
                       const Pairs    &geometry,
                       MomentLaw      &moment);
      /// The events of pair @p p at the end of its step (plastic
      /// returns, no tension, friction limits) and the energy they release,
      /// added to @p works (source/mca/pair_events.h).
      template <bool plastic, class Pairs, class FrictionLaw>
      void
      pair_events(const unsigned int p,
                  const Pairs       &geometry,
                  const FrictionLaw &law,
                  const Vec3        &t,
                  double            &alpha_i,
                  double            &alpha_j,
                  WorkSums          &works);
      /// Bond breaking and formation under the chosen criteria
      /// (source/mca/bond_switching.h), at the end of the pair kernel.
      template <bool plastic, class Breaking, class Formation>
      [[gnu::noipa]] void
      bond_switching(const Breaking &breaking, const Formation &formation);
      /// mu of unbonded pair @p p in this step under @p law.
      template <class Law>
      double
      friction_coefficient(const Law &law, const unsigned int p) const;
      // --- the energy of the pairs (pair_energy.cc, doc/theory/mca.md
      // §8.4): that of the owned sides and automata; kappa, gamma, G of
      // owned automaton k; sum of kappa G^2; the many-body stresses into
      // the sides' offsets (before automata migrate); the energy released
      // by unbonded pair p that opens (normal increment dr; switching
      // work); of side s (0: i, 1: j) of pair p, its many-body part D mu_a
      // + c_s, its spring's compliance 1/k and its weight g = beta / h
      // (pair_energy.h)
      double
      pair_elastic_energy() const;
      void
      update_many_body_state(const unsigned int k);
      /// The pair kernel's many-body work of a step (after pass A); dsm
      /// times K (sent to the ghosts) and mu anew; where the pairs store
      /// their sides' common stress only (PairArrays::sig_e), dsm then
      /// holds each automaton's many-body part m = D mu + c for pass C.
      /// For the owned automata k_begin ... k_end (a chunk of the pair
      /// kernel's pipeline; the ghosts after the @p last one), the
      /// many-body work added to @p work, in the automata's order.
      void
      many_body_step(const unsigned int k_begin,
                     const unsigned int k_end,
                     const bool         last,
                     double            &work);
      /// The shapes of the owned automata from their lambda (0: general).
      void
      sync_many_body_shapes();
      double
      many_body_energy() const;
      void
      fold_many_body_stress();
      void
      release_opening(const unsigned int p, const double dr);
      double
      side_many_body(const unsigned int p, const unsigned int s) const;
      /// Normal stress of side @p s (0: i, 1: j) of pair @p p (stored, or
      /// the common part plus the side's many-body part:
      /// PairArrays::sig_e).
      double
      side_sigma(const unsigned int p, const unsigned int s) const;
      /// The same where the pairs store their offsets (mb_stored): the
      /// events of a step (plastic returns, the limits of unbonded pairs),
      /// which only such scenes have.
      double
      stored_side_many_body(const unsigned int p, const unsigned int s) const;
      double
      side_compliance(const unsigned int p, const unsigned int s) const;
      double
      side_weight(const unsigned int p, const unsigned int s) const;
      /// Elastic energy sum |K|^2 / 2k of the relative-rotation moments
      /// K_ij (the moment law's, moment_laws.h) of the pairs counted by
      /// this rank.
      double
      pair_moment_energy() const;
      /// Pair vector x_j - x_i (with the cached periodic image shift);
      /// its length (the same bits as at the last evaluation of the pairs:
      /// positions change only in the drift); the unit normal n_ij (@p r:
      /// the distance).
      Vec3
      pair_vector(const unsigned int p) const
      {
        const unsigned int i = pi[p], j = pj[p];
        const auto        &s = partition.cells().shift_vector(pshift[p]);
        return {{(x[j][0] - x[i][0]) + s[0],
                 (x[j][1] - x[i][1]) + s[1],
                 (x[j][2] - x[i][2]) + s[2]}};
      }
      double
      pair_distance(const unsigned int p) const
      {
        const Vec3 dn = pair_vector(p);
        return std::sqrt(dot(dn, dn));
      }
      Vec3
      unit_normal(const unsigned int p, double &r) const
      {
        const Vec3 dn    = pair_vector(p);
        r                = std::sqrt(dot(dn, dn));
        const double inv = 1. / r;
        return {{dn[0] * inv, dn[1] * inv, dn[2] * inv}};
      }
      // --- restart on another number of ranks (redistribution.cc)
      /// The arrays of a saved state (checkpoint.cc), checked against this
      /// run (with @p same_ranks, also the number of ranks); the ghost
      /// lists go to @p offsets and @p send.
      void
      read_saved_arrays(boost::archive::binary_iarchive        &archive,
                        const bool                              same_ranks,
                        std::vector<unsigned int>              &offsets,
                        std::vector<std::vector<unsigned int>> &send);
      /// Records of the state in the arrays now (absorb_state()): owned
      /// automata and the pair states of their pairs, with this rank's sums.
      void
      absorb_current_arrays();
      struct Absorbed
      {
        std::vector<double> automata, pairs;
        WorkSums            work{};
        unsigned long long  dropped = 0;
        std::vector<Vec3>   group_reaction, group_displacement;
      };
      Absorbed absorbed;

      // --- neighbourhood weights (neighbourhood_weights.cc)
      /// Least-squares weights beta of the volumetric strain and inverse
      /// fabric tensors of the owned automata whose neighbourhoods changed.
      void
      update_neighbourhood_weights(const bool all);
      Sym3
      fabric_corrected(const unsigned int k, const Mat3 &t) const;
      /// Add the eq.-(4) stress contribution of side @p side (0: i, 1: j)
      /// of pair @p p, that of automaton @p a, to @p target: (q S / V_a) n
      /// (x) (@p sigma n + @p alpha tau), @p n the unit normal, @p r the
      /// distance.
      void
      add_side_stress(Mat3              &target,
                      const unsigned int p,
                      const unsigned int side,
                      const unsigned int a,
                      const double       sigma,
                      const double       alpha,
                      const double       r,
                      const Vec3        &n) const;
      /// Add the eq.-(4) stress contributions of pair @p p (unit normal
      /// @p n, distance @p r) to the owned automata of the pair in @p target
      /// (indexed by local automaton); with @p skip_elastic not to automata
      /// of elastic regions (the plastic trial stress needs none); with
      /// @p only, to the automata k with only[k] != 0.
      void
      add_pair_stress(const unsigned int   p,
                      const Vec3          &n,
                      const double         r,
                      std::vector<Mat3>   &target,
                      const bool           skip_elastic,
                      const unsigned char *only = nullptr) const;
      /// Fabric tensor B = sum_j (q S / V) n n of automaton @p k's
      /// interacting pairs, inverted when well conditioned (else identity).
      Sym3
      inverse_fabric(const unsigned int k) const;

      // --- automata of several sizes (graded_geometry.cc)
      double
      mass_of(const unsigned int k) const
      {
        return automaton_mass(*this, k);
      }
      double
      inertia_of(const unsigned int k) const
      {
        return automaton_inertia(*this, k);
      }
      /// Contact area and volume ratio of pair @p p (graded: its own).
      double
      area_of(const unsigned int p) const
      {
        return graded ? pair_area[p] : S;
      }
      /// Factor of the material table's relative-rotation stiffnesses for
      /// pair @p p (graded: graded_moment_scale() of its face and half rest
      /// length, as the kernel's GradedPairs::moment_scale(); 0 for an inert
      /// pair; uniform: 1). Defined in pair_moments.cc.
      double
      moment_scale_of(const unsigned int p) const;
      /// Pair-list ranges [near a change of size][size level] of @p
      /// prm's scene: d (1 + skin) 2^L, times transition_face_factor() near
      /// a change of size (RangeTable, pair_list_range():
      /// automaton_arrays.h).
      static RangeTable
      pair_list_ranges(const Parameters &prm);
      /// Squared pair-list range of automata @p a and @p b.
      double
      pair_range2(const unsigned int a, const unsigned int b) const
      {
        if (!graded)
          return range * range;
        const double r
          = pair_list_range(graded_range, size_level[a], size_level[b]);
        return r * r;
      }
      /// Area and half rest length of new pair @p p (inert, 0, when an
      /// automaton is near a change of size: those pairs get theirs from
      /// the Voronoi cells at set-up).
      double
      new_pair_area(const unsigned int p) const;
      double
      new_pair_half_rest(const unsigned int p) const;
      /// Set-up of a graded scene: Voronoi volumes of the automata near a
      /// change of size, areas and rest lengths of their pairs (symmetric
      /// over ranks), their bonds.
      void
      setup_graded_geometry();
      /// Drop the pairs near a change of size that can never interact
      /// (no area, or unbonded and beyond their contact range).
      void
      drop_inert_pairs();

      const Parameters &prm;
      MPI_Comm          comm;
      unsigned int      n_ranks, rank;

      /// Who holds which automaton: the mesh, the neighbour ranks, the
      /// migrations, the ghosts (automaton_partition.h).
      AutomatonPartition partition;

      void
      register_pair_fields();
      void
      register_automaton_fields();
      /// The friction laws of unbonded pairs (the chosen one holds its
      /// pair state, registered in pair_fields).
      FrictionLaws friction_laws;
      /// The relative-rotation moment K_ij (the chosen law holds the
      /// moment of each pair, registered in pair_fields) and the bond
      /// breaking and formation criteria (pair_law.h).
      MomentLaws         moment_laws;
      BondBreakingLaws   breaking_laws;
      BondFormationLaws  formation_laws;
      unsigned long long dropped_bonds = 0;

      // --- staged loading, contacting parts, energy bookkeeping
      /// What the boundary groups do to the automata (boundary_loads.h).
      BoundaryLoads loads;
      /// Set the contact time once the bodies touch (collective).
      void
      detect_first_contact();

      PartCounts part_counts;
      /// The works since the start, by Work (system_figures.h).
      WorkSums work{};
    };
  } // namespace mca
} // namespace tribodyn

#endif
