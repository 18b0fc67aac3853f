"""The partition weighted anew during a run (issue #18, item 4).

Arguments: the build folder of tests/mca, the 1-rank test, the rebalanced
test, their output folder and, optionally, the rebalanced run's mesh split
(summary.json's mesh_cell_split: 4 where the deal.II cells hold 4 x 4 x 4
search cells, partition/block_lifted_split.prm; default 1). The rebalanced run (partition/block_lifted.prm:
a block lifted and sheared across the partition's cuts, K_ij on, 3 ranks,
Partition/Rebalance threshold = 1.0001: a new partition whenever the
imbalance grew by 5e-5 since the last one) must

- have run on 3 ranks with ghosts and have repartitioned at least twice
  (the automata, their pair states and the ghosts moved to new ranks
  mid-run, more than once);
- give the 1-rank run's series.csv to 1e-9 relative to each column's
  largest magnitude (the tolerance of every partition test: the pairs are
  summed in a global order, so only the MPI reductions' round-off differs;
  a pair state lost in the move changes the series at the 1e-3 level:
  shown once by dropping the pair-state records of the move).
"""
import csv
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_tools import finish, report  # noqa: E402
from series_compare import largest_relative_difference  # noqa: E402

build, single, rebalanced, folder = sys.argv[1:5]
split = int(sys.argv[5]) if len(sys.argv) > 5 else 1


def load(test):
    path = os.path.join(build, test, folder)
    with open(os.path.join(path, "series.csv")) as f:
        rows = list(csv.reader(f))
    with open(os.path.join(path, "summary.json")) as f:
        return rows, json.load(f)


rows_1, summary_1 = load(single)
rows_n, summary_n = load(rebalanced)
report(summary_n["n_mpi_ranks"] == 3 and summary_1["n_mpi_ranks"] == 1,
       "ranks: %d and %d" % (summary_1["n_mpi_ranks"], summary_n["n_mpi_ranks"]))
report(summary_n["n_ghost_automata_max"] > 0,
       "the 3-rank run had ghosts (at most %d on a rank)"
       % summary_n["n_ghost_automata_max"])
report(summary_n["n_rebalances"] >= 2,
       "repartitioned during the run %d times (>= 2); work imbalance %.4f at "
       "set-up, %.4f at the end" % (summary_n["n_rebalances"],
                                    summary_n["work_imbalance"],
                                    summary_n["work_imbalance_end"]))
report(summary_1["n_rebalances"] == 0, "the 1-rank run never repartitions")
report(summary_n.get("mesh_cell_split") == split,
       "the rebalanced run's mesh: %s search cells per deal.II cell and "
       "direction (expected %d)" % (summary_n.get("mesh_cell_split"), split))
same = len(rows_1) == len(rows_n) and len(rows_1) > 5 and rows_1[0] == rows_n[0]
report(same, "same rows and columns (%d, %d)" % (len(rows_1), len(rows_n)))
worst, name = largest_relative_difference(rows_1, rows_n)
report(worst <= 1e-9, "largest relative difference %.3g in %s (tolerance 1e-9)"
       % (worst, name))
finish()
