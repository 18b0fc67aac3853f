#!/usr/bin/python3
"""Cost of automata scenes per simulated time, run in turn (issue #47 item
2: a lever's speed-up, or today's cost against an older binary's, measured
as ratios over alternating rounds in one call).

    python3 bench/alternating_prms.py [--ranks N] ROUNDS END_TIME CASE [CASE ...]

CASE is NAME=PRM or NAME=PRM@BINARY (the binary's libtribodyn.so is looked
for beside it, as a copied build keeps it; default: build/tribodyn). Each
round runs every case once, in the order given, on one rank (on N ranks
under mpirun with --ranks N: the same wall, so the cost of the whole
machine the ranks occupy); each run is
the PRM (included, so relative includes resolve beside it) cut to
Time/End time = END_TIME. Per run: the time loop's wall (summary.json
time_loop_s; set-up not counted) per simulated ns; per round the ratios
of the first case's cost to each other's; then each case's median ratio
with its range. Outputs in bench-output/alternating_prms/.

Example (the coarse layout against the campaign's, the seed-heights steel
scene at Courant 0.44):

    python3 bench/alternating_prms.py 5 6e-10 \\
        band=prm/mca/friction_seed_heights_steel_band.prm \\
        coarse=prm/mca/friction_seed_heights_steel_coarse.prm
"""
import json
import os
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.abspath(os.path.join("bench-output", "alternating_prms"))


def parse(case):
    name, rest = case.split("=", 1)
    prm, binary = (rest.split("@", 1) + [os.path.join(ROOT, "build", "tribodyn")])[:2]
    return name, os.path.abspath(prm), os.path.abspath(binary)


def run(name, prm, binary, end_time, round_, ranks):
    out = os.path.join(OUT, name)
    wrapper = os.path.join(OUT, name + ".prm")
    with open(wrapper, "w") as f:
        f.write(f"include {prm}\nset Output directory = {out}\n"
                f"subsection Time\n  set End time = {end_time}\nend\n")
    env = dict(os.environ, LD_LIBRARY_PATH=os.path.dirname(binary))
    command = [binary, wrapper]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks), "-x", "LD_LIBRARY_PATH"] + command
    p = subprocess.run(command, capture_output=True, text=True, env=env)
    if p.returncode != 0:
        sys.exit(f"{name} failed (exit {p.returncode}):\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    cost = s["time_loop_s"] / (s["end_time"] * 1e9)
    print(f"round {round_} {name} ({ranks} rank{'s' if ranks > 1 else ''}): "
          f"{s['time_loop_s']:.2f} s for {s['n_steps']} steps, "
          f"{s['n_automata']} automata: {cost:.1f} s per simulated ns", flush=True)
    return cost


def main():
    args = sys.argv[1:]
    ranks = 1
    if args[:1] == ["--ranks"]:
        if len(args) < 2 or not args[1].isdigit() or int(args[1]) < 1:
            sys.exit("--ranks needs a positive number of ranks\n" + __doc__)
        ranks, args = int(args[1]), args[2:]
    if len(args) < 3:
        sys.exit(__doc__)
    rounds, end_time = int(args[0]), args[1]
    cases = [parse(c) for c in args[2:]]
    os.makedirs(OUT, exist_ok=True)
    ratios = {name: [] for name, _, _ in cases[1:]}
    for r in range(1, rounds + 1):
        costs = {name: run(name, prm, binary, end_time, r, ranks)
                 for name, prm, binary in cases}
        first = cases[0][0]
        for name in ratios:
            ratios[name].append(costs[first] / costs[name])
    for name, values in ratios.items():
        print(f"{cases[0][0]} / {name}: median {statistics.median(values):.2f} "
              f"({min(values):.2f}-{max(values):.2f}) over {rounds} rounds: "
              + ", ".join(f"{v:.2f}" for v in values))


if __name__ == "__main__":
    main()
