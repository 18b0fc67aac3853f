#!/usr/bin/env python3
"""Benchmarks and studies of the homogenization problem (not run by ctest).

  bench/homogenization/run.py scaling      [--tribodyn build/tribodyn]
      wall time of a ~1.1e6-DoF cell problem (KUBC + SUBC, 3 load cases
      each = 6 solves) on 1 and 2 MPI ranks.
  bench/homogenization/run.py convergence
      E_L, E_T, G_LT (KUBC and SUBC) of the default morphology as the mesh is
      refined (h = 0.1, 0.05, 0.025, 0.0125 mm); error against the Richardson
      extrapolation of the three finest meshes, with the run time of each.
  bench/homogenization/run.py morphologies
      the five constants of the six random morphologies (seeds 1-6) against
      the seed's Table 1.

Each prints a Markdown table (copied into doc/performance.md or
doc/homogenization_morphologies.md). Runs go to bench-output/homogenization/.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
DEFAULT_PRM = os.path.join(ROOT, "prm", "homogenization", "default.prm")
OUT = os.path.join(ROOT, "bench-output", "homogenization")
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")


def run(tribodyn, name, overrides, ranks=1):
    """Run the default prm with @p overrides (list of prm lines) appended."""
    directory = os.path.join(OUT, name)
    os.makedirs(directory, exist_ok=True)
    prm = os.path.join(directory, "run.prm")
    with open(DEFAULT_PRM) as f:
        text = f.read()
    text += "\n# overrides\nset Output directory = %s\n" % directory
    text += "\n".join(overrides) + "\n"
    with open(prm, "w") as f:
        f.write(text)
    command = ([tribodyn, prm] if ranks == 1 else
               ["mpirun", "-np", str(ranks), tribodyn, prm])
    start = time.time()
    log = subprocess.run(command, env=ENV, capture_output=True, text=True)
    elapsed = time.time() - start
    if log.returncode != 0:
        sys.exit("run %s failed:\n%s\n%s" % (name, log.stdout, log.stderr))
    with open(os.path.join(directory, "summary.json")) as f:
        summary = json.load(f)
    return summary, elapsed, log.stdout


def cell(bcs="KUBC, SUBC", subdivisions=1, refinements=0, fields="false", seed=None):
    lines = ["subsection Cell problem",
             "  set Boundary conditions = " + bcs,
             "  set Subdivisions per pixel = %d" % subdivisions,
             "  set Global refinements = %d" % refinements,
             "end",
             "subsection Output",
             "  set Write fields = " + fields,
             "  set Write morphology = false",
             "end"]
    if seed is not None:
        lines += ["subsection Morphology", "  set Random seed = %d" % seed, "end"]
    return lines


def timer_sections(stdout):
    """Wall times of the TimerOutput sections printed by tribodyn."""
    sections = {}
    for line in stdout.splitlines():
        parts = [p.strip() for p in line.split("|")]
        if len(parts) >= 5 and parts[1] and parts[3].endswith("s"):
            try:
                sections[parts[1]] = float(parts[3][:-1])
            except ValueError:
                pass
    return sections


def scaling(args):
    print("| ranks | DoFs | wall time (s) | AMG setup (s) | CG solves (s) | CG iterations (KUBC; SUBC) |")
    print("|---|---|---|---|---|---|")
    for ranks in [1, 2]:
        s, elapsed, stdout = run(args.tribodyn, "scaling_%d" % ranks, cell(subdivisions=5), ranks)
        t = timer_sections(stdout)
        print("| %d | %d | %.1f | %.1f | %.1f | %s; %s |" % (
            ranks, s["n_dofs"], s["wall_time_s"], t.get("AMG setup", float("nan")),
            t.get("CG solve", float("nan")), s["KUBC"]["cg_iterations"], s["SUBC"]["cg_iterations"]))


def convergence(args):
    levels = [1, 2, 4, 8]
    results = []
    for n in levels:
        s, elapsed, _ = run(args.tribodyn, "convergence_%d" % n, cell(subdivisions=n), args.ranks)
        results.append((0.1 / n, s, s["wall_time_s"]))
    print("Richardson extrapolation from the three finest meshes (observed order p):\n")
    keys = [(bc, k) for bc in ["KUBC", "SUBC"] for k in ["E_L", "E_T", "G_LT"]]
    extrapolated = {}
    for bc, k in keys:
        a, b, c = (r[1][bc][k] for r in results[-3:])
        ratio = (a - b) / (b - c) if b != c else float("inf")
        p = math.log(ratio, 2) if ratio > 0 else float("nan")
        ext = c + (c - b) / (2 ** p - 1) if p == p and p > 0 else c
        extrapolated[(bc, k)] = ext
        print("- %s %s: p = %.2f, extrapolated %.4f GPa" % (bc, k, p, ext / 1e9))
    print("\n| h (mm) | DoFs | wall time (s) | " +
          " | ".join("%s %s rel. error" % key for key in keys) + " |")
    print("|---|---|---|" + "---|" * len(keys))
    for h, s, wall in results:
        errors = ["%.2e" % abs(s[bc][k] / extrapolated[(bc, k)] - 1) for bc, k in keys]
        print("| %.4f | %d | %.1f | %s |" % (h, s["n_dofs"], wall, " | ".join(errors)))


def morphologies(args):
    print("| seed | fraction | KUBC E_L | KUBC E_T | KUBC G_LT | SUBC E_L | SUBC E_T | SUBC G_LT | nu_LT | nu_TT |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    sums = {}
    for seed in range(1, 7):
        s, _, _ = run(args.tribodyn, "morphology_%d" % seed,
                      cell(refinements=1, seed=seed), args.ranks)
        row = [s["KUBC"]["E_L"], s["KUBC"]["E_T"], s["KUBC"]["G_LT"],
               s["SUBC"]["E_L"], s["SUBC"]["E_T"], s["SUBC"]["G_LT"]]
        for i, v in enumerate(row):
            sums.setdefault(i, []).append(v)
        print("| %d | %.4f | %s | %.3f | %.3f |" % (
            seed, s["volume_fraction"], " | ".join("%.2f" % (v / 1e9) for v in row),
            s["KUBC"]["nu_LT"], s["KUBC"]["nu_TT"]))
    means = [sum(v) / len(v) for _, v in sorted(sums.items())]
    print("| mean | | %s | | |" % " | ".join("%.2f" % (v / 1e9) for v in means))
    print("| seed 001 Table 1 | 0.10 | 31.9 | 34 | 13.3 | | | | 0.2 | 0.2 |")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("study", choices=["scaling", "convergence", "morphologies"])
    parser.add_argument("--tribodyn", default=os.path.join(ROOT, "build", "tribodyn"))
    parser.add_argument("--ranks", type=int, default=2)
    args = parser.parse_args()
    {"scaling": scaling, "convergence": convergence, "morphologies": morphologies}[args.study](args)
