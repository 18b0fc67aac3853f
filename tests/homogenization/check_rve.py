"""Check the outputs of the tiny RVE-size study (tests/homogenization/rve_small.prm).

rve.csv has one row per window size (2), boundary condition and property:
2 phase fractions (BC "none") + 2 BCs x 5 constants = 12 rows per size, 24
in all, each with n = 6 windows, a finite mean and std >= 0; the mean
heterogeneity fraction is that of the maps (0.1) within 0.05; Huet's
ordering holds on the means: KUBC >= SUBC for E_L, E_T and G_LT at every
size (it holds window by window, hence for the means); rve.md answers the
RVE question; summary.json has a fit per BC and property and records the
number of rank groups (one per rank: 'Ranks per window' = 1); rve.png exists when
/usr/bin/python3 has matplotlib.
"""
import csv
import json
import math
import os
import subprocess
import sys

out = os.path.join(sys.argv[1], "output")
failures = []


def check(condition, what):
    print(("PASS  " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


with open(os.path.join(out, "rve.csv")) as f:
    rows = list(csv.DictReader(f))
check(len(rows) == 24, "rve.csv has 24 rows (%d)" % len(rows))
for key in ["size_x_px", "size_y_px", "area_m2", "boundary_condition",
            "property", "n", "mean", "std", "bias", "eps_rel_n1",
            "eps_rel_n4", "alpha", "integral_range_px", "rve_area_m2_n1",
            "rve_area_m2_n4"]:
    check(key in rows[0], "rve.csv has column " + key)
sizes = sorted({(int(r["size_x_px"]), int(r["size_y_px"])) for r in rows})
check(sizes == [(20, 20), (40, 40)], "window sizes %s" % sizes)
for r in rows:
    ok = (int(r["n"]) == 6 and math.isfinite(float(r["mean"]))
          and float(r["std"]) >= 0)
    if not ok:
        check(False, "row %s" % r)
check(all(int(r["n"]) == 6 for r in rows), "every row has n = 6 windows")


def value(size, bc, prop, key="mean"):
    for r in rows:
        if ((int(r["size_x_px"]), int(r["size_y_px"])) == size
                and r["boundary_condition"] == bc and r["property"] == prop):
            return float(r[key])
    raise KeyError((size, bc, prop))


for size in sizes:
    f = value(size, "none", "fraction_heterogeneity")
    check(abs(f - 0.1) < 0.05, "%s mean fraction %.4f near 0.1" % (size, f))
    for prop in ["E_L", "E_T", "G_LT"]:
        k, s = value(size, "KUBC", prop), value(size, "SUBC", prop)
        check(k >= s, "%s %s: KUBC %.4f >= SUBC %.4f GPa"
              % (size, prop, k / 1e9, s / 1e9))

with open(os.path.join(out, "summary.json")) as f:
    summary = json.load(f)
check(summary.get("problem") == "rve", "summary.json problem = rve")
check(summary.get("n_windows") == 12, "summary.json n_windows = 12")
n_groups = summary.get("n_mpi_ranks")  # 'Ranks per window' = 1
check(summary.get("n_window_groups") == n_groups,
      "summary.json n_window_groups = n_mpi_ranks = %s" % n_groups)
check(len(summary.get("fits", [])) == 12, "summary.json has 12 fits")
with open(os.path.join(out, "rve.md")) as f:
    md = f.read()
check("Which windows are RVEs" in md and "| E_L | KUBC |" in md,
      "rve.md answers the RVE question")
has_mpl = os.path.exists("/usr/bin/python3") and subprocess.call(
    ["/usr/bin/python3", "-c", "import matplotlib"],
    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL) == 0
if has_mpl:
    check(os.path.exists(os.path.join(out, "rve.png")), "rve.png written")
sys.exit(1 if failures else 0)
