#ifndef tribodyn_core_progress_h
#define tribodyn_core_progress_h

#include <chrono>
#include <ostream>
#include <string>

namespace tribodyn
{
  /**
   * Prints a progress line (step, simulated time, percent done, ETA and a
   * key figure) at most every @p interval_seconds of wall time, on the
   * process given `active = true`. The ETA extrapolates the wall time spent
   * so far linearly in simulated time.
   */
  class ProgressReporter
  {
  public:
    ProgressReporter(std::ostream      &out,
                     const bool         active,
                     const double       end_time,
                     const double       interval_seconds,
                     const std::string &label);

    /// Report progress at @p step and simulated time @p time; @p key_figure
    /// is appended verbatim (e.g. "mu = 0.21").
    void
    update(const unsigned long step,
           const double        time,
           const std::string  &key_figure = "",
           const bool          force      = false);

    /// Resumed runs: the simulated time at which this run started (the
    /// ETA extrapolates from there).
    void
    set_start_time(const double time)
    {
      start_time = time;
    }

    /// Wall time since construction, in seconds.
    double
    elapsed_seconds() const;

  private:
    std::ostream                               &out;
    const bool                                  is_active;
    const double                                end_time;
    const double                                interval;
    const std::string                           label;
    const std::chrono::steady_clock::time_point start;
    double                                      last_report = -1e300;
    double                                      start_time  = 0;
  };

  /// "1 h 02 min", "3 min 12 s", "4.2 s".
  std::string
  format_duration(const double seconds);
} // namespace tribodyn

#endif
