"""The pair kernel's pipeline (issue #48; doc/performance.md, "The pair
kernel's pipeline"): the friction scene with K_ij (friction_small.prm with
the relative-rotation moments: plasticity, bond breaking and formation,
contacts, periodic x and y, pair-list rebuilds), its automata in slabs
(Partition/Automaton order), run

- mca_pipeline_1: on 1 rank in chunks of 16 pairs: the passes run as a
  pipeline, each some chunks behind the one before;
- mca_pipeline_whole_1: on 1 rank in one chunk: the passes one after the
  other over the whole list, as before the pipeline;
- mca_pipeline_2: on 2 ranks (neighbour ranks: one chunk each).

Every pass visits the pairs in the list's order in both 1-rank runs, so
each automaton's sums, and with them every output, must be the same bit for
bit: every CSV output (series.csv, the cross-section's) byte-identical (no
tolerance). The 2-rank
run must agree to 1e-9 relative, as mca_ranks_agree (the round-off of the
MPI reductions), which checks the slab order and the ghosts' exchange with
it. The pipelined run must really be one: more than 10 chunks, its passes
at least one chunk apart, and less than a quarter of the list (the slabs
keep them close; along the Morton curve the lag is most of the list).

    check_pipeline.py BUILD_DIR"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_tools import finish, report  # noqa: E402
from series_compare import largest_relative_difference  # noqa: E402

build = sys.argv[1]
folder = "output-mca-friction-small"


def run(test):
    path = os.path.join(build, test, folder)
    with open(os.path.join(path, "summary.json")) as f:
        return path, json.load(f)


piped, s_piped = run("mca_pipeline_1")
whole, s_whole = run("mca_pipeline_whole_1")
ranks, s_ranks = run("mca_pipeline_2")
chunks, lag = s_piped["pipeline_chunks"], s_piped["pipeline_lag"]
report(chunks > 10 and 1 <= lag and 4 * lag < chunks,
       f"pipelined on 1 rank: {chunks} chunks, passes {lag} chunk(s) apart "
       f"(more than 10 chunks; 1 <= lag < chunks / 4)")
report(s_whole["pipeline_chunks"] == 1 and s_whole["pipeline_lag"] == 0,
       f"one chunk: {s_whole['pipeline_chunks']} chunk(s), lag "
       f"{s_whole['pipeline_lag']}")
report(s_ranks["n_mpi_ranks"] == 2 and s_ranks["pipeline_chunks"] == 1
       and s_ranks.get("n_ghost_automata_max", 0) > 0,
       f"2 ranks with ghosts, one chunk each: {s_ranks['pipeline_chunks']}")
csvs = sorted(n for n in os.listdir(piped) if n.endswith(".csv"))
report("series.csv" in csvs, f"the outputs to compare: {csvs}")
for name in csvs:
    a = open(os.path.join(piped, name), "rb").read()
    b = open(os.path.join(whole, name), "rb").read()
    report(len(a) > 0 and a == b,
           f"{name}: the pipelined run and the one-chunk run byte-identical "
           f"({len(a)} and {len(b)} bytes)")
rows = []
for path in [piped, ranks]:
    with open(os.path.join(path, "series.csv")) as f:
        rows.append([line.rstrip("\n").split(",") for line in f])
worst, column = largest_relative_difference(*rows)
report(len(rows[0]) == len(rows[1]) > 5 and worst <= 1e-9,
       f"2 ranks against the pipelined rank: largest relative difference "
       f"{worst:.3g} in {column} (tolerance 1e-9)")
finish()
