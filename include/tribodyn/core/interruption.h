// The end of a long run by a signal (SIGTERM, SIGINT: a checkpoint, then a
// clean stop with exit code 128 + signal) and the health of a run as all
// its ranks agree on it at a check (core/time_loop.h).
#ifndef tribodyn_core_interruption_h
#define tribodyn_core_interruption_h

#include <csignal>
#include <deal.II/base/mpi.h>
#include <stdexcept>
#include <string>

namespace tribodyn
{
  /**
   * While an object of this class lives (the time loop of a long run),
   * SIGTERM and SIGINT only set a flag: the loop polls it between steps
   * (agree_on_health()), writes a checkpoint, flushes its outputs and
   * throws Interrupted. The destructor restores the previous handlers and,
   * if a signal arrived but was not acted upon, re-raises it. Handlers
   * nest (a study's around its scenes' time loops): the inner ones keep a
   * signal the outer ones recorded and leave an unacted one to them.
   */
  class InterruptHandlers
  {
  public:
    InterruptHandlers();
    ~InterruptHandlers();
    InterruptHandlers(const InterruptHandlers &) = delete;
    InterruptHandlers &
    operator=(const InterruptHandlers &)
      = delete;

    /// The run acted upon the signal (Interrupted thrown).
    static void
    acknowledge();

  private:
    struct sigaction previous_term, previous_int;
  };

  /// The signal received (SIGTERM, SIGINT) on this process, or 0.
  int
  local_interrupt_signal();

  /// A run ended by SIGTERM or SIGINT after saving its state; exit code
  /// 128 + signal.
  class Interrupted : public std::runtime_error
  {
  public:
    Interrupted(const int signal, const std::string &message);
    int signal_number;
  };

  /**
   * Health of a run as agreed by all ranks at a check: the largest
   * "badness" of the ranks (0: fine) and the interrupt signal if any rank
   * received one. One MPI_Allreduce (none on one rank). A caller with one
   * more quantity to agree on by its maximum passes it in @p shared_max,
   * which is replaced by the ranks' maximum in the same reduction.
   */
  struct RunHealth
  {
    double badness = 0;
    int    signal  = 0;
  };
  RunHealth
  agree_on_health(const double   local_badness,
                  const MPI_Comm comm,
                  double        *shared_max = nullptr);
} // namespace tribodyn

#endif
