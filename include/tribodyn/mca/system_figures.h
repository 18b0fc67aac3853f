// Global figures of an AutomatonSystem: energies and partition counts.
#ifndef tribodyn_mca_system_figures_h
#define tribodyn_mca_system_figures_h

#include <array>
#include <cstddef>

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
      /// The dissipation the constitutive laws prescribe, computed apart
      /// from the stress updates that the held terms book (doc/theory/
      /// mca.md §8.4, "What the balance checks"): the automata's J2
      /// dissipation sum V (sigma_y + sigma_y')/2 d eps_p of their radial
      /// returns (the flow rule), and the friction law's traction times
      /// the slip at the Coulomb limits (with the shear mixing and the
      /// moments' slip of unbonded pairs, booked alike in both)
      plastic_work_flow_rule,
      friction_work_law,
      n_works
    };
    /// One value per Work.
    using WorkSums = std::array<double, n_works>;

    /// What a term of the energy ledger is to the balance.
    enum class EnergyRole : unsigned char
    {
      /// held by the scene or dissipated since the start: the left side
      held,
      /// supplied: the work of the boundary groups (loads)
      supplied,
      /// a figure beside the balance (the pair forces' work on the
      /// automata, for the kinetic-energy identity)
      diagnostic,
      /// a count of pairs
      count
    };

    /// The terms of the ledger, in the order of its entries.
    enum class Energy : unsigned int
    {
      kinetic,
      elastic,
      plastic,
      friction,
      n_bonded,
      n_unbonded,
      load,
      damped,
      pair,
      switching,
      many_body,
      plastic_flow_rule,
      friction_law,
      n
    };

    /// One term of the energy ledger.
    struct LedgerEntry
    {
      Energy term;
      /// Its column in series.csv and its key in summary.json.
      const char *name;
      /// Its name on the screen.
      const char *label;
      EnergyRole  role;
      /// The accumulated work it reads (Work), or n_works: computed from
      /// the state (kinetic and elastic energies, counts).
      unsigned int work;
    };

    /**
     * The energy ledger (doc/theory/mca.md §8.4): each term of the balance
     * declared once. The energies postprocessor writes its columns and
     * summary keys in this order, the balance sums its held terms against
     * its supplied ones, and summary.json lists the roles
     * ("energy_ledger") for the test tools (tests/mca/check_tools.py).
     */
    // clang-format off
    inline constexpr std::array<LedgerEntry, std::size_t(Energy::n)>
      energy_ledger = {{
        // term               name                   label                role                  work
        {Energy::kinetic,    "kinetic_energy",      "kinetic",           EnergyRole::held,       n_works},
        {Energy::elastic,    "elastic_energy",      "elastic",           EnergyRole::held,       n_works},
        {Energy::plastic,    "plastic_work",        "plastic",           EnergyRole::held,       plastic_work},
        {Energy::friction,   "friction_work",       "friction",          EnergyRole::held,       friction_work},
        {Energy::n_bonded,   "n_bonded_pairs",      "bonded pairs",      EnergyRole::count,      n_works},
        {Energy::n_unbonded, "n_unbonded_contacts", "unbonded contacts", EnergyRole::count,      n_works},
        {Energy::load,       "load_work",           "load work",         EnergyRole::supplied,   load_work},
        {Energy::damped,     "damped_work",         "damped",            EnergyRole::held,       damped_work},
        {Energy::pair,       "pair_work",           "pair work",         EnergyRole::diagnostic, pair_work},
        {Energy::switching,  "switching_work",      "switching",         EnergyRole::held,       switching_work},
        {Energy::many_body,  "many_body_work",      "many-body",         EnergyRole::held,       many_body_work},
        {Energy::plastic_flow_rule, "plastic_work_flow_rule", "plastic (flow rule)", EnergyRole::diagnostic, plastic_work_flow_rule},
        {Energy::friction_law, "friction_work_law",  "friction (law)",    EnergyRole::diagnostic, friction_work_law},
      }};
    // clang-format on

    namespace internal
    {
      constexpr bool
      ledger_in_term_order()
      {
        for (std::size_t i = 0; i < energy_ledger.size(); ++i)
          if (static_cast<std::size_t>(energy_ledger[i].term) != i)
            return false;
        return true;
      }
    } // namespace internal
    static_assert(internal::ledger_in_term_order(),
                  "energy_ledger lists the terms in the order of Energy");

    /// The ledger's values for the current state (summed over ranks):
    /// energies and works in J, counts of pairs.
    struct SystemEnergies
    {
      std::array<double, std::size_t(Energy::n)> value{};

      double
      operator[](const Energy term) const
      {
        return value[static_cast<std::size_t>(term)];
      }
      double &
      operator[](const Energy term)
      {
        return value[static_cast<std::size_t>(term)];
      }
      /// Sum of the held terms minus the supplied ones (0 when the energy
      /// is balanced).
      double
      balance_residual() const
      {
        double held = 0, supplied = 0;
        for (const LedgerEntry &entry : energy_ledger)
          if (entry.role == EnergyRole::held)
            held += (*this)[entry.term];
          else if (entry.role == EnergyRole::supplied)
            supplied += (*this)[entry.term];
        return held - supplied;
      }
      /// The balance with the dissipation the laws prescribe (the
      /// diagnostics plastic_flow_rule and friction_law) in place of the
      /// plastic and friction work the events book: it fails where a stress
      /// update does not dissipate what its law says (a wrong radial return
      /// or Coulomb limit), which balance_residual() cannot see. Close in a
      /// plastic bulk and in elastic friction (to the step's first order);
      /// not where plastic flow is localized at rough contacts, whose
      /// returns dissipate more than the flow rule says (doc/theory/mca.md
      /// §8.4, "What the balance checks").
      double
      physical_balance_residual() const
      {
        return balance_residual() - (*this)[Energy::plastic]
               - (*this)[Energy::friction] + (*this)[Energy::plastic_flow_rule]
               + (*this)[Energy::friction_law];
      }
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
      /// report's estimate, measured (bench/mca/compare.py --memory,
      /// 2026-11-30): peak RSS per automaton of a 256 000-automaton
      /// elastic block on one rank (815 B), and the increase on two ranks
      /// divided by the ghosts (948 B per owned automaton with 0.119
      /// ghosts per owned one: 1 113 B per ghost, its own arrays and its
      /// pairs, stored on both ranks). Measured while the block stored its
      /// sides' many-body offsets (16 B a pair), as the scenes the report
      /// is for (friction: plastic, with contacts) do; the elastic block
      /// no longer does (PairArrays::mb_stored).
      constexpr double bytes_per_owned_automaton = 815;
      constexpr double bytes_per_ghost_automaton = 1115;
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
