// SIGTERM and SIGINT in long runs, and the health the ranks agree on
// (interruption.h).
#include <cstring>
#include <tribodyn/core/interruption.h>

namespace tribodyn
{
  namespace
  {
    volatile std::sig_atomic_t received_signal = 0;

    void
    record_signal(int signal_number)
    {
      // A second signal stops at once (no checkpoint): the usual
      // "press Ctrl-C twice".
      if (received_signal != 0)
        {
          std::signal(signal_number, SIG_DFL);
          std::raise(signal_number);
          return;
        }
      received_signal = signal_number;
    }

    bool acknowledged = false;
    /// Handlers alive: a study installs them around its scenes, each
    /// scene's time loop inside; a signal the outer ones recorded (between
    /// two scenes, during a scene's set-up) is not forgotten by the inner.
    unsigned int handler_depth = 0;
  } // namespace


  InterruptHandlers::InterruptHandlers()
  {
    if (handler_depth++ == 0)
      {
        received_signal = 0;
        acknowledged    = false;
      }
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = record_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGTERM, &action, &previous_term);
    sigaction(SIGINT, &action, &previous_int);
  }


  InterruptHandlers::~InterruptHandlers()
  {
    sigaction(SIGTERM, &previous_term, nullptr);
    sigaction(SIGINT, &previous_int, nullptr);
    if (--handler_depth > 0)
      return; // the outer handlers act on a pending signal
    const int pending = received_signal;
    received_signal   = 0;
    if (pending != 0 && !acknowledged)
      std::raise(pending);
  }


  void
  InterruptHandlers::acknowledge()
  {
    acknowledged = true;
  }


  int
  local_interrupt_signal()
  {
    return received_signal;
  }


  Interrupted::Interrupted(const int signal, const std::string &message)
      : std::runtime_error(message)
      , signal_number(signal)
  {
  }


  RunHealth
  agree_on_health(const double   local_badness,
                  const MPI_Comm comm,
                  double        *shared_max)
  {
    double values[3] = {local_badness >= 0 ? local_badness : 1e300,
                        static_cast<double>(received_signal),
                        shared_max ? *shared_max : 0.};
    if (dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
      MPI_Allreduce(
        MPI_IN_PLACE, values, shared_max ? 3 : 2, MPI_DOUBLE, MPI_MAX, comm);
    RunHealth h;
    h.badness = values[0];
    h.signal  = static_cast<int>(values[1]);
    if (shared_max)
      *shared_max = values[2];
    return h;
  }
} // namespace tribodyn
