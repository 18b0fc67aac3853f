"""End-to-end i.i.d. check of the RVE study, 2D (rve_prm/rve_iid.prm.in)
and 3D (rve_prm/volume_rve_iid.prm.in).

The heterogeneity fraction of an i.i.d. Bernoulli(p) map over N-pixel (or
N-voxel) windows has the variance p(1-p)/N: integral range A = 1 pixel (1
voxel), alpha = 1. This test reads the map itself (the grid file, or the raw
volume of the header, named in the run's parameters.prm) for p(1-p), and
from rve.csv only the measured data: each size's number of windows n_k, its
pixels or voxels N_k and the standard deviation s_k of the windows'
fractions. It fits the integral range and the exponent
itself, weighting each size by the sampling error of a variance (var(ln
s_k^2) = 2/(n_k - 1)):
  ln A_1 = sum w_k ln(s_k^2 N_k / p(1-p)) / sum w_k, w_k = (n_k - 1)/2,
  se(ln A_1) = (sum w_k)^-1/2 (about sqrt(2/(4 x 299)) = 4.1 %),
  alpha: the weighted least-squares slope of ln s_k^2 against ln N_k
  (negated), se(alpha) = (sum w_k (ln N_k - mean)^2)^-1/2;
and checks |ln A_1| <= 3 se and |alpha - 1| <= 3 se(alpha) (the i.i.d.
law), then that the study's own A_1 and alpha are these fits: alpha to
1e-6 (the same estimator; measured 1e-10), A_1 within a tenth of se (the
study's point variance, 0.2101, is that of the phase fractions it
measured, not of this count of the map's pixels, 0.2097: measured 0.14 %). Only the
fraction rows exist (no cell problems): 4 sizes x 2 phases = 8 rows.
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "mca"))
from check_tools import finish, parameter, report as check  # noqa: E402

out = os.path.join(sys.argv[1], "output")
volume = parameter(out, "Problem") == "volume_rve"
ones = total = 0
if volume:
    # the raw file the header names, one byte per voxel
    header = parameter(out, "Morphology/Raw header")
    entries = dict(line.split("#")[0].split("=", 1) for line in open(header)
                   if "=" in line.split("#")[0])
    entries = {k.strip(): v.strip() for k, v in entries.items()}
    with open(os.path.join(os.path.dirname(header), entries["file"]),
              "rb") as f:
        data = f.read()
    ones, total = sum(b == 1 for b in data), len(data)
else:
    with open(parameter(out, "Morphology/Grid file")) as f:
        for line in f:
            if line.startswith("#"):
                continue
            values = line.split()
            ones += sum(v == "1" for v in values)
            total += len(values)
p = ones / total
unit = "vox" if volume else "px"
element = "voxel" if volume else "pixel"
point_variance = p * (1 - p)

with open(os.path.join(out, "rve.csv")) as f:
    rows = list(csv.DictReader(f))
check(len(rows) == 8, "8 rows (4 sizes x 2 fractions): %d" % len(rows))
sizes = [r for r in rows if r["property"] == "fraction_heterogeneity"]
w = [(int(r["n"]) - 1) / 2 for r in sizes]
x = [math.log(float(r["volume_vox" if volume else "area_px"]))
     for r in sizes]
y = [math.log(float(r["std"]) ** 2) for r in sizes]
ln_A = [yk + xk - math.log(point_variance) for xk, yk in zip(x, y)]
W = sum(w)
ln_A1 = sum(wk * a for wk, a in zip(w, ln_A)) / W
se = W ** -0.5
x_mean = sum(wk * xk for wk, xk in zip(w, x)) / W
y_mean = sum(wk * yk for wk, yk in zip(w, y)) / W
Sxx = sum(wk * (xk - x_mean) ** 2 for wk, xk in zip(w, x))
alpha = -sum(wk * (xk - x_mean) * (yk - y_mean)
             for wk, xk, yk in zip(w, x, y)) / Sxx
alpha_se = Sxx ** -0.5
print("map: p = %.5f over %d %ss; %d sizes" % (p, total, element,
                                                len(sizes)))
check(abs(ln_A1) <= 3 * se,
      "integral range A_1 = %.4f %s, |ln A_1| = %.4f <= 3 se = %.4f"
      % (math.exp(ln_A1), element, abs(ln_A1), 3 * se))
check(abs(alpha - 1) <= 3 * alpha_se,
      "alpha = %.4f +- %.4f (1 within 3 se)" % (alpha, alpha_se))
r = sizes[0]
study_A1 = float(r["integral_range_alpha1_" + unit])
study_alpha = float(r["alpha"])
check(abs(math.log(study_A1) - ln_A1) <= 0.1 * se,
      "the study's A_1 = %.6f %s is this fit's %.6f within se/10"
      % (study_A1, element, math.exp(ln_A1)))
check(abs(study_alpha - alpha) <= 1e-6,
      "the study's alpha = %.6f is this fit's %.6f" % (study_alpha, alpha))
finish()
