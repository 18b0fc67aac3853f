#ifndef tribodyn_tests_test_utilities_h
#define tribodyn_tests_test_utilities_h

// Minimal checking helpers for tribodyn's unit tests: each check prints one
// line (on rank 0) with the measured value, the reference and the
// tolerance, and the test program returns the number of failed checks.

#include <cmath>
#include <deal.II/base/mpi.h>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

namespace tribodyn_test
{
  inline int &
  failure_count()
  {
    static int failures = 0;
    return failures;
  }

  inline bool
  is_root()
  {
    return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }

  /// Record a check; print it on rank 0.
  inline void
  check(const bool condition, const std::string &what)
  {
    if (!condition)
      ++failure_count();
    if (is_root())
      std::cout << (condition ? "PASS  " : "FAIL  ") << what << std::endl;
  }

  /// |value - reference| <= tolerance * |reference| (or <= tolerance when
  /// the reference is zero: pass a scale through @p scale then).
  inline void
  check_relative(const double       value,
                 const double       reference,
                 const double       tolerance,
                 const std::string &what,
                 const double       scale = 0)
  {
    const double denominator
      = scale > 0 ? scale : std::max(std::abs(reference), 1e-300);
    const double       error = std::abs(value - reference) / denominator;
    std::ostringstream s;
    s << std::setprecision(12) << what << ": " << value << " vs " << reference
      << " (relative error " << std::setprecision(3) << error << ", tolerance "
      << tolerance << ")";
    check(error <= tolerance, s.str());
  }

  /// Exit code of the test program.
  inline int
  result()
  {
    if (is_root())
      std::cout << (failure_count() == 0
                      ? "All checks passed."
                      : std::to_string(failure_count()) + " check(s) failed.")
                << std::endl;
    return failure_count() == 0 ? 0 : 1;
  }
} // namespace tribodyn_test

#endif
