#ifndef tribodyn_tests_homogenization_tools_h
#define tribodyn_tests_homogenization_tools_h

#include "../test_utilities.h"

#include <deal.II/base/timer.h>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/morphology_sources/laminate.h>
#include <tribodyn/core/morphology_sources/random_vertical.h>
#include <tribodyn/homogenization/cell_problem.h>

namespace tribodyn_test
{
  using namespace tribodyn;
  using namespace tribodyn::homogenization;

  inline std::vector<ElasticPhase>
  seed_phases()
  {
    return {IsotropicElasticMaterial{30e9, 0.2, 1770.},
            IsotropicElasticMaterial{80e9, 0.2, 1770.}};
  }

  /// A map of the seed's generator with pixels of 0.1 mm: @p nx x @p ny
  /// pixels, heterogeneities of height @p min_height to @p max_height (m).
  inline Morphology
  seed_generator_map(const unsigned int nx,
                     const unsigned int ny,
                     const double       min_height,
                     const double       max_height,
                     const double       fraction = 0.1,
                     const unsigned int seed     = 1)
  {
    MorphologyParameters p;
    p.n_pixels_x                = nx;
    p.n_pixels_y                = ny;
    p.width                     = nx * 1e-4;
    p.height                    = ny * 1e-4;
    auto &random                = p.use<RandomVerticalMorphology>();
    random.inclusion_min_height = min_height;
    random.inclusion_max_height = max_height;
    p.volume_fraction           = fraction;
    p.random_seed               = seed;
    return Morphology::create(p);
  }

  /// A laminate of 40 x 20 pixels over 20 x 10 mm, two periods, 30 % of
  /// heterogeneity, layers normal to @p normal.
  inline Morphology
  laminate_map(const LaminateMorphology::Normal normal)
  {
    MorphologyParameters p;
    auto                &laminate = p.use<LaminateMorphology>();
    laminate.normal               = normal;
    laminate.n_periods            = 2;
    p.n_pixels_x                  = 40;
    p.n_pixels_y                  = 20;
    p.width                       = 0.02;
    p.height                      = 0.01;
    p.volume_fraction             = 0.3;
    return Morphology::create(p);
  }

  /// Solve the boundary condition @p bc (the only one of @p parameters) on
  /// @p morphology, silently; @p levels (if given) gets the number of
  /// multigrid levels of the cell problem.
  inline CellProblemResult
  solve_cell(const Morphology                &morphology,
             const std::vector<ElasticPhase> &phases,
             const BoundaryCondition          bc,
             CellProblemParameters            parameters,
             unsigned int                    *levels = nullptr,
             const MPI_Comm                   comm   = MPI_COMM_WORLD)
  {
    parameters.boundary_conditions = {bc};
    dealii::TimerOutput timer(comm,
                              std::cout,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);
    CellProblem<2>      problem(comm, morphology, phases, parameters, timer);
    if (levels)
      *levels = problem.n_multigrid_levels();
    return problem.solve(bc);
  }

  /// Solve one boundary condition on @p morphology, silently.
  inline CellProblemResult
  solve_cell(const Morphology                &morphology,
             const std::vector<ElasticPhase> &phases,
             const BoundaryCondition          bc,
             const unsigned int               subdivisions = 1,
             const double                     tolerance    = 1e-12,
             const MPI_Comm                   comm         = MPI_COMM_WORLD)
  {
    CellProblemParameters parameters;
    parameters.subdivisions_per_pixel = subdivisions;
    parameters.solver_tolerance       = tolerance;
    return solve_cell(morphology, phases, bc, parameters, nullptr, comm);
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
