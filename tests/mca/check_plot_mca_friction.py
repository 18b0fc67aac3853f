#!/usr/bin/python3
"""Test of scripts/plot_mca_friction on synthetic run directories.

    check_plot_mca_friction.py PATH/TO/plot_mca_friction

The script runs through its own #! line (/usr/bin/python3, Debian's
matplotlib), as users run it. Writes 'steel' (mu = 0.40 +- 0.004) and
'composite' (mu = 0.38 +- 0.003) directories into a temporary folder, runs
the script on both and checks:
- exit code 0, mu.png and layer.png written (non-empty);
- each run's mu_steady +- stderr printed;
- the relative difference -5 % and its error bar
  0.95 * sqrt((0.003/0.38)^2 + (0.004/0.40)^2) = 1.2104 % printed, to the
  printed precision (1e-4 relative on the difference, 1e-2 on the error);
- when the composite reached no quasi-steady regime (summary.json:
  steady_state_found = false), no relative difference is printed but a
  line saying so and naming the run;
- a missing directory is refused with a non-zero exit and a message.
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile


def write_run(directory, mu, stderr, start, thickness, found=True):
    os.makedirs(directory)
    with open(os.path.join(directory, "friction.csv"), "w") as f:
        f.write("time,normal_force,tangential_force,mu,mu_smoothed,"
                "n_bonded,n_unbonded\n")
        for i in range(600):
            t = i * 1e-9
            m = mu + 0.2 * math.exp(-t / 80e-9) + 0.02 * math.sin(0.7 * i)
            s = mu + 0.2 * math.exp(-t / 80e-9)
            f.write("%g,%g,%g,%g,%g,%d,%d\n" % (t, 1e-4, m * 1e-4, m, s,
                                                 1000 - i, i))
    with open(os.path.join(directory, "layer.csv"), "w") as f:
        f.write("time,thickness,center\n")
        for i in range(0, 600, 10):
            t = i * 1e-9
            f.write("%g,%g,%g\n" % (t, thickness * (1 - math.exp(-t / 1e-7)),
                                    2e-9))
    with open(os.path.join(directory, "summary.json"), "w") as f:
        json.dump({"mu_steady": mu, "mu_steady_stderr": stderr,
                   "steady_state_found": found,
                   "steady_start_time": start,
                   "quasi_fluid_layer_thickness": thickness}, f)


def main():
    script = sys.argv[1]
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        steel = os.path.join(tmp, "steel")
        composite = os.path.join(tmp, "composite")
        write_run(steel, 0.40, 0.004, 350e-9, 12e-9)
        write_run(composite, 0.38, 0.003, 380e-9, 15e-9)
        out = os.path.join(tmp, "plots")
        p = subprocess.run([script, steel, composite,
                            "--out", out], capture_output=True, text=True)
        print(p.stdout + p.stderr)
        if p.returncode != 0:
            print("FAIL  exit code %d" % p.returncode)
            return 1
        for name in ("mu.png", "layer.png"):
            path = os.path.join(out, name)
            ok = os.path.exists(path) and os.path.getsize(path) > 1000
            print(("PASS" if ok else "FAIL") + "  " + name + " written")
            failures += not ok
        for label, value in (("steel", "0.4 +- 0.004"),
                             ("composite", "0.38 +- 0.003")):
            ok = ("%s: mu_steady = %s" % (label, value)) in p.stdout
            print(("PASS" if ok else "FAIL") + "  %s mu printed" % label)
            failures += not ok
        m = re.search(r"relative difference composite vs steel: "
                      r"([-+0-9.e]+) % \+- ([0-9.e]+) %", p.stdout)
        expected = (-5.0, 95 * math.hypot(0.003 / 0.38, 0.004 / 0.40))
        ok = (m is not None
              and abs(float(m.group(1)) - expected[0]) <= 1e-4 * 5
              and abs(float(m.group(2)) - expected[1]) <= 1e-2 * expected[1])
        print(("PASS" if ok else "FAIL")
              + "  relative difference %s %% +- %.4f %% printed"
              % (expected[0], expected[1]))
        failures += not ok

        drifting = os.path.join(tmp, "composite_drifting")
        write_run(drifting, 0.38, 0.003, 380e-9, 15e-9, found=False)
        r = subprocess.run([script, steel, drifting, "--reference", "steel",
                            "--compare", "composite_drifting", "--out", out],
                           capture_output=True, text=True)
        print(r.stdout + r.stderr)
        ok = (r.returncode == 0
              and not re.search(r"relative difference .*: [-+0-9.e]+ %",
                                r.stdout)
              and "no relative difference composite_drifting vs steel: "
              "composite_drifting reached no quasi-steady regime "
              "(summary.json: steady_state_found = false)" in r.stdout)
        print(("PASS" if ok else "FAIL") + "  no relative difference "
              "without a quasi-steady regime")
        failures += not ok

        q = subprocess.run([script,
                            os.path.join(tmp, "nowhere")],
                           capture_output=True, text=True)
        ok = q.returncode != 0 and "cannot read" in q.stderr
        print(("PASS" if ok else "FAIL") + "  missing directory refused: "
              + q.stderr.strip())
        failures += not ok
    print("All checks passed." if failures == 0
          else "%d check(s) failed." % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
