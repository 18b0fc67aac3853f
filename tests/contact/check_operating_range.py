#!/usr/bin/env python3
"""The postprocessor "operating range" (issue #50 item 3) on the held block
of operating_range.prm: 17 contact nodes, in contact from the first steps
on, pressed with P = 5 MPa while the plane slides at V = 2 m/s.

- node_steps_in_contact is at most n_contact_nodes x n_steps and above
  0.9 of it (the block is pressed from the start: the ramp starts at 0 but
  the nodes touch), and equals the histogram's counts (exact, both);
- the medians: the contact pressure within one bin (a factor 10^(1/20) =
  1.12) of P (the corner nodes' pressure λ_N/(h/2) equals the others' in
  uniform slip) and the slip rate within one bin of V; measured 4.96 MPa and
  2.00 m/s;
- the percentiles of operating_range.csv are those of the histogram
  recomputed here (geometric interpolation within the bin; the file's 4
  digits);
- the 0.25 % pressure percentile lies below P / 10 (the ramp from 0: its
  first steps press below 1 Pa, the histogram's lowest bin, reported as 0)
  and the 99.75 % one between P and 4 P: the two corner nodes (2 of 17)
  carry the edge concentration of a flat block on a rigid plane (measured
  14.0 MPa).

    check_operating_range.py OUTPUT_DIR
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


s = json.load(open(os.path.join(out, "summary.json")))
rows = {r["quantity"]: r for r in csv.DictReader(open(os.path.join(out, "operating_range.csv")))}
bins = list(csv.DictReader(open(os.path.join(out, "operating_range_histogram.csv"))))
n = int(rows["contact_pressure_Pa"]["node_steps_in_contact"])
full = s["n_contact_nodes"] * s["n_steps"]
check(0.9 * full < n <= full, f"{n} node-steps in contact of {full} node-steps")
bin_factor = 10 ** (1 / 20)


def percentile(name, q):
    h = [(float(b["bin_low"]), float(b["bin_high"]), int(b["count"]))
         for b in bins if b["quantity"] == name]
    total = sum(c for _, _, c in h)
    target, below = q * total, 0
    for low, high, c in h:
        if below + c >= target:
            if low == 0:
                return 0.0
            return low * 10 ** ((target - below) / c / 20)
        below += c


for name, nominal in (("contact_pressure_Pa", 5e6), ("slip_rate_m_per_s", 2.0)):
    counts = sum(int(b["count"]) for b in bins if b["quantity"] == name)
    check(counts == n, f"{name}: histogram counts {counts} = node-steps in contact")
    median = float(rows[name]["p50"])
    check(nominal / bin_factor <= median <= nominal * bin_factor,
          f"{name}: median {median:.4g} within a bin of {nominal:g}")
    for q, key in ((0.0025, "p0.25"), (0.5, "p50"), (0.9975, "p99.75")):
        mine, theirs = percentile(name, q), float(rows[name][key])
        check(abs(mine - theirs) <= 1e-3 * abs(mine) + 1e-300,
              f"{name}: {key} {theirs:.4g} = the histogram's ({mine:.4g})")
p = rows["contact_pressure_Pa"]
check(float(p["p0.25"]) < 5e5 and 5e6 < float(p["p99.75"]) < 4 * 5e6,
      f"pressure range {float(p['p0.25']):.3g} .. {float(p['p99.75']):.3g} Pa: from the "
      "ramp to the corners' edge concentration")
if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("All checks passed.")
