"""End-to-end i.i.d. check of the RVE study (rve_prm/rve_iid.prm.in).

The heterogeneity fraction of an i.i.d. Bernoulli(p) map over N-pixel
windows has the variance p(1-p)/N: integral range A = 1 pixel, alpha = 1.
Read from rve.csv as the study wrote it (windows cut by the driver, the
gather over ranks, the fits): |ln A_1| <= 3 se (se = the relative standard
error of A_1 the study reports, ~sqrt(2/(4 * 299)) = 4.1 %, from the
sampling error of a variance) and |alpha - 1| <= 3 alpha_se. Only the
fraction rows exist (no cell problems): 4 sizes x 2 phases = 8 rows.
"""
import csv
import math
import os
import sys

out = os.path.join(sys.argv[1], "output")
failures = []


def check(condition, what):
    print(("PASS  " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


with open(os.path.join(out, "rve.csv")) as f:
    rows = list(csv.DictReader(f))
check(len(rows) == 8, "8 rows (4 sizes x 2 fractions): %d" % len(rows))
r = [x for x in rows if x["property"] == "fraction_heterogeneity"][0]
A1, se = float(r["integral_range_alpha1_px"]), float(
    r["integral_range_alpha1_rel_se"])
check(abs(math.log(A1)) <= 3 * se,
      "integral range A_1 = %.4f pixel, |ln A_1| = %.4f <= 3 se = %.4f"
      % (A1, abs(math.log(A1)), 3 * se))
alpha, alpha_se = float(r["alpha"]), float(r["alpha_se"])
check(abs(alpha - 1) <= 3 * alpha_se,
      "alpha = %.4f +- %.4f (1 within 3 se); free-fit A = %s pixel"
      % (alpha, alpha_se, r["integral_range_px"]))
sys.exit(1 if failures else 0)
