#include <deal.II/base/mpi.h>
#include <fenv.h>
#include <tribodyn/core/application.h>
int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  feenableexcept(FE_INVALID | FE_DIVBYZERO);
  return tribodyn::run_application(argc, argv);
}
