// The moment of relative rotation K_ij of seed eq. (1) (issue #8):
// incremental twisting and bending springs of a pair, k_t = lambda k J and
// k_b = lambda k I with k = k_i k_j / (k_i + k_j) = 2G/d (two steel halves)
// and I = S^2/(4 pi), J = 2 I (doc/theory/mca.md §3).
//
// Two steel automata at contact distance d along n = (1, 1, 0)/sqrt 2:
//  1. stiffnesses: the system's k_t, k_b equal the formula to 1e-14;
//  2. imposed twist (no inertia), 50 increments of 1e-6 rad of one
//     automaton about n: K = k_t theta n on the automaton that is not
//     turned (it is dragged along), -K on the other, to 1e-12 relative
//     (the increments are exact; only round-off); the torques of the two
//     automata are opposite to 1e-14 of |K| (pure twist makes no shear);
//     imposed bending about t (perpendicular to n): K = k_b theta t;
//  3. free torsional oscillation (velocity Verlet, the automatic step):
//     omega_i = -omega_j along n. The period of K . n equals the leapfrog
//     period 2 pi / Omega, sin(Omega dt / 2) = omega_0 dt / 2, to 5e-7
//     (zero crossings found by linear interpolation between steps: error
//     O((omega_0 dt)^3) of a step, ~1e-6 of a period, averaged over the
//     crossings; measured 7.7e-8) and the analytic 2 pi sqrt(J_red / k_t)
//     (J_red = J / 2) to 1e-3 (the leapfrog shift, (omega_0 dt)^2 / 24,
//     is 5.7e-4 here); the energy 1/2 J (w_i^2 + w_j^2)
//     + |K|^2 / 2k_t exceeds its start by at most (x^2/4)/(1 - x^2/4),
//     x = omega_0 dt (the leapfrog's bounded oscillation, exact), and the
//     leapfrog invariant (K term times 1 - x^2/4) is constant to 1e-9; the
//     kinetic energy equals its start plus the pair work to 1e-9; the
//     system's elastic energy is |K|^2 / 2k_t computed here (pure twist
//     strains nothing else) to 1e-12 of E0 (round-off);
//  4. free tumbling with twist and bending and translation (the pair's
//     forces, torques and moments together): the total angular momentum
//     sum J w + m x cross v about the origin is conserved to 1e-12 of
//     sum J |w| (round-off: K acts as a pure couple, the pair forces are
//     central plus tangential with q_i + q_j = r);
//  5. an unbonded pair in compression, turned by 1e-5 rad a step: the
//     twisting moment stops at (2/3) mu |sigma| S a and the bending moment
//     at |sigma| S a / 4 (a = sqrt(S / pi)), never above (1e-12), and the
//     cut is counted as friction work;
//  6. lambda = 0: no moment, torques as before (the K path is off).

#include "mca_test_tools.h"

using namespace tribodyn_test;

namespace
{
  constexpr double d     = 1e-3;
  const double     a_lat = d * std::sqrt(2.);

  /// Two steel automata at distance d along (1, 1, 0)/sqrt 2; bonded (one
  /// body) or not (two bodies).
  Parameters
  pair_parameters(const double lambda,
                  const bool   bonded,
                  const bool   coarse = false)
  {
    Parameters   p = block_parameters(1, d, 0);
    const double a = a_lat;
    if (coarse)
      {
        // a size band of 2d over the whole box (no skin): the lattice of
        // 2d keeps the sites (a/4, a/4, a/4) and (5a/4, 5a/4, a/4) of the
        // body, 2d apart along (1, 1, 0)/sqrt 2
        p.geometry.domain_lower    = Point3(-4 * a, -4 * a, -4 * a);
        p.geometry.domain_upper    = Point3(6 * a, 6 * a, 6 * a);
        p.geometry.bodies[0].lower = Point3(0, 0, 0);
        p.geometry.bodies[0].upper = Point3(2 * a, 2 * a, a / 2);
        p.geometry.size_bands      = {{-4 * a, 6 * a, 1}};
        p.geometry.fine_free_faces = false;
        p.interaction.moment.get<ElasticMoment>().stiffness = lambda;
        return p;
      }
    p.geometry.domain_lower    = Point3(-2 * a, -2 * a, -2 * a);
    p.geometry.domain_upper    = Point3(3 * a, 3 * a, 3 * a);
    p.geometry.bodies[0].lower = Point3(0, 0, 0);
    p.geometry.bodies[0].upper = Point3(a, a, a / 2);
    if (!bonded)
      {
        Body b1                    = p.geometry.bodies[0];
        p.geometry.bodies[0].upper = Point3(a / 2, a / 2, a / 2);
        b1.lower                   = Point3(a / 2, a / 2, 0);
        p.geometry.bodies.push_back(b1);
      }
    p.interaction.moment.get<ElasticMoment>().stiffness = lambda;
    p.interaction.friction.get<Coulomb>().mu            = 0.3;
    return p;
  }

  struct Pair
  {
    Parameters      p;
    AutomatonSystem system;
    unsigned int    moving = 0; ///< local index of the turned automaton
    Vec3            n, t;
    /// +1 when the pair's i is the automaton that is not turned (the
    /// moment of the pair acts on i)
    double sign = 1;

    Pair(const double lambda, const bool bonded, const bool coarse = false)
        : p(pair_parameters(lambda, bonded, coarse))
        , system(p, MPI_COMM_WORLD)
    {
      system.setup();
      const auto  &x = system.positions();
      const double r = x[0].distance(x[1]);
      moving         = system.ids()[0] == 1 ? 0 : 1;
      for (unsigned int c = 0; c < 3; ++c)
        n[c] = (x[moving][c] - x[1 - moving][c]) / r;
      t    = {{-n[1], n[0], 0}};
      sign = system.pair_views().at(0).id_i == system.ids()[moving] ? -1 : 1;
    }

    /// Turn (and move) the moving automaton in one pseudo-step.
    AutomatonSystem::PairView
    move(const Vec3 &axis, const double angle, const Vec3 &dir, double dist)
    {
      unsigned int k = 0;
      system.impose_motion(
        [&](const Point3 &, Vec3 &du, Vec3 &dtheta) {
          for (unsigned int c = 0; c < 3; ++c)
            {
              du[c]     = k == moving ? dist * dir[c] : 0;
              dtheta[c] = k == moving ? angle * axis[c] : 0;
            }
          ++k;
        },
        1e-9);
      return system.pair_views().at(0);
    }
  };

  std::string
  sci(const double v)
  {
    std::ostringstream s;
    s << std::setprecision(3) << std::scientific << v;
    return s.str();
  }

  double
  norm(const Vec3 &v)
  {
    return std::sqrt(dot(v, v));
  }

  /// K of the pair on the automaton that is not turned.
  Vec3
  moment_on_fixed(const Pair &pair)
  {
    const Vec3 K = pair.system.pair_views().at(0).moment;
    return {{pair.sign * K[0], pair.sign * K[1], pair.sign * K[2]}};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MaterialParameters                 steel = Parameters().materials[0];
  const double                             G     = steel.shear_modulus();
  const double S = d * d / (2 * std::sqrt(2.)), I = S * S / (4 * M_PI);
  const double k_t = (2 * G / d) * 2 * I, k_b = (2 * G / d) * I;
  const double J = steel.density * d * d * d / std::sqrt(2.) * d * d / 10;

  // 1. stiffnesses
  {
    Pair       pair(1, true);
    const auto ks = pair.system.rotation_stiffnesses(0, 0);
    check(pair.system.n_global_automata() == 2, "two automata");
    check_relative(ks.first, k_t, 1e-14, "twisting stiffness lambda k J");
    check_relative(ks.second, k_b, 1e-14, "bending stiffness lambda k I");
  }

  // 2. imposed twist and bending
  {
    Pair         pair(1, true);
    const double delta = 1e-6;
    for (unsigned int s = 0; s < 50; ++s)
      pair.move(pair.n, delta, pair.n, 0);
    const Vec3 K = moment_on_fixed(pair);
    check_relative(dot(K, pair.n),
                   k_t * 50 * delta,
                   1e-12,
                   "twist: K . n = k_t theta on the automaton not turned");
    check(norm({{K[0] - dot(K, pair.n) * pair.n[0],
                 K[1] - dot(K, pair.n) * pair.n[1],
                 K[2] - dot(K, pair.n) * pair.n[2]}})
            <= 1e-12 * norm(K),
          "twist: no bending moment");
    const auto &tq    = pair.system.torques();
    const Vec3  fixed = tq[1 - pair.moving], turned = tq[pair.moving];
    check_relative(dot(fixed, pair.n),
                   k_t * 50 * delta,
                   1e-12,
                   "twist: torque on the automaton not turned = +K");
    check(
      norm({{fixed[0] + turned[0], fixed[1] + turned[1], fixed[2] + turned[2]}})
        <= 1e-14 * norm(K),
      "twist: torques of the two automata equal and opposite");

    Pair bend(1, true);
    for (unsigned int s = 0; s < 50; ++s)
      bend.move(bend.t, delta, bend.n, 0);
    const Vec3 Kb = moment_on_fixed(bend);
    check_relative(dot(Kb, bend.t),
                   k_b * 50 * delta,
                   1e-12,
                   "bending: K . t = k_b theta on the automaton not turned");
    check(std::abs(dot(Kb, bend.n)) <= 1e-12 * norm(Kb),
          "bending: no twisting moment");

    // a rigid rotation of the pair carries its moment along: 200
    // increments of 1e-3 rad about (1, 2, 3)/sqrt 14 turn K by the same
    // rotation R; the composition of the axis's swing and the spin about it
    // differs from R by O(delta^2) a step (measured 3e-9; tolerance 1e-6)
    const double len = std::sqrt(14.), step = 1e-3;
    const Vec3   axis{{1 / len, 2 / len, 3 / len}};
    auto         rotate = [&](const Vec3 &v, const double angle) {
      const double c = std::cos(angle), s = std::sin(angle);
      const Vec3   axv = cross(axis, v);
      const double av  = dot(axis, v) * (1 - c);
      return Vec3{{c * v[0] + s * axv[0] + av * axis[0],
                   c * v[1] + s * axv[1] + av * axis[1],
                   c * v[2] + s * axv[2] + av * axis[2]}};
    };
    const auto &x0 = bend.system.positions();
    const Vec3  centre{{0.5 * (x0[0][0] + x0[1][0]),
                        0.5 * (x0[0][1] + x0[1][1]),
                        0.5 * (x0[0][2] + x0[1][2])}};
    for (unsigned int s = 0; s < 200; ++s)
      bend.system.impose_motion(
        [&](const Point3 &x, Vec3 &du, Vec3 &dtheta) {
          const Vec3 rel{
            {x[0] - centre[0], x[1] - centre[1], x[2] - centre[2]}};
          const Vec3 moved = rotate(rel, step);
          for (unsigned int c = 0; c < 3; ++c)
            {
              du[c]     = moved[c] - rel[c];
              dtheta[c] = step * axis[c];
            }
        },
        1e-9);
    const Vec3   expected = rotate(Kb, 200 * step), Kr = moment_on_fixed(bend);
    const double error
      = norm({{Kr[0] - expected[0], Kr[1] - expected[1], Kr[2] - expected[2]}})
        / norm(Kb);
    check(error <= 1e-6,
          "rigid rotation by 0.2 rad turns K with the pair: error "
            + sci(error));
  }

  // 3. free torsional oscillation
  {
    Pair         pair(1, true);
    auto        &sys = pair.system;
    const double dt = sys.time_step(), w0 = 1e3;
    const double omega0 = std::sqrt(k_t / (J / 2)), x = omega0 * dt;
    const Vec3   n = pair.n;
    unsigned int k = 0;
    sys.set_velocities([&](const Point3 &, Vec3 &v, Vec3 &w) {
      v              = {{0, 0, 0}};
      const double s = k++ == pair.moving ? 1 : -1;
      for (unsigned int c = 0; c < 3; ++c)
        w[c] = s * w0 * n[c];
    });
    auto energies = [&](double &plain, double &invariant) {
      const auto  &w  = sys.angular_velocities();
      const double ek = 0.5 * J * (dot(w[0], w[0]) + dot(w[1], w[1]));
      const Vec3   K  = sys.pair_views().at(0).moment;
      const double ep = dot(K, K) / (2 * k_t);
      plain           = ek + ep;
      invariant       = ek + (1 - x * x / 4) * ep;
    };
    double E0, I0, E, Iv, worst_plain = 0, worst_inv = 0, worst_work = 0,
                          worst_elastic = 0;
    energies(E0, I0);
    std::vector<double> crossings;
    double              previous = 0, time = 0;
    const double        T       = 2 * M_PI / omega0;
    const unsigned int  n_steps = static_cast<unsigned int>(5.3 * T / dt);
    for (unsigned int s = 0; s < n_steps; ++s)
      {
        sys.step();
        time += dt;
        const double kn = dot(sys.pair_views().at(0).moment, n);
        if (s > 0 && (kn > 0) != (previous > 0))
          crossings.push_back(time - dt * kn / (kn - previous));
        previous = kn;
        energies(E, Iv);
        worst_plain  = std::max(worst_plain, std::abs(E - E0) / E0);
        worst_inv    = std::max(worst_inv, std::abs(Iv - I0) / I0);
        const auto e = sys.energies();
        worst_work
          = std::max(worst_work,
                     std::abs(e[Energy::kinetic] - e[Energy::pair] - E0) / E0);
        const Vec3 K = sys.pair_views().at(0).moment;
        worst_elastic
          = std::max(worst_elastic,
                     std::abs(e[Energy::elastic] - dot(K, K) / (2 * k_t)) / E0);
      }
    check(crossings.size() >= 8,
          std::to_string(crossings.size()) + " zero crossings of K . n");
    const double T_measured
      = 2 * (crossings.back() - crossings.front()) / (crossings.size() - 1);
    const double T_leapfrog = 2 * M_PI / (2 / dt * std::asin(x / 2));
    check_relative(T_measured,
                   T_leapfrog,
                   5e-7,
                   "torsion period = leapfrog period");
    check_relative(T_measured,
                   T,
                   1e-3,
                   "torsion period = 2 pi sqrt(J_red / k_t)");
    // E = I + (x^2/4) K^2/2k_t, with I the invariant and K^2/2k_t at
    // most I / (1 - x^2/4): E - E0 <= E0 (x^2/4) / (1 - x^2/4)
    const double bound = x * x / 4 / (1 - x * x / 4);
    check(worst_plain <= bound * (1 + 1e-6),
          "energy 1/2 J w^2 + K^2/2k_t within the leapfrog oscillation "
          "(x^2/4)/(1 - x^2/4) = "
            + std::to_string(bound) + " (x = omega_0 dt): " + sci(worst_plain));
    check(worst_inv <= 1e-9, "leapfrog invariant constant: " + sci(worst_inv));
    check(worst_work <= 1e-9,
          "kinetic energy = initial one + pair work: " + sci(worst_work));
    check(worst_elastic <= 1e-12,
          "elastic energy of the system = |K|^2 / 2k_t: " + sci(worst_elastic));
  }

  // 4. tumbling: total angular momentum
  {
    Pair         pair(1, true);
    auto        &sys = pair.system;
    unsigned int k   = 0;
    sys.set_velocities([&](const Point3 &, Vec3 &v, Vec3 &w) {
      const double s = k++ == 0 ? 1 : -0.6;
      v              = {{0.1 * s, -0.2 * s, 0.05}};
      w              = {{3e3 * s, 1e3, -2e3 * s}};
    });
    const double m        = steel.density * d * d * d / std::sqrt(2.);
    auto         momentum = [&](double &scale) {
      const auto &x = sys.positions();
      const auto &v = sys.velocities();
      const auto &w = sys.angular_velocities();
      Vec3        L{{0, 0, 0}};
      scale = 0;
      for (unsigned int k = 0; k < 2; ++k)
        {
          const Vec3 xk{{x[k][0], x[k][1], x[k][2]}};
          const Vec3 xv = cross(xk, v[k]);
          for (unsigned int c = 0; c < 3; ++c)
            L[c] += J * w[k][c] + m * xv[c];
          scale += J * norm(w[k]);
        }
      return L;
    };
    double     scale;
    const Vec3 L0    = momentum(scale);
    double     worst = 0, max_moment = 0;
    for (unsigned int s = 0; s < 2000; ++s)
      {
        sys.step();
        const Vec3 L = momentum(scale);
        worst
          = std::max(worst, norm({{L[0] - L0[0], L[1] - L0[1], L[2] - L0[2]}}));
        max_moment = std::max(max_moment, norm(sys.pair_views().at(0).moment));
      }
    check(max_moment > 0, "tumbling pair carries a moment");
    check(worst <= 1e-12 * scale,
          "total angular momentum conserved: " + sci(worst / scale));
  }

  // 5. unbonded pair in compression: the limits
  {
    Pair pair(1, false);
    check(!pair.system.pair_views().at(0).bonded, "two bodies: not bonded");
    auto pv = pair.move(pair.n, 0, pair.n, 0);
    for (unsigned int s = 0; s < 20; ++s)
      pv = pair.move(pair.n, 0, pair.n, -1e-5 * d);
    check(pv.sigma < 0 && !pv.bonded, "unbonded pair in compression");
    const double a = std::sqrt(S / M_PI), mu = 0.3;
    const double twist_limit = 2. / 3. * mu * -pv.sigma * S * a;
    double       worst = 0, last = 0;
    for (unsigned int s = 0; s < 400; ++s)
      {
        pv    = pair.move(pair.n, 1e-5, pair.n, 0);
        last  = std::abs(dot(pv.moment, pair.n));
        worst = std::max(worst, last);
      }
    check(worst <= twist_limit * (1 + 1e-12),
          "twisting moment never above (2/3) mu |sigma| S a");
    check_relative(last,
                   twist_limit,
                   1e-12,
                   "twisting moment at the limit while slipping");
    check(pair.system.energies()[Energy::friction] > 0,
          "slip of the twisting moment counted as friction work");
    const double bend_limit = 0.25 * -pv.sigma * S * a;
    double       worst_b = 0, last_b = 0;
    for (unsigned int s = 0; s < 400; ++s)
      {
        pv              = pair.move(pair.t, 1e-5, pair.n, 0);
        const Vec3   K  = pv.moment;
        const double kn = dot(K, pair.n);
        last_b          = std::sqrt(std::max(0., dot(K, K) - kn * kn));
        worst_b         = std::max(worst_b, last_b);
      }
    const double bend_limit_now = 0.25 * -pv.sigma * S * a;
    check(std::abs(bend_limit_now - bend_limit) <= 1e-9 * bend_limit,
          "bending leaves the normal stress unchanged");
    check(worst_b <= bend_limit * (1 + 1e-12),
          "bending moment never above |sigma| S a / 4");
    check_relative(last_b, bend_limit, 1e-12, "bending moment at the limit");
  }

  // 7. automata of 2d (a size band, the graded pair geometry: the pair's
  //    own face S_ij and half rest length q0 from its Voronoi cells): the
  //    parallel-bond law of that pair, k = 2G/(2d) and S_ij = 4S, so
  //    k_t and k_b are 2^4 / 2 = 8 times those of d (to 1e-12: the Voronoi
  //    face is 4S to round-off). With the area or the half length of the
  //    uniform pair (factor 1 or 16) it fails.
  {
    Pair         pair(1, true, true);
    const double delta = 1e-6;
    check(pair.system.n_global_automata() == 2
            && pair.system.size_levels().at(0) == 1,
          "two automata of 2d");
    for (unsigned int s = 0; s < 50; ++s)
      pair.move(pair.n, delta, pair.n, 0);
    const Vec3 K = moment_on_fixed(pair);
    check_relative(dot(K, pair.n),
                   8 * k_t * 50 * delta,
                   1e-12,
                   "2d: twist K . n = 8 k_t(d) theta");
    Pair bend(1, true, true);
    for (unsigned int s = 0; s < 50; ++s)
      bend.move(bend.t, delta, bend.t, 0);
    check_relative(dot(moment_on_fixed(bend), bend.t),
                   8 * k_b * 50 * delta,
                   1e-12,
                   "2d: bending K . t = 8 k_b(d) theta");
  }

  // 6. lambda = 0: no moment
  {
    Pair pair(0, true);
    for (unsigned int s = 0; s < 10; ++s)
      pair.move(pair.n, 1e-6, pair.n, 0);
    // (the shear springs' torque of a pure twist is round-off: omega
    // parallel to n up to the rounding of n)
    const auto &tq = pair.system.torques();
    check(norm(pair.system.pair_views().at(0).moment) == 0
            && norm(tq[0]) <= 1e-12 * k_t * 1e-5
            && norm(tq[1]) <= 1e-12 * k_t * 1e-5,
          "lambda = 0: no moment, pure twist gives no torque ("
            + sci(norm(tq[0])) + " N m)");
  }
  return result();
}
