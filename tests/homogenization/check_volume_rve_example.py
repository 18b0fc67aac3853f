"""The shipped 3D RVE-size study prm/homogenization/volume_rve.prm (test
homogenization_volume_rve_example, 2 ranks; issue #51 item 2).

Checked from the run's outputs:
- rve.csv has 4 sizes x (2 fractions + 3 conditions x 9 constants) = 116
  rows, each size with the 16 windows asked for; rve.md and summary.json
  are written (summary: problem volume_rve, 64 windows on 2 groups of one
  rank, a fit per property and condition with its RVE volumes), and
  rve.png when /usr/bin/python3 has matplotlib;
- Huet's ordering on the means of every size (it holds window by window):
  KUBC >= periodic >= SUBC for k, mu and the Young and shear moduli, to
  1e-9 relative (CG tolerance 1e-8 on each window's six load cases moves a
  constant by ~1e-9 at most);
- the systematic error shrinks as the windows grow: the KUBC - SUBC gap of
  k and of mu falls from each size to the next (measured 36.8, 24.4, 15.2,
  10.2 % for k; 108.3, 71.7, 45.9, 30.4 % for mu), and the periodic means
  lie closer to SUBC than to KUBC at the largest size (as for any
  inclusion composite: KUBC over-constrains the cut inclusions).
"""
import csv
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "mca"))
from check_tools import finish, report as check  # noqa: E402

out = os.path.join(sys.argv[1], "output", "homogenization", "volume_rve")


with open(os.path.join(out, "rve.csv")) as f:
    rows = list(csv.DictReader(f))
check(len(rows) == 116, "rve.csv has 116 rows: %d" % len(rows))
check(all(int(r["n"]) == 16 for r in rows), "16 windows of each size")
sizes = sorted({int(r["size_x_vox"]) for r in rows})
check(sizes == [8, 12, 16, 24], "window sizes %s voxels" % sizes)


def mean(size, bc, prop):
    for r in rows:
        if (int(r["size_x_vox"]) == size and r["boundary_condition"] == bc
                and r["property"] == prop):
            return float(r["mean"])
    raise KeyError((size, bc, prop))


broken = []
for size in sizes:
    for c in ("k", "mu", "E_x", "E_y", "E_z", "G_yz", "G_xz", "G_xy"):
        K, P, S = (mean(size, bc, c) for bc in ("KUBC", "periodic", "SUBC"))
        if not (K >= P * (1 - 1e-9) and P >= S * (1 - 1e-9)):
            broken.append("%d^3 %s: %g %g %g" % (size, c, K, P, S))
check(not broken, "KUBC >= periodic >= SUBC for the 8 moduli at every size %s"
      % broken)
for c in ("k", "mu"):
    gaps = [mean(s, "KUBC", c) / mean(s, "SUBC", c) - 1 for s in sizes]
    check(all(a > b for a, b in zip(gaps, gaps[1:])) and gaps[-1] > 0,
          "the KUBC - SUBC gap of %s shrinks: %s" % (
              c, ", ".join("%.1f %%" % (100 * g) for g in gaps)))
    K, P, S = (mean(24, bc, c) for bc in ("KUBC", "periodic", "SUBC"))
    check(P - S < K - P, "24^3, %s: periodic %.3f GPa nearer SUBC %.3f than "
          "KUBC %.3f" % (c, P / 1e9, S / 1e9, K / 1e9))
with open(os.path.join(out, "summary.json")) as f:
    s = json.load(f)
check(s["problem"] == "volume_rve" and s["n_windows"] == 64
      and s["n_window_groups"] == 2 and len(s["fits"]) == 29
      and all(len(f["rve_volume_m3"]) == 2 for f in s["fits"]),
      "summary.json: volume_rve, 64 windows on 2 groups, 29 fits with the "
      "RVE volumes for n = 1 and 5")
check(os.path.getsize(os.path.join(out, "rve.md")) > 0, "rve.md written")
has_mpl = subprocess.run(["/usr/bin/python3", "-c", "import matplotlib"],
                         capture_output=True).returncode == 0
if has_mpl:
    with open(os.path.join(out, "rve.png"), "rb") as f:
        check(f.read(8) == b"\x89PNG\r\n\x1a\n", "rve.png written (a PNG)")
finish()
