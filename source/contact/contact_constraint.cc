// Forward-increment Lagrange multipliers and the friction laws (doc/theory/
// contact.md sections 3 and 4).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <tribodyn/contact/contact_solver.h>
#include <tribodyn/contact/spectrum.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/progress.h>

namespace tribodyn
{
  namespace contact
  {
    using namespace dealii;
    double
    ContactSolver::plane_height(const double x, const double plane_x) const
    {
      const double A = prm.loading.imperfection_amplitude;
      if (A == 0)
        return 0.;
      const double xi = x - plane_x;
      return -0.5 * A
             * (1.
                - std::cos(2. * M_PI * xi
                           / prm.loading.imperfection_wavelength));
    }


    template <class Law>
    void
    ContactSolver::contact_node_wise(const Law &law)
    {
      const double  gap0  = prm.loading.initial_gap;
      const double  slide = plane_slide;
      const bool    keep  = prm.contact.recontact_state == RecontactState::keep;
      const double *uv    = u.begin();
      const double *up    = u_prev.begin();
      double       *un    = u_next.begin();
      double       *av    = a.begin();
      double        wc = 0, df = 0;
      for (ContactNode &node : contact_nodes)
        {
          // Gap at t_{n+1} of the predicted configuration (plane at
          // y = -gap0 + plane_height).
          const double g = un[node.iy] + gap0
                           - plane_height(node.x + un[node.ix], plane_x_next);
          if (g >= 0)
            {
              node.lambda_n = node.lambda_t = 0;
              if (!keep)
                node.tau = 0;
              node.status    = separated;
              node.slip_rate = std::abs(un[node.ix] - uv[node.ix] - slide) / dt;
              law.end_step(node, dt);
              continue;
            }
          const double lambda_n = -node.m * g / h;
          const double trial = node.m * (uv[node.ix] + slide - un[node.ix]) / h;
          ContactStatus status;
          const double lambda_t = law.tangential(node, trial, lambda_n, status);
          node.lambda_n         = lambda_n;
          node.lambda_t         = lambda_t;
          node.tau              = lambda_t;
          node.status           = status;
          un[node.iy] += h * lambda_n / node.m;
          un[node.ix] += h * lambda_t / node.m;
          av[node.iy] += lambda_n / node.m;
          av[node.ix] += lambda_t / node.m;
          wc += 0.5
                * (lambda_n * (un[node.iy] - up[node.iy])
                   + lambda_t * (un[node.ix] - up[node.ix]));
          df += lambda_t * (slide - (un[node.ix] - uv[node.ix]));
          node.slip_rate = std::abs(un[node.ix] - uv[node.ix] - slide) / dt;
          law.end_step(node, dt);
        }
      work_contact += wc;
      dissipation_friction += df;
    }


    template <class Law>
    void
    ContactSolver::contact_gauss_seidel(const Law &law)
    {
      // General projected Gauss-Seidel over constraint rows. A row is a list
      // of (dof, coefficient); the normal row of contact k reads
      // g_k = G_N u + gap0 - plane height >= 0, the tangential row the slip
      // increment G_T (u_{n+1} - u_n) - (plane displacement). Each update
      // changes u_{n+1} by h M^-1 G^T d(lambda), so rows sharing dofs see
      // each other's corrections (that is what makes the path valid for
      // coupled constraints). Against the rigid plane the rows are decoupled
      // and the first sweep gives the closed form; the second confirms
      // convergence.
      const double  gap0  = prm.loading.initial_gap;
      const double  slide = plane_slide;
      const double *uv    = u.begin();
      const double *up    = u_prev.begin();
      double       *un    = u_next.begin();
      double       *av    = a.begin();
      // State before the step (the friction law's tau_n and the status).
      std::vector<ContactNode> before(contact_nodes);
      // The plane's height under each node, at the predicted position (the
      // constraint rows are built once per step on the predicted
      // configuration, as in the node-wise path).
      std::vector<double> height(contact_nodes.size());
      for (std::size_t k = 0; k < contact_nodes.size(); ++k)
        {
          ContactNode &node = contact_nodes[k];
          height[k]         = plane_height(node.x + un[node.ix], plane_x_next);
          node.lambda_n = node.lambda_t = 0;
        }
      // Rows of node k: normal (dof iy, coefficient 1), tangential (ix, 1).
      auto apply = [&](const unsigned int dof,
                       const double       coefficient,
                       const double       d_lambda,
                       const double       m) {
        un[dof] += h * coefficient * d_lambda / m;
        av[dof] += coefficient * d_lambda / m;
      };
      unsigned int iteration = 0;
      for (; iteration < prm.contact.pgs_max_iterations; ++iteration)
        {
          double change = 0, largest = 0;
          for (std::size_t k = 0; k < contact_nodes.size(); ++k)
            {
              ContactNode &node = contact_nodes[k];
              const double W    = h / node.m; // G M^-1 G^T h, diagonal entry
              // Normal row.
              const double g        = un[node.iy] + gap0 - height[k];
              const double lambda_n = std::max(0., node.lambda_n - g / W);
              apply(node.iy, 1., lambda_n - node.lambda_n, node.m);
              change = std::max(change, std::abs(lambda_n - node.lambda_n));
              node.lambda_n = lambda_n;
              // Tangential row.
              double        lambda_t = 0;
              ContactStatus status   = separated;
              if (lambda_n > 0)
                {
                  const double s     = (un[node.ix] - uv[node.ix]) - slide;
                  const double trial = node.lambda_t - s / W;
                  lambda_t = law.tangential(before[k], trial, lambda_n, status);
                }
              apply(node.ix, 1., lambda_t - node.lambda_t, node.m);
              change = std::max(change, std::abs(lambda_t - node.lambda_t));
              node.lambda_t = lambda_t;
              node.status   = status;
              largest       = std::max(largest, std::abs(lambda_n));
            }
          if (change <= prm.contact.pgs_tolerance * largest || largest == 0)
            {
              ++iteration;
              break;
            }
        }
      pgs_iterations_max = std::max(pgs_iterations_max, iteration);
      const bool keep    = prm.contact.recontact_state == RecontactState::keep;
      double     wc = 0, df = 0;
      for (std::size_t k = 0; k < contact_nodes.size(); ++k)
        {
          ContactNode &node = contact_nodes[k];
          node.tau          = node.lambda_t;
          if (node.lambda_n <= 0)
            {
              node.status = separated;
              if (keep)
                node.tau = before[k].tau;
            }
          wc += 0.5
                * (node.lambda_n * (un[node.iy] - up[node.iy])
                   + node.lambda_t * (un[node.ix] - up[node.ix]));
          df += node.lambda_t * (slide - (un[node.ix] - uv[node.ix]));
          node.slip_rate = std::abs(un[node.ix] - uv[node.ix] - slide) / dt;
          law.end_step(node, dt);
        }
      work_contact += wc;
      dissipation_friction += df;
    }


    void
    ContactSolver::solve_contact(const double time_next)
    {
      // Plane motion over the step t_n -> t_{n+1} (exactly V dt for the
      // constant plane velocity of the default loading).
      const auto  &L = prm.loading;
      const double t = time_next - dt;
      PlaneStep    step;
      step.dt                = dt;
      step.h                 = h;
      step.speed             = std::abs(L.plane_velocity);
      step.constant_velocity = L.constant_plane_velocity();
      if (step.constant_velocity)
        {
          plane_slide  = L.plane_velocity * dt;
          plane_x_next = L.plane_velocity * time_next;
        }
      else
        {
          plane_x_next = L.plane_position_at(time_next);
          plane_slide  = plane_x_next - L.plane_position_at(t);
        }
      step.slide = plane_slide;
      // The law chosen for the run: the contact loops are compiled per law.
      const bool gs
        = prm.contact.algorithm == ContactAlgorithm::projected_gauss_seidel;
      FrictionLaws::visit(friction_law, [&](auto &law) {
        law.begin_step(step);
        gs ? contact_gauss_seidel(law) : contact_node_wise(law);
      });
    }


    void
    ContactSolver::report_friction_law(JsonValue    &summary,
                                       std::ostream &figures) const
    {
      FrictionLaws::visit(friction_law, [&](const auto &l) {
        l.report(summary, figures, comm);
      });
    }


    std::string
    classify_regime(const double stick,
                    const double slip,
                    const double separation,
                    const double threshold)
    {
      const bool st = stick > threshold, sl = slip > threshold,
                 se = separation > threshold;
      return st && sl && se ? "stick-slip-separation"
             : sl && se     ? "slip-separation"
             : st && sl     ? "stick-slip"
             : sl           ? "slip"
             : st           ? (se ? "stick-separation" : "stick")
             : se           ? "separation"
                            : "none";
    }
  } // namespace contact
} // namespace tribodyn
