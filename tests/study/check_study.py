"""Check the outputs of the tiny study (tests/study/tiny_study.prm).

table2.csv has the documented columns and one row per (pressure, model);
n_runs is 1 for the homogeneous pins and 'Number of morphologies' for the
meso pin; every error bar is positive and finite; the fractions add up to
1 (1e-5: 6 significant digits in the file); the regime names agree with the fractions and the
documented threshold; each row's mean, error bar and fractions are computed
again here from cases.csv (the documented se^2 = max(s_between^2/g,
sum se_i^2/n^2)); the contact-face friction ratio of every case is the law's
alpha*mu = 0.25 within 2 % (measured: 0.45 % at most; the pins slip on 98 % of
the node-samples, and the regularized law relaxes to alpha*mu in 1.5 us of the
20 us window) and every global mean within 3 of its standard errors of it; the homogenization runs were chained (one per
morphology) and the homogenized pin's stiffness is their average, which
differs from the matrix's (so the two homogeneous models are not the same
pin); every case wrote its series; summary.json has the study keys.
"""
import csv
import json
import math
import os
import sys

out = os.path.join(sys.argv[1], "output")
failures = []


def check(condition, what):
    print(("PASS  " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def regime(st, sl, se, thr):
    a, b, c = st > thr, sl > thr, se > thr
    if a and b and c:
        return "stick-slip-separation"
    if b and c:
        return "slip-separation"
    if a and b:
        return "stick-slip"
    if b:
        return "slip"
    if a:
        return "stick-separation" if c else "stick"
    return "separation" if c else "none"


with open(os.path.join(out, "table2.csv")) as f:
    rows = list(csv.DictReader(f))
cols = ["pressure", "model", "n_runs", "mu_mean", "mu_stderr", "stick_fraction",
        "slip_fraction", "separation_fraction", "regime", "dominant_frequency_hz"]
check(list(rows[0].keys()) == cols, "table2.csv columns " + ",".join(cols))
check(len(rows) == 6, "6 rows (2 pressures x 3 models)")
for r in rows:
    n = int(r["n_runs"])
    check(n == (2 if r["model"] == "meso" else 1), "n_runs of " + r["model"])
    se = float(r["mu_stderr"])
    check(math.isfinite(se) and se > 0, "positive error bar (%g)" % se)
    fr = [float(r[k]) for k in cols[5:8]]
    check(abs(sum(fr) - 1) < 1e-5, "fractions add up to 1 (6 digits written)")
    check(r["regime"] == regime(*fr, 0.01), "regime '%s' from the fractions" % r["regime"])

# Table 2 again from cases.csv (written with 8 digits; table2.csv has 6).
with open(os.path.join(out, "cases.csv")) as f:
    cases = list(csv.DictReader(f))
mu_law = 0.25  # Contact/Friction coefficient (default) x alpha (default 1)


def close(a, b):
    return abs(a - b) <= 1e-5 * max(abs(a), abs(b)) + 1e-12


for r in rows:
    runs = [c for c in cases
            if float(c["pressure"]) == float(r["pressure"]) and c["model"] == r["model"]]
    n = len(runs)
    check(n == int(r["n_runs"]), "cases.csv has n_runs = %d cases of %s at %s Pa"
          % (n, r["model"], r["pressure"]))
    if n == 0:
        continue
    mean = sum(float(c["mu_mean"]) for c in runs) / n
    within = sum(float(c["mu_stderr_blocking"]) ** 2 for c in runs) / n ** 2
    between = (sum((float(c["mu_mean"]) - mean) ** 2 for c in runs) / ((n - 1) * n)
               if n > 1 else 0.0)
    se = math.sqrt(max(between, within))
    check(close(mean, float(r["mu_mean"])), "%s mu_mean %s = mean of its cases %.6g"
          % (r["model"], r["mu_mean"], mean))
    check(close(se, float(r["mu_stderr"])), "%s mu_stderr %s = combined error %.6g"
          % (r["model"], r["mu_stderr"], se))
    for k in ["stick_fraction", "slip_fraction", "separation_fraction",
              "dominant_frequency_hz"]:
        check(close(sum(float(c[k]) for c in runs) / n, float(r[k])),
              "%s %s = mean of its cases" % (r["model"], k))
    check(abs(float(r["mu_mean"]) - mu_law) < 3 * se,
          "%s mu_mean %s within 3 standard errors (%.3g) of alpha*mu = %g"
          % (r["model"], r["mu_mean"], se, mu_law))
for c in cases:
    check(abs(float(c["mu_contact_mean"]) / mu_law - 1) < 0.02,
          "%s contact-face friction ratio %s = alpha*mu within 2 %%"
          % (c["case"], c["mu_contact_mean"]))

with open(os.path.join(out, "homogenization", "homogenized_stiffness.json")) as f:
    h = json.load(f)
check(len(h["summaries"]) == 2, "two homogenization runs chained")
C = [[0.0] * 3 for _ in range(3)]
for s in h["summaries"]:
    path = s if os.path.isabs(s) else os.path.join(sys.argv[1], s)
    with open(path) as f:
        k = json.load(f)["KUBC"]["C"]
    for i in range(3):
        for j in range(3):
            C[i][j] += k[i][j] / 2
check(all(abs(C[i][j] - h["C"][i][j]) <= 1e-9 * abs(C[0][0])
          for i in range(3) for j in range(3)),
      "homogenized stiffness = average of the KUBC stiffnesses")
E, nu = 30e9, 0.2
C11_matrix = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
check(h["C"][1][1] > 1.1 * C11_matrix,
      "homogenized C22 (%g) above the matrix's (%g): 10 %% of E = 80 GPa"
      % (h["C"][1][1], C11_matrix))

check(len(cases) == 8, "8 cases")
for c in cases:
    d = os.path.join(out, "cases", c["case"])
    for name in ["summary.json", "friction.csv", "point_M.csv"]:
        check(os.path.isfile(os.path.join(d, name)), c["case"] + "/" + name)

with open(os.path.join(out, "summary.json")) as f:
    s = json.load(f)
for key in ["table2", "n_cases", "mesh_size", "averaging_window", "wall_time_s",
            "n_mpi_ranks", "tribodyn_version", "regime_threshold"]:
    check(key in s, "summary.json has " + key)
check(abs(s["mesh_size"] - 0.25e-3) < 1e-12, "one mesh for every model: h = pixel size")
check(os.path.isfile(os.path.join(out, "table2.md")), "table2.md written")

if failures:
    sys.exit("%d check(s) failed" % len(failures))
