#!/usr/bin/env python3
"""MCA benchmark (issue #7): tribodyn's automaton-steps per second per core
against LAMMPS's granular FCC benchmark, side by side in one run, and the
memory per automaton.

usage: compare.py --tribodyn build/tribodyn [--steps 300] [--ranks 1,2]
                  [--memory] [--large] [--friction] [--repeat N] [--work DIR]

Rates: an elastic bonded FCC block of 29 x 29 x 30 cells (100,920 automata
of d = 1 mm, periodic in x and y; make_block.py), time-step loop only
(summary.json). LAMMPS (Debian package 'lammps', command lmp): the same FCC
lattice of 100,920 spheres of diameter 1.001 d (12 contacts per sphere),
pair_style gran/hooke/history, fix nve/sphere, the same time step and number
of steps; its 'Loop time'. With 2 in --ranks, LAMMPS also runs on 2
processes (per process: the reference of the per-rank criterion), and two
independent one-rank runs of the block run at once: what each core delivers
when both are busy (shared caches, memory bandwidth), the ceiling of a
two-rank run on this machine. The ratios tribodyn / LAMMPS are printed, on 1
rank and per rank on 2, with their per-round ranges. Both codes run one after
the other on the same machine, so they see the same load; check that the
machine is idle (uptime) before quoting figures.

--large: the 10^6 block (63^3 cells, 1,000,188 automata, 40 steps) on 1 and
2 ranks, for the parallel efficiency at size. --friction: the friction scene
of the examples (plasticity, bonds, contacts). --repeat N: N alternating runs
of each rate, medians reported (a shared virtual machine drifts by 10-30 %).

--memory: peak resident set size of a ~2.56e5-automaton block (40 x 40 x 40
cells) minus that of a tiny one (4 x 4 x 4), per automaton, on one rank,
and on two ranks per owned automaton.
"""
import argparse
import json
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")


def peak_rss_kb(command, cwd):
    """Run command; return the peak RSS (KB) of its largest process."""
    wrapped = ["/usr/bin/time", "-f", "%M"] + command if os.path.exists("/usr/bin/time") else command
    run = subprocess.run(wrapped, cwd=cwd, env=env, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(command), run.stderr[-2000:]))
    if wrapped is command:
        return resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    return int(run.stderr.strip().splitlines()[-1])


def tribodyn_block(args, cells_xy, cells_z, steps, ranks, name):
    prm = os.path.join(args.work, name + ".prm")
    with open(prm, "w") as f:
        subprocess.run([sys.executable, os.path.join(here, "make_block.py"), str(cells_xy),
                        str(cells_z), "elastic", str(steps), "out_" + name], stdout=f, check=True)
    command = ([] if ranks == 1 else ["mpirun", "-np", str(ranks)]) + [args.tribodyn, prm]
    rss = peak_rss_kb(command, args.work)
    summary = json.load(open(os.path.join(args.work, "out_" + name, "summary.json")))
    return summary, rss


def tribodyn_concurrent_pair(args, cells_xy, cells_z, steps, name):
    """Two independent one-rank runs of the same block at the same time:
    the rate each gets when both cores are busy and share the caches and
    memory bandwidth, but nothing is exchanged. The ceiling of a two-rank
    run's efficiency on this machine."""
    processes, outs = [], []
    for copy in (0, 1):
        prm = os.path.join(args.work, "%s_%d.prm" % (name, copy))
        out = "out_%s_%d" % (name, copy)
        with open(prm, "w") as f:
            subprocess.run([sys.executable, os.path.join(here, "make_block.py"), str(cells_xy),
                            str(cells_z), "elastic", str(steps), out], stdout=f, check=True)
        processes.append(subprocess.Popen([args.tribodyn, prm], cwd=args.work, env=env,
                                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                          text=True))
        outs.append(out)
    for process in processes:
        _, err = process.communicate()
        if process.returncode != 0:
            sys.exit("failed: concurrent run\n" + err[-2000:])
    rates = [json.load(open(os.path.join(args.work, out, "summary.json")))
             ["automaton_steps_per_second_per_rank"] for out in outs]
    return sum(rates) / len(rates)


def spread(values):
    """' (min .. max of n runs)' when there are several runs."""
    if len(values) < 2:
        return ""
    return " (%.3e .. %.3e over %d runs)" % (min(values), max(values), len(values))


def round_ratios(ours, theirs):
    """' (per round: median, min .. max)' of the ratios of runs made in the
    same round (alternating), when there are several rounds."""
    ratios = [a / b for a, b in zip(ours, theirs)]
    if len(ratios) < 2:
        return ""
    return " (per round: median %.2f, %.2f .. %.2f)" % (statistics.median(ratios), min(ratios),
                                                         max(ratios))


def print_efficiency(block, medians, runs):
    """The two-rank efficiency of a block against one rank and against two
    independent one-rank runs at once (medians, and the runs' ranges)."""
    print("tribodyn  two independent 1-rank runs at once: %.3e automaton-steps/s each%s"
          % (medians["pair"], spread(runs["pair"])))
    print("tribodyn  1 -> 2 ranks parallel efficiency (%s block): %.0f %% (target >= 90); "
          "two concurrent 1-rank runs reach %.0f %% of one alone (the machine's shared "
          "caches and memory), so the decomposition's own efficiency is %.0f %%"
          % (block, 100 * medians[2] / medians[1], 100 * medians["pair"] / medians[1],
             100 * medians[2] / medians["pair"]))


def tribodyn_friction_scene(args):
    """The friction scene of the examples, its output redirected to the work dir."""
    source = os.path.join(here, "..", "..", "prm", "mca", "two_body_friction.prm")
    prm = os.path.join(args.work, "friction_scene.prm")
    out = os.path.join(args.work, "out_friction_scene")
    with open(source) as f, open(prm, "w") as g:
        for line in f:
            if re.match(r"\s*set Output directory\s*=", line):
                line = "  set Output directory = %s\n" % out
            g.write(line)
    run = subprocess.run([args.tribodyn, prm], cwd=args.work, env=env, capture_output=True,
                         text=True)
    if run.returncode != 0:
        sys.exit("failed: friction scene\n" + run.stderr[-2000:])
    return json.load(open(os.path.join(out, "summary.json")))


def lammps_rate(args, steps, procs=1):
    """LAMMPS's atom-steps per second per process on `procs` processes."""
    lmp = shutil.which("lmp") or shutil.which("lmp_serial")
    if not lmp:
        return None
    d = 1e-3
    c_p = 5810.6
    dt = 0.2 * d / c_p
    script = f"""units si
atom_style sphere
boundary p p p
comm_modify vel yes
lattice fcc {d * 2 ** 0.5!r}
region box block 0 29 0 29 0 30
create_box 1 box
create_atoms 1 box
set type 1 diameter {1.001 * d!r}
set type 1 density 7800
pair_style gran/hooke/history 2.0e6 NULL 0.0 NULL 0.5 1
pair_coeff * *
neighbor {0.2 * d!r} bin
neigh_modify delay 0
velocity all create 1e-9 4928459 loop geom
fix 1 all nve/sphere
timestep {dt!r}
thermo {steps}
run {steps}
"""
    path = os.path.join(args.work, "lammps_fcc.in")
    with open(path, "w") as f:
        f.write(script)
    command = ([] if procs == 1 else ["mpirun", "-np", str(procs)]) + [lmp, "-in", path,
                                                                       "-log", "none"]
    run = subprocess.run(command, cwd=args.work, env=env, capture_output=True, text=True)
    m = re.search(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms",
                  run.stdout)
    if not m:
        sys.exit("LAMMPS did not run:\n" + run.stdout[-2000:] + run.stderr[-2000:])
    seconds, ran_on, n_steps, atoms = float(m[1]), int(m[2]), int(m[3]), int(m[4])
    if ran_on != procs:
        # (a LAMMPS built without MPI runs mpirun's copies each on its own)
        print("LAMMPS    ran on %d process(es) where %d were asked (not built with MPI?): "
              "no %d-process figure" % (ran_on, procs, procs))
        return None
    return atoms * n_steps / seconds / procs


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tribodyn", required=True)
    parser.add_argument("--steps", type=int, default=300)
    parser.add_argument("--ranks", default="1,2")
    parser.add_argument("--memory", action="store_true")
    parser.add_argument("--work", default="bench-mca-work")
    parser.add_argument("--repeat", type=int, default=1,
                        help="runs of each rate (alternating); medians reported")
    parser.add_argument("--large", action="store_true",
                        help="also the 10^6 block (63 x 63 x 63 cells, 40 steps) on 1 and 2 ranks")
    parser.add_argument("--friction", action="store_true",
                        help="also the friction scene prm/mca/two_body_friction.prm")
    args = parser.parse_args()
    args.tribodyn = os.path.abspath(args.tribodyn)
    # A copied build (tribodyn and libtribodyn.so in one directory) runs
    # with the library beside it, not with the one its RUNPATH names (the
    # build tree it was linked in), as in bench/alternating_prms.py.
    env["LD_LIBRARY_PATH"] = os.pathsep.join(
        [os.path.dirname(args.tribodyn)]
        + ([env["LD_LIBRARY_PATH"]] if env.get("LD_LIBRARY_PATH") else []))
    args.work = os.path.abspath(args.work)
    os.makedirs(args.work, exist_ok=True)
    print("load average before:", open("/proc/loadavg").read().split()[:3])

    # Repeats alternate tribodyn and LAMMPS so that both see the same drift
    # of a shared (virtual) machine; the medians are reported.
    runs = {}
    lammps_runs, lammps_runs_2 = [], []
    ranks_list = [int(r) for r in args.ranks.split(",")]
    for _ in range(args.repeat):
        for ranks in ranks_list:
            s, _ = tribodyn_block(args, 29, 30, args.steps, ranks, "block_1e5_%d" % ranks)
            runs.setdefault(ranks, []).append(s["automaton_steps_per_second_per_rank"])
            n_block = s["n_automata"]
        if 2 in ranks_list:
            runs.setdefault("pair", []).append(
                tribodyn_concurrent_pair(args, 29, 30, args.steps, "block_1e5_pair"))
        lammps = lammps_rate(args, args.steps)
        if lammps is not None:
            lammps_runs.append(lammps)
            # the same lattice on 2 processes: the per-rank criterion's
            # reference (both codes then share the caches and the bandwidth)
            lammps_2 = lammps_rate(args, args.steps, 2) if 2 in ranks_list else None
            if lammps_2 is not None:
                lammps_runs_2.append(lammps_2)
    rates = {ranks: statistics.median(r) for ranks, r in runs.items()}
    for ranks, rate in rates.items():
        if ranks != "pair":
            print("tribodyn  %d automata, %d rank(s): %.3e automaton-steps/s per core%s"
                  % (n_block, ranks, rate, spread(runs[ranks])))
    if 1 in rates and 2 in rates:
        print_efficiency("10^5", rates, runs)
    if not lammps_runs:
        print("LAMMPS    not installed (apt-get install lammps): no side-by-side figure")
    else:
        lammps = statistics.median(lammps_runs)
        print("LAMMPS    100920 spheres, gran/hooke/history, 1 proc: %.3e atom-steps/s%s"
              % (lammps, spread(lammps_runs)))
        if 1 in rates:
            print("ratio     tribodyn / LAMMPS = %.2f (issue #48: >= 1.0 per core)%s"
                  % (rates[1] / lammps, round_ratios(runs[1], lammps_runs)))
        if lammps_runs_2:
            lammps_2 = statistics.median(lammps_runs_2)
            print("LAMMPS    100920 spheres, gran/hooke/history, 2 procs: %.3e atom-steps/s per "
                  "proc%s" % (lammps_2, spread(lammps_runs_2)))
            if 2 in rates:
                print("ratio     tribodyn / LAMMPS on 2 ranks = %.2f per rank (issue #48: >= 1.0)%s; "
                      "against LAMMPS on 1 proc %.2f"
                      % (rates[2] / lammps_2, round_ratios(runs[2], lammps_runs_2),
                         rates[2] / lammps))

    if args.large:
        large_runs = {}
        for _ in range(args.repeat):
            for ranks in [1, 2]:
                s, _ = tribodyn_block(args, 63, 63, 40, ranks, "block_1e6_%d" % ranks)
                large_runs.setdefault(ranks, []).append(s["automaton_steps_per_second_per_rank"])
            large_runs.setdefault("pair", []).append(
                tribodyn_concurrent_pair(args, 63, 63, 40, "block_1e6_pair"))
        large = {ranks: statistics.median(r) for ranks, r in large_runs.items()}
        for ranks in [1, 2]:
            print("tribodyn  %d automata, %d rank(s), 40 steps: %.3e automaton-steps/s per core%s"
                  % (s["n_automata"], ranks, large[ranks], spread(large_runs[ranks])))
        print_efficiency("10^6", large, large_runs)

    if args.friction:
        friction = []
        for _ in range(args.repeat):
            s = tribodyn_friction_scene(args)
            friction.append(s["automaton_steps_per_second_per_rank"])
        print("tribodyn  friction scene prm/mca/two_body_friction.prm (%d automata, plasticity, "
              "bonds, contacts): %.3e automaton-steps/s (target >= 1.5e6)%s"
              % (s["n_automata"], statistics.median(friction), spread(friction)))

    if args.memory:
        tiny, rss_tiny = tribodyn_block(args, 4, 4, 20, 1, "memory_tiny")
        big, rss_big = tribodyn_block(args, 40, 40, 20, 1, "memory_big")
        per = (rss_big - rss_tiny) * 1024 / (big["n_automata"] - tiny["n_automata"])
        print("memory    1 rank: peak RSS %d KB (%d automata) - %d KB (%d) = %.0f B per automaton "
              "(target <= 600, issue #48); arrays: %.0f B per automaton"
              % (rss_big, big["n_automata"], rss_tiny, tiny["n_automata"], per,
                 big["memory_bytes_max"] / big["n_automata"]))
        big2, rss_big2 = tribodyn_block(args, 40, 40, 20, 2, "memory_big_2")
        tiny2, rss_tiny2 = tribodyn_block(args, 4, 4, 20, 2, "memory_tiny_2")
        owned = big2["n_owned_automata_max"]
        per2 = (rss_big2 - rss_tiny2) * 1024 / owned
        print("memory    2 ranks: peak RSS of the largest rank %d KB - %d KB over %d owned "
              "automata = %.0f B per owned automaton (target <= 1500)"
              % (rss_big2, rss_tiny2, owned, per2))


if __name__ == "__main__":
    main()
