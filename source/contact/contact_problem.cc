#include <chrono>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <tribodyn/contact/contact_problem.h>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/json.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/time_loop.h>

namespace tribodyn
{
  namespace contact
  {
    using dealii::ParameterHandler;

    void
    ContactProblem::declare_parameters(ParameterHandler &prm)
    {
      ContactParameters::declare_parameters(prm);
      CheckpointParameters::declare_parameters(prm);
    }


    ContactProblem::ContactProblem(ParameterHandler &prm,
                                   const RunContext &context)
        : context(context)
    {
      parameters.parse_parameters(prm);
      checkpoint.parse_parameters(prm);
      parameters.check_averaging_window(checkpoint.interval > 0);
      checkpoint_lines = resumable_parameters(prm, "Time/End time");
      checkpoints_on   = true;
    }


    ContactProblem::ContactProblem(const ContactParameters &parameters,
                                   const RunContext        &context)
        : context(context)
        , parameters(parameters)
    {
    }


    void
    ContactProblem::run()
    {
      const auto     start = std::chrono::steady_clock::now();
      const MPI_Comm comm  = context.mpi_communicator;
      const bool     root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      dealii::ConditionalOStream pcout(std::cout, root);
      auto                       timer = std::make_unique<dealii::TimerOutput>(
        comm,
        pcout,
        dealii::TimerOutput::summary,
        dealii::TimerOutput::wall_times);
      try
        {
          run_with_timer(*timer, start);
        }
      catch (...)
        {
          // No timing table (and no MPI exchange in its destructor while an
          // exception is in flight) for a run that failed.
          timer->disable_output();
          timer.reset();
          throw;
        }
    }


    void
    ContactProblem::run_with_timer(
      dealii::TimerOutput                         &timer,
      const std::chrono::steady_clock::time_point &start)
    {
      const MPI_Comm comm = context.mpi_communicator;
      const bool     root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      dealii::ConditionalOStream pcout(std::cout, root);

      ContactSolver solver(comm, parameters, timer);
      solver.setup();
      if (checkpoints_on)
        solver.enable_checkpoints(checkpoint, checkpoint_lines);
      if (!context.output_directory.empty())
        solver.set_output_claim(
          [this](const OutputClaim how) { context.claim_output(how); });
      const unsigned long n_steps
        = TimeLoop::n_steps(parameters.time.end_time, solver.time_step());
      pcout << "Pin: " << solver.material_description() << "\n"
            << "Mesh: " << solver.n_dofs() << " degrees of freedom, "
            << solver.n_contact_nodes() << " contact nodes, "
            << dealii::Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)\n"
            << "Time step " << solver.time_step() << " s (critical "
            << solver.critical_time_step() << " s, CFL l_min/c_max "
            << solver.cfl_time_step() << " s), " << n_steps << " steps, "
            << "friction law " << parameters.contact.friction.selected_name()
            << ", P = " << parameters.loading.pressure / 1e6 << " MPa"
            << std::endl;

      {
        dealii::TimerOutput::Scope scope(timer, "time loop");
        solver.run(context.output_directory, context.progress_interval);
      }
      RunSummary s;
      {
        dealii::TimerOutput::Scope scope(timer, "summary");
        s = solver.summarize();
      }
      recorded_samples       = solver.samples();
      run_summary            = s;
      const double wall_time = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - start)
                                 .count();

      JsonValue summary           = summary_header("contact", comm);
      summary["material"]         = solver.material_description();
      summary["friction_law"]     = parameters.contact.friction.selected_name();
      summary["pressure"]         = parameters.loading.pressure;
      summary["plane_velocity"]   = parameters.loading.plane_velocity;
      summary["mu_global_mean"]   = s.mu_global_mean;
      summary["mu_contact_mean"]  = s.mu_contact_mean;
      summary["averaging_window"] = json_array(
        {parameters.output.average_start,
         parameters.output.average_end < 0 ? parameters.time.end_time
                                           : parameters.output.average_end});
      summary["n_samples_averaged"] = s.n_samples_averaged;
      // A leg that ends before its window: the averages are undefined
      // (null), the next leg reaches the window.
      summary["averaging_window_empty"] = s.n_samples_averaged == 0;
      summary["dominant_frequency_hz"]  = s.dominant_frequency_hz;
      summary["energy_balance_error"]   = s.energy_balance_error;
      summary["stick_fraction"]         = s.stick_fraction;
      summary["slip_fraction"]          = s.slip_fraction;
      summary["separation_fraction"]    = s.separation_fraction;
      JsonValue M                       = JsonValue::object();
      M["stick_fraction"]               = s.M_stick_fraction;
      M["slip_fraction"]                = s.M_slip_fraction;
      M["separation_fraction"]          = s.M_separation_fraction;
      summary["point_M"]                = M;
      summary["regime"]                 = s.regime;
      summary["regime_contact_face"]    = s.regime_contact_face;
      summary["regime_threshold"]       = parameters.output.regime_threshold;
      summary["normal_force_dominant_frequency_hz"]
        = s.normal_force_dominant_frequency_hz;
      summary["n_dofs"] = static_cast<unsigned long long>(solver.n_dofs());
      summary["n_contact_nodes"]      = solver.n_contact_nodes();
      summary["n_contact_face_ranks"] = solver.n_contact_face_ranks();
      summary["n_steps"]              = solver.n_steps_done();
      summary["dt"]                   = solver.time_step();
      summary["critical_dt"]          = solver.critical_time_step();
      summary["cfl_dt"]               = solver.cfl_time_step();
      summary["omega_max"]            = solver.omega_max();
      summary["end_time"]             = parameters.time.end_time;
      summary["time_loop_s"]          = s.time_loop_s;
      summary["dof_steps_per_second"] = s.dof_steps_per_second;
      summary["dof_steps_per_second_per_rank"]
        = s.dof_steps_per_second
          / dealii::Utilities::MPI::n_mpi_processes(comm);
      summary["wall_time_s"] = wall_time;
      std::ostringstream law_figures;
      solver.report_friction_law(summary, law_figures);
      solver.finish_outputs(summary, law_figures);
      if (root)
        write_file_atomically(join_path(context.output_directory,
                                        "summary.json"),
                              summary.dump() + "\n");

      if (s.n_samples_averaged == 0)
        pcout << "\nThe averaging window (from "
              << parameters.output.average_start
              << " s) is empty: this run ends at " << parameters.time.end_time
              << " s. A resumed leg (Checkpoint/Resume) reaches it; the "
                 "averages below are undefined (null in summary.json)."
              << std::endl;
      pcout << std::fixed << std::setprecision(4)
            << "\nmu_global (time average over the window) = "
            << s.mu_global_mean << "  (from the contact multipliers "
            << s.mu_contact_mean << ")\n"
            << "contact nodes: stick " << s.stick_fraction << ", slip "
            << s.slip_fraction << ", separated " << s.separation_fraction
            << "; point M: " << s.regime << "\n"
            << std::scientific << std::setprecision(3)
            << "dominant frequency of mu_global " << s.dominant_frequency_hz
            << " Hz, energy balance error " << s.energy_balance_error << "\n"
            << "performance: " << s.dof_steps_per_second << " DoF-steps/s ("
            << s.dof_steps_per_second
                 / dealii::Utilities::MPI::n_mpi_processes(comm)
            << " per rank)\n"
            << law_figures.str() << "Results written to "
            << context.output_directory
            << "/ (summary.json, friction.csv, point_M.csv, "
               "contact_status.csv, spectrum.csv, fields.pvd)"
            << std::endl;
    }

    namespace
    {
      const bool contact_problem_registered = register_problem(
        {"contact",
         "explicit dynamics of a 2D pin in contact with friction on a moving "
         "rigid plane (forward-increment Lagrange multipliers, beta2 scheme)",
         &ContactProblem::declare_parameters,
         [](ParameterHandler &prm, const RunContext &context) {
           return std::unique_ptr<Problem>(new ContactProblem(prm, context));
         },
         {},
         &MorphologyMaterials::declare_material_sections});
    } // namespace
  }   // namespace contact
} // namespace tribodyn
