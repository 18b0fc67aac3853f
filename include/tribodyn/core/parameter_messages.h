#ifndef tribodyn_core_parameter_messages_h
#define tribodyn_core_parameter_messages_h

#include <deal.II/base/exceptions.h>
#include <functional>
#include <string>
#include <utility>

namespace tribodyn
{
  /**
   * The one-paragraph message for a parameter file that deal.II's
   * ParameterHandler refused with @p exception: the file and line, the
   * subsection the offending line is in, the parameter, and for a value
   * the expected form in words (pattern_in_words()); then how to list the
   * valid parameters. @p origin, when given, maps a line of the text that
   * was parsed to the file and line it came from (a file with its includes
   * expanded).
   */
  std::string
  describe_parameter_error(
    const dealii::ExceptionBase                           &exception,
    const std::string                                     &file,
    const std::function<std::pair<std::string, int>(int)> &origin = {});

  /// deal.II's pattern description (e.g. "[Double 0...MAX_DOUBLE
  /// (inclusive)]") in words ("a number of at least 0").
  std::string
  pattern_in_words(const std::string &pattern);
} // namespace tribodyn

#endif
