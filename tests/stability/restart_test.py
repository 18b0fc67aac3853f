#!/usr/bin/env python3
"""Checkpoint and restart acceptance test (issue #10).

Runs a parameter file three times, each in its own output directory:
  A: uninterrupted to 2T;
  B: to T with Checkpoint/Interval = T/2 (checkpoints at T/2 and T),
     then resumed (Checkpoint/Resume = true) to 2T, after the files of the
     other slot (the T/2 checkpoint) were overwritten with garbage, as a
     crash while writing a next checkpoint would leave them.
and checks that B's CSV series have exactly A's rows (no duplicate, no
missing row) with equal values, and that every figure of summary.json is
equal, except wall-clock timings and memory. Tolerance: 0 (bit for bit:
the CSV text and the JSON numbers, written with 17 digits, must be
identical) for contact, 1e-12 relative for mca.

Usage: restart_test.py TRIBODYN BASE.prm WORKDIR END_SECTION T TOLERANCE
       "LAUNCHER" FILE [FILE...] [--before-checkpoint KEY]
       [--resume-launcher "LAUNCHER2"] [--written-before-renames]
       [--first-order ORDER]
END_SECTION is the subsection holding 'End time' ('Time' in every
engine); FILE are the CSV files to compare. With
--before-checkpoint KEY, the first part's summary.json must have KEY > 0
(e.g. n_rebalances: the state to restore existed at the checkpoint).

With --written-before-renames (issue #52 item 3), the checkpoint of the
first part is rewritten as a version before the parameter renames would
have written it: its parameter lines in the old names (OLD_NAMES, the
names tribodyn used up to commit 6969d3e), without the lines of entries
added since at their defaults (ADDED_SINCE). The resumed run must accept it
and still equal the uninterrupted run.

With --first-order ORDER (mca), the first part stores its automata in
ORDER (Partition/Automaton order, an entry of the work's layout only), A
and the resumed part in the default order: the resumed part must take the
checkpoint, and its values are judged as after a restart on another number
of ranks (below), the pair sums having changed their order.

With --resume-launcher (restart on another number of ranks, issue #21), A
and the resumed part run with LAUNCHER2 (e.g. "mpirun -np 1") and the first
part with LAUNCHER (e.g. "mpirun -np 2"): the resumed part must say that it
redistributed the state, and the CSV values agree to TOLERANCE relative to
the largest magnitude of their column's family (family(): the sums over
ranks change order, so a quantity that vanishes is judged at the scale of
its kind, not of its round-off), the summary's numbers to TOLERANCE
relative to the larger of the two (lists: to their largest component),
except round-off errors (..._error) and n_rebalances (the partitions of
each part's own ranks); a summary figure that is also a column of a
compared series (an energy, a work) is judged as that column is, at its
family's scale (a work that is round-off, 1e-30 J beside energies of
1e-13 J, cannot agree to its own digits when the sums change order).
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys

TIMING_KEYS = {"wall_time_s", "time_loop_s", "dof_steps_per_second",
               "dof_steps_per_second_per_rank", "automaton_steps_per_second",
               "automaton_steps_per_second_per_rank", "memory_bytes_max",
               "memory_bytes_by_part",
               "tribodyn_version"}


# (engine, current text in a checkpoint's parameter line, text before the
# renames of issue #52 item 3)
OLD_NAMES = [
    ("contact", "parameter Time/", "parameter Time integration/"),
    ("contact", "parameter Materials/", "parameter Material/"),
    ("contact", "Loading/Sliding velocity", "Loading/Plane velocity"),
    ("contact", "Loading/Sliding start time", "Loading/Plane start time"),
    ("contact", "Morphology/Seed =", "Morphology/Random seed ="),
    # defaults as the declarations spelled them (since 2026-11-29 they are
    # written from the parameter structs: 5e5, not 0.5e6)
    ("contact", "Loading/Pressure = 5e5", "Loading/Pressure = 0.5e6"),
    ("contact", "Geometry/Width = 0.028", "Geometry/Width = 28e-3"),
    ("mca", "Interaction/Rate and state friction/", "Interaction/Dieterich/"),
    ("mca", "Friction law = rate and state", "Friction law = Dieterich"),
    ("mca", "Friction law = Coulomb", "Friction law = Amontons-Coulomb"),
]


# (engine, a checkpoint's parameter line of an entry added since, at its
# default: a version before it wrote no such line)
ADDED_SINCE = [
    ("mca", "parameter Partition/Mesh cells per rank = 1000"),
]


def write_old_names(latest_path):
    """Rewrite the parameter lines of a checkpoint's 'latest' file in the
    names before the renames, without the entries added since; returns the
    number of lines changed or removed."""
    lines = open(latest_path).read().split("\n")
    problem = [l for l in lines if l.startswith("problem = ")][0][10:]
    added = [l for engine, l in ADDED_SINCE if engine == problem]
    changed = sum(l in added for l in lines)
    lines = [l for l in lines if l not in added]
    for k, line in enumerate(lines):
        if not line.startswith("parameter "):
            continue
        old = line
        for engine, new_text, old_text in OLD_NAMES:
            if engine == problem:
                line = line.replace(new_text, old_text)
        if line != old:
            lines[k] = line
            changed += 1
    with open(latest_path, "w") as f:
        f.write("\n".join(lines))
    return changed


def write_prm(path, base, out, section, end, interval, resume, order=None):
    with open(path, "w") as f:
        f.write(f"include {base}\n"
                f"set Output directory = {out}\n"
                f"set Progress interval = 1000\n"
                f"subsection {section}\n  set End time = {end!r}\nend\n"
                f"subsection Checkpoint\n  set Interval = {interval!r}\n"
                f"  set Resume = {'true' if resume else 'false'}\nend\n")
        if order is not None:
            f.write(f"subsection Partition\n  set Automaton order = {order}\n"
                    "end\n")


def run(launcher, tribodyn, prm, cwd):
    command = launcher.split() + [tribodyn, prm]
    result = subprocess.run(command, cwd=cwd, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"FAIL: {' '.join(command)} exited with {result.returncode}:"
                 f"\n{result.stdout[-2000:]}\n{result.stderr[-2000:]}")
    return result.stdout


def close(a, b, tolerance):
    if a == b or (math.isnan(a) and math.isnan(b)):
        return True
    if tolerance == 0:
        return False
    return abs(a - b) <= tolerance * max(abs(a), abs(b), 1e-300)


def compare_csv(name, path_a, path_b, tolerance):
    rows_a = open(path_a).read().splitlines()
    rows_b = open(path_b).read().splitlines()
    if len(rows_a) != len(rows_b):
        return [f"{name}: {len(rows_b) - 1} rows after the restart, "
                f"{len(rows_a) - 1} uninterrupted"]
    if tolerance == 0:
        bad = [k for k in range(len(rows_a)) if rows_a[k] != rows_b[k]]
        return [f"{name}: row {bad[0]} differs:\n  {rows_a[bad[0]]}\n"
                f"  {rows_b[bad[0]]}"] if bad else []
    errors = []
    for k, (ra, rb) in enumerate(zip(rows_a[1:], rows_b[1:]), start=1):
        fa, fb = ra.split(","), rb.split(",")
        for x, y in zip(fa, fb):
            try:
                if not close(float(x), float(y), tolerance):
                    errors.append(f"{name}: row {k}: {x} vs {y}")
                    break
            except ValueError:
                if x != y:
                    errors.append(f"{name}: row {k}: {x} vs {y}")
                    break
    return errors[:5]


# Restart on another number of ranks: lists of numbers are compared at the
# scale of their largest component (a force component that vanishes by
# symmetry is round-off noise).
VECTOR_SCALE = False
# Restart on another number of ranks: the largest magnitude of each column
# family of the uninterrupted run's series (compare_csv_scaled()), by
# column name, for the summary's figures of the same name.
COLUMN_SCALE = {}


def compare_json(a, b, tolerance, where="summary.json"):
    errors = []
    if isinstance(a, dict):
        for key in a:
            if key in TIMING_KEYS:
                continue
            if key not in b:
                errors.append(f"{where}: key {key} missing after restart")
            else:
                errors += compare_json(a[key], b[key], tolerance,
                                       f"{where}/{key}")
    elif isinstance(a, list):
        if len(a) != len(b):
            errors.append(f"{where}: lengths differ")
        numbers = all(isinstance(x, (int, float)) and not isinstance(x, bool)
                      for x in a + b)
        if VECTOR_SCALE and numbers and a:
            # a vector (a group's force): its components at its own scale
            scale = max(abs(x) for x in a + b)
            if any(abs(x - y) > tolerance * scale for x, y in zip(a, b)):
                errors.append(f"{where}: {a!r} uninterrupted, {b!r} restarted")
            return errors
        for k, (x, y) in enumerate(zip(a, b)):
            errors += compare_json(x, y, tolerance, f"{where}[{k}]")
    elif isinstance(a, (int, float)) and not isinstance(a, bool):
        key = where.split("/", 1)[-1]
        if key in COLUMN_SCALE and isinstance(b, (int, float)):
            if abs(a - b) > tolerance * max(abs(a), abs(b), COLUMN_SCALE[key]):
                errors.append(f"{where}: {a!r} uninterrupted, {b!r} "
                              f"restarted (column family scale "
                              f"{COLUMN_SCALE[key]:.3g})")
        elif not (isinstance(b, (int, float)) and close(a, b, tolerance)):
            errors.append(f"{where}: {a!r} uninterrupted, {b!r} restarted")
    elif a != b:
        errors.append(f"{where}: {a!r} uninterrupted, {b!r} restarted")
    return errors


def family(name):
    """Columns judged at one scale: those with the same last word
    (tangential_velocity and normal_velocity; kinetic_energy and
    elastic_energy), the components of a vector (<group>_fx, _fy, _fz)."""
    last = name.split("_")[-1]
    return last[0] if re.fullmatch(r"[fu][xyz]", last) else last


def compare_csv_scaled(name, path_a, path_b, tolerance):
    """Every value within tolerance of the largest magnitude of its
    column's family in the uninterrupted run; columns of round-off errors
    (..._error) are not compared (their values are noise)."""
    rows_a = [r.split(",") for r in open(path_a).read().splitlines()]
    rows_b = [r.split(",") for r in open(path_b).read().splitlines()]
    if len(rows_a) != len(rows_b) or rows_a[0] != rows_b[0]:
        return [f"{name}: {len(rows_b) - 1} rows after the restart, "
                f"{len(rows_a) - 1} uninterrupted (or other columns)"]
    header = rows_a[0]
    columns_a = [[float(r[c]) for r in rows_a[1:]] for c in range(len(header))]
    columns_b = [[float(r[c]) for r in rows_b[1:]] for c in range(len(header))]
    scale = {}
    for c, h in enumerate(header):
        m = max((abs(x) for x in columns_a[c]), default=0.0)
        scale[family(h)] = max(scale.get(family(h), 0.0), m)
    for h in header:
        COLUMN_SCALE[h] = max(COLUMN_SCALE.get(h, 0.0), scale[family(h)])
    worst, column = 0.0, ""
    for c, h in enumerate(header):
        if h.endswith("error"):
            continue
        d = max((abs(x - y) for x, y in zip(columns_a[c], columns_b[c])),
                default=0.0) / max(scale[family(h)], 1e-300)
        if d > worst:
            worst, column = d, h
    print(f"{name}: largest difference {worst:.3g} of its column family's "
          f"largest magnitude (column {column or '-'}; tolerance {tolerance})")
    return [f"{name}: column {column} differs by {worst:.3g}"] \
        if not worst <= tolerance else []


def main():
    args = sys.argv[1:]
    resume_launcher = None
    if "--resume-launcher" in args:
        at = args.index("--resume-launcher")
        resume_launcher = args[at + 1]
        args = args[:at] + args[at + 2:]
    first_order = None
    if "--first-order" in args:
        at = args.index("--first-order")
        first_order = args[at + 1]
        args = args[:at] + args[at + 2:]
    old_names = "--written-before-renames" in args
    if old_names:
        args.remove("--written-before-renames")
    tribodyn, base, work, section, t_end, tolerance, launcher = args[:7]
    files = args[7:]
    required = None
    if "--before-checkpoint" in files:
        at = files.index("--before-checkpoint")
        required = files[at + 1]
        files = files[:at] + files[at + 2:]
    t_end, tolerance = float(t_end), float(tolerance)
    base = os.path.abspath(base)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    a, b = os.path.join(work, "A"), os.path.join(work, "B")
    write_prm(os.path.join(work, "a.prm"), base, a, section, 2 * t_end, 0,
              False)
    write_prm(os.path.join(work, "b1.prm"), base, b, section, t_end,
              t_end / 2, False, first_order)
    write_prm(os.path.join(work, "b2.prm"), base, b, section, 2 * t_end,
              t_end / 2, True)
    run(resume_launcher or launcher, tribodyn, "a.prm", work)
    run(launcher, tribodyn, "b1.prm", work)
    if required is not None:
        value = json.load(open(os.path.join(b, "summary.json"))).get(required)
        print(f"first part: {required} = {value}")
        if not value or value <= 0:
            sys.exit(f"FAIL: the first part has {required} = {value}, "
                     "not > 0: the restart would not test it")
    if old_names:
        changed = write_old_names(os.path.join(b, "checkpoint", "latest"))
        print(f"checkpoint rewritten with the names before the renames: "
              f"{changed} parameter lines")
        if changed == 0:
            sys.exit("FAIL: no parameter line of the checkpoint has a "
                     "renamed name: the test would test nothing")
    latest = open(os.path.join(b, "checkpoint", "latest")).read()
    print("checkpoint after the first part:",
          " ".join(l for l in latest.splitlines()[1:6]))
    # A crash while writing the next checkpoint: it would go to the other
    # slot, whose files are then partial; 'latest' still names the complete
    # one, from which the run must resume.
    slot = [l for l in latest.splitlines() if l.startswith("slot = ")][0][7:]
    other = os.path.join(b, "checkpoint", f"slot_{1 - int(slot)}")
    for name in (os.listdir(other) if os.path.isdir(other) else []):
        with open(os.path.join(other, name), "wb") as f:
            f.write(b"partial")
        with open(os.path.join(other, name + ".tmp"), "wb") as f:
            f.write(b"partial")
    ranks_b1 = json.load(open(os.path.join(b, "summary.json")))["n_mpi_ranks"]
    prm_b1 = open(os.path.join(b, "parameters.prm")).read()
    out = run(resume_launcher or launcher, tribodyn, "b2.prm", work)
    if "Resuming from the checkpoint" not in out:
        sys.exit("FAIL: the second part did not resume")
    errors = []
    # another number of ranks or another order: the sums change their order
    scaled = resume_launcher is not None or first_order is not None
    if first_order is not None:
        prm_b2 = open(os.path.join(b, "parameters.prm")).read()
        orders = [re.search(r"set Automaton order += (.*)\n", t).group(1)
                  for t in (prm_b1, prm_b2)]
        print(f"first part in the order '{orders[0]}', resumed in "
              f"'{orders[1]}'")
        if orders[0] != first_order or orders[0] == orders[1]:
            errors.append("the two parts did not run in the two orders")
    if scaled:
        ranks_b2 = json.load(open(os.path.join(b, "summary.json")))["n_mpi_ranks"]
        line = [l for l in out.splitlines() if "Resuming" in l][0]
        print(f"first part on {ranks_b1} rank(s), resumed on {ranks_b2}: "
              f"{line.strip()}")
        if resume_launcher and (ranks_b1 == ranks_b2
                                or "redistributed" not in line):
            errors.append("the resumed part did not change the number of "
                          "ranks or did not redistribute the state")
        # n_rebalances counts the partitions of each part's own ranks
        TIMING_KEYS.update({"energy_balance_error", "n_rebalances"})
        global VECTOR_SCALE
        VECTOR_SCALE = True
    for name in files:
        compare = compare_csv_scaled if scaled else compare_csv
        errors += compare(name, os.path.join(a, name),
                          os.path.join(b, name), tolerance)
        last = open(os.path.join(b, name)).read().splitlines()[-1]
        print(f"{name}: last row after the restart: {last[:150]}")
    summary_a = json.load(open(os.path.join(a, "summary.json")))
    summary_b = json.load(open(os.path.join(b, "summary.json")))
    errors += compare_json(summary_a, summary_b, tolerance)
    for e in errors:
        print("FAIL", e)
    if errors:
        sys.exit(1)
    print(f"PASS: the resumed run equals the uninterrupted one "
          f"(tolerance {tolerance}) in {', '.join(files)} and summary.json")


if __name__ == "__main__":
    main()
