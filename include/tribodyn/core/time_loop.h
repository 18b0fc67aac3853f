// The time loop of the time-stepping engines (contact pin, automata): one
// loop, written once, that both drive through the small interface
// SteppedRun. The loop owns what every long run does the same way — the
// step count, the cadence of samples and checkpoints, signals (SIGTERM,
// SIGINT: checkpoint, clean stop), health checks, progress lines with an
// ETA, the wall time of the steps — and the engine owns what is its own:
// how a step advances, what a sample records, what a checkpoint holds.
#ifndef tribodyn_core_time_loop_h
#define tribodyn_core_time_loop_h

#include <deal.II/base/timer.h>
#include <ostream>
#include <string>
#include <tribodyn/core/interruption.h>

namespace tribodyn
{
  /// One step of the loop, as the engine's hooks see it.
  struct LoopStep
  {
    /// Steps done before this one: the step advances from t_index to
    /// t_index+1.
    unsigned long index = 0;
    /// A regular sample follows this step (SteppedRun::sample_due()).
    bool sample = false;
    /// The run's last step.
    bool last = false;
  };

  /**
   * A time-stepping engine as TimeLoop drives it. After each step, in this
   * order: health check (when due) — after_step() — sample() (regular
   * samples) — checkpoint (at the interval, at the end, on a signal) —
   * end_of_run() (last step) — progress line. The checkpoint comes before
   * the end-of-run work, which a longer run would not do at this step.
   */
  class SteppedRun
  {
  public:
    virtual ~SteppedRun() = default;

    /// Steps done so far (0 on a fresh start, the checkpoint's on resume).
    virtual unsigned long
    steps_done() const = 0;

    /// Simulated time after steps_done() steps.
    virtual double
    time() const = 0;

    /// Whether a regular sample follows the step from t_index.
    virtual bool
    sample_due(const unsigned long index) const = 0;

    /// Advance one step.
    virtual void
    advance(const LoopStep &step)
      = 0;

    /// Whether the ranks agree on the run's health after @p step (the
    /// check is one small MPI_Allreduce; an engine may space them).
    virtual bool
    health_due(const LoopStep &) const
    {
      return true;
    }

    /// Collective: the run's health agreed by all ranks (agree_on_health(),
    /// with whatever else the engine reduces in the same call).
    virtual RunHealth
    agree_on_health(const LoopStep &step)
      = 0;

    /// The run became unstable at @p step: throw the engine's RunError
    /// (after stop_early()).
    [[noreturn]] virtual void
    report_instability(const LoopStep &step)
      = 0;

    /// Every step, after the health check (outputs that need every step).
    virtual void
    after_step(const LoopStep &)
    {
    }

    /// A regular sample after @p step.
    virtual void
    sample(const LoopStep &step)
      = 0;

    /// After the last step's checkpoint: the samples and outputs the end
    /// of the run needs that the regular cadence did not give.
    virtual void
    end_of_run(const LoopStep &step)
      = 0;

    /// Collective: save the state after steps_done() steps (called at the
    /// checkpoint times and on a signal; does nothing for runs that keep
    /// no checkpoints).
    virtual void
    save_checkpoint()
      = 0;

    /// The run stops early (a signal after its checkpoint, or an
    /// instability): write what the samples so far give.
    virtual void
    stop_early()
    {
    }

    /// The key figure the progress lines show (e.g. "mu = 0.41"): that of
    /// the latest sample.
    virtual std::string
    progress_key() const
    {
      return {};
    }
  };

  /// How TimeLoop runs an engine.
  struct TimeLoopSettings
  {
    /// Steps of the whole run (TimeLoop::n_steps()).
    unsigned long n_steps = 0;
    /// The time step and the run's end time (s).
    double time_step = 0;
    double end_time  = 0;
    /// Simulated time between checkpoints (s); 0: only at signals.
    double checkpoint_interval = 0;
    /// Where the checkpoints go (the Interrupted message); empty for a run
    /// that keeps none.
    std::string checkpoint_directory;
    /// Progress lines on this process, at most every progress_interval
    /// seconds, labelled (e.g. "mca").
    bool        show_progress     = false;
    double      progress_interval = 5.;
    std::string label;
    /// Optional: the TimerOutput section the steps are timed in (left
    /// while samples, outputs and checkpoints are written).
    dealii::TimerOutput *timer = nullptr;
    std::string          timer_section;
  };

  /// The loop itself.
  class TimeLoop
  {
  public:
    explicit TimeLoop(const TimeLoopSettings &settings);

    /// Steps of a run to @p end_time at @p time_step.
    static unsigned long
    n_steps(const double end_time, const double time_step);

    /**
     * A resumed run whose checkpoint is already at or beyond its end time
     * has nothing to do: InputError naming @p end_time_entry ("Time/End
     * time") and the fix.
     */
    static void
    check_something_to_resume(const unsigned long steps_done,
                              const double        time,
                              const unsigned long n_steps,
                              const std::string  &end_time_entry,
                              const double        end_time);

    /// Run @p run from its steps_done() to the end (collective). Throws
    /// Interrupted on a signal (after the checkpoint), the engine's error
    /// on an instability.
    void
    run(SteppedRun &run);

    /// Wall time of the steps of the last run() (advance, health check):
    /// samples, outputs, checkpoints and progress lines not counted.
    double
    step_seconds() const
    {
      return seconds_stepping;
    }

    /// Steps the last run() made.
    unsigned long
    steps_run() const
    {
      return n_run;
    }

  private:
    TimeLoopSettings settings;
    double           seconds_stepping = 0;
    unsigned long    n_run            = 0;
  };
} // namespace tribodyn

#endif
