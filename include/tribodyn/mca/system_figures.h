// Global figures of an AutomatonSystem: energies and partition counts.
#ifndef tribodyn_mca_system_figures_h
#define tribodyn_mca_system_figures_h

namespace tribodyn
{
  namespace mca
  {
    /// Global figures of the current state (summed over ranks).
    struct SystemEnergies
    {
      double             kinetic             = 0;
      double             elastic             = 0;
      double             plastic_work        = 0;
      double             friction_work       = 0;
      unsigned long long n_bonded            = 0;
      unsigned long long n_unbonded_contacts = 0;
      /// Work of the boundary groups (applied forces and prescribed
      /// velocities, damping excluded) and energy removed by damping, both
      /// since the start (see AutomatonSystem::step()).
      double load_work   = 0;
      double damped_work = 0;
      /// Work of the pair forces and torques on the automata since the
      /// start (minus the energy the pairs stored or dissipated).
      double pair_work = 0;
    };

    /// Number of automata per rank for a partition (partition report).
    struct PartitionFigures
    {
      unsigned long long n_automata = 0;
      unsigned int       n_ranks    = 0;
      double             owned_min = 0, owned_mean = 0, owned_max = 0;
      double             ghosts_min = 0, ghosts_mean = 0, ghosts_max = 0;
      double             bytes_per_rank_max = 0;
    };
  } // namespace mca
} // namespace tribodyn

#endif
