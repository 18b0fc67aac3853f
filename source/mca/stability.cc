// The automata's step limit and blow-up detection (doc/stability.md): the
// largest Courant factor the scene's stiffest automaton allows, checked at
// set-up; a cheap count of implausible automata after each step, and the
// report naming the worst one and the likely cause when the count is not
// zero on some rank.
#include <array>
#include <boost/serialization/array.hpp>
#include <cmath>
#include <limits>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/mca/automaton_system.h>

namespace tribodyn
{
  namespace mca
  {
    double
    AutomatonSystem::stiffest_courant_limit(
      const std::vector<unsigned int> &used) const
    {
      // The springs acting on each owned automaton at set-up (bonded pairs
      // and contacts) held against fixed neighbours: translation
      // omega_t^2 = sum k_f / m, rotation omega_r^2 = sum (k_f a^2 +
      // k_twist) / I, with k_f = k S (2G/q0 per unit area, the face S) the
      // pair's spring, a its arm and k_twist its relative-rotation
      // twisting spring (the stiffer of the moment's two).
      std::vector<double> translation(n_owned, 0.), rotation(n_owned, 0.);
      for (unsigned int p = 0; p < pi.size(); ++p)
        {
          const unsigned int i = pi[p], j = pj[p];
          if (i >= n_owned && j >= n_owned)
            continue;
          double r;
          unit_normal(p, r);
          const double arm   = graded ? pair_half_rest[p] : r0;
          const double touch = 2 * arm;
          if (arm <= 0 || (!bonded[p] && r >= touch))
            continue; // an inert pair, or one out of contact
          const SeriesSprings &k = springs[mat[i] * n_materials + mat[j]];
          const double         kf
            = k.ki * k.kj * k.inv_sum * (graded ? pair_area[p] * r0 / arm : S);
          const double twist
            = rotation_stiffnesses(mat[i], mat[j]).first * moment_scale_of(p);
          for (const unsigned int k : {i, j})
            if (k < n_owned)
              {
                translation[k] += kf;
                rotation[k] += kf * arm * arm + twist;
              }
        }
      const auto omega =
        [&](const double m, const double I, const double t, const double rot) {
          return std::max(std::sqrt(t / m),
                          rotations ? std::sqrt(rot / I) : 0.);
        };
      double highest = 0;
      for (unsigned int k = 0; k < n_owned; ++k)
        highest = std::max(highest,
                           omega(automaton_mass(*this, k),
                                 automaton_inertia(*this, k),
                                 translation[k],
                                 rotation[k]));
      highest = dealii::Utilities::MPI::max(highest, comm);

      // The same for an automaton of size d inside a uniform FCC lattice of
      // each material the scene uses (12 neighbours at d, faces S, arms
      // r0 = d/2), at that lattice's own limit TimeParameters::max_courant
      // d / c_p: omega dt there is the level known stable, the highest of
      // the scene's materials (it depends on their Poisson ratios).
      double stable_level = 0;
      for (unsigned int m = 0; m < n_materials; ++m)
        if (used[m])
          {
            const SeriesSprings &k    = springs[m * n_materials + m];
            const double         kf   = k.ki * k.kj * k.inv_sum * S;
            const double         mass = mc[m].rho * V;
            const double         lattice
              = omega(mass,
                      mass * d * d / 10,
                      12 * kf,
                      12 * (kf * r0 * r0 + rotation_stiffnesses(m, m).first));
            stable_level = std::max(stable_level,
                                    lattice * TimeParameters::max_courant * d
                                      / prm.materials[m].p_wave_speed());
          }
      // The Courant factor (of this scene's d / c_p,max) that brings its
      // stiffest automaton to that level; rounded down to 1/1000, so that
      // the sums' order (which differs with the number of ranks) cannot
      // change it but at a boundary.
      const double limit = stable_level / (highest * critical_dt);
      if (limit >= TimeParameters::max_courant * (1 - 1e-9))
        return TimeParameters::max_courant;
      return std::floor(1000 * limit) / 1000;
    }


    unsigned int
    AutomatonSystem::count_unstable_automata(const double limit) const
    {
      // |v| and the surface speed |w| d_k/2 against the limit; comparisons
      // written so that NaN counts as unstable.
      const double limit2 = limit * limit;
      unsigned int n      = 0;
      for (unsigned int k = 0; k < n_owned; ++k)
        n += too_fast(k, limit2, 0.5 * automaton_size(k));
      return n;
    }


    void
    AutomatonSystem::report_instability(const double limit) const
    {
      // Worst owned automaton of this rank (non-finite: infinitely bad).
      double       worst = -1;
      unsigned int index = 0;
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          const double s
            = std::max(std::sqrt(dot(v[k], v[k])),
                       std::sqrt(dot(w[k], w[k])) * 0.5 * automaton_size(k));
          const double b = std::isfinite(s + x[k][0] + x[k][1] + x[k][2])
                             ? s
                             : std::numeric_limits<double>::infinity();
          if (b > worst)
            {
              worst = b;
              index = k;
            }
        }
      std::array<double, 9> mine = {{worst, 0, 0, 0, 0, 0, 0, 0, 0}};
      if (n_owned > 0)
        mine = {
          {worst,
           double(id[index]),
           x[index][0],
           x[index][1],
           x[index][2],
           double(mat[index]),
           double(groups[index]),
           std::sqrt(dot(v[index], v[index])),
           std::sqrt(dot(w[index], w[index])) * 0.5 * automaton_size(index)}};
      const auto  all  = dealii::Utilities::MPI::all_gather(comm, mine);
      std::size_t best = 0;
      for (std::size_t r = 1; r < all.size(); ++r)
        if (all[r][0] > all[best][0])
          best = r;
      const auto        &a    = all[best];
      const unsigned int mask = static_cast<unsigned int>(a[6]);

      std::ostringstream m;
      m.precision(4);
      m << "The run became unstable at step " << n_steps_done
        << " (t = " << current_time << " s): automaton " << std::size_t(a[1])
        << " (material " << prm.materials[static_cast<unsigned int>(a[5])].name
        << ", at (" << a[2] << ", " << a[3] << ", " << a[4] << ") m";
      std::string damped_group, loaded_group;
      double      damping_product = prm.boundary.global_damping * dt;
      for (unsigned int g = 0; g < prm.boundary.groups.size(); ++g)
        if (mask & (1u << g))
          {
            const auto &grp = prm.boundary.groups[g];
            m << ", group '" << grp.name << "'";
            if (grp.type == BoundaryGroup::Type::damping)
              for (const double c : grp.value)
                if (c * dt > damping_product)
                  {
                    damping_product = c * dt;
                    damped_group    = grp.name;
                  }
            if (grp.type == BoundaryGroup::Type::velocity
                || grp.type == BoundaryGroup::Type::force)
              loaded_group = grp.name;
          }
      m << ") moves at |v| = " << a[7] << " m/s (rotation: |w| d/2 = " << a[8]
        << " m/s); the limit is twice the largest P-wave speed, " << limit
        << " m/s. Likely cause: ";
      const double courant = dt / critical_dt;
      if (damping_product > 1)
        m << "the damping: c dt = " << damping_product << " > 1 in "
          << (damped_group.empty() ? std::string("'Boundary conditions/Global "
                                                 "damping'")
                                   : "the damping group '" + damped_group
                                       + "' of 'Boundary conditions/Groups'")
          << " (explicit viscous damping needs c dt < 1); lower the "
             "coefficient.";
      else if (courant > 0.9 * courant_max)
        m << "the time step: dt = " << courant << " d/c_p is near the limit "
          << courant_max
          << " this scene allows; lower 'Time/Courant factor' or 'Time/Time "
             "step'.";
      else if (!loaded_group.empty())
        m << "the loading of group '" << loaded_group
          << "' (a prescribed velocity near the wave speed or a force too "
             "large for the automata it acts on); lower it or ramp it "
             "more slowly ('Boundary conditions/Ramp time').";
      else
        m << "the contacts (automata overlapping deeply, e.g. bodies driven "
             "into each other too fast, or an automaton torn free); lower "
             "the loading velocities or the time step (dt = "
          << courant << " d/c_p).";
      throw RunError(m.str());
    }
  } // namespace mca
} // namespace tribodyn
