// The staged friction loading of seed 000 Sec. 2.2 (issue #8), on a small
// rough-interface scene (4 x 4 x 8 FCC cells of steel, d = 7.5 nm).
//
// Checks and tolerances:
// - stages 2-3 (separate, shift) are rigid moves of the upper body at the
//   packing: every automaton of body 1 sits at its unstaged position plus
//   (0, W/2 wrapped into the period, separation), body 0 is unchanged
//   (1e-12 of the box width: round-off of the wrap);
// - the automatic separation leaves no pair of the two bodies within the
//   contact range d (brute force over the periodic images), and it is no
//   larger than needed: the closest pair is nearer than 1.25 d + a + d
//   (the margin over the continuous surfaces is 1.25 d in z; the sites
//   nearest to each surface lie within one layer spacing a/2 of it; the
//   lateral offset of the closest pair adds at most d);
// - the damping coefficient of the loading layers is the seed criterion
//   c_p / (2 h), h = 2 automaton layers = a, with c_p computed here from
//   E, nu, rho (1e-12);
// - stage 4: the bodies touch (contact_time >= 0) at a time no earlier than
//   the closing distance (closest pair distance - d) over the closing speed
//   2 V_z allows (the layers move at V_z at most, ramp included);
// - stage 5: after the contact and the ramp, the top and bottom layers
//   slide at exactly +V_y and -V_y along y and 0 along x (prescribed), and
//   the mean reaction of the top layer along z over one period of the
//   sliding over the box (W / 2V_y) balances the applied force F = p W^2
//   within 2 %. Within the period the reaction swings between ~0 and ~2 F
//   (printed per 0.1 ns): at this size one asperity pair rides over the
//   other, the plate rises and falls with it and its damper carries part of
//   the load; over a whole period the plate returns, so only its momentum
//   change and the damping of its net drift remain (measured 0.1 %);
// - with a Sliding delay D (the static coefficient's loading), the layers
//   stay at rest along x and y from the contact to the contact + D, with z
//   released at the contact (the layer moves under the load, not at
//   -V_z), then slide at exactly +-V_y after the ramp (1e-12: prescribed).

#include "mca_test_tools.h"

using namespace tribodyn_test;

namespace
{
  const double d = 7.5e-9, a = d * std::sqrt(2.), W = 4 * a;

  Parameters
  scene(const bool staged, const double delay = 0)
  {
    std::ostringstream text;
    text << std::setprecision(17) << rough_interface_geometry(d)
         << "subsection Interaction\nset Plasticity = false\n"
         << "set Friction coefficient = 0.3\nend\n"
         << "subsection Boundary conditions\nset Ramp time = 1e-10\nend\n"
         << "subsection Friction loading\nset Enabled = "
         << (staged ? "true" : "false")
         << "\nset Approach velocity = 5\nset Pressure = 300e6\n"
         << "set Sliding velocity = 10\nset Sliding delay = " << delay
         << "\nend\n";
    return parameters_from_text(text.str());
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Parameters                         flat   = scene(false);
  const Parameters                         staged = scene(true);
  const double                             gap = staged.geometry.interface_gap;

  // Stages 2-3: rigid moves at the packing.
  const auto before = pack_automata(flat.geometry, 2);
  const auto after  = pack_automata(staged.geometry, 2);
  check(before.size() == after.size() && !before.empty(),
        "same automata with and without the staging ("
          + std::to_string(before.size()) + ")");
  double worst = 0;
  for (std::size_t k = 0; k < std::min(before.size(), after.size()); ++k)
    {
      Point3 expected = before[k].position;
      if (before[k].body == 1)
        {
          expected[1] += W / 2;
          if (expected[1] >= W)
            expected[1] -= W;
          expected[2] += gap;
        }
      worst = std::max(worst, expected.distance(after[k].position));
      if (before[k].id != after[k].id || before[k].body != after[k].body)
        worst = 1e300;
    }
  check_relative(worst, 0, 1e-12, "body 1 moved by (0, W/2, gap)", W);

  // Separation: closest pair of the two bodies.
  double closest = 1e300;
  for (const auto &p : after)
    if (p.body == 0)
      for (const auto &q : after)
        if (q.body == 1)
          for (int sx = -1; sx <= 1; ++sx)
            for (int sy = -1; sy <= 1; ++sy)
              {
                Point3 r = q.position;
                r[0] += sx * W;
                r[1] += sy * W;
                closest = std::min(closest, p.position.distance(r));
              }
  check(closest > d && closest < 2.25 * d + a,
        "closest pair of the two bodies at the start: "
          + std::to_string(closest / d)
          + " d (in (1, 2.25 + sqrt 2) d); separation "
          + std::to_string(gap / d) + " d");

  // Damping from the seed criterion.
  const auto  &m = staged.materials[0];
  const double E = m.youngs_modulus, nu = m.poisson_ratio;
  const double c_p
    = std::sqrt(E * (1 - nu) / (m.density * (1 + nu) * (1 - 2 * nu)));
  check_relative(staged.loading_damping,
                 c_p / (2 * a),
                 1e-12,
                 "damping of the loading layers = c_p / (2 h)");

  // Stages 4-5: run.
  AutomatonSystem system(staged, MPI_COMM_WORLD);
  system.setup();
  unsigned int top = 0, bottom = 0;
  for (unsigned int g = 0; g < staged.boundary.groups.size(); ++g)
    {
      if (staged.boundary.groups[g].name == "top")
        top = g;
      if (staged.boundary.groups[g].name == "bottom")
        bottom = g;
    }
  const double F = 300e6 * W * W, Vy = 10, Vz = 5, ramp = 1e-10;
  double       mean_reaction = 0;
  unsigned int samples       = 0;
  while (system.contact_time() < 0 && system.time() < 2e-9)
    system.step();
  const double t_contact = system.contact_time();
  check(t_contact >= (closest - d) / (2 * Vz),
        "the bodies touch at t = " + std::to_string(t_contact * 1e9)
          + " ns, no earlier than (closest - d) / (2 V_z) = "
          + std::to_string((closest - d) / (2 * Vz) * 1e9) + " ns");
  if (t_contact < 0)
    return result();
  // one period of the sliding over the box (the roughness repeats after
  // W / (2 V_y)), after 0.5 ns of settling
  const double period    = W / (2 * Vy);
  const double t_end     = t_contact + ramp + 5e-10 + period;
  double       window    = 0;
  unsigned int in_window = 0;
  while (system.time() < t_end)
    {
      system.step();
      const double fz = system.boundary_loads().reactions()[top][2];
      window += fz;
      ++in_window;
      if (in_window == 400)
        {
          std::cout << "  t - t_contact = " << (system.time() - t_contact) * 1e9
                    << " ns: mean reaction " << window / in_window / F << " F"
                    << std::endl;
          window    = 0;
          in_window = 0;
        }
      if (system.time() > t_end - period)
        {
          mean_reaction += fz;
          ++samples;
        }
    }
  mean_reaction /= samples;
  check_relative(mean_reaction,
                 F,
                 0.02,
                 "mean reaction of the top layer over one sliding period vs "
                 "the applied force p W^2");
  double worst_v = 0;
  for (unsigned int k = 0; k < system.n_owned_automata(); ++k)
    {
      const auto  &x  = system.positions()[k];
      const auto  &u  = system.displacements()[k];
      const double z0 = x[2] - u[2];
      const auto  &G  = staged.boundary.groups;
      const auto  &v  = system.velocities()[k];
      if (z0 >= G[top].lower[2])
        worst_v = std::max({worst_v, std::abs(v[1] - Vy), std::abs(v[0])});
      if (z0 <= G[bottom].upper[2])
        worst_v = std::max({worst_v, std::abs(v[1] + Vy), std::abs(v[0])});
    }
  check_relative(worst_v, 0, 1e-12, "layers slide at +-V_y, 0 along x", Vy);

  // The sliding delayed by D: at rest along x, y over the delay, z free.
  const double     D       = 3e-10;
  const Parameters delayed = scene(true, D);
  AutomatonSystem  held(delayed, MPI_COMM_WORLD);
  held.setup();
  const auto layer_velocities =
    [&](const double vy, double &worst_xy, double &largest_z_deviation) {
      const auto &G = delayed.boundary.groups;
      for (unsigned int k = 0; k < held.n_owned_automata(); ++k)
        {
          const double z0 = held.positions()[k][2] - held.displacements()[k][2];
          const auto  &v  = held.velocities()[k];
          const double sign = z0 >= G[top].lower[2]      ? 1.
                              : z0 <= G[bottom].upper[2] ? -1.
                                                         : 0.;
          if (sign == 0)
            continue;
          worst_xy
            = std::max({worst_xy, std::abs(v[1] - sign * vy), std::abs(v[0])});
          largest_z_deviation
            = std::max(largest_z_deviation, std::abs(v[2] + sign * Vz));
        }
    };
  while (held.contact_time() < 0 && held.time() < 2e-9)
    held.step();
  check(held.contact_time() >= 0, "the delayed scene's bodies touch");
  double at_rest = 0, z_moves = 0;
  while (held.time() < held.contact_time() + D)
    {
      held.step();
      if (held.time() < held.contact_time() + D)
        layer_velocities(0, at_rest, z_moves);
    }
  check_relative(
    at_rest, 0, 1e-12, "layers at rest along x, y over the sliding delay", Vy);
  check(z_moves > 1e-3 * Vz,
        "the approach along z is released at the contact (largest |v_z -+ "
        "V_z| over the delay: "
          + std::to_string(z_moves) + " m/s)");
  while (held.time() < held.contact_time() + D + ramp + 1e-11)
    held.step();
  double sliding = 0, ignored = 0;
  layer_velocities(Vy, sliding, ignored);
  check_relative(sliding,
                 0,
                 1e-12,
                 "layers slide at +-V_y after the delay and the ramp",
                 Vy);
  return result();
}
