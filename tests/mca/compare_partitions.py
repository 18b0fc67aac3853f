"""Same answers on any partition (issue #7): the runs of one scene on 1, 2,
3, 4, 6 and 8 ranks (argument 1: the build folder, 2: the test name prefix,
3 and 4: optionally the mean height of a rough contact interface and its
half-width, roughness amplitude plus automaton size) must give the same
series.csv (energies, plastic and friction work, pair counts, group forces
and displacements at every sample) to 1e-9 relative to each column's
largest magnitude. The pairs are summed in a global order, so the runs
differ only by the round-off of the MPI reductions (~1e-16); 1e-9 leaves
room for its growth over 500+ steps and nothing else.

Also checked, so that the test cannot pass vacuously: the multi-rank runs
had ghosts (the partition cut the block), every run rebuilt its pair list
(automata moved, crossing periodic faces), and with an interface height,
the automata within the interface band belong to at least two ranks on 2+
ranks (the partition cuts the contact interface)."""
import csv
import glob
import json
import os
import re
import sys

from check_tools import finish, plot_tools, report  # plot_tools: read_vtu

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from series_compare import largest_relative_difference  # noqa: E402

build, prefix = sys.argv[1], sys.argv[2]
interface = float(sys.argv[3]) if len(sys.argv) > 4 else None
band = float(sys.argv[4]) if len(sys.argv) > 4 else 0
ranks = [1, 2, 3, 4, 6, 8]


def output(n):
    dirs = [root for root, _, files in os.walk(os.path.join(build, "%s_%d" % (prefix, n)))
            if "summary.json" in files]
    return dirs[0] if dirs else None



def ranks_near_interface(folder, z0):
    """Ranks owning automata within the band around z0 in the last particle
    output (its 'rank' field)."""
    files = sorted(glob.glob(os.path.join(folder, "particles_*.*.vtu")))
    last = sorted({re.sub(r"\.\d+\.vtu$", "", f) for f in files})[-1]
    owners = set()
    for f in glob.glob(last + ".*.vtu"):
        a = plot_tools.read_vtu(f)
        for r, xyz in zip(a.get("rank", []), a.get("points", [])):
            if abs(xyz[2] - z0) < band:
                owners.add(int(r))
    return owners


reference = output(1)
report(reference is not None, "1-rank run wrote its outputs")
if reference:
    a = list(csv.reader(open(os.path.join(reference, "series.csv"))))
    for n in ranks[1:]:
        folder = output(n)
        if folder is None:
            report(False, "%d-rank run wrote its outputs" % n)
            continue
        b = list(csv.reader(open(os.path.join(folder, "series.csv"))))
        same_shape = len(a) == len(b) and len(a) > 5 and a[0] == b[0]
        report(same_shape, "%d ranks: same rows and columns (%d, %d)" % (n, len(a), len(b)))
        if not same_shape:
            continue
        worst, name = largest_relative_difference(a, b)
        report(worst <= 1e-9, "%d ranks: largest relative difference %.3g (%s; tolerance 1e-9)"
               % (n, worst, name or "-"))
        s = json.load(open(os.path.join(folder, "summary.json")))
        report(s.get("n_ghost_automata_max", 0) > 0 and s.get("n_pair_list_rebuilds", 0) > 1,
               "%d ranks: %d ghosts on the largest rank, %d pair-list rebuilds"
               % (n, s.get("n_ghost_automata_max", 0), s.get("n_pair_list_rebuilds", 0)))
        if interface is not None:
            owners = ranks_near_interface(folder, interface)
            report(len(owners) >= 2, "%d ranks: the contact interface is cut (ranks %s own automata "
                   "of the interface band)" % (n, sorted(owners)))
finish()
