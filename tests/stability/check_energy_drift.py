"""Energy drift of the undamped frictionless pin (energy_drift.prm): the
run has >= 10^6 steps, and the largest energy balance error over it (the
discrete energy identity of the beta2 = 1/2 scheme, relative to the largest
energy seen) is below 1e-3 (0.1 %, issue #10)."""
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
ok = s["n_steps"] >= 1000000 and worst < 1e-3
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
