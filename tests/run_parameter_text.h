#ifndef tribodyn_tests_run_parameter_text_h
#define tribodyn_tests_run_parameter_text_h

// Run tribodyn in the test's own process on a parameter file written by the
// test: what the plugin tests do, so that the plugins they register from
// their own files are in the run's lists.

#include <fstream>
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
} // namespace tribodyn_test

#endif
