#ifndef tribodyn_mca_automaton_system_h
#define tribodyn_mca_automaton_system_h

#include <array>
#include <cstdint>
#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/particles/particle_handler.h>
#include <memory>
#include <tribodyn/mca/parameters.h>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    using Vec3 = std::array<double, 3>;
    using Sym3 = std::array<double, 6>; ///< xx yy zz yz xz xy

    /// One automaton of the initial packing (global numbering = id).
    struct PackedAutomaton
    {
      Point3        position;
      unsigned char material = 0;
      unsigned char body     = 0;
    };

    /**
     * FCC packing of the bodies with the regions applied, in a
     * deterministic global order (the index is the automaton id).
     */
    std::vector<PackedAutomaton>
    pack_automata(const GeometryParameters &geometry,
                  const unsigned int        n_materials);

    /**
     * Ghost-automaton communication between MPI ranks: after each pair-list
     * rebuild, every rank knows which of its ghosts each other rank owns;
     * update() then copies a few doubles per automaton from owners to
     * ghosts with point-to-point messages.
     */
    class GhostExchange
    {
    public:
      /// @p ghost_owner / @p ghost_ids for local ghosts n_owned + k;
      /// @p owned_index maps an owned id to its local index.
      void
      setup(const MPI_Comm                    comm,
            const std::vector<unsigned int>  &ghost_owner,
            const std::vector<std::uint64_t> &ghost_ids,
            const std::vector<std::uint64_t> &owned_ids,
            const unsigned int                n_owned);

      /// Copy @p width doubles per automaton of @p data (array of local
      /// automata, stride width) from owners to ghosts.
      void
      update(double *data, const unsigned int width) const;

      bool
      active() const
      {
        return !neighbors.empty();
      }

    private:
      MPI_Comm                                 comm    = MPI_COMM_SELF;
      unsigned int                             n_owned = 0;
      std::vector<unsigned int>                neighbors;
      std::vector<std::vector<unsigned int>>   send_indices; ///< owned local
      std::vector<std::vector<unsigned int>>   recv_indices; ///< ghost local
      mutable std::vector<std::vector<double>> send_buffers, recv_buffers;
    };

    /// Global figures of the current state (summed over ranks).
    struct SystemEnergies
    {
      double             kinetic             = 0;
      double             elastic             = 0;
      double             plastic_work        = 0;
      double             friction_work       = 0;
      unsigned long long n_bonded            = 0;
      unsigned long long n_unbonded_contacts = 0;
    };

    /**
     * The automata and their pairs. Automata are particles of a
     * Particles::ParticleHandler<3> over a parallel::distributed background
     * mesh (periodic faces added for periodic directions); the particle
     * properties hold the automaton state (and, under MPI, the states of the
     * pairs in which the automaton has the smaller id), and travel with the
     * particles when they are sorted into subdomains. Between two pair-list
     * rebuilds the working state lives in flat arrays indexed by a local
     * automaton index: owned automata first, then ghosts.
     *
     * A time step (velocity Verlet) is: half kick, drift, ghost update,
     * pair kernel (strain increments -> mean-stress increments -> pair
     * stresses -> plastic correction -> contact constraints -> forces and
     * torques), boundary conditions, half kick. The pair kernel is
     * compiled for each combination of {rotations, plasticity, bond
     * switching} so that scenes pay only for what they use.
     */
    class AutomatonSystem
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

      /// One velocity-Verlet step.
      void
      step();

      /// Recompute the stress tensor, pressure and von Mises stress of every
      /// owned automaton from the current pair stresses (seed eq. 4).
      void
      compute_automaton_stresses();

      SystemEnergies
      energies() const;

      /// Reaction (sum of pair forces) on each boundary group, global.
      std::vector<Vec3>
      group_forces() const;
      /// Mean displacement of each group's automata, global.
      std::vector<Vec3>
      group_displacements() const;
      /// Number of automata in each group, global.
      std::vector<unsigned long long>
      group_sizes() const;

      unsigned long long
      n_global_automata() const
      {
        return n_global;
      }
      unsigned int
      n_owned_automata() const
      {
        return n_owned;
      }
      unsigned long long
      n_global_pairs() const;
      unsigned int
      n_rebuilds() const
      {
        return rebuild_count;
      }

      /// Write particles_NNNN.pvtu (+ .vtu per rank); returns the pvtu name
      /// relative to @p directory. With @p slab, only automata whose
      /// coordinate along @p axis lies within [lo, hi].
      std::string
      write_particles(const std::string &directory,
                      const std::string &base,
                      const unsigned int number,
                      const bool         with_stress,
                      const bool         slab    = false,
                      const unsigned int axis    = 0,
                      const double       slab_lo = 0,
                      const double       slab_hi = 0) const;

      // ---- access for analyses and tests (owned automata: index < n_owned)
      const std::vector<Point3> &
      positions() const
      {
        return x;
      }
      /// Displacement accumulated since the start (unaffected by periodic
      /// wrapping).
      const std::vector<Vec3> &
      displacements() const
      {
        return u;
      }
      const std::vector<std::uint64_t> &
      ids() const
      {
        return id;
      }
      const std::vector<Sym3> &
      stresses() const
      {
        return stress;
      }
      const std::vector<Vec3> &
      velocities() const
      {
        return v;
      }
      const std::vector<double> &
      plastic_strains() const
      {
        return eps_p;
      }
      const std::vector<unsigned char> &
      materials() const
      {
        return mat;
      }
      /// Number of bonded pairs of each local automaton (owned: complete).
      std::vector<unsigned int>
      bonded_neighbour_counts() const;

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
                dx[k][c] = du[c];
                x[k][c] += du[c];
                u[k][c] += du[c];
                w[k][c] = dtheta[c] / pseudo_dt;
                v[k][c] = du[c] / pseudo_dt;
              }
          }
        evaluate_pairs(pseudo_dt, false);
      }

      // ---- pair access (tests)
      struct PairView
      {
        std::uint64_t id_i, id_j;
        bool          bonded;
        double        sigma; ///< mean of the two sides
        Vec3          tau;
        double        heat;
        double        distance;
      };
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

    private:
      // --- set-up and rebuild
      void
      make_background_mesh();
      void
      insert_packing();
      void
      rebuild(const bool initial);
      void
      write_state_to_particles();
      void
      read_state_from_particles(const bool initial);
      /// MPI: receive the automata of other ranks within the interaction
      /// range of this rank's slab as ghosts (ghost_records).
      void
                                exchange_ghosts();
      std::vector<double>       ghost_records;
      std::vector<unsigned int> ghost_record_owner;
      void
      build_pair_list(const bool initial);

      // --- dynamics
      void
      evaluate_pairs(const double step, const bool integrate);
      template <bool rotations, bool plastic, bool bonds>
      void
      pair_kernel(const double step);
      void
      apply_boundary_forces(const double t);
      /// Least-squares weights beta of the volumetric strain and inverse
      /// fabric tensors of the owned automata (after rebuilds and changes
      /// of the neighbourhoods).
      void
      update_neighbourhood_weights();
      Sym3
      fabric_corrected(const unsigned int k, const Sym3 &t) const;
      /// Add the eq.-(4) stress contributions of pair @p p to the owned
      /// automata of the pair in @p target (indexed by local automaton).
      void
      add_pair_stress(const unsigned int p, std::vector<Sym3> &target) const;
      /// Sum of @p field (per local automaton) over the owned automata of
      /// each boundary group, over all ranks.
      std::vector<Vec3>
      sum_over_groups(const std::vector<Vec3> &field) const;
      void
      apply_kinematic_constraints(const double t);
      double
      ramp(const double t) const;
      Vec3
      group_value(const BoundaryGroup &g, const double t) const;

      /// Minimum-image vector x_j - x_i.
      dealii::Tensor<1, 3>
      min_image(const Point3 &xi, const Point3 &xj) const;

      const Parameters &prm;
      MPI_Comm          comm;
      unsigned int      n_ranks, rank;

      dealii::parallel::distributed::Triangulation<3>        tria;
      dealii::MappingQ1<3>                                   mapping;
      std::unique_ptr<dealii::Particles::ParticleHandler<3>> particles;
      unsigned int n_automaton_properties = 0, n_slot_fields = 0;

      // material constants indexed by material
      struct MaterialConstants
      {
        double             rho, G, K, D, two_G, yield0, sigma_b, w_b;
        MaterialParameters m;
      };
      std::vector<MaterialConstants> mc;
      bool   plastic_scene = false, bond_scene = false, rotations = true;
      double d = 0, r0 = 0, S = 0, V = 0, mass_factor = 0;
      Vec3   period                = {{0, 0, 0}};
      std::array<bool, 3> periodic = {{false, false, false}};

      double             dt = 0, critical_dt = 0, current_time = 0;
      unsigned long      n_steps_done  = 0;
      unsigned long long n_global      = 0;
      unsigned int       rebuild_count = 0;

      // --- automata (local: owned first, then ghosts)
      unsigned int               n_owned = 0, n_local = 0;
      std::vector<std::uint64_t> id;
      std::vector<Point3>        x, x_at_rebuild;
      std::vector<Vec3>          dx, v, w, f, f_tot, torque, u;
      std::vector<double>        mass, inertia;
      std::vector<unsigned char> mat, body;
      std::vector<std::uint32_t> groups;
      std::vector<double>        eps_p, sigma_y;
      std::vector<Sym3>          stress;
      /// Per-step exchange buffers (stride given by their use).
      std::vector<double> kin;   ///< x(3) dx(3) w(3)
      std::vector<double> mean;  ///< dsm, sum qS, dsm_prev
      std::vector<double> plast; ///< sigma_m trial, M, heat share
      std::vector<double> sum_qs, dsm, dsm_prev, acc_qse;
      std::vector<double> return_factor, mean_trial, heat_share;
      std::vector<Sym3>   trial;
      GhostExchange       ghosts;

      // --- pairs (flat arrays indexed by pair)
      std::vector<std::uint32_t> pi, pj;
      std::vector<unsigned char> bonded, owned_i, owned_j;
      std::vector<double>        q_i, sig_i, sig_j, heat, r_now;
      std::vector<Vec3>          tau_i, tau_j, normal;
      std::vector<double>        deps_i, deps_j, beta_i, beta_j;
      std::vector<Sym3>          fabric_inverse;
      bool                       weights_stale = true;
      std::vector<unsigned char> in_contact;

      double                    plastic_work = 0, friction_work = 0;
      std::vector<Vec3>         group_force_local;
      std::vector<unsigned int> group_count_local;
    };
  } // namespace mca
} // namespace tribodyn

#endif
