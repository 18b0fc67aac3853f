"""friction.csv of the runs of short_pin.prm on 2, 3 and 4 ranks equals the
1-rank run's to 1e-9 (relative to each column's largest value): the
Gauss-Seidel sweep over the contact nodes runs in the same order on any
partition (measured: 1.4e-14 on 2 and 3 ranks, 1.4e-13 on 4: round-off
of the MPI sums). Each run must have had the ranks its name says, and its
contact face must have been split across at least 2 of them (summary key
n_contact_face_ranks), so that the sweep really crossed ranks.

Usage: compare_ranks.py PREFIX [RANKS...]: compares PREFIX_1rank with
PREFIX_<n>ranks for each n of RANKS (default: 2)."""
import csv
import json
import os
import sys

base = sys.argv[1]
ranks = [int(n) for n in sys.argv[2:]] or [2]
failed = False


def report(good, text):
    global failed
    failed = failed or not good
    print(("PASS  " if good else "FAIL  ") + text)


def read(directory):
    with open(os.path.join(directory, "output", "friction.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(directory, "output", "summary.json")) as f:
        return rows, json.load(f)


a, sa = read(base + "_1rank")
report(sa["n_mpi_ranks"] == 1, "reference run on 1 rank")
for n in ranks:
    b, sb = read("%s_%dranks" % (base, n))
    split = sb.get("n_contact_face_ranks", 0)
    report(sb["n_mpi_ranks"] == n and split >= 2,
           "%d ranks, contact face on %s of them" % (sb["n_mpi_ranks"], split))
    if len(a) != len(b):
        report(False, "%d ranks: different numbers of rows" % n)
        continue
    worst = 0
    for column in ["mu_global", "contact_normal_force", "contact_tangential_force",
                   "kinetic_energy", "elastic_energy"]:
        scale = max(abs(float(r[column])) for r in a) or 1
        worst = max(worst, max(abs(float(x[column]) - float(y[column])) / scale
                               for x, y in zip(a, b)))
    report(worst < 1e-9, "%d ranks = 1 rank (%.2e, tolerance 1e-9)" % (n, worst))
sys.exit(1 if failed else 0)
