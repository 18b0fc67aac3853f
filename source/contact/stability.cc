// What the blow-up detection of the contact time loop reports: the worst
// node over all ranks, where it is and the likely cause (doc/stability.md).
#include <array>
#include <boost/serialization/array.hpp>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <limits>
#include <map>
#include <sstream>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/core/errors.h>

namespace tribodyn
{
  namespace contact
  {
    using namespace dealii;

    namespace
    {
      const char *
      status_name(const double status)
      {
        return status == stick  ? "stick"
               : status == slip ? "slip"
                                : "separated";
      }
    } // namespace


    void
    ContactSolver::report_instability(const unsigned long step,
                                      const double        time) const
    {
      // Worst owned dof of this rank: a non-finite velocity counts as
      // infinitely bad.
      const unsigned int n_owned = mass.size();
      double             worst   = -1;
      unsigned int       index   = 0;
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          const double v = p.local_element(i);
          const double b = std::isfinite(v)
                             ? std::abs(v)
                             : std::numeric_limits<double>::infinity();
          if (b > worst)
            {
              worst = b;
              index = i;
            }
        }
      // Its position, component, contact status.
      std::array<double, 8> mine = {{worst, 0, 0, 0, -1, 0, 0, 0}};
      if (n_owned > 0)
        {
          std::map<types::global_dof_index, Point<2>> points;
          DoFTools::map_dofs_to_support_points(MappingQ1<2>(),
                                               dof_handler,
                                               points);
          const auto global = u.get_partitioner()->local_to_global(index);
          const auto it     = points.find(global);
          if (it != points.end())
            {
              mine[1] = it->second[0];
              mine[2] = it->second[1];
            }
          mine[3] = component[index];
          for (const ContactNode &node : contact_nodes)
            if (node.ix == index || node.iy == index)
              {
                mine[4] = node.status;
                mine[5] = node.lambda_n;
              }
          mine[6] = p.local_element(index);
          mine[7] = u.local_element(index);
        }
      const auto  all  = Utilities::MPI::all_gather(comm, mine);
      std::size_t best = 0;
      for (std::size_t r = 1; r < all.size(); ++r)
        if (all[r][0] > all[best][0])
          best = r;
      const auto &w = all[best];

      std::ostringstream m;
      m.precision(4);
      const char *axis = w[3] == 0 ? "x" : "y";
      m << "The run became unstable at step " << step << " (t = " << time
        << " s): at the node (x, y) = (" << w[1] << ", " << w[2] << ") m";
      if (w[4] >= 0)
        m << ", a contact node (status " << status_name(w[4])
          << ", lambda_N = " << w[5] << " N/m)";
      else
        m << ", not a contact node";
      m << ", the velocity v_" << axis << " = " << w[6] << " m/s (u_" << axis
        << " = " << w[7] << " m) "
        << (std::isfinite(w[6]) ? "exceeds" : "is not finite; the limit is")
        << " the plausibility limit c_max + |V| + |v_0| = " << velocity_limit()
        << " m/s (a velocity near the wave speed means strains of order "
           "one). Likely cause: ";
      const double ratio = dt / dt_critical;
      if (ratio > 1)
        m << "the time step: dt = " << dt << " s is " << ratio
          << " times the critical step " << dt_critical
          << " s of the damped beta2 scheme (beta2 = " << prm.time.beta2
          << ", damping beta = " << prm.time.damping
          << " s); lower 'Time/Time step' or set 'Automatic "
             "time step = true'.";
      else if (w[4] >= 1)
        m << "contact at this node (P = " << prm.loading.pressure / 1e6
          << " MPa, V = " << prm.loading.plane_velocity
          << " m/s): the contact correction h lambda / m is too large for "
             "the step; lower 'Time/Time step' (now "
          << ratio << " of the critical step) or the load.";
      else if (ratio > 0.9)
        m << "the time step, " << ratio
          << " of the critical step (the element bound of omega_max is not "
             "exact for every mesh and material); lower "
             "'Time/Time step'.";
      else
        m << "the loading or the material (P = " << prm.loading.pressure / 1e6
          << " MPa, V = " << prm.loading.plane_velocity
          << " m/s, dt = " << ratio
          << " of the critical step): check the moduli, the density and the "
             "loads, and lower the time step.";
      if (prm.time.damping == 0)
        m << " The damping is off ('Damping coefficient' = 0): the highest "
             "modes are not damped.";
      throw RunError(m.str());
    }
  } // namespace contact
} // namespace tribodyn
