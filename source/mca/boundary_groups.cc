// Boundary groups: kinematic constraints (fixed, prescribed velocity),
// loads (rigid loading plates) and damping layers, with smooth ramps; and
// the group reductions reported to the observers.

#include <cmath>
#include <tribodyn/mca/automaton_system.h>

namespace tribodyn
{
  namespace mca
  {
    double
    AutomatonSystem::ramp(const double t) const
    {
      const double T = prm.boundary.ramp_time;
      if (T <= 0 || t >= T)
        return 1;
      if (t <= 0)
        return 0;
      const double s = t / T;
      return s * s * (3 - 2 * s);
    }


    Vec3
    AutomatonSystem::group_value(const BoundaryGroup &g, const double t) const
    {
      Vec3 value;
      if (g.switch_time < 0 || t <= g.switch_time)
        {
          for (unsigned int c = 0; c < 3; ++c)
            value[c] = g.value[c]
                       * (g.type == BoundaryGroup::Type::damping ? 1 : ramp(t));
          return value;
        }
      const double s = ramp(t - g.switch_time);
      for (unsigned int c = 0; c < 3; ++c)
        value[c] = (1 - s) * g.value[c] + s * g.second_value[c];
      return value;
    }


    void
    AutomatonSystem::apply_kinematic_constraints(const double t)
    {
      const auto &grp = prm.boundary.groups;
      if (grp.empty())
        return;
      std::vector<Vec3> values(grp.size());
      for (unsigned int gi = 0; gi < grp.size(); ++gi)
        values[gi] = group_value(grp[gi], t);
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          if (groups[k] == 0)
            continue;
          for (unsigned int gi = 0; gi < grp.size(); ++gi)
            if (groups[k] & (1u << gi))
              {
                if (grp[gi].type == BoundaryGroup::Type::fixed)
                  v[k] = {{0, 0, 0}};
                else if (grp[gi].type == BoundaryGroup::Type::velocity)
                  for (unsigned int c = 0; c < 3; ++c)
                    if (!std::isnan(values[gi][c]))
                      v[k][c] = values[gi][c];
              }
        }
    }


    void
    AutomatonSystem::apply_boundary_forces(const double t)
    {
      // Adds external and damping forces to the pair forces f, which then
      // hold the total forces of the kicks; the pair-force reaction of each
      // group (what the observers report) is summed first, per rank.
      const auto               &grp      = prm.boundary.groups;
      const double              c_global = prm.boundary.global_damping;
      std::vector<Vec3>         values(grp.size());
      std::vector<unsigned int> plates;
      for (unsigned int gi = 0; gi < grp.size(); ++gi)
        {
          values[gi] = group_value(grp[gi], t);
          if (grp[gi].type == BoundaryGroup::Type::force)
            plates.push_back(gi);
        }
      group_reaction = local_group_sums(f);
      if (c_global > 0)
        for (unsigned int k = 0; k < n_owned; ++k)
          {
            const double mass = mc[mat[k]].mass;
            for (unsigned int c = 0; c < 3; ++c)
              f[k][c] -= c_global * mass * v[k][c];
          }
      for (unsigned int k = 0; k < n_owned; ++k)
        {
          if (groups[k] == 0)
            continue;
          const double mass = mc[mat[k]].mass;
          for (unsigned int gi = 0; gi < grp.size(); ++gi)
            if (groups[k] & (1u << gi))
              {
                if (grp[gi].type == BoundaryGroup::Type::force)
                  for (unsigned int c = 0; c < 3; ++c)
                    f[k][c] += values[gi][c] / group_size[gi];
                else if (grp[gi].type == BoundaryGroup::Type::damping)
                  for (unsigned int c = 0; c < 3; ++c)
                    f[k][c] -= values[gi][c] * mass * v[k][c];
              }
        }
      if (plates.empty())
        return;
      // A force group is a rigid loading plate: its automata share the
      // acceleration of the group's total force over its total mass. One
      // reduction for all plates.
      std::vector<double> sums(4 * plates.size(), 0.);
      for (unsigned int k = 0; k < n_owned; ++k)
        if (groups[k] != 0)
          for (unsigned int q = 0; q < plates.size(); ++q)
            if (groups[k] & (1u << plates[q]))
              {
                for (unsigned int c = 0; c < 3; ++c)
                  sums[4 * q + c] += f[k][c];
                sums[4 * q + 3] += mc[mat[k]].mass;
              }
      dealii::Utilities::MPI::sum(sums, comm, sums);
      for (unsigned int k = 0; k < n_owned; ++k)
        if (groups[k] != 0)
          for (unsigned int q = 0; q < plates.size(); ++q)
            if ((groups[k] & (1u << plates[q])) && sums[4 * q + 3] > 0)
              for (unsigned int c = 0; c < 3; ++c)
                f[k][c] = mc[mat[k]].mass * sums[4 * q + c] / sums[4 * q + 3];
    }


    std::vector<Vec3>
    AutomatonSystem::local_group_sums(const std::vector<Vec3> &field) const
    {
      const unsigned int n_groups = prm.boundary.groups.size();
      std::vector<Vec3>  sums(n_groups, Vec3{{0, 0, 0}});
      for (unsigned int k = 0; k < n_owned; ++k)
        if (groups[k] != 0)
          for (unsigned int gi = 0; gi < n_groups; ++gi)
            if (groups[k] & (1u << gi))
              for (unsigned int c = 0; c < 3; ++c)
                sums[gi][c] += field[k][c];
      return sums;
    }


    std::vector<Vec3>
    AutomatonSystem::global_group_sums(const std::vector<Vec3> &local) const
    {
      const unsigned int  n_groups = prm.boundary.groups.size();
      std::vector<double> sums(3 * n_groups, 0.);
      for (unsigned int gi = 0; gi < local.size(); ++gi)
        for (unsigned int c = 0; c < 3; ++c)
          sums[3 * gi + c] = local[gi][c];
      dealii::Utilities::MPI::sum(sums, comm, sums);
      std::vector<Vec3> out(n_groups);
      for (unsigned int gi = 0; gi < n_groups; ++gi)
        for (unsigned int c = 0; c < 3; ++c)
          out[gi][c] = sums[3 * gi + c];
      return out;
    }


    std::vector<Vec3>
    AutomatonSystem::sum_over_groups(const std::vector<Vec3> &field) const
    {
      return global_group_sums(local_group_sums(field));
    }


    std::vector<Vec3>
    AutomatonSystem::group_forces() const
    {
      // the pair-force reactions summed at the last step
      return global_group_sums(group_reaction);
    }


    std::vector<Vec3>
    AutomatonSystem::group_displacements() const
    {
      std::vector<Vec3> out = sum_over_groups(u);
      for (unsigned int gi = 0; gi < out.size(); ++gi)
        for (unsigned int c = 0; c < 3; ++c)
          out[gi][c] = group_size[gi] > 0 ? out[gi][c] / group_size[gi] : 0;
      return out;
    }
  } // namespace mca
} // namespace tribodyn
