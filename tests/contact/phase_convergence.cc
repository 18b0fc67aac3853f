// Convergence in h and dt of the phase diagram of point M (seed 001 Fig. 5)
// in the developed slip-separation regime, as statistics.
// The homogenized pin (Table 1 constants) at P = 0.5 MPa with the pressure
// applied as a step (Ramp time = 0): the friction-induced instability is
// developed from about 50 us on (25-30 % of the nodes separated) and the
// histories of different discretizations diverge: only statistics over the
// window 50-250 us can converge. Compared: (h, dt) = (0.25 mm, 5 ns)
// against (0.25 mm, 2.5 ns) and (0.125 mm, 5 ns), L*/|V| fixed at 1.5 us.
// Statistics of the phase diagram of M: mean and standard deviation of the
// tangential velocity, standard deviation of the tangential displacement
// (the extent of the orbit).
// Tolerance: each difference within 3 combined standard errors
// sqrt(se_a^2 + se_b^2), the standard errors from block averaging
// (Flyvbjerg-Petersen, statistics::block_average) of the series of the
// statistic (v, (v - mean)^2, (u - mean)^2). So that
// the test can fail, the tolerances must also be tight: 3 combined standard
// errors below 25 % of the statistic (below half the velocity's standard
// deviation for the mean velocity, which is about 0).
// Measured: dt 5/2.5 ns and h 0.25/0.125 mm agree within 1 % on the
// velocity's standard deviation (0.063-0.064 m/s) and within 13 % on the
// displacement's (7.7e-8 / 7.8e-8 / 8.7e-8 m), inside 3 standard errors.
// Not checked (printed; a finding recorded in doc/theory/contact.md §8):
// the separated fractions do NOT converge in h over this window: 0.25 of
// all contact nodes (M: 0.25) at h = 0.25 mm against 0.17 (M: 0.12) at
// 0.125 mm, a difference of 5 standard errors; dt 5/2.5 ns agree (0.252 /
// 0.256).
// and mu_global's mean (its 71 kHz oscillation over 14 periods leaves the
// blocking estimate without a plateau; regularized_convergence checks it
// before the instability).

#include "contact_test_tools.h"

#include <cmath>
#include <tribodyn/core/statistics.h>

namespace
{
  using namespace tribodyn_test;

  struct Statistic
  {
    std::string name;
    double      value, stderr_;
  };

  std::vector<Statistic>
  run_statistics(const std::string &h, const std::string &dt)
  {
    ContactRun          run(R"(
      subsection Geometry
        set Mesh size = )"
                   + h + R"(
      end
      subsection Materials
        set Type = engineering constants
      end
      subsection Loading
        set Ramp time = 0
      end
      subsection Time
        set Time step = )"
                   + dt + R"(
        set End time = 250e-6
      end
      subsection Output
        set Sample interval = )"
                   + (dt == "5e-9" ? "20" : "40") + R"(
        set Averaging start time = 50e-6
      end)");
    const auto         &samples = run.run();
    std::vector<double> v, u, sep, face;
    for (const auto &s : samples)
      if (s.time >= 50e-6)
        {
          v.push_back(s.M_vx);
          u.push_back(s.M_ux);
          sep.push_back(s.M_status == 0);
          face.push_back(s.separation_fraction);
        }
    using tribodyn::statistics::block_average;
    const auto          bv = block_average(v), bu = block_average(u);
    std::vector<double> v2, u2;
    for (const double x : v)
      v2.push_back((x - bv.mean) * (x - bv.mean));
    for (const double x : u)
      u2.push_back((x - bu.mean) * (x - bu.mean));
    const auto             bv2 = block_average(v2), bu2 = block_average(u2);
    const double           sv = std::sqrt(bv2.mean), su = std::sqrt(bu2.mean);
    const auto             bs = block_average(sep), bf = block_average(face);
    std::vector<Statistic> r
      = {{"mean tangential velocity of M (m/s)", bv.mean, bv.standard_error},
         {"std of the tangential velocity of M (m/s)",
          sv,
          bv2.standard_error / (2 * sv)},
         {"std of the tangential displacement of M (m)",
          su,
          bu2.standard_error / (2 * su)},
         {"separated fraction of all contact nodes (not checked)",
          bf.mean,
          bf.standard_error},
         {"separated fraction of M (not checked)", bs.mean, bs.standard_error}};
    if (is_root())
      {
        std::cout << "h = " << h << ", dt = " << dt << ":\n";
        for (const auto &s : r)
          std::cout << "  " << s.name << " = " << s.value << " +- " << s.stderr_
                    << "\n";
      }
    return r;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto base  = run_statistics("0.25e-3", "5e-9");
  const auto small = run_statistics("0.25e-3", "2.5e-9");
  const auto fine  = run_statistics("0.125e-3", "5e-9");
  for (const auto *other : {&small, &fine})
    for (unsigned int i = 0; i < 3; ++i)
      {
        const double tol
          = 3
            * std::sqrt(base[i].stderr_ * base[i].stderr_
                        + (*other)[i].stderr_ * (*other)[i].stderr_);
        const std::string what
          = base[i].name
            + (other == &small ? ": dt 5 vs 2.5 ns" : ": h 0.25 vs 0.125 mm");
        check(std::abs(base[i].value - (*other)[i].value) <= tol,
              what + " within 3 standard errors (" + std::to_string(tol) + ")");
        // The mean velocity is about 0: resolved to half the spread.
        const double tight
          = i == 0 ? 0.5 * base[1].value : 0.25 * std::abs(base[i].value);
        check(tol < tight, what + ": tolerance tight enough");
      }
  return result();
}
