#!/usr/bin/env python3
"""The automata's displacements stored only where an output reads them
(issue #48): an elastic block of the benchmark (bench/mca/make_block.py,
6 x 6 x 6 FCC cells, periodic in x and y, its top layer driven down at
0.05 m/s, its bottom fixed), no ramp.

Checked:
- without particle output the block stores no displacement
  (memory_bytes_by_part "displacement" = 0) and with it 24 bytes per
  automaton;
- the groups' mean displacements, now sums of their automata's drifts,
  against the exact ones: the bottom's 0 exactly, the top's z the
  prescribed -0.05 m/s times the time to 1e-9 relative (the drifts of each
  step are dt * -0.05, summed over the group's members and the steps, to
  round-off; series.csv keeps 10 significant digits, one unit of the last
  ~1e-10 relative: a step missed or counted twice is 1/40 off);
- series.csv is the same file with and without particle output (storing
  the displacements changes nothing the engine computes);
- the groups' sums are checkpointed: the block run in two legs (no
  particles, checkpointed halfway, resumed) writes the uninterrupted run's
  series.csv.

A resumed run may not change 'Output/Write particles' (nor anything but
the end time and the checkpoints), so whether the displacements are
stored is the same in every leg.

usage: check_displacements_on_demand.py TRIBODYN SOURCE_DIR WORK_DIR
"""
import csv
import json
import os
import shutil
import subprocess
import sys

from check_tools import finish, report

tribodyn, source, work = (os.path.abspath(a) for a in sys.argv[1:4])
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
make_block = os.path.join(source, "bench", "mca", "make_block.py")
STEPS = 40
base = os.path.join(work, "block.prm")
with open(base, "w") as f:
    subprocess.run([sys.executable, make_block, "6", "6", "elastic", str(STEPS),
                    os.path.join(work, "unused")], stdout=f, check=True)
with open(base) as f:
    end_time = float(next(line for line in f if "End time" in line).split("=")[1])


def run(name, particles, end=end_time, interval=0.0, resume=False):
    """Run the block into WORK/NAME; its exit code and output."""
    out = os.path.join(work, name)
    prm = out + ".prm"
    with open(prm, "w") as f:
        f.write(f"include {base}\nset Output directory = {out}\n"
                f"subsection Boundary conditions\n  set Ramp time = 0\nend\n"
                f"subsection Output\n"
                f"  set Write particles = {'true' if particles else 'false'}\n"
                f"  set Series interval = {end_time / STEPS!r}\nend\n"
                f"subsection Time\n  set End time = {end!r}\nend\n"
                f"subsection Checkpoint\n  set Interval = {interval!r}\n"
                f"  set Resume = {'true' if resume else 'false'}\nend\n")
    result = subprocess.run([tribodyn, prm], cwd=work, capture_output=True, text=True)
    return result.returncode, result.stdout + result.stderr


def summary(name):
    with open(os.path.join(work, name, "summary.json")) as f:
        return json.load(f)


def series(name):
    with open(os.path.join(work, name, "series.csv")) as f:
        return f.read()


def last_row(name):
    with open(os.path.join(work, name, "series.csv")) as f:
        return list(csv.DictReader(f))[-1]


def must_run(name, *args, **kwargs):
    code, text = run(name, *args, **kwargs)
    if code != 0:
        sys.exit(f"FAIL: run {name} exited with {code}:\n{text[-2000:]}")


# Without and with the particles.
must_run("plain", False)
must_run("particles", True)
plain, particles = summary("plain"), summary("particles")
n = plain["n_automata"]
report(plain["memory_bytes_by_part"].get("displacement", 0) == 0,
       "no particle output: no displacement stored (%s B)"
       % plain["memory_bytes_by_part"].get("displacement", 0))
report(particles["memory_bytes_by_part"].get("displacement", 0) == 24 * n,
       "particle output: 24 B of displacement per automaton (%s B for %d)"
       % (particles["memory_bytes_by_part"].get("displacement"), n))
report(series("plain") == series("particles"),
       "series.csv the same with and without particle output")

row = last_row("plain")
t, uz = float(row["time"]), float(row["top_uz"])
exact = -0.05 * t
report(abs(uz - exact) <= 1e-9 * abs(exact),
       "top group's mean z displacement %.17g against -0.05 m/s x t = %.17g (%.1e relative, "
       "tolerance 1e-9: series.csv keeps 10 digits)" % (uz, exact, abs(uz - exact) / abs(exact)))
bottom = [float(row["bottom_u" + c]) for c in "xyz"]
report(bottom == [0.0, 0.0, 0.0], "fixed bottom group's mean displacement exactly 0 (%s)"
       % bottom)

# In legs: the first half, checkpointed at its end, then resumed.
half = end_time / 2
must_run("legs", False, end=half, interval=half)
must_run("legs", False, interval=half, resume=True)
report(series("legs") == series("plain"),
       "in two legs: series.csv equals the uninterrupted run's")
finish()
