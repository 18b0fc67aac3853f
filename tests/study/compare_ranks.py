"""The tiny study on 2 ranks (2 groups of 1 rank running different cases)
gives the same table2.csv and cases.csv numbers as on 1 rank (each case
runs on one rank in both: identical up to 1e-12 relative; wall times are
not compared). The 2-rank run must have had 2 ranks in 2 groups of cases
(summary keys n_mpi_ranks, n_case_groups)."""
import csv
import json
import sys

base = sys.argv[1]
bad = 0
with open(base + "_2ranks/output/summary.json") as f:
    s = json.load(f)
groups = s["n_mpi_ranks"] == 2 and s.get("n_case_groups") == 2
print(("PASS  " if groups else "FAIL  ") + "2 ranks (%s) in 2 groups of cases (%s)"
      % (s["n_mpi_ranks"], s.get("n_case_groups")))
bad += 0 if groups else 1
for name in ["table2.csv", "cases.csv"]:
    a = list(csv.reader(open(base + "_1rank/output/" + name)))
    b = list(csv.reader(open(base + "_2ranks/output/" + name)))
    if len(a) != len(b) or a[0] != b[0]:
        print("FAIL  %s: different rows or columns" % name)
        bad += 1
        continue
    for ra, rb in zip(a[1:], b[1:]):
        for c, x, y in zip(a[0], ra, rb):
            if c == "wall_time_s":
                continue
            try:
                ok = abs(float(x) - float(y)) <= 1e-12 * max(1, abs(float(x)))
            except ValueError:
                ok = x == y
            if not ok:
                print("FAIL  %s column %s: %s != %s" % (name, c, x, y))
                bad += 1
    print(("PASS  " if bad == 0 else "FAIL  ") + name + " agrees")
sys.exit(1 if bad else 0)
