#ifndef tribodyn_contact_contact_solver_h
#define tribodyn_contact_contact_solver_h

#include <array>
#include <deal.II/base/index_set.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <tribodyn/contact/contact_parameters.h>
#include <tribodyn/contact/friction_laws.h>
#include <tribodyn/contact/postprocessor.h>
#include <tribodyn/core/checkpoint.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/output_directory.h>
#include <vector>

namespace tribodyn
{
  namespace contact
  {
    /// One record of the time series (all ranks hold the reduced values).
    struct Sample
    {
      double time = 0;
      /// Resultant of the applied pressure (N per m of thickness).
      double normal_force = 0;
      /// Reaction of the top face along x (the friction force seen there).
      double tangential_force = 0;
      /// -sign(V) tangential_force / normal_force.
      double mu_global = 0;
      /// Sums of the contact multipliers (forces of the plane on the pin).
      double contact_tangential_force = 0;
      double contact_normal_force     = 0;
      double mu_contact               = 0;
      /// Energies (J per m of thickness), see doc/theory/contact.md.
      double kinetic_energy       = 0;
      double elastic_energy       = 0;
      double external_work        = 0;
      double contact_work         = 0;
      double damping_dissipation  = 0;
      double friction_dissipation = 0;
      double energy_balance_error = 0;
      /// Linear momentum of the pin.
      double momentum_x = 0;
      double momentum_y = 0;
      /// Point M (central contact node): displacement, velocity, status.
      double       M_ux = 0, M_vx = 0, M_uy = 0, M_vy = 0;
      unsigned int M_status = 0;
      /// Fractions of the contact nodes in each status.
      double stick_fraction = 0, slip_fraction = 0, separation_fraction = 0;
    };

    /**
     * Name of a contact regime from the time fractions of the statuses:
     * a status counts when its fraction is above @p threshold
     * ("slip", "slip-separation", "stick-slip", "stick-slip-separation",
     * "stick", "stick-separation", "separation"; "none" if nothing does).
     */
    std::string
    classify_regime(const double stick,
                    const double slip,
                    const double separation,
                    const double threshold);

    /// Headline figures of a run (summary.json).
    struct RunSummary
    {
      double mu_global_mean        = 0;
      double mu_contact_mean       = 0;
      double dominant_frequency_hz = 0;
      double energy_balance_error  = 0;
      double stick_fraction = 0, slip_fraction = 0, separation_fraction = 0;
      double M_stick_fraction = 0, M_slip_fraction = 0,
             M_separation_fraction = 0;
      std::string regime;
      /// Regime from the time fractions of all contact node-samples.
      std::string  regime_contact_face;
      double       normal_force_dominant_frequency_hz = 0;
      unsigned int n_samples_averaged                 = 0;
      double       wall_time_s                        = 0;
      double       time_loop_s                        = 0;
      double       dof_steps_per_second               = 0;
    };

    /**
     * The explicit dynamic contact-with-friction solver of seed 001, §2.3:
     * a Q1 plane-strain pin with lumped mass on a rigid plane translating
     * at V, the beta2 scheme with stiffness-proportional damping applied
     * explicitly, forward-increment Lagrange multipliers for contact and
     * friction. See doc/theory/contact.md for the equations in the symbols
     * used here.
     */
    class ContactSolver
    {
    public:
      ContactSolver(const MPI_Comm           comm,
                    const ContactParameters &parameters,
                    dealii::TimerOutput     &timer);

      /// Mesh, dofs, element matrices, lumped mass, loads, critical dt.
      /// Throws InputError when the time step is above the critical one
      /// (unless the automatic time step is on).
      void
      setup();

      /**
       * Checkpoints of the next run() (called before it): periodic ones
       * every @p parameters.interval of simulated time, one at the end and
       * on SIGTERM/SIGINT; with @p parameters.resume, run() continues from
       * the latest checkpoint of its output directory. @p parameter_lines
       * identify the run (resumable_parameters()).
       */
      void
      enable_checkpoints(const CheckpointParameters &parameters,
                         const ResumableParameters  &parameter_lines);

      /**
       * Called by run() once the run has passed its last check (the resume
       * checks) and before it writes its first file: the driver claims the
       * output directory there (RunContext::claim_output()). None by
       * default (tests, runs without output).
       */
      void
      set_output_claim(std::function<void(OutputClaim)> claim)
      {
        output_claim = std::move(claim);
      }

      /// This rank's contact nodes and their state after the last step.
      const std::vector<ContactNode> &
      contact_node_states() const
      {
        return contact_nodes;
      }

      /// The friction law's figures at the end of the run (collective).
      void
      report_friction_law(JsonValue &summary, std::ostream &figures) const;

      /// The summary.json keys and screen figures of the last run's
      /// outputs (their finish(), in the list's order; collective).
      void
      finish_outputs(JsonValue &summary, std::ostream &figures) const;

      /// The default key figure of the progress lines: mu_global and the
      /// stick/slip/separation fractions of the contact nodes.
      static std::string
      friction_progress_key(const Sample &sample);

      /**
       * The progress lines of run(): their @p label ("contact" by default)
       * and the key figure printed from the latest sample (by default
       * mu_global and the stick/slip/separation fractions). A driver that
       * uses the solver for something else (the beam verification) says
       * what it measures.
       */
      void
      set_progress_report(const std::string                         &label,
                          std::function<std::string(const Sample &)> key)
      {
        progress_label = label;
        progress_key   = std::move(key);
      }

      /**
       * Integrate to the end time. With a non-empty @p output_directory,
       * write friction.csv, point_M.csv, contact_status.csv, spectrum.csv,
       * fields_*.vtu + fields.pvd. @p progress_interval: seconds between
       * progress lines (negative: none).
       *
       * Every step, each rank checks that the velocities of its dofs are
       * finite and below c_max + |V| + |v_0| (a material velocity near the
       * wave speed means strains of order one: the scheme is unstable); the
       * ranks agree on it every step on one rank, every
       * health_check_interval steps and at each sample on several. An
       * unstable run throws RunError naming the step, the time, the node
       * and the likely cause, before the bad state is sampled.
       */
      void
      run(const std::string &output_directory,
          const double       progress_interval = 5.);

      /**
       * The fields of t_n (displacement, velocity, stresses, contact
       * status) as the VTU file @p file_name in @p dir, called after step n
       * (the state then holds t_{n+1}; the postprocessor "fields").
       */
      void
      write_fields_of_step(const std::string &dir,
                           const double       time,
                           const std::string &file_name);

      /// Time averages, spectrum peaks and regime over the averaging
      /// window.
      RunSummary
      summarize() const;

      /// The series the spectra are taken of (doc/theory/contact.md Sec.
      /// 5): mu_global and the contact normal force of the samples in the
      /// averaging window on the regular cadence (every Output/Sample
      /// interval steps: the sample of a run's last step is off that grid,
      /// and a spectrum assumes equal spacing), and their spacing (s).
      struct SpectrumSeries
      {
        std::vector<double> mu, normal;
        double              spacing = 0;
        /// The lowest frequency a peak is looked for at (the lower ones are
        /// trends over the window).
        double
        lowest_peak_frequency() const
        {
          return mu.empty() ? 0 : 2. / (mu.size() * spacing);
        }
      };
      SpectrumSeries
      spectrum_series() const;

      const std::vector<Sample> &
      samples() const
      {
        return history;
      }

      double
      time_step() const
      {
        return dt;
      }
      /// Steps between two collective stability checks on several ranks.
      static constexpr unsigned int health_check_interval = 10;

      /// Critical dt of the damped beta2 scheme (element eigenvalue bound).
      double
      critical_time_step() const
      {
        return dt_critical;
      }
      /// l_min / c_max (seed eq. (3)), for information.
      double
      cfl_time_step() const
      {
        return dt_cfl;
      }
      /// Largest element eigenfrequency omega_max (rad/s).
      double
      omega_max() const
      {
        return omega_maximum;
      }
      dealii::types::global_dof_index
      n_dofs() const;
      unsigned long
      n_steps_done() const
      {
        return step_count;
      }
      unsigned int
      n_contact_nodes() const
      {
        return n_contact_nodes_global;
      }
      /// Ranks that own contact nodes (the Gauss-Seidel sweep over the
      /// contact face crosses them).
      unsigned int
      n_contact_face_ranks() const
      {
        return n_contact_face_ranks_global;
      }
      double
      total_mass() const
      {
        return mass_total;
      }
      /// Length of the contact face: the nodes' tributary lengths summed
      /// over all ranks (the bottom face less its voids).
      double
      contact_face_length() const;
      /// Area fraction of the cells with material index 1 (meso pins:
      /// the heterogeneities), over all ranks.
      double
      heterogeneity_area_fraction() const;
      std::string
      material_description() const
      {
        return material_text;
      }

      /// Testing aid: set the displacement (velocity zero) to @p field.
      void
      set_displacement(
        const std::function<dealii::Tensor<1, 2>(const dealii::Point<2> &)>
          &field);
      /// Add the velocity field @p field (evaluated at the nodes) to the
      /// initial velocity of the next run() (after setup(); held dofs stay
      /// at rest). Used by the beam-vibration verification.
      void
      set_initial_velocity_field(
        const std::function<dealii::Tensor<1, 2>(const dealii::Point<2> &)>
          &field);
      /// Testing aid: largest |internal force| entry for the current
      /// displacement (no damping), and the largest von Mises stress of the
      /// cell-centre stresses.
      double
      max_internal_force();
      double
      max_von_mises();

    private:
      /// The run as the common time loop drives it (integrator.cc).
      class Steps;
      /// Counters of run() that a checkpoint carries besides the solver
      /// state (the rows of the series already written, the fields).
      struct LoopState
      {
        /// The postprocessors' states by name (Postprocessor::save()).
        std::vector<std::pair<std::string, std::string>> outputs;
      };
      /// Initial state u_0 = 0, p_0 = v_0 (run() without resume).
      void
      set_initial_state();
      /// The state after step_count steps as a Boost binary archive, and
      /// back from this rank's share of the writers' archives (any number
      /// of ranks; source/contact/checkpoint.cc).
      std::string
      save_state(const LoopState &loop) const;
      void
      load_state(const std::vector<std::string> &blobs, LoopState &loop);
      /// Coordinates of the node of each owned dof (local index).
      std::vector<std::array<double, 2>>
      owned_dof_points() const;
      /// Collective: find the worst dof and throw RunError describing the
      /// instability found at step @p step (time @p time).
      [[noreturn]] void
      report_instability(const unsigned long step, const double time) const;
      /// Velocity above which a dof counts as unstable (m/s).
      double
      velocity_limit() const;

      void
      make_mesh();
      /// The meso pin's mesh with the pores of @p pores (by material id)
      /// cut out, and the solid fragments they detach from the top face.
      void
      make_porous_mesh(const Morphology        &morphology,
                       const std::vector<bool> &pores);
      void
      setup_materials();
      void
      setup_element_data();
      void
      setup_vectors_and_nodes();
      void
      compute_critical_time_step();

      /// r += internal force of w (small strain: K (u + beta p)).
      void
      internal_forces_small_strain();
      /// r += f_int(u) + beta K p (total Lagrangian St Venant-Kirchhoff).
      void
      internal_forces_large_deformation();
      /// Refresh the ghosts the internal forces need, add them to r with
      /// the small-strain or the large-deformation path, and compress r.
      void
      add_internal_forces(const bool large);
      template <class Law>
      void
      contact_node_wise(const Law &law);
      template <class Law>
      void
      contact_gauss_seidel(const Law &law);
      void
      solve_contact(const double time_next);
      /// The predictor of a step at load factor @p s: u_next = u* and
      /// a = a*.
      void
      predict(const double s);
      /// After the contact correction: velocities p_{n+1}, w = u + beta p,
      /// the works of the step; returns the number of dofs whose velocity
      /// is not finite or above @p v_limit.
      unsigned int
      correct(const double s, const double beta, const double v_limit);

      void
      record_sample(const double time);
      void
      write_fields(const std::string &dir,
                   const double       time,
                   const std::string &file_name);
      void
      cell_stresses(std::vector<std::array<double, 4>> &stress) const;

      MPI_Comm                                        comm;
      const ContactParameters                        &prm;
      dealii::TimerOutput                            &timer;
      dealii::parallel::distributed::Triangulation<2> triangulation;
      dealii::FESystem<2>                             fe;
      dealii::DoFHandler<2>                           dof_handler;
      dealii::IndexSet                                locally_owned;
      dealii::IndexSet                                locally_relevant;

      using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;
      VectorType u, u_prev, u_next, p, w, r, a, scratch, scratch_result;

      // Per owned dof: lumped mass, its inverse (0 on held dofs), the
      // nodal load of a unit pressure, and the component.
      std::vector<double>        mass, mass_inverse, unit_load;
      std::vector<unsigned char> component;
      std::vector<unsigned int>  top_x_dofs; // held dofs (local indices)
      std::vector<double>        initial_velocity_field; // owned dofs, or empty
      std::vector<unsigned int>  top_y_dofs;

      // Cells: 8 local dof indices each, material index, element data.
      std::vector<unsigned int>                     cell_dofs;
      std::vector<unsigned char>                    cell_material;
      std::vector<dealii::types::global_cell_index> cell_active_index;
      std::vector<std::array<double, 64>> element_stiffness; // per material
      std::vector<VoigtStiffness>         stiffness;         // per material
      std::vector<dealii::Tensor<1, 3>>   stiffness_z;       // per material
      std::vector<double>                 density;           // per material
      // Shape data of the (identical) rectangular cells: for local dof i,
      // node and component; gradients of the node's shape function at the
      // four Gauss points and at the centre; JxW.
      std::array<unsigned int, 8> dof_node, dof_component;
      std::array<std::array<dealii::Tensor<1, 2>, 4>, 4> grad_q;
      std::array<dealii::Tensor<1, 2>, 4>                grad_center;
      std::array<double, 4>                              JxW;
      // The same gradients per local dof and Gauss point as plain arrays,
      // pre-multiplied by JxW for the force (large-deformation loop).
      double grad_x[4][8], grad_y[4][8], grad_x_w[4][8], grad_y_w[4][8];
      double cell_hx = 0, cell_hy = 0;
      /// Width of the pin's rectangle (its bottom face with the voids).
      double pin_width       = 0;
      bool   single_material = true;
      /// Whether any cell of the mesh (on any rank) has material k: the
      /// materials of the time step bound (a pore's is cut out).
      std::vector<bool> material_in_mesh;

      // Contact nodes (owned; include/tribodyn/contact/friction_law.h).
      /// Plane height under a node at x (current position) when the plane
      /// has moved by @p plane_x: 0 for a flat plane, in [-A, 0] with the
      /// waviness (y = -gap + this).
      double
      plane_height(const double x, const double plane_x) const;
      std::vector<ContactNode> contact_nodes;
      unsigned int             n_contact_nodes_global      = 0;
      unsigned int             n_contact_face_ranks_global = 0;
      int                      point_M_index               = -1; // local, or -1
      double                   point_M_x                   = 0;

      double dt = 0, h = 0, dt_critical = 0, dt_cfl = 0, omega_maximum = 0;
      double c_maximum      = 0; ///< largest P-wave speed of the materials
      bool   checkpoints_on = false;
      std::function<void(OutputClaim)>           output_claim;
      std::string                                progress_label = "contact";
      std::function<std::string(const Sample &)> progress_key
        = &friction_progress_key;
      CheckpointParameters checkpoint;
      ResumableParameters  checkpoint_parameters;
      /// The last run's outputs (source/contact/postprocessors/), kept
      /// for finish_outputs().
      std::vector<std::unique_ptr<Postprocessor>> outputs;
      double                                      mass_total = 0;
      std::string                                 material_text;
      /// The friction law of the run (Contact/Friction law).
      FrictionLaws::Variant friction_law;
      // Plane motion over the current step (t_n -> t_{n+1}): displacement
      // and position at t_{n+1}.
      double        plane_slide = 0, plane_x_next = 0;
      unsigned long step_count         = 0;
      unsigned long steps_at_start     = 0; ///< step_count when run() began
      unsigned int  pgs_iterations_max = 0;

      // Energy accumulators (local sums; reduced when sampled).
      double work_external = 0, work_internal = 0, work_contact = 0,
             dissipation_friction = 0, energy_initial = 0;
      double scale_energy = 0; // largest energy seen (for the error)

      std::vector<Sample> history;
      double              run_wall_time = 0, loop_wall_time = 0;
    };
  } // namespace contact
} // namespace tribodyn

#endif
