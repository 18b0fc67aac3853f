#!/usr/bin/python3
"""Throughput of two tribodyn binaries, old and new in turn (issue #17 item
8, #20 item 1: a speed claim is a ratio taken in one run, alternating).

    python3 bench/alternating_throughput.py OLD_TRIBODYN NEW_TRIBODYN [REPEATS]
        [--old-lib DIR] [--only CASE]

Cases: the pin of prm/contact/homogeneous_matrix.prm cut to 100 us (1 rank;
dof_steps_per_second), prm/mca/two_body_friction.prm, the 10^5
elastic block of bench/mca/make_block.py 29 30 elastic 300 and the first
0.2 ns of prm/mca/friction_seed_heights_steel.prm
(automaton_steps_per_second); REPEATS runs each (default 5), the order
of old and new swapped every repeat; prints each pair and the medians with
new / old. --old-lib: LD_LIBRARY_PATH for the old binary (a copied build
needs its libtribodyn.so). --only: one case ("contact pin",
"two_body_friction", "10^5 block", "seed heights steel"; repeated for
several). Outputs in bench-output/alternating/.

--by-wall: compare 1 / wall_time_s of the whole run (set-up included)
instead of the throughput figure, for binaries whose figures are defined
differently (the time-loop change of issue #52: time_loop_s no longer counts
the automata's samples and outputs).

--concurrent: old and new at the same time instead, each pinned to a core
of its own (taskset; cores swapped every repeat), and the median of the
pairs' ratios new / old: both runs see the same moment of a shared host,
whose drift from one run to the next (10-30 %) then cancels in each pair.
(They share the memory bandwidth and the last-level cache; a ratio, not a
one-rank rate.)
"""
import argparse
import json
import os
import statistics
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.abspath(os.path.join("bench-output", "alternating"))


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("repeats", type=int, nargs="?", default=5)
    parser.add_argument("--old-lib", default="")
    parser.add_argument("--only", action="append", default=[])
    parser.add_argument("--concurrent", action="store_true")
    parser.add_argument("--by-wall", action="store_true")
    args = parser.parse_args()
    os.makedirs(OUT, exist_ok=True)
    block = os.path.join(OUT, "block.prm")
    with open(block, "w") as f:
        subprocess.run(["python3", os.path.join(ROOT, "bench/mca/make_block.py"),
                        "29", "30", "elastic", "300",
                        os.path.join(OUT, "block_out")], stdout=f, check=True)
    cases = {
        "contact pin": (os.path.join(ROOT, "prm/contact/homogeneous_matrix.prm"),
                        "subsection Time\nset End time = 100e-6\n"
                        "end\nsubsection Output\nset Averaging start time = "
                        "20e-6\nset Field interval = 0\nend\n",
                        "dof_steps_per_second"),
        "two_body_friction": (os.path.join(ROOT,
                                           "prm/mca/two_body_friction.prm"),
                              "", "automaton_steps_per_second"),
        "10^5 block": (block, "", "automaton_steps_per_second"),
        # the automata study's scene at the seed's heights (graded, K_ij,
        # plasticity, bonds), its first 0.2 ns
        "seed heights steel": (os.path.join(
            ROOT, "prm/mca/friction_seed_heights_steel.prm"),
            "subsection Time\nset End time = 0.2e-9\nend\n",
            "automaton_steps_per_second"),
    }
    if args.only:
        cases = {c: cases[c] for c in args.only}
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    results = {c: {"old": [], "new": []} for c in cases}
    for rep in range(args.repeats):
        for case, (prm, extra, key) in cases.items():
            order = ("old", "new") if rep % 2 == 0 else ("new", "old")
            runs = []
            for core, which in enumerate(order):
                d = os.path.join(OUT, "%s_%s" % (case.replace(" ", "_")
                                                 .replace("^", ""), which))
                with open(d + ".prm", "w") as f:
                    f.write(open(prm).read() + "\nset Output directory = %s\n"
                            % d + extra)
                e = dict(env)
                if which == "old" and args.old_lib:
                    e["LD_LIBRARY_PATH"] = args.old_lib
                command = [getattr(args, which), d + ".prm"]
                if args.concurrent:
                    command = ["taskset", "-c", str(core)] + command
                run = subprocess.Popen(command, env=e,
                                       stdout=subprocess.DEVNULL,
                                       stderr=subprocess.DEVNULL)
                if not args.concurrent and run.wait() != 0:
                    raise SystemExit("failed: " + " ".join(command))
                runs.append((which, d, run))
            for which, d, run in runs:
                if run.wait() != 0:
                    raise SystemExit("failed: %s %s.prm" % (which, d))
                with open(os.path.join(d, "summary.json")) as f:
                    summary = json.load(f)
                results[case][which].append(1 / summary["wall_time_s"]
                                            if args.by_wall else summary[key])
            print(rep, case, results[case]["old"][-1],
                  results[case]["new"][-1], "%.3f" % (results[case]["new"][-1]
                                                      / results[case]["old"][-1]),
                  flush=True)
    for case in cases:
        old = statistics.median(results[case]["old"])
        new = statistics.median(results[case]["new"])
        ratios = [n / o for n, o in zip(results[case]["new"],
                                        results[case]["old"])]
        print("%s: median old %.4g, new %.4g, new/old %.3f; median of the "
              "pairs' ratios %.3f (%.3f-%.3f)"
              % (case, old, new, new / old, statistics.median(ratios),
                 min(ratios), max(ratios)))


if __name__ == "__main__":
    main()
