#ifndef tribodyn_tests_homogenization_tools_h
#define tribodyn_tests_homogenization_tools_h

#include "../test_utilities.h"

#include <deal.II/base/timer.h>
#include <tribodyn/core/morphology.h>
#include <tribodyn/homogenization/cell_problem.h>

namespace tribodyn_test
{
  using namespace tribodyn;
  using namespace tribodyn::homogenization;

  inline std::vector<IsotropicElasticMaterial>
  seed_phases()
  {
    return {IsotropicElasticMaterial{30e9, 0.2, 1770.},
            IsotropicElasticMaterial{80e9, 0.2, 1770.}};
  }

  /// Solve one boundary condition on @p morphology, silently.
  inline CellProblemResult
  solve_cell(const Morphology                            &morphology,
             const std::vector<IsotropicElasticMaterial> &phases,
             const BoundaryCondition                      bc,
             const unsigned int                           subdivisions = 1,
             const double                                 tolerance    = 1e-12,
             const MPI_Comm                               comm = MPI_COMM_WORLD)
  {
    CellProblemParameters parameters;
    parameters.boundary_conditions    = {bc};
    parameters.subdivisions_per_pixel = subdivisions;
    parameters.solver_tolerance       = tolerance;
    dealii::TimerOutput timer(comm,
                              std::cout,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);
    CellProblem         problem(comm, morphology, phases, parameters, timer);
    return problem.solve(bc);
  }

  /// Largest |A_ij - B_ij| relative to the largest |B_ij|.
  inline double
  matrix_relative_difference(const VoigtMatrix &A, const VoigtMatrix &B)
  {
    double difference = 0, scale = 0;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        {
          difference = std::max(difference, std::abs(A[i][j] - B[i][j]));
          scale      = std::max(scale, std::abs(B[i][j]));
        }
    return difference / scale;
  }
} // namespace tribodyn_test

#endif
