// The shear state of a pair survives a relabelling at a rebuild.
//
// A pair's i is the automaton of smaller global order key (cell along the
// space-filling curve, then rank in the cell), so when automata move into
// other cells a pair may change orientation at a pair-list rebuild. The
// shear stresses tau_i, tau_j follow the relative displacement x_j - x_i:
// they are odd under the relabelling i <-> j, and the rebuild must negate
// them. The check: two bonded automata are sheared once (a tangential
// relative displacement), then translated rigidly, in a periodic box, along
// a path that crosses many cells, with a pair-list rebuild after each move.
// The shear force on the automaton of the smaller id, +S tau if it is i,
// -S tau if it is j, is invariant under rigid translation: it must stay what it
// was after the shear, to 1e-12 relative (rounding of the rigid moves), and the
// path must relabel the pair at least once (else the test proves nothing).
// The relative-rotation moment K_ij (on i; odd like tau) is on: the shear
// move also turns automaton 1 (twist and bending), and the moment on
// automaton 0 must stay unchanged to 1e-12 as well.

#include "mca_test_tools.h"

using namespace tribodyn_test;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             d = 1e-3, a = d * std::sqrt(2.);
  Parameters                               p = block_parameters(1, d, 0);
  p.geometry.domain_lower                    = Point3(0, 0, 0);
  p.geometry.domain_upper                    = Point3(8 * a, 8 * a, 2 * a);
  p.geometry.periodic                        = {{true, true, false}};
  p.geometry.bodies[0].lower                 = Point3(0, 0, 0);
  p.geometry.bodies[0].upper                 = Point3(a, a, a / 2);
  p.interaction.moment.get<ElasticMoment>().stiffness = 1;
  AutomatonSystem system(p, MPI_COMM_WORLD);
  system.setup();
  check(system.n_global_automata() == 2,
        "two automata (" + std::to_string(system.n_global_automata()) + ")");
  // without the pair the rest proves nothing: a failure, not a silent pass
  check(system.pair_views().size() == 1,
        "the two automata form one pair ("
          + std::to_string(system.pair_views().size()) + ")");
  if (system.n_global_automata() != 2 || system.pair_views().size() != 1)
    return result();

  // the automaton of the smaller id is called "0", the other "1"; pair
  // direction n (from 0 to 1) and a tangent t
  const std::uint32_t id0 = std::min(system.ids()[0], system.ids()[1]);
  Vec3                n, t;
  {
    const auto  &x  = system.positions();
    const double r  = x[0].distance(x[1]);
    const int    s1 = system.ids()[1] != id0 ? 1 : 0;
    for (unsigned int c = 0; c < 3; ++c)
      n[c] = (x[s1][c] - x[1 - s1][c]) / r;
    t = {{-n[1], n[0], 0}};
  }
  auto shear_on_0 = [&]() {
    const auto   pv   = system.pair_views().at(0);
    const double sign = pv.id_i == id0 ? 1. : -1.;
    return Vec3{{sign * pv.tau[0], sign * pv.tau[1], sign * pv.tau[2]}};
  };
  auto moment_on_0 = [&]() {
    const auto   pv   = system.pair_views().at(0);
    const double sign = pv.id_i == id0 ? 1. : -1.;
    return Vec3{
      {sign * pv.moment[0], sign * pv.moment[1], sign * pv.moment[2]}};
  };
  {
    unsigned int k = 0;
    system.impose_motion(
      [&](const Point3 &, Vec3 &du, Vec3 &dtheta) {
        for (unsigned int c = 0; c < 3; ++c)
          {
            du[c] = system.ids()[k] != id0 ? 1e-5 * d * t[c] : 0.;
            dtheta[c]
              = system.ids()[k] != id0 ? 1e-5 * (n[c] + 0.5 * t[c]) : 0.;
          }
        ++k;
      },
      1e-9);
  }
  // one evaluation at rest: the shear move turned the pair's normal by
  // ~1e-5 rad, and the stored shear stress is projected onto the new
  // tangent plane at the next evaluation (a change of that order)
  system.impose_motion(
    [&](const Point3 &, Vec3 &du, Vec3 &dtheta) {
      du     = {{0, 0, 0}};
      dtheta = {{0, 0, 0}};
    },
    1e-9);
  const Vec3   reference = shear_on_0();
  const double size      = std::sqrt(dot(reference, reference));
  check(size > 0, "the shear produced a shear stress");
  const Vec3   moment0     = moment_on_0();
  const double moment_size = std::sqrt(dot(moment0, moment0));
  check(moment_size > 0, "the rotation produced a moment");
  double worst_moment = 0;

  const std::uint64_t first_i  = system.pair_views().at(0).id_i;
  unsigned int        n_flips  = 0;
  std::uint64_t       last_i   = first_i;
  double              worst    = 0;
  const Vec3          step_dir = {{0.83 * a, 0.31 * a, 0}};
  for (unsigned int s = 0; s < 40; ++s)
    {
      system.impose_motion(
        [&](const Point3 &, Vec3 &du, Vec3 &dtheta) {
          du     = step_dir;
          dtheta = {{0, 0, 0}};
        },
        1e-9);
      system.rebuild_pair_list();
      // evaluate the pairs at rest after the rebuild (a zero move)
      system.impose_motion(
        [&](const Point3 &, Vec3 &du, Vec3 &dtheta) {
          du     = {{0, 0, 0}};
          dtheta = {{0, 0, 0}};
        },
        1e-9);
      const auto pv = system.pair_views();
      if (pv.size() != 1)
        {
          check(false, "the pair survives the rebuild");
          return result();
        }
      if (pv[0].id_i != last_i)
        ++n_flips;
      last_i       = pv[0].id_i;
      const Vec3 f = shear_on_0();
      for (unsigned int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(f[c] - reference[c]) / size);
      const Vec3 m = moment_on_0();
      for (unsigned int c = 0; c < 3; ++c)
        worst_moment
          = std::max(worst_moment, std::abs(m[c] - moment0[c]) / moment_size);
    }
  check(n_flips > 0,
        "the path relabels the pair (" + std::to_string(n_flips)
          + " relabellings in 40 rebuilds)");
  check_relative(worst,
                 0,
                 1e-12,
                 "shear force on automaton 0 unchanged by rigid moves and "
                 "rebuilds",
                 1.);
  check_relative(worst_moment,
                 0,
                 1e-12,
                 "relative-rotation moment on automaton 0 unchanged by rigid "
                 "moves and rebuilds",
                 1.);
  return result();
}
