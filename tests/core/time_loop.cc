// The common time loop (core/time_loop.h) on a toy engine, a harmonic
// oscillator integrated by velocity Verlet: the cadence of samples and
// checkpoints against the closed-form step numbers, the order of the
// hooks, a run in two legs against one leg (bitwise), a signal (checkpoint,
// partial results, Interrupted) and an instability (partial results, the
// engine's error), and the refusal of a resume with nothing to do.
#include "../test_utilities.h"

#include <cmath>
#include <csignal>
#include <deal.II/base/mpi.h>
#include <string>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/time_loop.h>
#include <vector>

using namespace tribodyn;
using tribodyn_test::check;

namespace
{
  /// x'' = -x by velocity Verlet; records every hook call.
  class Oscillator : public SteppedRun
  {
  public:
    Oscillator(const double dt, const unsigned long sample_every)
        : dt(dt)
        , every(sample_every)
    {
    }

    unsigned long
    steps_done() const override
    {
      return n;
    }
    double
    time() const override
    {
      return n * dt;
    }
    bool
    sample_due(const unsigned long index) const override
    {
      return (index + 1) % every == 0;
    }
    void
    advance(const LoopStep &step) override
    {
      check_order(step);
      v -= 0.5 * dt * x;
      x += dt * v;
      v -= 0.5 * dt * x;
      ++n;
      if (n == raise_at)
        std::raise(SIGTERM);
    }
    RunHealth
    agree_on_health(const LoopStep &) override
    {
      return tribodyn::agree_on_health(n == unstable_at ? 1. : 0.,
                                       MPI_COMM_WORLD);
    }
    [[noreturn]] void
    report_instability(const LoopStep &step) override
    {
      events.push_back("instability " + std::to_string(step.index + 1));
      throw RunError("unstable");
    }
    void
    after_step(const LoopStep &) override
    {
      events.push_back("after_step " + std::to_string(n));
    }
    void
    sample(const LoopStep &) override
    {
      samples.push_back(n);
      events.push_back("sample " + std::to_string(n));
    }
    void
    end_of_run(const LoopStep &step) override
    {
      ++n_end_of_run;
      if (!step.sample)
        samples.push_back(n);
      events.push_back("end " + std::to_string(n));
    }
    void
    save_checkpoint() override
    {
      checkpoints.push_back(n);
      events.push_back("checkpoint " + std::to_string(n));
    }
    void
    stop_early() override
    {
      events.push_back("stop_early " + std::to_string(n));
    }

    double                     dt;
    unsigned long              every;
    unsigned long              n = 0;
    double                     x = 1, v = 0;
    unsigned long              raise_at = 0, unstable_at = 0;
    unsigned int               n_end_of_run = 0;
    std::vector<unsigned long> samples, checkpoints;
    std::vector<std::string>   events;

  private:
    /// advance() is called once per step, in order.
    void
    check_order(const LoopStep &step)
    {
      if (step.index != n)
        ++order_errors;
    }

  public:
    unsigned int order_errors = 0;
  };

  TimeLoopSettings
  settings(const unsigned long n_steps,
           const double        dt,
           const double        interval,
           const std::string  &directory = "ckpt")
  {
    TimeLoopSettings s;
    s.n_steps              = n_steps;
    s.time_step            = dt;
    s.end_time             = n_steps * dt;
    s.checkpoint_interval  = interval;
    s.checkpoint_directory = directory;
    s.label                = "toy";
    return s;
  }

  /// The closed form: a checkpoint after the first step whose time reaches
  /// k * interval - dt/2, for k = 1, 2, ..., and one after the last step.
  std::vector<unsigned long>
  expected_checkpoints(const unsigned long first,
                       const unsigned long n_steps,
                       const double        dt,
                       const double        interval)
  {
    std::vector<unsigned long> out;
    for (unsigned long k = 1;; ++k)
      {
        const unsigned long n = static_cast<unsigned long>(
          std::ceil((k * interval - 0.5 * dt) / dt - 1e-12));
        if (n > n_steps)
          break;
        if (n > first && (out.empty() || out.back() != n))
          out.push_back(n);
      }
    if (out.empty() || out.back() != n_steps)
      out.push_back(n_steps);
    return out;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // Step counts: 1.0 / 0.1 is 9.999... in floating point, yet 10 steps.
  check(TimeLoop::n_steps(1.0, 0.1) == 10, "n_steps(1.0, 0.1) = 10");
  check(TimeLoop::n_steps(1.05, 0.1) == 11, "n_steps(1.05, 0.1) = 11");

  // One leg of 47 steps, samples every 5, checkpoints every 0.317.
  const double dt = 0.1, interval = 0.317; // no ties k*interval - dt/2 = n*dt
  Oscillator   one(dt, 5);
  TimeLoop(settings(47, dt, interval)).run(one);
  std::vector<unsigned long> samples;
  for (unsigned long n = 5; n <= 47; n += 5)
    samples.push_back(n);
  samples.push_back(47); // the end-of-run sample (47 is not regular)
  check(one.samples == samples, "samples at 5, 10, ..., 45 and the end");
  check(one.checkpoints == expected_checkpoints(0, 47, dt, interval),
        "checkpoints at the closed-form steps (3, 6, 10, ...) and the end");
  check(one.n_end_of_run == 1 && one.order_errors == 0,
        "end_of_run once; advance() once per step, in order");
  // The last step: its checkpoint before the end-of-run work.
  const auto &e = one.events;
  check(e.size() >= 3 && e[e.size() - 3] == "after_step 47"
          && e[e.size() - 2] == "checkpoint 47" && e.back() == "end 47",
        "last step: after_step, checkpoint, then end_of_run");

  // The same run in two legs (20 steps, then resumed to 47): the state
  // bitwise, the samples and the checkpoints of the second leg those of
  // the one leg after step 20.
  Oscillator legs(dt, 5);
  TimeLoop(settings(20, dt, interval)).run(legs);
  const unsigned long checkpoints_leg_1 = legs.checkpoints.size();
  TimeLoop(settings(47, dt, interval)).run(legs);
  check(legs.x == one.x && legs.v == one.v, "two legs: state bitwise equal");
  std::vector<unsigned long> leg2(legs.checkpoints.begin() + checkpoints_leg_1,
                                  legs.checkpoints.end());
  check(leg2 == expected_checkpoints(20, 47, dt, interval),
        "second leg: checkpoints continue the cadence of the first");
  check(std::vector<unsigned long>(legs.samples.begin() + 4, legs.samples.end())
          == std::vector<unsigned long>(one.samples.begin() + 4,
                                        one.samples.end()),
        "second leg: samples continue those of the one leg (the first "
        "leg's end at step 20 is a regular sample: none added)");

  // The toy's physics: velocity Verlet conserves the oscillator's shadow
  // energy (v^2 + (1 - dt^2/4) x^2)/2 exactly; 47 steps of round-off
  // (measured 3e-16) against a tolerance of 1e-13.
  const double shadow
    = 0.5 * (one.v * one.v + (1 - 0.25 * dt * dt) * one.x * one.x);
  tribodyn_test::check_relative(shadow,
                                0.5 * (1 - 0.25 * dt * dt),
                                1e-13,
                                "Verlet's shadow energy of the oscillator");

  // A signal at step 13: a checkpoint there, partial results, Interrupted
  // naming the checkpoint directory; no end-of-run work.
  Oscillator stopped(dt, 5);
  stopped.raise_at = 13;
  bool interrupted = false;
  try
    {
      TimeLoop(settings(47, dt, 0.)).run(stopped);
    }
  catch (const Interrupted &err)
    {
      interrupted
        = err.signal_number == SIGTERM
          && std::string(err.what()).find("'ckpt'") != std::string::npos;
    }
  check(interrupted && stopped.checkpoints == std::vector<unsigned long>{13}
          && stopped.events.back() == "stop_early 13"
          && stopped.n_end_of_run == 0,
        "SIGTERM at step 13: checkpoint 13, stop_early, Interrupted");

  // An instability at step 8: partial results, then the engine's error,
  // before the step is sampled or saved.
  Oscillator unstable(dt, 4);
  unstable.unstable_at = 8;
  bool failed          = false;
  try
    {
      TimeLoop(settings(47, dt, interval)).run(unstable);
    }
  catch (const RunError &)
    {
      failed = true;
    }
  check(failed && unstable.events.back() == "instability 8"
          && unstable.events[unstable.events.size() - 2] == "stop_early 8"
          && unstable.samples == std::vector<unsigned long>{4},
        "instability at step 8: stop_early, error, step 8 not sampled");

  // Nothing to resume: the message names the end-time parameter.
  bool refused = false;
  try
    {
      TimeLoop::check_something_to_resume(47, 4.7, 47, "Time/End time", 4.7);
    }
  catch (const InputError &err)
    {
      refused
        = std::string(err.what()).find("'Time/End time'") != std::string::npos;
    }
  check(refused, "a resume at the end time is refused, naming Time/End time");

  return tribodyn_test::result();
}
