#!/usr/bin/env python3
"""The README's table of the micrograph pin study is the data kept in
data/micrograph_pins (issue #50 item 2), and its figure redraws from it.

    check_pin_study_data.py SOURCE_DIR WORK_DIR

From data/micrograph_pins: PROVENANCE names a commit; table2.csv's two rows
(n_runs, mu_mean ± mu_stderr to the README's digits, the fractions, the
regime, the spectrum peak in kHz) and paired.csv's row (the difference and
its error to 3 decimals, the windows with the same regime) appear in the
README's table as written there; scripts/plot_study redraws paired.png
(and the three other plots) from the kept data alone, into a copy in
WORK_DIR.
"""
import csv
import os
import re
import shutil
import subprocess
import sys

source, work = sys.argv[1:3]
data = os.path.join(source, "data", "micrograph_pins")
failures = []


def check(condition, what):
    print(("PASS  " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


readme = " ".join(open(os.path.join(source, "README.md")).read().split())
provenance = open(os.path.join(data, "PROVENANCE")).read()
check(re.search(r"^commit: [0-9a-f]{40}", provenance, re.M) is not None,
      "PROVENANCE names the commit")
rows = {r["model"]: r for r in csv.DictReader(open(os.path.join(data, "table2.csv")))}
for model, label in (("homogenized", "homogenized (own constants per window)"),
                     ("meso", "meso (pores cut out)")):
    r = rows[model]
    fr = " / ".join(f"{float(r[k]):.3f}" for k in
                    ("stick_fraction", "slip_fraction", "separation_fraction"))
    line = (f"| {label} | {r['n_runs']} | {float(r['mu_mean']):.3f} ± "
            f"{float(r['mu_stderr']):.4f} | {fr} | {r['regime'].replace('-', '–')} | "
            f"{float(r['dominant_frequency_hz']) / 1e3:.0f} kHz |")
    check(line in readme, "README: " + line)
p = next(csv.DictReader(open(os.path.join(data, "paired.csv"))))
line = (f"| **meso − homogenized, paired by window** | {p['n_morphologies']} windows | "
        f"**{float(p['mu_meso_minus_homogenized']):+.3f} ± {float(p['mu_stderr']):.3f}**"
        f" | | same regime in {p['regimes_agree']} of {p['n_morphologies']} | |"
        ).replace("**-", "**−")
check(line in readme, "README: " + line)
copy = os.path.join(work, "micrograph_pins")
shutil.rmtree(copy, ignore_errors=True)
shutil.copytree(data, copy)
# (the script's own interpreter line: the python with matplotlib)
r = subprocess.run([os.path.join(source, "scripts", "plot_study"), copy],
                   capture_output=True, text=True)
check(r.returncode == 0 and all(os.path.exists(os.path.join(copy, f)) for f in
                                ("paired.png", "table2.png", "mu_global.png", "phase_M.png")),
      "scripts/plot_study redraws the figures from the kept data: " + r.stdout.strip())
if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("All checks passed.")
