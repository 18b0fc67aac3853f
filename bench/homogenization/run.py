#!/usr/bin/env python3
"""Benchmarks and studies of the homogenization problem (not run by ctest).

  bench/homogenization/run.py scaling      [--tribodyn build/tribodyn]
                                           [--old OLD --old-lib DIR --repeats N]
      wall time of a ~1.1e6-DoF cell problem (KUBC + SUBC, 3 load cases
      each = 6 solves) on 1 and 2 MPI ranks. With --old (an older
      tribodyn binary; --old-lib the directory of its libtribodyn.so) the
      two binaries alternate N times per rank count and the ratio of the
      mean wall times is printed (a speed claim taken in one run).
  bench/homogenization/run.py large        [--ranks 2]
      a 2000 x 2000-pixel three-phase micrograph (written to
      bench-output/homogenization/large.png; fibres, matrix, pores),
      homogenized with KUBC + SUBC: 8.0e6 DoFs; wall time, CG iterations
      and the peak resident memory of each rank, per DoF.
  bench/homogenization/run.py convergence
      E_L, E_T, G_LT (KUBC and SUBC) of the default morphology as the mesh is
      refined (h = 0.1, 0.05, 0.025, 0.0125 mm); error against the Richardson
      extrapolation of the three finest meshes, with the run time of each.
  bench/homogenization/run.py volume       [--sizes 16 32 64 128] [--ranks 2]
                                           [--preconditioner multigrid|AMG]
                                           [--conditions "KUBC, SUBC, periodic"]
                                           [--contrasts 10 0.1 ...]
      bench/homogenization/volume_128.prm (random glass spheres in epoxy)
      at n^3 voxels for each n of --sizes: DoFs, wall time, CG iterations
      per condition, memory_bytes_per_dof (the ranks' peak RSS over the
      DoFs), time per DoF and iteration, and the load (uptime) when it ran.
      --contrasts: for each value c, the matrix's Young modulus set to 1
      GPa and the spheres' to c GPa (the prm's glass in epoxy: c = 23.3),
      c < 1 for soft inclusions: the iteration counts against contrast.
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


def run(tribodyn, name, overrides, ranks=1, lib=None, base_prm=DEFAULT_PRM,
        memory=False):
    """Run @p base_prm with @p overrides (list of prm lines) appended; with
    @p memory, each rank runs under /usr/bin/time and the summary gets
    "peak_rss_kb" (one value per rank)."""
    directory = os.path.join(OUT, name)
    os.makedirs(directory, exist_ok=True)
    prm = os.path.join(directory, "run.prm")
    with open(base_prm) as f:
        text = f.read()
    text += "\n# overrides\nset Output directory = %s\n" % directory
    text += "\n".join(overrides) + "\n"
    with open(prm, "w") as f:
        f.write(text)
    env = dict(ENV)
    if lib:
        env["LD_LIBRARY_PATH"] = lib
    rank_command = [tribodyn, prm]
    if memory:
        rank_command = ["/usr/bin/time", "-f", "peak_rss_kb %M", "-a", "-o",
                        directory + "_memory.txt"] + rank_command
        if os.path.exists(directory + "_memory.txt"):
            os.remove(directory + "_memory.txt")
    command = (rank_command if ranks == 1 else
               ["mpirun", "-np", str(ranks)] + (["-x", "LD_LIBRARY_PATH"] if lib else [])
               + rank_command)
    start = time.time()
    log = subprocess.run(command, env=env, capture_output=True, text=True)
    elapsed = time.time() - start
    if log.returncode != 0:
        sys.exit("run %s failed:\n%s\n%s" % (name, log.stdout, log.stderr))
    with open(os.path.join(directory, "summary.json")) as f:
        summary = json.load(f)
    if memory:
        with open(directory + "_memory.txt") as f:
            summary["peak_rss_kb"] = [int(line.split()[1]) for line in f
                                      if line.startswith("peak_rss_kb")]
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
        lines += ["subsection Morphology", "  set Seed = %d" % seed, "end"]
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
    if args.old:
        return scaling_alternating(args)
    print("| ranks | DoFs | wall time (s) | AMG setup (s) | CG solves (s) | CG iterations (KUBC; SUBC) |")
    print("|---|---|---|---|---|---|")
    for ranks in [1, 2]:
        s, elapsed, stdout = run(args.tribodyn, "scaling_%d" % ranks, cell(subdivisions=5), ranks)
        t = timer_sections(stdout)
        print("| %d | %d | %.1f | %.1f | %.1f | %s; %s |" % (
            ranks, s["n_dofs"], s["wall_time_s"], t.get("AMG setup", float("nan")),
            t.get("CG solve", float("nan")), s["KUBC"]["cg_iterations"], s["SUBC"]["cg_iterations"]))


def scaling_alternating(args):
    """Old and new binaries alternating on the scaling problem."""
    print("uptime before: " + open("/proc/loadavg").read().split()[0])
    print("| ranks | binary | wall times (s) | mean (s) | CG iterations (KUBC; SUBC) |")
    print("|---|---|---|---|---|")
    for ranks in [1, 2]:
        walls = {"old": [], "new": []}
        iterations = {}
        for _ in range(args.repeats):
            for which, binary, lib in (("old", args.old, args.old_lib),
                                       ("new", args.tribodyn, None)):
                s, elapsed, _ = run(binary, "scaling_%s_%d" % (which, ranks),
                                    cell(subdivisions=5), ranks, lib)
                walls[which].append(elapsed)
                iterations[which] = "%s; %s" % (s["KUBC"]["cg_iterations"],
                                                s["SUBC"]["cg_iterations"])
        for which in ("old", "new"):
            w = walls[which]
            print("| %d | %s | %s | %.1f | %s |" % (
                ranks, which, ", ".join("%.1f" % x for x in w), sum(w) / len(w),
                iterations[which]))
        print("| %d | ratio old/new | | **%.2f** | |" % (
            ranks, (sum(walls["old"]) / len(walls["old"]))
            / (sum(walls["new"]) / len(walls["new"]))))
    print("uptime after: " + open("/proc/loadavg").read().split()[0])


def large_micrograph(path, size=2000, seed=4):
    """A size x size three-phase micrograph: fibre sections (radius 6 px),
    pores (radius 2-3 px) and matrix, grey levels 200 / 35 / 120 with noise
    (the example micrograph's recipe, placed on a grid of jittered sites so
    that it takes seconds for 4e6 pixels)."""
    import importlib.machinery
    import importlib.util
    import random
    loader = importlib.machinery.SourceFileLoader(
        "make_synthetic_images", os.path.join(ROOT, "scripts", "make_synthetic_images"))
    spec = importlib.util.spec_from_loader(loader.name, loader)
    images = importlib.util.module_from_spec(spec)
    loader.exec_module(images)
    rng = random.Random(seed)
    phase = [bytearray([1]) * size for _ in range(size)]
    spacing = 20
    for cy in range(spacing // 2, size, spacing):
        for cx in range(spacing // 2, size, spacing):
            kind = 2 if rng.random() < 0.6 else (0 if rng.random() < 0.3 else 1)
            if kind == 1:
                continue
            r = 6.0 if kind == 2 else rng.uniform(2.0, 3.0)
            x = cx + rng.uniform(-3, 3)
            y = cy + rng.uniform(-3, 3)
            for j in range(max(0, int(y - r)), min(size, int(y + r) + 1)):
                for i in range(max(0, int(x - r)), min(size, int(x + r) + 1)):
                    if math.hypot(i + 0.5 - x, j + 0.5 - y) < r:
                        phase[j][i] = kind
    levels = [35, 120, 200]
    grey = [[max(0, min(255, levels[p] + int(rng.gauss(0, 8)))) for p in row]
            for row in phase]
    images.write(path, images.png_bytes(size, size, grey, pixels_per_metre=10 ** 6))


def large(args):
    path = os.path.join(OUT, "large.png")
    os.makedirs(OUT, exist_ok=True)
    if not os.path.exists(path):
        large_micrograph(path)
    micrograph_prm = os.path.join(ROOT, "prm", "homogenization", "micrograph.prm")
    overrides = ["subsection Morphology", "  subsection Image",
                 "    set File = " + path, "  end", "end"] + cell()
    s, elapsed, stdout = run(args.tribodyn, "large", overrides, args.ranks,
                             base_prm=micrograph_prm, memory=True)
    rss = s["peak_rss_kb"]
    print("| pixels | DoFs | ranks | wall time (s) | CG iterations (KUBC; SUBC) | peak RSS per rank (GB) | memory per DoF (B) | time per DoF (us) |")
    print("|---|---|---|---|---|---|---|---|")
    print("| 2000 x 2000 | %d | %d | %.1f | %s; %s | %s | %.0f | %.2f |" % (
        s["n_dofs"], args.ranks, elapsed, s["KUBC"]["cg_iterations"],
        s["SUBC"]["cg_iterations"], ", ".join("%.2f" % (r / 1e6) for r in rss),
        sum(rss) * 1024.0 / s["n_dofs"], 1e6 * elapsed / s["n_dofs"]))
    print(stdout[stdout.find("+---"):])


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


VOLUME_PRM = os.path.join(ROOT, "bench", "homogenization", "volume_128.prm")


def volume(args):
    contrasts = args.contrasts or [None]
    print("| voxels | " + ("contrast | " if args.contrasts else "")
          + "DoFs | ranks | preconditioner | grid | wall time (s) | "
          + " | ".join("%s: iterations, time (s)" % bc
                       for bc in args.conditions.split(", "))
          + " | B per DoF | core-ns per DoF and iteration | load |")
    print("|---" * (9 + bool(args.contrasts) + len(args.conditions.split(", ")))
          + "|")
    for n, contrast in [(n, c) for n in args.sizes for c in contrasts]:
        overrides = ["subsection Morphology"]
        overrides += ["  set Voxels in %s = %d" % (axis, n) for axis in "xyz"]
        overrides += ["end", "subsection Cell problem",
                      "  set Boundary conditions = " + args.conditions,
                      "  set Preconditioner = " + args.preconditioner,
                      "  set Grid = " + args.grid, "end"]
        name = "volume_%d" % n
        if contrast is not None:
            overrides += ["subsection Materials", "  subsection Matrix",
                          "    set Young modulus = 1e9", "  end",
                          "  subsection Heterogeneity",
                          "    set Young modulus = %r" % (contrast * 1e9),
                          "  end", "end"]
            name += "_contrast_%g" % contrast
        with open("/proc/loadavg") as f:
            load = f.read().split()[0]
        s, elapsed, stdout = run(args.tribodyn, name, overrides,
                                 args.ranks, base_prm=VOLUME_PRM)
        cells, solve_time, iterations = [], 0.0, 0
        for bc in args.conditions.split(", "):
            r = s[bc]
            its = r["cg_iterations"]
            cells.append("%s, %.1f" % ("%d-%d" % (min(its), max(its))
                                       if min(its) != max(its) else str(its[0]),
                                       r["wall_time_s"]))
            solve_time += r["wall_time_s"]
            iterations += sum(its)
        print("| %d³ | %s%d | %d | %s | %s | %.1f | %s | %.0f | %.0f | %s |" % (
            n, "" if contrast is None else "%g | " % contrast, s["n_dofs"], s["n_mpi_ranks"], args.preconditioner,
            s.get("grid", "mesh"), elapsed,
            " | ".join(cells), s["memory_bytes_per_dof"],
            1e9 * solve_time / (s["n_dofs"] * max(iterations, 1)) * s["n_mpi_ranks"],
            load), flush=True)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("study", choices=["scaling", "convergence", "morphologies", "large",
                                          "volume"])
    parser.add_argument("--old", help="older tribodyn binary to alternate with (scaling)")
    parser.add_argument("--old-lib", help="directory of the older binary's libtribodyn.so")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--tribodyn", default=os.path.join(ROOT, "build", "tribodyn"))
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--sizes", type=int, nargs="+", default=[16, 32, 64, 128])
    parser.add_argument("--preconditioner", default="multigrid")
    parser.add_argument("--grid", default="auto",
                        help="Cell problem/Grid of the volume study: auto, mesh or 'voxel grid'")
    parser.add_argument("--conditions", default="KUBC, SUBC, periodic")
    parser.add_argument("--contrasts", type=float, nargs="+", default=[])
    args = parser.parse_args()
    {"scaling": scaling, "convergence": convergence, "morphologies": morphologies,
     "large": large, "volume": volume}[args.study](args)
