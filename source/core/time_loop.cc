#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <limits>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/progress.h>
#include <tribodyn/core/time_loop.h>

namespace tribodyn
{
  namespace
  {
    using Clock = std::chrono::steady_clock;

    double
    seconds_since(const Clock::time_point t0)
    {
      return std::chrono::duration<double>(Clock::now() - t0).count();
    }

    /// Leaves the loop's timer section for the lifetime of the object
    /// (samples, outputs, checkpoints are timed in their own sections).
    class OutsideSteps
    {
    public:
      explicit OutsideSteps(const TimeLoopSettings &s)
          : timer(s.timer)
          , section(s.timer_section)
      {
        if (timer)
          timer->leave_subsection(section);
      }
      ~OutsideSteps()
      {
        // Not while an exception leaves the loop (a signal's Interrupted):
        // the run's timing table is not printed then.
        if (timer && std::uncaught_exceptions() == 0)
          timer->enter_subsection(section);
      }

    private:
      dealii::TimerOutput *timer;
      const std::string   &section;
    };
  } // namespace


  TimeLoop::TimeLoop(const TimeLoopSettings &settings)
      : settings(settings)
  {
  }


  unsigned long
  TimeLoop::n_steps(const double end_time, const double time_step)
  {
    return static_cast<unsigned long>(std::ceil(end_time / time_step - 1e-9));
  }


  void
  TimeLoop::check_something_to_resume(const unsigned long steps_done,
                                      const double        time,
                                      const unsigned long n_steps,
                                      const std::string  &end_time_entry,
                                      const double        end_time)
  {
    if (steps_done >= n_steps)
      throw InputError("Nothing to resume: the checkpoint is at step "
                       + std::to_string(steps_done)
                       + " (t = " + format_number(time) + " s), at or beyond '"
                       + end_time_entry + "' = " + format_number(end_time)
                       + " s. Raise the end time to continue the run.");
  }


  void
  TimeLoop::run(SteppedRun &run)
  {
    const TimeLoopSettings &s        = settings;
    const double            dt       = s.time_step;
    const double            interval = s.checkpoint_interval;
    // SIGTERM/SIGINT: polled between steps (checkpoint, clean stop).
    const InterruptHandlers interrupt_handlers;
    ProgressReporter        progress(
      std::cout, s.show_progress, s.end_time, s.progress_interval, s.label);
    progress.set_start_time(run.time());
    double next_checkpoint
      = interval > 0 ? (std::floor(run.time() / interval + 1e-9) + 1) * interval
                     : std::numeric_limits<double>::max();
    seconds_stepping = 0;
    n_run            = 0;

    if (s.timer)
      s.timer->enter_subsection(s.timer_section);
    const unsigned long first = run.steps_done();
    for (unsigned long n = first; n < s.n_steps; ++n)
      {
        const auto     t0 = Clock::now();
        const LoopStep step{n, run.sample_due(n), n + 1 == s.n_steps};
        run.advance(step);
        // Stability and interruption: agreed by all ranks before the state
        // is sampled or saved.
        int signal = 0;
        if (run.health_due(step))
          {
            const RunHealth health = run.agree_on_health(step);
            if (health.badness > 0)
              {
                if (s.timer)
                  s.timer->leave_subsection(s.timer_section);
                run.stop_early();
                run.report_instability(step);
              }
            signal = health.signal;
          }
        seconds_stepping += seconds_since(t0);
        ++n_run;

        run.after_step(step);
        const double t = run.time();
        const bool   checkpoint_due
          = (interval > 0 && (t >= next_checkpoint - 0.5 * dt || step.last))
            || signal != 0;
        if (step.sample || checkpoint_due || step.last)
          {
            const OutsideSteps outside(s);
            if (step.sample)
              run.sample(step);
            // Checkpoint at the interval, at the end and on a signal:
            // before the end-of-run work, which a longer run would not do.
            if (checkpoint_due)
              {
                run.save_checkpoint();
                while (next_checkpoint <= t + 0.5 * dt)
                  next_checkpoint += interval;
              }
            if (signal != 0)
              {
                run.stop_early();
                InterruptHandlers::acknowledge();
                throw Interrupted(
                  signal,
                  "signal " + std::to_string(signal) + " received at step "
                    + std::to_string(n + 1) + " (t = " + format_number(t)
                    + " s)"
                    + (s.checkpoint_directory.empty()
                         ? std::string(" (no checkpoint: no output directory).")
                         : "; the state was saved in '" + s.checkpoint_directory
                             + "': continue with 'Checkpoint/Resume = "
                               "true'."));
              }
            if (step.last)
              run.end_of_run(step);
          }
        progress.update(n + 1, t, run.progress_key());
      }
    // A finished run resumed from its last checkpoint (to analyse its
    // record again, McaProblem): no step is left, and the end-of-run work,
    // which follows that checkpoint, is done again on the same state.
    if (first >= s.n_steps && s.n_steps > 0)
      {
        const unsigned long last = s.n_steps - 1;
        run.end_of_run({last, run.sample_due(last), true});
      }
    if (s.timer)
      s.timer->leave_subsection(s.timer_section);
    progress.update(run.steps_done(), run.time(), run.progress_key(), true);
  }
} // namespace tribodyn
