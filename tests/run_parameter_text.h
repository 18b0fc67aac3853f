#ifndef tribodyn_tests_run_parameter_text_h
#define tribodyn_tests_run_parameter_text_h

// Run tribodyn in the test's own process on a parameter file written by the
// test: what the plugin tests do, so that the plugins they register from
// their own files are in the run's lists.

#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <tribodyn/core/application.h>

namespace tribodyn_test
{
  /// Write @p text to @p file and run `tribodyn FILE`; its exit code.
  inline int
  run_parameter_text(const std::string &file, const std::string &text)
  {
    std::ofstream(file) << text;
    std::string name = "tribodyn", path = file;
    char       *args[] = {name.data(), path.data(), nullptr};
    return tribodyn::run_application(2, args);
  }

  /// The same, with what the run writes to std::cerr (its refusal) in
  /// @p errors.
  inline int
  run_parameter_text(const std::string &file,
                     const std::string &text,
                     std::string       &errors)
  {
    std::ostringstream err;
    std::streambuf    *old  = std::cerr.rdbuf(err.rdbuf());
    const int          code = run_parameter_text(file, text);
    std::cerr.rdbuf(old);
    errors = err.str();
    return code;
  }

  /// `tribodyn --print-parameters PROBLEM` run in this process (with the
  /// plugins the test registers), its exit code in @p code; the
  /// documentation comments unwrapped, so that a text the reference wraps
  /// over lines is found as one line.
  inline std::string
  printed_parameters(const std::string &problem, int &code)
  {
    std::ostringstream out;
    std::streambuf    *old = std::cout.rdbuf(out.rdbuf());
    std::string name = "tribodyn", flag = "--print-parameters", which = problem;
    char       *args[] = {name.data(), flag.data(), which.data(), nullptr};
    code               = tribodyn::run_application(3, args);
    std::cout.rdbuf(old);
    return std::regex_replace(out.str(), std::regex("\\s*\\n\\s*#\\s*"), " ");
  }
} // namespace tribodyn_test

#endif
