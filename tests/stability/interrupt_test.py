#!/usr/bin/env python3
"""SIGTERM or SIGINT ends a run cleanly, and the run continues from there
(issue #10).

A run with a long end time is sent the signal (environment variable
INTERRUPT_SIGNAL: TERM, the default, or INT) once its series has a few rows.
Checks: exit code 128 + the signal number (143, 130), a message naming the
checkpoint,
no summary.json, a complete checkpoint (checkpoint/latest), series whose
rows are all whole. Then the run is resumed to t_k + DELTA (t_k: the time
of the checkpoint written at the signal) and compared with an uninterrupted
run to the same end time, as in restart_test.py (same tolerance rules).

Usage: interrupt_test.py TRIBODYN BASE.prm WORKDIR END_SECTION LONG_END
       DELTA TOLERANCE SERIES FILE [FILE...]
SERIES: the CSV watched before the signal; FILE: the CSVs compared.
"""
import json
import os
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from restart_test import compare_csv, compare_json, run, write_prm  # noqa


def main():
    tribodyn, base, work, section, long_end, delta, tolerance, series = \
        sys.argv[1:9]
    files = sys.argv[9:]
    long_end, delta, tolerance = float(long_end), float(delta), \
        float(tolerance)
    base = os.path.abspath(base)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    c, d = os.path.join(work, "C"), os.path.join(work, "D")
    write_prm(os.path.join(work, "c1.prm"), base, c, section, long_end, 0,
              False)
    process = subprocess.Popen([tribodyn, "c1.prm"], cwd=work,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True)
    watched = os.path.join(c, series)
    start = time.time()
    while time.time() - start < 120:
        if process.poll() is not None:
            sys.exit("FAIL: the run ended before the signal: "
                     + process.stderr.read()[-2000:])
        try:
            if len(open(watched).read().splitlines()) >= 4:
                break
        except OSError:
            pass
        time.sleep(0.05)
    which = getattr(signal, "SIG" + os.environ.get("INTERRUPT_SIGNAL", "TERM"))
    process.send_signal(which)
    out, err = process.communicate(timeout=120)
    print(f"exit code {process.returncode}; stderr: {err.strip()[-400:]}")
    errors = []
    if process.returncode != 128 + which:
        errors.append(f"exit code {process.returncode}, expected {128 + which}")
    if "interrupted" not in err or "Checkpoint/Resume = true" not in err:
        errors.append("no message naming the checkpoint on stderr")
    if os.path.exists(os.path.join(c, "summary.json")):
        errors.append("an interrupted run left a summary.json")
    for name in files:
        lines = open(os.path.join(c, name)).read().splitlines()
        width = len(lines[0].split(","))
        if any(len(l.split(",")) != width for l in lines):
            errors.append(f"{name} has a partial row")
    latest = open(os.path.join(c, "checkpoint", "latest")).read().splitlines()
    t_k = float([l for l in latest if l.startswith("time = ")][0][7:])
    print(f"checkpoint written at the signal: t = {t_k}")
    end = t_k + delta
    write_prm(os.path.join(work, "c2.prm"), base, c, section, end, 0, True)
    write_prm(os.path.join(work, "d.prm"), base, d, section, end, 0, False)
    run("", tribodyn, "c2.prm", work)
    run("", tribodyn, "d.prm", work)
    for name in files:
        errors += compare_csv(name, os.path.join(d, name),
                              os.path.join(c, name), tolerance)
    errors += compare_json(json.load(open(os.path.join(d, "summary.json"))),
                           json.load(open(os.path.join(c, "summary.json"))),
                           tolerance)
    for e in errors:
        print("FAIL", e)
    if errors:
        sys.exit(1)
    print(f"PASS: {which.name} saved the state; the resumed run equals an "
          f"uninterrupted one to t = {end} (tolerance {tolerance})")


if __name__ == "__main__":
    main()
