#ifndef tribodyn_contact_contact_problem_h
#define tribodyn_contact_contact_problem_h

#include <chrono>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <tribodyn/contact/contact_parameters.h>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/core/checkpoint.h>
#include <tribodyn/core/problem.h>

namespace tribodyn
{
  namespace contact
  {
    /**
     * `set Problem = contact`: the explicit dynamic contact-with-friction
     * model of seed 001, §2.3 (a pin pressed on a rigid plane sliding at
     * V). Runs the ContactSolver and writes friction.csv, point_M.csv,
     * contact_status.csv, spectrum.csv, fields.pvd and summary.json.
     */
    class ContactProblem : public Problem
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      ContactProblem(dealii::ParameterHandler &prm, const RunContext &context);

      /// From parsed (and possibly modified) parameters: used by the study
      /// driver, which runs many cases.
      ContactProblem(const ContactParameters &parameters,
                     const RunContext        &context);

      void
      run() override;

      /// After run(): the recorded time series and the headline figures.
      const std::vector<Sample> &
      samples() const
      {
        return recorded_samples;
      }
      const RunSummary &
      summary() const
      {
        return run_summary;
      }

    private:
      void
      run_with_timer(dealii::TimerOutput                         &timer,
                     const std::chrono::steady_clock::time_point &start);

      RunContext        context;
      ContactParameters parameters;
      /// Checkpoints (runs read from a parameter file only; the study
      /// driver's cases have none).
      bool                 checkpoints_on = false;
      CheckpointParameters checkpoint;
      ResumableParameters  checkpoint_lines;
      std::vector<Sample>  recorded_samples;
      RunSummary           run_summary;
    };
  } // namespace contact
} // namespace tribodyn

#endif
