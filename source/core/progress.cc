#include <cmath>
#include <iomanip>
#include <sstream>
#include <tribodyn/core/progress.h>

namespace tribodyn
{
  ProgressReporter::ProgressReporter(std::ostream      &out,
                                     const bool         active,
                                     const double       end_time,
                                     const double       interval_seconds,
                                     const std::string &label)
      : out(out)
      , is_active(active)
      , end_time(end_time)
      , interval(interval_seconds)
      , label(label)
      , start(std::chrono::steady_clock::now())
  {
  }


  double
  ProgressReporter::elapsed_seconds() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now()
                                         - start)
      .count();
  }


  void
  ProgressReporter::update(const unsigned long step,
                           const double        time,
                           const std::string  &key_figure,
                           const bool          force)
  {
    if (!is_active)
      return;
    const double elapsed = elapsed_seconds();
    if (!force && elapsed - last_report < interval)
      return;
    last_report = elapsed;

    const double fraction
      = end_time > 0 ? std::min(1.0, std::max(0.0, time / end_time)) : 1.0;
    std::ostringstream line;
    line << label << ": step " << step << "  t = " << std::setprecision(4)
         << std::scientific << time << " s  " << std::fixed
         << std::setprecision(1) << 100. * fraction << " %";
    // Fraction of this run's part of the simulated time (resumed runs
    // start at start_time).
    const double done = end_time > start_time
                          ? (time - start_time) / (end_time - start_time)
                          : 1.0;
    if (done > 0 && done < 1)
      line << "  ETA " << format_duration(elapsed * (1 - done) / done);
    line << "  elapsed " << format_duration(elapsed);
    if (!key_figure.empty())
      line << "  " << key_figure;
    out << line.str() << std::endl;
  }


  std::string
  format_duration(const double seconds)
  {
    std::ostringstream s;
    if (seconds < 60)
      s << std::fixed << std::setprecision(1) << seconds << " s";
    else if (seconds < 3600)
      s << static_cast<int>(seconds / 60) << " min "
        << static_cast<int>(std::fmod(seconds, 60.)) << " s";
    else
      s << static_cast<int>(seconds / 3600) << " h " << std::setw(2)
        << std::setfill('0') << static_cast<int>(std::fmod(seconds, 3600.) / 60)
        << " min";
    return s.str();
  }
} // namespace tribodyn
