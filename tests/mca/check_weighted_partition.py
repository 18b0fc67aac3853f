"""Weighted partition (issue #18, item 4): the block filling the lower third
of its box (partition/block_partly_filled.prm) run on 1, 3 and 4 ranks
(argument 1: the build folder, 2: the test name prefix).

- The 4-rank run's work imbalance (largest number of owned automata of a
  rank over the mean, summary.json 'work_imbalance') must be at most 1.10:
  p4est's curve is cut by the cells' weights (8 per automaton + 1), so the
  weighted partition measured 1.06 on 3 and 4 ranks. With the weights
  switched off (a deliberately broken build) the unweighted partition
  printed an imbalance of 2.53 on 3 ranks and 2.58 on 4 (check fails), and
  those runs did not finish in 48 min (with most of its cells empty, a
  rank hangs the engine: a bug of its own, noted on issue #18).
- The 3- and 4-rank series.csv equal the 1-rank one to 1e-9 relative to
  each column's largest magnitude (the tolerance of compare_partitions.py:
  MPI round-off only), and the multi-rank runs had ghosts."""
import csv
import json
import os
import sys

from check_tools import finish, report

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from series_compare import largest_relative_difference  # noqa: E402

build, prefix = sys.argv[1], sys.argv[2]


def output(n):
    for root, _, files in os.walk(os.path.join(build, "%s_%d" % (prefix, n))):
        if "summary.json" in files and "previous_run" not in root:
            return root
    sys.exit(f"FAIL: no finished run for {n} ranks")


summaries = {n: json.load(open(os.path.join(output(n), "summary.json")))
             for n in (1, 3, 4)}


def rows(n):
    return list(csv.reader(open(os.path.join(output(n), "series.csv"))))


for n in (3, 4):
    s = summaries[n]
    report(s["n_mpi_ranks"] == n, f"the {n}-rank run had {n} ranks")
    report(s["n_ghost_automata_max"] > 0, f"the {n}-rank run had ghosts")
    diff, column = largest_relative_difference(rows(1), rows(n))
    report(diff <= 1e-9, f"series on {n} ranks equal 1 rank's: largest "
           f"difference {diff:.2e} ({column}) <= 1e-9")
imbalance = summaries[4]["work_imbalance"]
report(imbalance <= 1.10, f"work imbalance on 4 ranks {imbalance:.3f} <= 1.10")
report(summaries[1]["work_imbalance"] == 1.0,
       "one rank is balanced (imbalance 1)")
finish()
