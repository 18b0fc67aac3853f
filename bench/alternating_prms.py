#!/usr/bin/python3
"""Cost of automata scenes per simulated time, run in turn (issue #47 item
2: a lever's speed-up, or today's cost against an older binary's, measured
as ratios over alternating rounds in one call).

    python3 bench/alternating_prms.py [--ranks N] [--leg START] \\
        ROUNDS END_TIME CASE [CASE ...]

CASE is NAME=PRM or NAME=PRM@BINARY (the binary's libtribodyn.so is looked
for beside it, as a copied build keeps it; default: build/tribodyn). Each
round runs every case once, in the order given, on one rank (on N ranks
under mpirun with --ranks N: the same wall, so the cost of the whole
machine the ranks occupy); each run is the PRM (included, so relative
includes resolve beside it) cut to Time/End time = END_TIME. Per run: the
time loop's wall (summary.json time_loop_s; set-up not counted) per
simulated ns; per round the ratios of the first case's cost to each
other's; then each case's median ratio with its range, and the ratio of
the cases' fastest runs. Outputs in
bench-output/alternating_prms/.

--leg START times only the leg from START to END_TIME: before the rounds,
each case runs once to START and writes a checkpoint there (Checkpoint/
Interval = START); each round restores that run's output directory and
resumes it (Checkpoint/Resume = true) to END_TIME. Each binary resumes its
own checkpoint, so binaries of other checkpoint formats compare too.

Example (the coarse layout against the campaign's, the seed-heights steel
scene at Courant 0.44):

    python3 bench/alternating_prms.py 5 6e-10 \\
        band=prm/mca/friction_seed_heights_steel_band.prm \\
        coarse=prm/mca/friction_seed_heights_steel_coarse.prm
"""
import json
import os
import shutil
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.abspath(os.path.join("bench-output", "alternating_prms"))


def parse(case):
    name, rest = case.split("=", 1)
    prm, binary = (rest.split("@", 1) + [os.path.join(ROOT, "build", "tribodyn")])[:2]
    return name, os.path.abspath(prm), os.path.abspath(binary)


def run(name, prm, binary, end_time, ranks, leg=None, resume=False):
    """One run of a case; returns its summary. With @p leg, the run writes
    a checkpoint at the leg's start (the same entries for the first run
    and the resumed ones, which a resume requires)."""
    out = os.path.join(OUT, name)
    wrapper = os.path.join(OUT, name + ".prm")
    with open(wrapper, "w") as f:
        f.write(f"include {prm}\nset Output directory = {out}\n"
                f"subsection Time\n  set End time = {end_time}\nend\n")
        if leg is not None:
            f.write(f"subsection Checkpoint\n  set Interval = {leg}\n"
                    f"  set Resume = {'true' if resume else 'false'}\nend\n")
    env = dict(os.environ, LD_LIBRARY_PATH=os.path.dirname(binary))
    command = [binary, wrapper]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks), "-x", "LD_LIBRARY_PATH"] + command
    p = subprocess.run(command, capture_output=True, text=True, env=env)
    if p.returncode != 0:
        sys.exit(f"{name} failed (exit {p.returncode}):\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def timed_run(name, prm, binary, end_time, round_, ranks, leg):
    out = os.path.join(OUT, name)
    if leg is not None:
        shutil.rmtree(out, ignore_errors=True)
        shutil.copytree(out + ".leg_start", out)
    s = run(name, prm, binary, end_time, ranks, leg, resume=leg is not None)
    span = s["end_time"] - (float(leg) if leg is not None else 0.)
    cost = s["time_loop_s"] / (span * 1e9)
    print(f"round {round_} {name} ({ranks} rank{'s' if ranks > 1 else ''}"
          f"{f', leg from {leg} s' if leg is not None else ''}): "
          f"{s['time_loop_s']:.2f} s, {s['n_steps']} steps in all, "
          f"{s['n_automata']} automata: {cost:.1f} s per simulated ns", flush=True)
    return cost


def main():
    args = sys.argv[1:]
    ranks, leg = 1, None
    while args[:1] in (["--ranks"], ["--leg"]):
        if len(args) < 2:
            sys.exit(f"{args[0]} needs a value\n" + __doc__)
        if args[0] == "--ranks":
            if not args[1].isdigit() or int(args[1]) < 1:
                sys.exit("--ranks needs a positive number of ranks\n" + __doc__)
            ranks = int(args[1])
        else:
            try:
                leg = args[1]
                if float(leg) <= 0:
                    raise ValueError
            except ValueError:
                sys.exit("--leg needs a positive start time (s)\n" + __doc__)
        args = args[2:]
    if len(args) < 3:
        sys.exit(__doc__)
    rounds, end_time = int(args[0]), args[1]
    if leg is not None and float(leg) >= float(end_time):
        sys.exit(f"--leg {leg} starts at or after END_TIME {end_time}")
    cases = [parse(c) for c in args[2:]]
    os.makedirs(OUT, exist_ok=True)
    if leg is not None:
        # each case's run to the leg's start, once (not timed)
        for name, prm, binary in cases:
            s = run(name, prm, binary, leg, ranks, leg)
            start = os.path.join(OUT, name) + ".leg_start"
            shutil.rmtree(start, ignore_errors=True)
            shutil.copytree(os.path.join(OUT, name), start)
            print(f"{name}: run to the leg's start {leg} s in {s['time_loop_s']:.2f} s "
                  f"({s['n_steps']} steps), checkpoint kept", flush=True)
    ratios = {name: [] for name, _, _ in cases[1:]}
    fastest = {name: float("inf") for name, _, _ in cases}
    first = cases[0][0]
    for r in range(1, rounds + 1):
        costs = {name: timed_run(name, prm, binary, end_time, r, ranks, leg)
                 for name, prm, binary in cases}
        for name, cost in costs.items():
            fastest[name] = min(fastest[name], cost)
        for name in ratios:
            ratios[name].append(costs[first] / costs[name])
    # (on a host whose neighbours slow some runs by a third, the fastest
    # run of each case is its least disturbed one: their ratio beside the
    # median of the rounds')
    for name, values in ratios.items():
        print(f"{first} / {name}: median {statistics.median(values):.2f} "
              f"({min(values):.2f}-{max(values):.2f}) over {rounds} rounds: "
              + ", ".join(f"{v:.2f}" for v in values)
              + f"; fastest runs {fastest[first] / fastest[name]:.2f}")


if __name__ == "__main__":
    main()
