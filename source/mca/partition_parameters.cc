// Subsection "Partition" of the automata engine: when the partition is
// weighted anew during a run (source/mca/automaton_partition.cc).

#include "parameter_tools.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>
#include <tribodyn/mca/parameters.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      const SelectionTable<PartitionParameters::AutomatonOrder, 2>
        automaton_order_table{
          {{"Morton curve", PartitionParameters::AutomatonOrder::curve},
           {"slabs", PartitionParameters::AutomatonOrder::slabs}}};
    } // namespace


    ParameterBinding
    PartitionParameters::binding()
    {
      ParameterBinding b("Partition");
      b.add("Rebalance threshold",
            rebalance_threshold,
            "The mesh cells are weighted by the automata they hold at set-up "
            "(p4est's weighted partition). As the automata move, the work of "
            "the ranks drifts apart: at a pair-list rebuild where the work "
            "imbalance (the largest rank's automata over the mean) exceeds "
            "this value, and has grown by half of (value - 1) since the last "
            "partition, the cells are weighted and partitioned anew and the "
            "automata move to their new ranks (results do not change beyond "
            "round-off). 0 = never; otherwise >= 1. Ignored on one rank.",
            dealii::Patterns::Double(0));
      b.add("Mesh cells per rank",
            mesh_cells_per_rank,
            "The automata are searched for in cells one interaction range "
            "wide; the background mesh (deal.II's cells, ~280 bytes each in "
            "3D, ~130 bytes per automaton of a uniform scene at one search "
            "cell each) holds 4 x 4 x 4 of them per cell where every rank "
            "still gets at least this many mesh cells, else 2 x 2 x 2 where "
            "it does, one otherwise. The mesh cell is the partition's "
            "grain: fewer than ~1000 a rank make the ranks' work uneven in "
            "graded scenes, whose cells weigh up to 64 times more than "
            "others. Results do not change. 0 = one search cell per mesh "
            "cell always.",
            dealii::Patterns::Integer(0))
        .layout_only();
      b.add("Automaton order",
            automaton_order,
            "The order in which each rank stores its automata, and with "
            "them their pairs (each pair listed once, by the automaton that "
            "comes first): 'slabs': the cells row by row, layer by layer "
            "across the longest direction without periodic faces (the "
            "longest of all where every direction is periodic), so that the "
            "pairs of an automaton's neighbours lie within about one layer "
            "of its own in the pair list; or 'Morton curve' of the search "
            "cells (the default until 2026-12-07, slower on every scene "
            "measured: doc/performance.md, \"The automata in slabs by "
            "default\"). Within a cell the automata go by id. The order is "
            "global, the same on any partition; it sets the order of the "
            "pair sums, so the two orders' results differ at round-off, "
            "which the friction scenes amplify into different trajectories "
            "of the same statistics (five roughness seeds: "
            "prm/study/mca_automaton_order.prm).",
            automaton_order_table)
        .layout_only();
      b.add("Pairs per chunk",
            pairs_per_chunk,
            "On a rank without neighbour ranks the pair kernel's passes run "
            "as a pipeline over chunks of its pair list, each pass some "
            "chunks behind the one before, so that the pairs between them "
            "stay in the cache (doc/performance.md, \"The friction scene's "
            "step, tenth round\"); a chunk holds the pairs of whole automata, "
            "about "
            "this many. Results do not change, bit for bit. The 'slabs' "
            "order above keeps the passes a few chunks apart; along the "
            "curve they are far apart, most of the list.",
            dealii::Patterns::Integer(1))
        .layout_only();
      return b;
    }


    void
    PartitionParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      PartitionParameters().binding().declare(prm);
    }


    void
    PartitionParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      const ParameterBinding b = binding();
      b.parse(prm);
      check_parameter(rebalance_threshold == 0 || rebalance_threshold >= 1,
                      b.path("Rebalance threshold"),
                      "it is " + format_number(rebalance_threshold)
                        + ", but an imbalance (max/mean) is never below 1. "
                          "Use 0 (never repartition) or a value >= 1, e.g. "
                          "1.1.");
    }
  } // namespace mca
} // namespace tribodyn
