// tribodyn with a fault injected into one stress update, for verification
// (issue #49 item 5; doc/theory/mca.md §8.4, "What the balance checks").
// The environment variable TRIBODYN_FAULT names the update and its factor:
//   radial_return=0.99   the radial return's M of every returning automaton
//   coulomb_limit=0.9    the Coulomb limit mu |sigma| of every slipping side
// The arguments are tribodyn's. The tests mca_plastic_energy_faulted and
// mca_friction_energy_faulted run it to show that the physical energy
// balance fails on such a fault while the booked one still closes. Without
// TRIBODYN_FAULT the program refuses to run (it is not tribodyn).

#include <cstdlib>
#include <deal.II/base/mpi.h>
#include <iostream>
#include <string>
#include <tribodyn/core/application.h>
#include <tribodyn/mca/plasticity.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const char       *fault = std::getenv("TRIBODYN_FAULT");
  const std::string text  = fault != nullptr ? fault : "";
  const auto        equal = text.find('=');
  const std::string name  = text.substr(0, equal);
  const double      factor
    = equal == std::string::npos ? 0 : std::atof(text.c_str() + equal + 1);
  namespace fault_of = tribodyn::mca::verification;
  if (name == "radial_return" && factor > 0)
    fault_of::radial_return_factor = factor;
  else if (name == "coulomb_limit" && factor > 0)
    fault_of::coulomb_limit_factor = factor;
  else
    {
      std::cerr << "TRIBODYN_FAULT must be radial_return=F or "
                   "coulomb_limit=F with F > 0 (got '"
                << text << "')" << std::endl;
      return 2;
    }
  std::cout << "Fault injected: " << name << " x " << factor << std::endl;
  return tribodyn::run_application(argc, argv);
}
