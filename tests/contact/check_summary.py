"""Check the outputs of a contact run (tests/contact/short_pin.prm).

summary.json has every documented key; the automatic time step is half the
critical one (Safety factor = 0.5, requested 1 us is above it); the CSV files
have their header and rows; the VTU fields and their .pvd index exist.
"""
import csv
import json
import os
import sys

out = os.path.join(sys.argv[1], "output")
with open(os.path.join(out, "summary.json")) as f:
    s = json.load(f)
failures = []


def check(condition, what):
    print(("PASS  " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


for key in ["mu_global_mean", "dominant_frequency_hz", "energy_balance_error",
            "stick_fraction", "slip_fraction", "separation_fraction", "n_dofs",
            "n_steps", "dt", "critical_dt", "wall_time_s", "dof_steps_per_second",
            "tribodyn_version", "n_mpi_ranks", "regime", "point_M"]:
    check(key in s, "summary.json has key " + key)
check(abs(s["dt"] - 0.5 * s["critical_dt"]) <= 1e-12 * s["dt"],
      "automatic dt = 0.5 x critical dt (%g, %g)" % (s["dt"], s["critical_dt"]))
check(s["n_dofs"] == 7458, "n_dofs = 7458 (112 x 32 Q1 cells)")
check(s["energy_balance_error"] < 1e-10, "energy balance error < 1e-10")
check(abs(s["stick_fraction"] + s["slip_fraction"] + s["separation_fraction"] - 1)
      < 1e-12, "status fractions sum to 1")
for name, column in [("friction.csv", "mu_global"), ("point_M.csv", "status"),
                     ("contact_status.csv", "slip_fraction"),
                     ("spectrum.csv", "amplitude")]:
    with open(os.path.join(out, name)) as f:
        rows = list(csv.DictReader(f))
    check(len(rows) > 2 and column in rows[0], name + " has rows and column " + column)
for name in ["fields.pvd", "fields_00000.vtu", "fields_00001.vtu", "parameters.prm"]:
    check(os.path.exists(os.path.join(out, name)), name + " exists")
sys.exit(1 if failures else 0)
