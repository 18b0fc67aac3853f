// Blow-up detection of the automata (doc/stability.md): a cheap count of
// implausible automata after each step, and the report naming the worst one
// and the likely cause when the count is not zero on some rank.
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
    unsigned int
    AutomatonSystem::count_unstable_automata(const double limit) const
    {
      // |v| and the surface speed |w| d_k/2 against the limit; comparisons
      // written so that NaN counts as unstable.
      const double limit2 = limit * limit;
      unsigned int n      = 0;
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          const double half = 0.5 * automaton_size(k);
          const double s    = dot(v[k], v[k]);
          const double r    = dot(w[k], w[k]) * half * half;
          n += !(s <= limit2 && r <= limit2);
        }
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
      else if (courant > 0.9 * TimeParameters::max_courant)
        m << "the time step: dt = " << courant << " d/c_p is near the limit "
          << TimeParameters::max_courant
          << "; lower 'Time/Courant factor' or 'Time/Time step'.";
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
