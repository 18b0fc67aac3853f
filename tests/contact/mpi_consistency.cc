// Run on 2 MPI ranks. The default pin (regularized friction, P = 0.5 MPa,
// h = 0.25 mm, 10 us):
// (a) on 2 ranks equals the serial run (every rank also runs the pin
//     alone on MPI_COMM_SELF): mu_global, contact forces, energies and the
//     motion of M agree to 1e-9 relative (only the summation order of the
//     ghost contributions differs);
// (b) the projected Gauss-Seidel path gives the node-wise closed form
//     (rigid plane: decoupled constraints) to 1e-9.

#include "contact_test_tools.h"

#include <cmath>

namespace
{
  using namespace tribodyn_test;

  double
  largest_difference(const std::vector<Sample> &a, const std::vector<Sample> &b)
  {
    if (a.size() != b.size())
      return 1e300;
    double d = 0, scale_f = 0, scale_e = 0, scale_u = 0, scale_mu = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      {
        scale_f  = std::max(scale_f, std::abs(a[i].contact_normal_force));
        scale_e  = std::max(scale_e,
                           std::abs(a[i].kinetic_energy)
                             + std::abs(a[i].elastic_energy));
        scale_u  = std::max(scale_u, std::abs(a[i].M_ux));
        scale_mu = std::max(scale_mu, std::abs(a[i].mu_global));
      }
    for (std::size_t i = 0; i < a.size(); ++i)
      {
        d = std::max(d, std::abs(a[i].mu_global - b[i].mu_global) / scale_mu);
        d = std::max(d,
                     std::abs(a[i].contact_normal_force
                              - b[i].contact_normal_force)
                       / scale_f);
        d = std::max(d,
                     std::abs(a[i].contact_tangential_force
                              - b[i].contact_tangential_force)
                       / scale_f);
        d = std::max(d,
                     std::abs(a[i].kinetic_energy - b[i].kinetic_energy)
                       / scale_e);
        d = std::max(d,
                     std::abs(a[i].elastic_energy - b[i].elastic_energy)
                       / scale_e);
        d = std::max(d, std::abs(a[i].M_ux - b[i].M_ux) / scale_u);
        d = std::max(d, a[i].M_status != b[i].M_status ? 1. : 0.);
      }
    return d;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        prm = R"(
    subsection Time
      set End time = 10e-6
    end
    subsection Loading
      set Ramp time = 2e-6
    end
    subsection Output
      set Sample interval = 10
      set Averaging start time = 0
    end)";
  ContactRun                               parallel(prm);
  ContactRun                               serial(prm, MPI_COMM_SELF);
  ContactRun                               pgs(prm + R"(
    subsection Contact
      set Algorithm = projected Gauss-Seidel
    end)");
  const auto                              &a = parallel.run();
  const auto                              &b = serial.run();
  const auto                              &c = pgs.run();
  check(dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 2,
        "runs on 2 ranks");
  const double d_ranks = largest_difference(a, b);
  check(d_ranks < 1e-9,
        "2 ranks = 1 rank to 1e-9 (" + std::to_string(d_ranks) + ")");
  const double d_pgs = largest_difference(a, c);
  check(d_pgs < 1e-9,
        "projected Gauss-Seidel = node-wise to 1e-9 (" + std::to_string(d_pgs)
          + ")");
  check(a.back().mu_global > 0.05,
        "friction developed (mu_global = " + std::to_string(a.back().mu_global)
          + ")");
  return result();
}
