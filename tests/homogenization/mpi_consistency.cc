// Run on 2 MPI ranks: the same cell problems solved on both ranks together
// (MPI_COMM_WORLD) and on rank 0 alone (MPI_COMM_SELF) must agree. Both are
// converged to a relative residual of 1e-12; the partition changes only the
// AMG hierarchy and the order of sums, so the apparent stiffnesses agree to
// a relative 1e-10 (issue #2).

#include "homogenization_test_tools.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace tribodyn_test;

  const unsigned int n_ranks
    = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  check(n_ranks == 2,
        "runs on 2 MPI ranks (got " + std::to_string(n_ranks) + ")");

  MorphologyParameters p;
  p.width                     = 0.014;
  p.height                    = 0.004;
  p.n_pixels_x                = 140;
  p.n_pixels_y                = 40;
  p.volume_fraction           = 0.1;
  const Morphology morphology = Morphology::create(p);

  for (const BoundaryCondition bc : {BoundaryCondition::kubc,
                                     BoundaryCondition::subc,
                                     BoundaryCondition::periodic})
    {
      const CellProblemResult parallel
        = solve_cell(morphology, seed_phases(), bc, 1, 1e-12, MPI_COMM_WORLD);
      // Rank 0 alone solves the serial problem and broadcasts its C.
      VoigtMatrix serial_C;
      if (is_root())
        serial_C
          = solve_cell(morphology, seed_phases(), bc, 1, 1e-12, MPI_COMM_SELF)
              .properties.C;
      serial_C = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, serial_C, 0);
      check_relative(matrix_relative_difference(parallel.properties.C,
                                                serial_C),
                     0,
                     1e-10,
                     to_string(bc) + ": C on 2 ranks vs 1 rank",
                     1.);
    }
  return result();
}
