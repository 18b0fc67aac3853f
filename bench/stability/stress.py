#!/usr/bin/env python3
"""Stability stress cases of issue #10 run through the executable
(doc/stability.md). Each case is a base prm file of the repository plus
overrides; the script runs it with a timeout and prints one markdown table
row: case, exit code, wall time, and the first line of the outcome (the
message of a stopped run, or key figures of summary.json).

Usage: stress.py TRIBODYN [CASE ...]   (default: every case; --list)
The long cases (marked long) take minutes on a laptop core.
"""
import json
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))
SHORT_PIN = os.path.join(ROOT, "tests/contact/short_pin.prm")
MCA_SMALL = os.path.join(ROOT, "tests/mca/friction_small.prm")
BLOCK = """set Problem = mca
subsection Geometry
  set Automaton size = 7.5e-9
  set Domain lower   = -1e-8, -1e-8, -1e-8
  set Domain upper   = 5.3e-8, 5.3e-8, {top}
  set Bodies         = 0 0 0 4.24264069e-8 4.24264069e-8 4.24264069e-8 steel
end
subsection Interaction
  set Plasticity    = {plastic}
  set Bond breaking = {breaking}
end
subsection Boundary conditions
  set Groups = {groups}
  set Ramp time = {ramp}
end
subsection Time
  set End time = {end}
end
subsection Output
  set Series interval = {series}
  set Write particles = false
end
"""

CASES = {
    # contact (pin of tests/contact/short_pin.prm: 28 x 8 mm, h = 0.25 mm)
    "contact_contrast_1000": (SHORT_PIN, """
subsection Materials
  set Type = morphology
  subsection Matrix
    set Young modulus = 0.08e9
  end
  subsection Heterogeneity
    set Young modulus = 80e9
  end
end
subsection Morphology
  set Width = 28e-3
  set Height = 8e-3
  set Pixels in x = 112
  set Pixels in y = 32
  set Volume fraction = 0.1
  set Heterogeneity width = 0.25e-3
end
subsection Time
  set End time = 20e-6
end"""),
    "contact_nu_0.499": (SHORT_PIN, """
subsection Materials
  subsection Matrix
    set Poisson ratio = 0.499
  end
end
subsection Time
  set End time = 20e-6
end"""),
    "contact_P100MPa_V100": (SHORT_PIN, """
subsection Loading
  set Pressure = 100e6
  set Sliding velocity = -100
end
subsection Time
  set End time = 20e-6
end"""),
    # mca
    "mca_plate_0.9_cp": (None, BLOCK.format(
        top="5.3e-8", plastic="true", breaking="true", ramp="0",
        groups="top velocity -1 -1 3.8e-8 1 1 1 * * -5226; "
               "bottom fixed -1 -1 -1 1 1 4e-9",
        end="4e-12", series="2.5e-13")),
    "mca_leaving_box": (None, BLOCK.format(
        top="4.5e-8", plastic="false", breaking="false", ramp="0",
        groups="top velocity -1 -1 3.8e-8 1 1 1 * * 200; "
               "bottom fixed -1 -1 -1 1 1 4e-9",
        end="2e-10", series="1e-11")),
    "mca_bond_cascade": (None, BLOCK.format(
        top="2e-7", plastic="true", breaking="true", ramp="0",
        groups="top velocity -1 -1 3.8e-8 1 1 1 * * 1000; "
               "bottom fixed -1 -1 -1 1 1 4e-9",
        end="1e-10", series="1e-11")),
    "mca_courant_0.5": (MCA_SMALL, """
subsection Time
  set Courant factor = 0.5
end"""),
    # long: 10^5 steps (minutes)
    "mca_energy_drift_1e5": (os.path.join(ROOT, "bench/stability/"
                                          "mca_energy_drift.prm"), ""),
}


def energy_drift(series, release=3e-11):
    """Kinetic + elastic energy after the release: the trend (linear fit
    over the run, relative to the mean) and the fluctuation about it. The
    elastic energy of series.csv is estimated from the automata's stresses
    (V s:C^-1:s / 2), not the exact potential of the pair law, so the sum
    fluctuates even for an exact integrator; the trend is the drift."""
    import csv
    import statistics
    rows = [r for r in csv.DictReader(open(series))
            if float(r["time"]) >= release]
    t = [float(r["time"]) for r in rows]
    e = [float(r["kinetic_energy"]) + float(r["elastic_energy"])
         for r in rows]
    mt, me = statistics.mean(t), statistics.mean(e)
    slope = sum((x - mt) * (y - me) for x, y in zip(t, e)) / \
        sum((x - mt) ** 2 for x in t)
    return (f"energy after the release: mean {me:.4g} J, trend over the run "
            f"{slope * (t[-1] - t[0]) / me:.2e} of the mean (drift), "
            f"fluctuation {(max(e) - min(e)) / 2 / me:.2e} (estimate of the "
            f"elastic energy), {len(e)} samples")


def run(tribodyn, name, timeout=1800):
    base, text = CASES[name]
    work = os.path.join("/tmp/tribodyn-stress", name)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    prm = os.path.join(work, "case.prm")
    with open(prm, "w") as f:
        if base:
            f.write(f"include {base}\n")
        f.write(text + f"\nset Output directory = {work}/out\n"
                "set Progress interval = 1000\n")
    start = time.time()
    try:
        r = subprocess.run([tribodyn, prm], cwd=ROOT, capture_output=True,
                           text=True, timeout=timeout)
        code, err, out = r.returncode, r.stderr, r.stdout
    except subprocess.TimeoutExpired:
        code, err, out = "timeout", "", ""
    wall = time.time() - start
    summary = os.path.join(work, "out", "summary.json")
    if code == 0 and os.path.exists(summary):
        s = json.load(open(summary))
        keys = ["n_steps", "dt", "critical_dt", "mu_global_mean",
                "energy_balance_error", "n_bonded_pairs", "kinetic_energy",
                "n_dropped_bonds", "mean_friction_coefficient"]
        outcome = "completed: " + ", ".join(
            f"{k} {s[k]:.4g}" if isinstance(s[k], float) else f"{k} {s[k]}"
            for k in keys if k in s)
    else:
        outcome = " ".join(err.split())[:400]
    if name.startswith("mca_energy_drift") and code == 0:
        outcome += "; " + energy_drift(os.path.join(work, "out",
                                                    "series.csv"))
    print(f"| {name} | {code} | {wall:.1f} s | {outcome} |", flush=True)


def main():
    tribodyn = os.path.abspath(sys.argv[1])
    names = sys.argv[2:] or list(CASES)
    if names == ["--list"]:
        print("\n".join(CASES))
        return
    print("| case | exit | wall | outcome |\n|---|---|---|---|")
    for name in names:
        run(tribodyn, name)


if __name__ == "__main__":
    main()
