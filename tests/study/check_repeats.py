"""Check a study with 'Study/Repeats' = 3 (tests/study/repeats_study.prm).

cases.csv has one case per repeat (repeat 0, 1, 2; one pressure, one
model); the perturbation acts (repeat 0 is unperturbed: the three mu_mean
differ from each other by more than 1e-9 relative) but stays small (the
repeats' mu within 0.05 of each other: a 1e-3 m/s kick against a 1 m/s
plane); table2.csv's one row has n_runs = 3 and the mean of the three, and
its error bar is the documented se^2 = max(s_between^2/n, sum se_i^2/n^2),
computed here from cases.csv (to the 6 significant digits of the table).
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "mca"))
from check_tools import finish, report as check  # noqa: E402

out = os.path.join(sys.argv[1], "output")

with open(os.path.join(out, "cases.csv")) as f:
    cases = list(csv.DictReader(f))
check(sorted(int(c["repeat"]) for c in cases) == [0, 1, 2],
      "cases.csv: repeats 0, 1, 2 (%d cases)" % len(cases))
mu = [float(c["mu_mean"]) for c in cases]
se = [float(c["mu_stderr_blocking"]) for c in cases]
distinct = all(abs(a - b) > 1e-9 * abs(a)
               for i, a in enumerate(mu) for b in mu[i + 1:])
check(distinct, "the repeats differ: mu_mean %s" % mu)
check(max(mu) - min(mu) < 0.05, "and stay close (spread %.4f < 0.05)"
      % (max(mu) - min(mu)))
with open(os.path.join(out, "table2.csv")) as f:
    rows = list(csv.DictReader(f))
check(len(rows) == 1 and int(rows[0]["n_runs"]) == 3,
      "table2.csv: one row, n_runs = 3")
n = len(mu)
mean = sum(mu) / n
s2 = sum((m - mean) ** 2 for m in mu) / (n - 1)
expected_se = math.sqrt(max(s2 / n, sum(e * e for e in se) / n ** 2))
row = rows[0]
check(abs(float(row["mu_mean"]) - mean) <= 5e-6 * abs(mean),
      "table mean %s = the repeats' mean %.6g" % (row["mu_mean"], mean))
check(abs(float(row["mu_stderr"]) - expected_se) <= 5e-6 * expected_se,
      "table error bar %s = max(s/sqrt(n), sqrt(sum se_i^2)/n) = %.6g"
      % (row["mu_stderr"], expected_se))
finish()
