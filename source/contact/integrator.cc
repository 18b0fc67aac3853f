// The beta2 time loop: internal forces, predictor, update (doc/theory/
// contact.md section 2).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/contact/element_kernels.h>
#include <tribodyn/contact/postprocessor.h>
#include <tribodyn/contact/spectrum.h>
#include <tribodyn/core/checkpoint.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/interruption.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/plugin_states.h>
#include <tribodyn/core/time_loop.h>

namespace tribodyn
{
  namespace contact
  {
    using namespace dealii;

    namespace
    {
      /// A number in [0, 1) from (seed, index) (splitmix64): the same on any
      /// partition of the dofs.
      double
      uniform_hash(const std::uint64_t seed, const std::uint64_t index)
      {
        std::uint64_t z = seed * 0x9E3779B97F4A7C15ULL + index + 1;
        z               = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z               = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        z               = z ^ (z >> 31);
        return (z >> 11) * (1. / 9007199254740992.);
      }
    } // namespace
    void
    ContactSolver::internal_forces_small_strain()
    {
      if (single_material)
        apply_element_stiffness<true>(
          cell_dofs, cell_material, element_stiffness, w.begin(), r.begin());
      else
        apply_element_stiffness<false>(
          cell_dofs, cell_material, element_stiffness, w.begin(), r.begin());
    }


    void
    ContactSolver::internal_forces_large_deformation()
    {
      const double     *uv      = u.begin();
      const double     *pv      = p.begin();
      double           *rv      = r.begin();
      const double      beta    = prm.time.damping;
      const std::size_t n_cells = cell_material.size();
      // Component of each local dof as a 0/1 mask (no branches below).
      double is_y[8];
      for (unsigned int i = 0; i < 8; ++i)
        is_y[i] = dof_component[i];
      for (std::size_t c = 0; c < n_cells; ++c)
        {
          const unsigned int *idx = &cell_dofs[8 * c];
          const unsigned int  mat = cell_material[c];
          const double C00 = stiffness[mat][0][0], C01 = stiffness[mat][0][1],
                       C02 = stiffness[mat][0][2], C11 = stiffness[mat][1][1],
                       C12 = stiffness[mat][1][2], C22 = stiffness[mat][2][2];
          const double *K = element_stiffness[mat].data();
          double        ue[8], pe[8], fe_[8] = {};
          for (unsigned int j = 0; j < 8; ++j)
            {
              ue[j] = uv[idx[j]];
              pe[j] = pv[idx[j]];
            }
          for (unsigned int q = 0; q < 4; ++q)
            {
              // Displacement gradient H[c][d] = sum_i u_i delta(c_i, c)
              // dN/dx_d.
              double Hx0 = 0, Hx1 = 0, Hy0 = 0, Hy1 = 0;
              for (unsigned int i = 0; i < 8; ++i)
                {
                  const double ux = ue[i] * (1. - is_y[i]),
                               uy = ue[i] * is_y[i];
                  Hx0 += ux * grad_x[q][i];
                  Hx1 += ux * grad_y[q][i];
                  Hy0 += uy * grad_x[q][i];
                  Hy1 += uy * grad_y[q][i];
                }
              const double F00 = 1 + Hx0, F01 = Hx1, F10 = Hy0, F11 = 1 + Hy1;
              // Green-Lagrange strain (Voigt, 2 E_xy) and S = C E.
              const double E00 = 0.5 * (F00 * F00 + F10 * F10 - 1.);
              const double E11 = 0.5 * (F01 * F01 + F11 * F11 - 1.);
              const double G01 = F00 * F01 + F10 * F11;
              const double S0  = C00 * E00 + C01 * E11 + C02 * G01;
              const double S1  = C01 * E00 + C11 * E11 + C12 * G01;
              const double S2  = C02 * E00 + C12 * E11 + C22 * G01;
              // First Piola-Kirchhoff P = F S.
              const double P00 = F00 * S0 + F01 * S2, P01 = F00 * S2 + F01 * S1;
              const double P10 = F10 * S0 + F11 * S2, P11 = F10 * S2 + F11 * S1;
              for (unsigned int i = 0; i < 8; ++i)
                {
                  const double fx = P00 * grad_x_w[q][i] + P01 * grad_y_w[q][i];
                  const double fy = P10 * grad_x_w[q][i] + P11 * grad_y_w[q][i];
                  fe_[i] += fx + is_y[i] * (fy - fx);
                }
            }
          for (unsigned int i = 0; i < 8; ++i)
            {
              double s = 0;
              for (unsigned int j = 0; j < 8; ++j)
                s += K[8 * i + j] * pe[j];
              rv[idx[i]] += fe_[i] + beta * s;
            }
        }
    }


    void
    ContactSolver::set_initial_state()
    {
      // u_0 = 0, p_0 = v_0 (held dofs at rest), a = 0, and u_{-1} = u_0 -
      // dt p_0 so that p_n = (u_n - u_{n-1})/dt (energy accounting).
      const unsigned int n_owned     = mass.size();
      const double       beta        = prm.time.damping;
      double            *pv          = p.begin();
      double             e0          = 0;
      const auto        &partitioner = *u.get_partitioner();
      const double       noise       = prm.loading.velocity_perturbation;
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          pv[i] = mass_inverse[i] == 0
                    ? 0.
                    : prm.loading.initial_velocity[component[i]];
          if (!initial_velocity_field.empty() && mass_inverse[i] != 0)
            pv[i] += initial_velocity_field[i];
          if (noise > 0 && mass_inverse[i] != 0)
            pv[i] += noise
                     * (2.
                          * uniform_hash(prm.loading.perturbation_seed,
                                         partitioner.local_to_global(i))
                        - 1.);
          u.local_element(i)      = 0;
          u_prev.local_element(i) = -dt * pv[i];
          a.local_element(i)      = 0;
          w.local_element(i)      = beta * pv[i];
          e0 += 0.5 * mass[i] * pv[i] * pv[i];
        }
      energy_initial = Utilities::MPI::sum(e0, comm);
      r              = 0;
      step_count     = 0;
      work_external = work_internal = work_contact = dissipation_friction = 0;
      scale_energy = energy_initial;
      history.clear();
      for (ContactNode &node : contact_nodes)
        node = ContactNode{node.ix, node.iy, node.m, node.x, node.length};
    }


    void
    ContactSolver::enable_checkpoints(
      const CheckpointParameters &parameters,
      const ResumableParameters  &parameter_lines)
    {
      checkpoints_on        = true;
      checkpoint            = parameters;
      checkpoint_parameters = parameter_lines;
    }


    std::string
    ContactSolver::friction_progress_key(const Sample &smp)
    {
      std::ostringstream key;
      key << "mu_global = " << std::fixed << std::setprecision(4)
          << smp.mu_global << "  stick/slip/sep = " << std::setprecision(2)
          << smp.stick_fraction << "/" << smp.slip_fraction << "/"
          << smp.separation_fraction;
      return key.str();
    }


    double
    ContactSolver::velocity_limit() const
    {
      const auto &L = prm.loading;
      return c_maximum + L.plane_speed_maximum() + L.initial_velocity.norm()
             + L.velocity_perturbation;
    }


    /**
     * The beta2 run as the common time loop drives it: a step is the
     * internal forces, the predictor, the contact multipliers of t_{n+1}
     * and the corrector; the ranks agree on its health every step on one
     * rank, every health_check_interval steps and at each sample on
     * several; a sample records the solver's Sample and hands it to the
     * postprocessors; a checkpoint carries the solver's state and the
     * postprocessors' by name.
     */
    class ContactSolver::Steps : public SteppedRun
    {
    public:
      Steps(ContactSolver                               &solver,
            LoopState                                   &loop,
            std::vector<std::unique_ptr<Postprocessor>> &outputs,
            const std::vector<std::string>              &output_names,
            CheckpointStore                             *store,
            const bool                                   large)
          : solver(solver)
          , loop(loop)
          , outputs(outputs)
          , output_names(output_names)
          , store(store)
          , large(large)
          , several(Utilities::MPI::n_mpi_processes(solver.comm) > 1)
          , v_limit(solver.velocity_limit())
      {
      }

      unsigned long
      steps_done() const override
      {
        return solver.step_count;
      }

      double
      time() const override
      {
        return solver.step_count * solver.dt;
      }

      bool
      sample_due(const unsigned long index) const override
      {
        return index % solver.prm.output.sample_interval == 0;
      }

      void
      advance(const LoopStep &step) override
      {
        ContactSolver &S = solver;
        const double   t = step.index * S.dt;
        const double   s = S.prm.loading.pressure_at(t);
        // Internal forces of u_n and the damping force beta K p_n.
        S.add_internal_forces(large);
        S.predict(s);
        if (step.sample || step.last)
          {
            // Reaction of the held top face: R = r - f (a = 0 there).
            double f = 0;
            if (S.prm.loading.top_held_in_x)
              for (const unsigned int i : S.top_x_dofs)
                f += S.r.local_element(i) - s * S.unit_load[i];
            top_force = Utilities::MPI::sum(f, S.comm);
          }
        // Contact and friction: multipliers at t_{n+1}.
        S.solve_contact(t + S.dt);
        n_bad += S.correct(s, S.prm.time.damping, v_limit);
        S.u_prev.swap(S.u); // u_prev = u_n
        S.u.swap(S.u_next); // u = u_{n+1}
        ++S.step_count;
      }

      bool
      health_due(const LoopStep &step) const override
      {
        return !several || step.sample || step.last
               || solver.step_count % health_check_interval == 0;
      }

      RunHealth
      agree_on_health(const LoopStep &) override
      {
        const RunHealth health = tribodyn::agree_on_health(n_bad, solver.comm);
        n_bad                  = 0;
        return health;
      }

      [[noreturn]] void
      report_instability(const LoopStep &step) override
      {
        solver.report_instability(step.index,
                                  step.index * solver.dt + solver.dt);
      }

      void
      after_step(const LoopStep &step) override
      {
        for (auto &o : outputs)
          o->after_step(step.index * solver.dt);
      }

      void
      sample(const LoopStep &step) override
      {
        take_sample(step);
      }

      void
      end_of_run(const LoopStep &step) override
      {
        if (!step.sample)
          take_sample(step);
      }

      /// Flush the series and save the state after step_count steps.
      void
      save_checkpoint() override
      {
        if (!store)
          return;
        flush_outputs(true);
        loop.outputs = save_plugin_states(outputs, output_names);
        store->write(solver.save_state(loop),
                     solver.step_count,
                     solver.step_count * solver.dt,
                     solver.checkpoint_parameters);
      }

      void
      stop_early() override
      {
        flush_outputs(true);
      }

      std::string
      progress_key() const override
      {
        return key;
      }

    private:
      /// Record the sample of step n (time t_n), its rows and the key
      /// figure of the progress lines.
      void
      take_sample(const LoopStep &step)
      {
        const unsigned long n = step.index;
        const double        t = n * solver.dt;
        solver.record_sample(t);
        Sample &smp          = solver.history.back();
        smp.tangential_force = top_force;
        smp.mu_global = solver.prm.loading.top_held_in_x && smp.normal_force > 0
                          ? -(solver.prm.loading.plane_velocity >= 0 ? 1. : -1.)
                              * top_force / smp.normal_force
                          : smp.mu_contact;
        for (auto &o : outputs)
          o->sample(smp);
        flush_outputs(false);
        key = solver.progress_key(smp);
        if (!std::isfinite(smp.kinetic_energy) || !std::isfinite(smp.mu_global))
          throw RunError("The solution became non-finite at t = "
                         + format_number(t) + " s (step " + std::to_string(n)
                         + "): the run is unstable.");
      }

      void
      flush_outputs(const bool complete)
      {
        for (auto &o : outputs)
          o->flush(complete);
      }

      ContactSolver                               &solver;
      LoopState                                   &loop;
      std::vector<std::unique_ptr<Postprocessor>> &outputs;
      const std::vector<std::string>              &output_names;
      CheckpointStore                             *store;
      const bool                                   large;
      const bool                                   several;
      const double                                 v_limit;
      /// The reaction of the held top face at the step's sample.
      double top_force = 0;
      /// Unstable dofs counted since the last health check.
      double      n_bad = 0;
      std::string key;
    };


    void
    ContactSolver::run(const std::string &output_directory,
                       const double       progress_interval)
    {
      const bool root  = Utilities::MPI::this_mpi_process(comm) == 0;
      const auto start = std::chrono::steady_clock::now();
      const bool large
        = prm.material.kinematics
          == ContactMaterialParameters::Kinematics::large_deformation;
      const bool write = !output_directory.empty();

      // Initial state, or the state of the latest checkpoint.
      LoopState                        loop;
      std::unique_ptr<CheckpointStore> store;
      if (write && checkpoints_on)
        store = std::make_unique<CheckpointStore>(output_directory,
                                                  "contact",
                                                  comm);
      const bool resumed = store && checkpoint.resume;
      if (resumed)
        {
          CheckpointInfo info;
          load_state(store->read(checkpoint_parameters, info), loop);
          const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
          if (root)
            {
              std::cout << "Resuming from the checkpoint at t = " << info.time
                        << " s (step " << info.step << ")";
              if (info.n_ranks != n_ranks)
                std::cout << ", written by " << info.n_ranks
                          << " MPI rank(s): state redistributed over "
                          << n_ranks;
              std::cout << std::endl;
            }
        }
      else
        set_initial_state();
      const unsigned long n_steps = TimeLoop::n_steps(prm.time.end_time, dt);
      if (resumed)
        TimeLoop::check_something_to_resume(step_count,
                                            step_count * dt,
                                            n_steps,
                                            "Time/End time",
                                            prm.time.end_time);
      // The outputs (source/contact/postprocessors/): made for runs that
      // write (the user's list checked before anything is touched), each
      // with its state from the checkpoint (by name).
      outputs.clear();
      std::vector<std::string> output_names;
      if (write)
        outputs = PostprocessorRegistry::create_all(
          {*this, prm, output_directory, comm, root},
          output_names,
          prm.output.postprocessors);
      // Every check passed: the output directory may be touched from here.
      if (output_claim)
        output_claim(resumed ? OutputClaim::resume : OutputClaim::fresh);
      if (store && !resumed)
        store->discard();
      steps_at_start = step_count;

      if (write)
        {
          load_plugin_states(loop.outputs, outputs, output_names);
          for (auto &o : outputs)
            o->open(resumed);
        }
      // The steps: the common loop (core/time_loop.h) drives Steps below.
      Steps steps(*this, loop, outputs, output_names, store.get(), large);
      TimeLoopSettings settings;
      settings.n_steps             = n_steps;
      settings.time_step           = dt;
      settings.end_time            = n_steps * dt;
      settings.checkpoint_interval = store ? checkpoint.interval : 0.;
      if (store)
        settings.checkpoint_directory = store->directory();
      settings.show_progress     = root && progress_interval >= 0;
      settings.progress_interval = std::max(0., progress_interval);
      settings.label             = progress_label;
      TimeLoop time_loop(settings);
      time_loop.run(steps);
      const double loop_seconds = time_loop.step_seconds();
      loop_wall_time            = loop_seconds;
      for (auto &o : outputs)
        {
          o->flush(true);
          o->close();
        }
      run_wall_time = std::chrono::duration<double>(
                        std::chrono::steady_clock::now() - start)
                        .count();
    }


    void
    ContactSolver::finish_outputs(JsonValue    &summary,
                                  std::ostream &figures) const
    {
      for (const auto &o : outputs)
        o->finish(summary, figures);
    }


    void
    ContactSolver::predict(const double s)
    {
      // a* = M^-1 (f_n - r), u* = u_n + dt p_n + h a*.
      const unsigned int n_owned = mass.size();
      const double      *uv      = u.begin();
      const double      *pv      = p.begin();
      const double      *rv      = r.begin();
      double            *un      = u_next.begin();
      double            *av      = a.begin();
      const double      *fv      = unit_load.data();
      const double      *mi      = mass_inverse.data();
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          const double ai = (s * fv[i] - rv[i]) * mi[i];
          un[i]           = uv[i] + dt * pv[i] + h * ai;
          av[i]           = ai;
        }
    }


    unsigned int
    ContactSolver::correct(const double s,
                           const double beta,
                           const double v_limit)
    {
      const unsigned int n_owned = mass.size();
      const double      *up      = u_prev.begin();
      const double      *un      = u_next.begin();
      const double      *av      = a.begin();
      double            *pv      = p.begin();
      double            *wv      = w.begin();
      double            *rv      = r.begin();
      const double      *fv      = unit_load.data();
      double             we = 0, wi = 0;
      unsigned int       bad = 0;
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          const double d = 0.5 * (un[i] - up[i]);
          we += s * fv[i] * d;
          wi += rv[i] * d;
          const double pn = pv[i] + dt * av[i];
          pv[i]           = pn;
          wv[i]           = un[i] + beta * pn;
          rv[i]           = 0;
          bad += !(std::abs(pn) <= v_limit);
        }
      work_external += we;
      work_internal += wi;
      return bad;
    }


    void
    ContactSolver::add_internal_forces(const bool large)
    {
      // r += K(u_n + beta p_n) (small strain: w holds u + beta p) or the
      // total-Lagrangian internal forces of u and p; ghosts are refreshed
      // first, contributions to ghost rows are sent to their owners after.
      if (large)
        {
          u.update_ghost_values();
          p.update_ghost_values();
          internal_forces_large_deformation();
        }
      else
        {
          w.update_ghost_values();
          internal_forces_small_strain();
        }
      r.compress(VectorOperation::add);
    }


    double
    ContactSolver::max_internal_force()
    {
      r = 0;
      const bool large
        = prm.material.kinematics
          == ContactMaterialParameters::Kinematics::large_deformation;
      add_internal_forces(large);
      const double result = r.linfty_norm();
      r                   = 0;
      return result;
    }


  } // namespace contact
} // namespace tribodyn
