"""Energy drift of the undamped frictionless pin (energy_drift.prm): the
run has >= 10^6 steps, and the largest energy balance error over it (the
discrete energy identity of the beta2 = 1/2 scheme, relative to the largest
energy seen) is below 1e-11.

The identity is exact for beta2 = 1/2, so what is left is round-off:
measured 9.5e-14 over the 10^6 steps (2026-11-26); 1e-11 leaves 100x for
its growth on another compiler or library build. The former limit, 1e-3
(issue #10), could not fail: with beta2 = 0.5001 (a scheme that is not
the one asked for) the error is 1.1e-5, which 1e-3 accepted and 1e-11
refuses (issue #21)."""
import csv
import json
import os
import sys

out = os.path.join(sys.argv[1], "output")
s = json.load(open(os.path.join(out, "summary.json")))
rows = list(csv.DictReader(open(os.path.join(out, "friction.csv"))))
worst = max(float(r["energy_balance_error"]) for r in rows)
print(f"steps {s['n_steps']}, dt {s['dt']:.4g} s (critical "
      f"{s['critical_dt']:.4g} s); largest energy balance error {worst:.3e}; "
      f"last row: {rows[-1]['energy_balance_error']}")
ok = s["n_steps"] >= 1000000 and worst < 1e-11
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
