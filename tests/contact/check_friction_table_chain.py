#!/usr/bin/python3
"""The bridge between the scales as one command chain (issue #20 item 4),
small: scripts/mca_friction_table on a 2 x 2 grid of pressures and sliding
speeds of prm/mca/friction_steel.prm cut to 0.6 ns (one seed, one rank:
the bodies touch at ~0.59 ns, so each run's mu is that of its first
samples: this checks the chain, not the physics), then the short pin with
`Friction law = tabulated` reading the table.

    check_friction_table_chain.py TRIBODYN SOURCE_DIR OUT_DIR

Checks: the table holds the full grid, one row per (pressure, speed), each
mu equal to its run's mu_steady (summary.json, exactly: the script copies,
not recomputes); the pin runs with it (summary: friction_law = tabulated,
the clamped evaluations counted) and its contact mu, sum |lambda_T| / sum
lambda_N, lies within [0, the table's largest mu] (every node's |lambda_T|
<= mu(p, v) lambda_N with mu from the table). Then an exact identity: the
same pin reading the table at the corner (lowest pressure, highest speed:
`Pressure scale` 1e-300 and `Speed = plane speed` with `Speed scale` 1e300
clamp every look-up there, where the table returns its entry exactly) is,
bit for bit (friction.csv, point_M.csv and contact_status.csv as text),
the pin with `Friction law = Coulomb` and that entry as its coefficient,
read here from mu_table.csv: a look-up, a scale or a clamp applied wrongly
changes the series.
"""
import csv
import json
import math
import os
import subprocess
import sys

tribodyn, source, out = sys.argv[1:4]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
           OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
table_dir = os.path.join(out, "table")
subprocess.run([os.path.join(source, "scripts", "mca_friction_table"),
                "--scene", os.path.join(source, "prm/mca/friction_steel.prm"),
                "--pressures", "150e6,300e6", "--speeds", "5,10",
                "--seeds", "1", "--ranks", "1", "--end-time", "6e-10",
                "--tribodyn", tribodyn, "--out", table_dir],
               check=True, env=env, stdout=subprocess.DEVNULL)
failures = 0


def check(condition, what):
    global failures
    print(("PASS  " if condition else "FAIL  ") + what)
    failures += 0 if condition else 1


path = os.path.join(table_dir, "mu_table.csv")
with open(path) as f:
    rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
grid = {(float(r["pressure"]), float(r["speed"])) for r in rows}
check(len(rows) == 4 and grid == {(p, v) for p in (150e6, 300e6)
                                  for v in (5., 10.)},
      "mu_table.csv: the full 2 x 2 grid (%d rows)" % len(rows))
copied = True
with open(os.path.join(table_dir, "scenes.csv")) as f:
    scenes = {(float(s["Friction loading/Pressure"]),
               float(s["Friction loading/Sliding velocity"])): s["scene"]
              for s in csv.DictReader(f)}
for r in rows:
    d = os.path.join(table_dir, "scenes",
                     scenes[(float(r["pressure"]), float(r["speed"]))])
    with open(os.path.join(d, "summary.json")) as f:
        copied = copied and float(r["mu"]) == json.load(f)["mu_steady"]
check(copied, "each mu = its run's mu_steady")
check(os.path.exists(os.path.join(table_dir, "mu_table.png")),
      "mu_table.png written")
mu_max = max(float(r["mu"]) for r in rows)

pin_dir = os.path.join(out, "pin")
prm = os.path.join(out, "pin.prm")
with open(os.path.join(source, "tests/contact/short_pin.prm")) as f:
    text = f.read()
with open(prm, "w") as f:
    f.write(text.replace("set Output directory = output",
                         "set Output directory = " + pin_dir)
            + "subsection Contact\n  set Friction law = tabulated\n"
            "  subsection Tabulated friction\n    set File = " + path
            + "\n    set Pressure scale = 300\n    set Speed scale = 3.75\n"
            "  end\nend\n")
subprocess.run([tribodyn, prm], check=True, env=env,
               stdout=subprocess.DEVNULL)
with open(os.path.join(pin_dir, "summary.json")) as f:
    s = json.load(f)
check(s["friction_law"] == "tabulated", "pin: friction_law = tabulated")
share = s.get("tabulated_clamped_fraction")
check(share is not None and 0 <= share <= 1 and s["tabulated_contact_node_steps"] > 0,
      "pin: share of the node-steps read outside the table reported (%s of %s)"
      % (share, s.get("tabulated_contact_node_steps")))
mu = s["mu_contact_mean"]
check(mu is not None and math.isfinite(mu) and 0 <= abs(mu) <= mu_max * (1 + 1e-9),
      "pin: contact mu %r within [0, largest mu of the table %r]"
      % (mu, mu_max))

# The identity at the table's corner.
p_min = min(float(r["pressure"]) for r in rows)
v_max = max(float(r["speed"]) for r in rows)
corner = [r["mu"] for r in rows
          if float(r["pressure"]) == p_min and float(r["speed"]) == v_max][0]
runs = {}
for name, law in (("corner", "  set Friction law = tabulated\n"
                   "  subsection Tabulated friction\n    set File = " + path
                   + "\n    set Pressure scale = 1e-300\n"
                   "    set Speed = plane speed\n"
                   "    set Speed scale = 1e300\n  end\n"),
                  ("coulomb", "  set Friction law = Coulomb\n"
                   "  set Friction coefficient = " + corner + "\n")):
    run_dir = os.path.join(out, name)
    run_prm = os.path.join(out, name + ".prm")
    with open(run_prm, "w") as f:
        f.write(text.replace("set Output directory = output",
                             "set Output directory = " + run_dir)
                + "subsection Contact\n" + law + "end\n")
    subprocess.run([tribodyn, run_prm], check=True, env=env,
                   stdout=subprocess.DEVNULL)
    runs[name] = {}
    for series in ("friction.csv", "point_M.csv", "contact_status.csv"):
        with open(os.path.join(run_dir, series)) as f:
            runs[name][series] = f.read()
same = [series for series in runs["corner"]
        if runs["corner"][series] == runs["coulomb"][series]]
check(len(same) == 3 and len(runs["corner"]["friction.csv"]) > 1000,
      "the table read at its corner (mu = %s) = Coulomb with that mu, bit "
      "for bit (%s identical)" % (corner, ", ".join(same) or "no series"))
sys.exit(1 if failures else 0)
