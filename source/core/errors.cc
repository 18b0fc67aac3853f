#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <iomanip>
#include <limits>
#include <sstream>
#include <tribodyn/core/errors.h>

namespace tribodyn
{
  InputError::InputError(const std::string &message)
      : std::runtime_error(message)
  {
  }


  RunError::RunError(const std::string &message)
      : std::runtime_error(message)
  {
  }


  namespace
  {
    /// Collective: whether any rank @p failed, and then in @p text the
    /// @p message of the lowest failing rank (on every rank).
    bool
    lowest_failure(const MPI_Comm     comm,
                   const bool         failed,
                   const std::string &message,
                   std::string       &text)
    {
      const unsigned int n_ranks
        = dealii::Utilities::MPI::n_mpi_processes(comm);
      const unsigned int me = dealii::Utilities::MPI::this_mpi_process(comm);
      const unsigned int first
        = dealii::Utilities::MPI::min(failed ? me : n_ranks, comm);
      if (first == n_ranks)
        return false;
      text = dealii::Utilities::MPI::broadcast(
        comm, me == first ? message : std::string(), first);
      return true;
    }
  } // namespace


  void
  throw_collectively(const MPI_Comm     comm,
                     const bool         failed,
                     const std::string &message)
  {
    std::string text;
    if (lowest_failure(comm, failed, message, text))
      throw RunError(text);
  }


  void
  refuse_collectively(const MPI_Comm     comm,
                      const bool         failed,
                      const std::string &message)
  {
    std::string text;
    if (lowest_failure(comm, failed, message, text))
      throw InputError(text);
  }


  std::string
  format_number(const double value)
  {
    std::ostringstream s;
    s << std::setprecision(10) << value;
    return s.str();
  }


  /// @p value with the fewest significant digits that read back to it,
  /// as one writes a default by hand: 0.9, 0.028, 500 but 5e5, 2.5e-4,
  /// 1.1e-9 (the exponent without '+' and leading zeros).
  std::string
  exact_number(const double value)
  {
    const double magnitude = std::abs(value);
    const bool   exponent
      = magnitude != 0 && (magnitude < 1e-2 || magnitude >= 1e5);
    char text[32];
    for (int digits = 1; digits <= 17; ++digits)
      {
        std::snprintf(text,
                      sizeof(text),
                      exponent ? "%.*e" : "%.*g",
                      exponent ? digits - 1 : digits,
                      value);
        // fixed notation below 1e5: "%.1g" writes 10 as 1e+01
        if (std::stod(text) == value
            && (exponent || std::string(text).find('e') == std::string::npos))
          break;
      }
    std::string out = text;
    const auto  e   = out.find('e');
    if (e == std::string::npos)
      return out;
    std::string mantissa = out.substr(0, e), power = out.substr(e + 1);
    const bool  negative = power[0] == '-';
    power = power.substr(power[0] == '-' || power[0] == '+' ? 1 : 0);
    power
      = power.substr(std::min(power.find_first_not_of('0'), power.size() - 1));
    return mantissa + "e" + (negative ? "-" : "") + power;
  }


  void
  check_parameter_range(const std::string &name,
                        const double       value,
                        const double       lower,
                        const double       upper,
                        const bool         lower_open,
                        const bool         upper_open,
                        const std::string &hint)
  {
    const bool above = lower_open ? (value > lower) : (value >= lower);
    const bool below = upper_open ? (value < upper) : (value <= upper);
    if (above && below)
      return;

    std::ostringstream message;
    message << "Parameter '" << name << "' = " << format_number(value)
            << " is out of range: it must lie in " << (lower_open ? "(" : "[")
            << (lower == -std::numeric_limits<double>::max()
                  ? std::string("-inf")
                  : format_number(lower))
            << ", "
            << (upper == std::numeric_limits<double>::max()
                  ? std::string("inf")
                  : format_number(upper))
            << (upper_open ? ")" : "]") << ".";
    if (!hint.empty())
      message << " " << hint;
    throw InputError(message.str());
  }


  void
  check_parameter(const bool         condition,
                  const std::string &name,
                  const std::string &what_is_allowed)
  {
    if (!condition)
      throw InputError("Parameter '" + name + "': " + what_is_allowed);
  }
} // namespace tribodyn
