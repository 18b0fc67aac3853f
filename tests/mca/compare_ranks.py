"""2 ranks equal 1 rank (friction_small.prm, or the tests and output folder
given as arguments 2-4, e.g. friction_carbon_small.prm: periodic x and y,
contacts, plasticity, bond breaking and formation, pair-list rebuilds with
automata crossing periodic faces and rank boundaries). Every number of
series.csv must agree to 1e-9 relative to its column's largest magnitude
(the pair loop runs in the same id order on any partition, so the runs
agree to round-off of the MPI reductions). The runs must have had 1 and 2
ranks, and the 2-rank run ghosts (automata seen across the cut)."""
import csv
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from series_compare import largest_relative_difference  # noqa: E402

build = os.path.dirname(sys.argv[1])
tests = sys.argv[2:4] if len(sys.argv) > 4 else ["mca_ranks_1", "mca_ranks_2"]
folder = sys.argv[4] if len(sys.argv) > 4 else "output-mca-friction-small"
rows = []
for test in tests:
    with open(os.path.join(build, test, folder, "series.csv")) as f:
        rows.append(list(csv.reader(f)))
a, b = rows
summaries = []
for test in tests:
    with open(os.path.join(build, test, folder, "summary.json")) as f:
        summaries.append(json.load(f))
ranks = [x["n_mpi_ranks"] for x in summaries]
ghosts = summaries[1].get("n_ghost_automata_max", 0)
split = ranks == [1, 2] and ghosts > 0
print(("PASS  " if split else "FAIL  ") + "ranks %s, ghosts on the 2-rank run %s" % (ranks, ghosts))
ok = len(a) == len(b) and len(a) > 5 and a[0] == b[0]
print(("PASS  " if ok else "FAIL  ") + "same rows and columns (%d, %d)" % (len(a), len(b)))
worst, name = largest_relative_difference(a, b)
good = worst <= 1e-9
print(("PASS  " if good else "FAIL  ") + "largest relative difference %.3g (tolerance 1e-9)" % worst)
sys.exit(0 if ok and good and split else 1)
