#!/usr/bin/env python3
"""Run time against error of the friction scene (issue #8 item 5): the
steel scene of prm/mca/friction_steel.prm at several automaton sizes and
Courant factors, with its steady friction coefficient, quasi-fluid layer
thickness and wall time.

usage: friction_convergence.py --tribodyn build/tribodyn [--ranks 2]
           [--sizes 15e-9,10e-9,7.5e-9] [--courant 0.35,0.2]
           [--courant-size 10e-9] [--end-time T] [--work DIR] [--skip-runs]
           [--reuse-finished]

The physical scene is the same at every size: the box (16 FCC cells of
a = d sqrt 2 at d = 7.5 nm, 169.7 nm) and the bodies' height (127.3 nm) are
whole numbers of FCC cells at d = 7.5, 10 and 15 nm (16, 12 and 8 cells
across; 12, 9 and 6 high), the rough surface (amplitude, wavelength, seed),
the materials, the loading protocol (pressure, velocities, ramps) and the
analysis windows are unchanged. What changes with d: the number of automata
(~ d^-3), the time step (~ d), the loading layers (2 automaton layers, so
their thickness ~ d; their damping follows the seed's criterion for that
thickness) and the room below the bodies (2 cells).

Each size runs at the prm's Courant factor; the size given by
--courant-size also runs at the other Courant factors (time-step error).
Printed: a table of d, automata, steps, wall time (s), mu_steady +-
standard error, steady start, layer thickness, and the difference of mu
from the finest run in units of the combined standard error. Written:
WORK/convergence.csv and WORK/convergence.md.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BASE_PRM = os.path.join(ROOT, "prm", "mca", "friction_steel.prm")
BASE_D = 7.5e-9
BOX = 16 * BASE_D * math.sqrt(2)         # periodic width (m)
BODIES_HEIGHT = 12 * BASE_D * math.sqrt(2)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")


def overrides(entries):
    """Parameter-file lines setting ENTRIES ('Subsection/Name' -> value);
    appended after the base file, they replace its values (deal.II's
    ParameterHandler keeps the last 'set' of an entry): nothing is edited."""
    lines = []
    for path, value in entries.items():
        *sections, name = path.split("/")
        lines += ["subsection %s" % s for s in sections]
        lines.append("set %s = %s" % (name, value))
        lines += ["end"] * len(sections)
    return "\n# convergence case (bench/mca/friction_convergence.py)\n" \
        + "\n".join(lines) + "\n"


def make_prm(d, courant, end_time, out_dir):
    a = d * math.sqrt(2)
    for length, what in ((BOX, "box width"), (BODIES_HEIGHT, "bodies' height")):
        cells = length / a
        if abs(cells - round(cells)) > 1e-6:
            sys.exit("friction_convergence: d = %g m: the %s is %.4g FCC cells, "
                     "not a whole number; use d = 7.5e-9 * 16 / k for a k that "
                     "divides 16 and 12 (7.5, 10, 15 nm)" % (d, what, cells))
    entries = {"Output directory": out_dir,
               "Geometry/Automaton size": repr(d),
               "Geometry/Domain lower": "0, 0, %r" % (-2 * a),
               "Time/Courant factor": repr(courant),
               "Output/Write particles": "false",
               "Output/Cross section": "false"}
    if end_time is not None:
        entries["Time/End time"] = repr(end_time)
    return open(BASE_PRM).read() + overrides(entries)


def in_nm(value):
    """A length or time of summary.json in nm or ns (NaN when null)."""
    return float("nan") if value is None else value * 1e9


def run_case(args, d, courant):
    name = "d%.3gnm_c%.3g" % (d * 1e9, courant)
    out = os.path.join(args.work, "out_" + name)
    prm = os.path.join(args.work, name + ".prm")
    text = make_prm(d, courant, args.end_time, out)
    finished = os.path.exists(os.path.join(out, "summary.json")) and \
        os.path.exists(prm) and open(prm).read() == text
    if args.reuse_finished and finished:
        print("reusing the finished run %s" % out, flush=True)
    elif not args.skip_runs:
        with open(prm, "w") as f:
            f.write(text)
        # an interrupted run must not look finished to --reuse-finished
        if os.path.exists(os.path.join(out, "summary.json")):
            os.remove(os.path.join(out, "summary.json"))
        command = ([] if args.ranks == 1 else ["mpirun", "-np", str(args.ranks)]) \
            + [args.tribodyn, prm]
        print("running %s ..." % " ".join(command), flush=True)
        start = time.time()
        with open(os.path.join(args.work, name + ".log"), "w") as log:
            code = subprocess.call(command, cwd=args.work, env=env, stdout=log,
                                   stderr=subprocess.STDOUT)
        if code != 0:
            sys.exit("friction_convergence: %s failed (exit %d), see %s.log"
                     % (name, code, os.path.join(args.work, name)))
        print("  %.0f s" % (time.time() - start), flush=True)
    s = json.load(open(os.path.join(out, "summary.json")))
    return {"d_nm": d * 1e9, "courant": courant, "n_automata": s["n_automata"],
            "n_steps": s["n_steps"], "wall_time_s": s["wall_time_s"],
            "mu_steady": s["mu_steady"], "mu_steady_stderr": s["mu_steady_stderr"],
            "steady_start_time_ns": in_nm(s.get("steady_start_time")),
            "layer_thickness_nm": in_nm(s.get("quasi_fluid_layer_thickness"))}


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tribodyn", default=os.path.join(ROOT, "build", "tribodyn"))
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--sizes", default="15e-9,10e-9,7.5e-9")
    parser.add_argument("--courant", default="0.35,0.2")
    parser.add_argument("--courant-size", type=float, default=10e-9)
    parser.add_argument("--end-time", type=float, default=None)
    parser.add_argument("--work", default="bench-mca-work/friction_convergence")
    parser.add_argument("--skip-runs", action="store_true",
                        help="only tabulate the summaries of earlier runs")
    parser.add_argument("--reuse-finished", action="store_true",
                        help="do not rerun a case whose work directory holds "
                             "a finished run (summary.json) of the same prm")
    args = parser.parse_args()
    args.work = os.path.abspath(args.work)
    args.tribodyn = os.path.abspath(args.tribodyn)
    os.makedirs(args.work, exist_ok=True)
    sizes = [float(x) for x in args.sizes.split(",")]
    courants = [float(x) for x in args.courant.split(",")]
    cases = [(d, courants[0]) for d in sizes]
    cases += [(args.courant_size, c) for c in courants[1:]]
    rows = [run_case(args, d, c) for d, c in cases]

    finest = min(rows[:len(sizes)], key=lambda r: r["d_nm"])
    for r in rows:
        combined = math.hypot(r["mu_steady_stderr"], finest["mu_steady_stderr"])
        r["mu_difference"] = r["mu_steady"] - finest["mu_steady"]
        r["difference_in_stderr"] = r["mu_difference"] / combined if combined > 0 else float("nan")
    keys = list(rows[0].keys())
    with open(os.path.join(args.work, "convergence.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=keys)
        writer.writeheader()
        writer.writerows(rows)
    lines = ["| d (nm) | Courant | automata | steps | wall (s) | mu_steady | steady from (ns) "
             "| layer (nm) | mu - mu_finest (in stderr) |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %.3g | %.3g | %d | %d | %.0f | %.3f ± %.3f | %.2f | %.1f | %+.3f (%+.1f) |"
                     % (r["d_nm"], r["courant"], r["n_automata"], r["n_steps"],
                        r["wall_time_s"], r["mu_steady"], r["mu_steady_stderr"],
                        r["steady_start_time_ns"], r["layer_thickness_nm"],
                        r["mu_difference"], r["difference_in_stderr"]))
    table = "\n".join(lines)
    open(os.path.join(args.work, "convergence.md"), "w").write(table + "\n")
    print(table)


if __name__ == "__main__":
    main()
