// Global figures of an AutomatonSystem: energies and partition counts.
#ifndef tribodyn_mca_system_figures_h
#define tribodyn_mca_system_figures_h

#include <array>

namespace tribodyn
{
  namespace mca
  {
    /**
     * The works an AutomatonSystem accumulates from the start, by index in
     * its one array of them (AutomatonSystem::work): what the checkpoints,
     * the restarts on another number of ranks and energies() carry, each
     * written once.
     */
    enum Work : unsigned int
    {
      /// plastic returns of the side stresses (doc/theory/mca.md §8.4)
      plastic_work,
      /// Coulomb limits of unbonded contacts and their moments
      friction_work,
      /// contacts that open or lose their tension, bonds broken beyond
      /// the contact distance, re-weighted neighbourhoods
      switching_work,
      /// the non-conservative work of the many-body law (§8.4)
      many_body_work,
      /// boundary groups (loads), damping, and the pair forces and
      /// torques on the automata
      load_work,
      damped_work,
      pair_work,
      n_works
    };
    /// One value per Work.
    using WorkSums = std::array<double, n_works>;

    /// Global figures of the current state (summed over ranks).
    struct SystemEnergies
    {
      double kinetic       = 0;
      double elastic       = 0;
      double plastic_work  = 0;
      double friction_work = 0;
      /// Released where the state of a pair switches (contacts opening or
      /// losing their tension, bonds broken beyond contact, re-weighted
      /// neighbourhoods), and the non-conservative work of the many-body
      /// law (doc/theory/mca.md §8.4), both since the start.
      double             switching_work = 0, many_body_work = 0;
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
      /// Automata of size d, 2d, 4d (Geometry/Size bands).
      std::array<unsigned long long, 3> n_per_size = {{0, 0, 0}};
      unsigned int                      n_ranks    = 0;
      double owned_min = 0, owned_mean = 0, owned_max = 0;
      double ghosts_min = 0, ghosts_mean = 0, ghosts_max = 0;
      /// Ghosts per rank (mean) if whole boundary cells were sent: the
      /// ghost layer as thick as the cells, before exchange_ghosts()
      /// chose the automata within their pair-list range.
      double whole_cell_ghosts_mean = 0;
      double bytes_per_rank_max     = 0;
    };


    /// Measured cost of an automaton: memory for the partition report's
    /// estimate, work for the weighted partition.
    namespace cost_model
    {
      /// Memory per owned and per ghost automaton for the partition
      /// report's estimate, measured (bench/mca/compare.py --memory): peak
      /// RSS per automaton of a 256 000-automaton elastic block on one rank
      /// (955 B), and the increase on two ranks divided by the ghosts
      /// (1118 B per owned automaton with 0.12 ghosts per owned one: the
      /// ghost's own arrays and its pairs, stored on both ranks).
      constexpr double bytes_per_owned_automaton = 960;
      constexpr double bytes_per_ghost_automaton = 1400;
      /// Added per automaton (owned or ghost) by the relative-rotation
      /// moments (24 B a pair): measured +142 B of peak RSS and of arrays
      /// per automaton on the 128 000-automaton elastic block.
      constexpr double bytes_per_automaton_moments = 145;
      /// p4est weight of a cell per automaton it holds (an empty cell
      /// weighs 1: its bins and ghost-layer share, ~1/8 of an automaton).
      constexpr unsigned int cost_per_automaton = 8;
    } // namespace cost_model
  }   // namespace mca
} // namespace tribodyn

#endif
