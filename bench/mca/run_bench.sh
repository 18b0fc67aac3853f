#!/bin/sh
# MCA benchmark (issue #4): automaton-steps per second per rank for an
# elastic and a plastic bonded FCC block at ~1e5 and ~1e6 automata, on 1 and
# 2 MPI ranks. Usage: bench/mca/run_bench.sh BUILD_DIR [WORK_DIR]
# (BUILD_DIR: a Release build). Prints one line per run; figures are the
# time-step loop only (summary.json: automaton_steps_per_second_per_rank).
set -e
build=$(cd "$1" && pwd)
work=${2:-bench-mca-work}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work" && cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
printf "%-8s %-8s %10s %6s %6s %14s\n" kind size automata ranks steps "steps/s/rank"
for size in 1e5 1e6; do
  if [ $size = 1e5 ]; then n=29; nz=30; steps=200; else n=63; nz=63; steps=40; fi
  for kind in elastic plastic; do
    for ranks in 1 2; do
      name=${kind}_${size}_${ranks}
      python3 "$here/make_block.py" $n $nz $kind $steps "out_$name" > "$name.prm"
      mpirun -np $ranks --oversubscribe "$build/tribodyn" "$name.prm" > "$name.log" 2>&1
      python3 - "$name" $kind $size $ranks $steps <<'PY'
import json, sys
name, kind, size, ranks, steps = sys.argv[1:]
s = json.load(open("out_%s/summary.json" % name))
print("%-8s %-8s %10d %6s %6s %14.3e" % (kind, size, s["n_automata"], ranks, steps,
      s["automaton_steps_per_second_per_rank"]))
PY
    done
  done
done
