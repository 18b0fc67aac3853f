#include <deal.II/base/mpi.h>
#include <tribodyn/core/application.h>

int
main(int argc, char **argv)
{
  // One thread per MPI rank: the solvers are MPI-parallel, and TBB threads
  // on top of ranks would oversubscribe the cores.
  dealii::Utilities::MPI::MPI_InitFinalize mpi_initialization(argc, argv, 1);
  return tribodyn::run_application(argc, argv);
}
