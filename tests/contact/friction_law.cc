// The friction laws of the contact loop (include/tribodyn/contact/
// friction_laws/) against their closed forms (round-off tolerances 1e-14),
// and the meso pin against its morphology.
// (a) Coulomb: stick inside the cone (lambda_T = trial), slip on it
//     (lambda_T = mu lambda_N sign(trial)).
// (b) Regularized law, seed eq. (4): with lambda_N fixed and the trial
//     outside the cone, n steps from tau = 0 give
//     tau_n = alpha mu lambda_N (1 - exp(-n dt / t*)) exactly (the exact
//     exponential integration); a trial inside the cone sticks; the force
//     never exceeds the stick trial.
// (c) Meso pin: the same morphology parameters give the same pin as the
//     homogenization module (Morphology::create): the heterogeneity area
//     fraction of the mesh equals the morphology's pixel fraction.

#include "contact_test_tools.h"

#include <cmath>
#include <tribodyn/contact/friction_laws.h>
#include <tribodyn/core/morphology.h>

int
main(int argc, char **argv)
{
  using namespace tribodyn_test;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ContactLawParameters                     contact;
  contact.friction_coefficient = 0.25;
  ContactStatus status;
  ContactNode   node; // in contact before the step (status stick)
  node.status = stick;
  {
    const Coulomb law(contact, {}, 5e-9);
    const double  t = law.tangential(node, 0.2, 1., status);
    check(t == 0.2 && status == stick, "Coulomb: inside the cone sticks");
    const double s = law.tangential(node, -0.3, 1., status);
    check(s == -0.25 && status == slip, "Coulomb: outside slips at -mu N");
  }
  {
    const double dt = 5e-9, t_star = 1.5e-6, lambda_n = 2.;
    contact.regularization_time = t_star;
    Regularized law(contact, {}, dt);
    PlaneStep   step;
    step.dt    = dt;
    step.speed = 1;
    law.begin_step(step);
    node.tau = 0;
    for (unsigned int n = 1; n <= 1000; ++n)
      node.tau = law.tangential(node, -10., lambda_n, status);
    check_relative(node.tau,
                   -0.25 * lambda_n * (1 - std::exp(-1000 * dt / t_star)),
                   1e-14,
                   "regularized: exact relaxation over 1000 steps");
    check(status == slip, "regularized: status slip");
    const double inside = law.tangential(node, 0.4, lambda_n, status);
    check(inside == 0.4 && status == stick,
          "regularized: inside the cone sticks");
    // tau_old above the cone (normal force dropped): relaxation would give
    // more than the stick trial, so the point sticks instead.
    node.tau            = 5.;
    const double capped = law.tangential(node, 0.6, lambda_n, status);
    check(capped == 0.6 && status == stick,
          "regularized: never more than the stick trial");
  }
  {
    const std::string       prm = R"(
      subsection Materials
        set Type = morphology
      end
      subsection Morphology
        set Seed = 3
      end
      subsection Output
        set Averaging start time = 0
      end)";
    ContactRun              run(prm);
    const ContactParameters p = contact_parameters(prm);
    const Morphology        m = Morphology::create(p.morphology);
    check_relative(run.solver->heterogeneity_area_fraction(),
                   m.heterogeneity_fraction(),
                   1e-12,
                   "meso pin: heterogeneity area fraction = morphology's");
    check(m.heterogeneity_fraction() > 0.05,
          "the morphology has heterogeneities");
  }
  return result();
}
