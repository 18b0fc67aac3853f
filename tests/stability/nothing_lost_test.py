#!/usr/bin/env python3
"""Nothing lost (issue #22): a refused run leaves an existing output
directory byte for byte as it was, and a new run that is killed never
leaves a directory that mixes two runs.

Each case first makes a finished run A in WORKDIR/out, takes a snapshot of
every file under it (relative path -> bytes), then:

  time_step   reruns with 'Automatic time step = false', 'Time step = 1e-7'
              (above the pin's critical step): refused at set-up;
  resume      resumes A's checkpoint with 'Loading/Pressure' changed:
              refused (parameters differ);
  mca_time    reruns the MCA wave pulse with 'Time/Time step = 1e-9'
              (above the automata's sound-crossing time): refused at
              set-up;
  mca_resume  resumes the MCA wave pulse's checkpoint with the steel's
              density changed: refused (parameters differ);
  resume_none resumes where A wrote no checkpoint: refused;
  resume_other_problem
              resumes A's (contact) checkpoint with an MCA prm (the wave
              pulse) in the same directory: refused (another problem);
  resume_corrupt, resume_missing
              resume after the rank file of A's latest checkpoint slot was
              overwritten with garbage / deleted: refused (damaged /
              incomplete);
  killed      starts a fresh run B with a long end time and kills it
              (SIGKILL, no chance to clean up) once B's series has rows.

Refusals must exit with 2 and leave the snapshot identical (no file added,
removed or changed). The killed run must leave A whole (byte for byte) in
out/previous_run/, and at the top of out/ only B's files: no summary.json,
B's parameters.prm (its end time), series with B's rows.

Usage: nothing_lost_test.py TRIBODYN CASE BASE.prm WORKDIR
"""
import os
import shutil
import signal
import subprocess
import sys
import time


def write_prm(path, base, out, extra):
    with open(path, "w") as f:
        f.write(f"include {base}\nset Output directory = {out}\n"
                f"set Progress interval = 1000\n{extra}")


def run(tribodyn, prm, cwd):
    r = subprocess.run([tribodyn, prm], cwd=cwd, capture_output=True,
                       text=True)
    return r.returncode, r.stdout, r.stderr


def snapshot(directory):
    files = {}
    for root, _, names in os.walk(directory):
        for name in names:
            path = os.path.join(root, name)
            with open(path, "rb") as f:
                files[os.path.relpath(path, directory)] = f.read()
    return files


def inodes(directory):
    return {os.path.relpath(os.path.join(root, n), directory):
            os.stat(os.path.join(root, n)).st_ino
            for root, _, names in os.walk(directory) for n in names}


def differences(before, after):
    out = []
    for name in sorted(set(before) | set(after)):
        if name not in after:
            out.append(f"removed: {name}")
        elif name not in before:
            out.append(f"added: {name}")
        elif before[name] != after[name]:
            out.append(f"changed: {name}")
    return out


def section_text(section, lines):
    return f"subsection {section}\n" + "".join(
        f"  set {l}\n" for l in lines) + "end\n"


SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
RESUME_CONTACT = (section_text("Checkpoint", ["Resume = true"])
                  + section_text("Time", ["End time = 20e-6"]))


def latest_rank_file(out):
    """The rank-0 file of the slot that out/checkpoint/latest names."""
    latest = open(os.path.join(out, "checkpoint", "latest")).read()
    slot = [l for l in latest.splitlines() if l.startswith("slot = ")][0][7:]
    return os.path.join(out, "checkpoint", f"slot_{slot}", "rank_0000.bin")


def overwrite(path):
    with open(path, "wb") as f:
        f.write(b"not a checkpoint" * 8)


# The finished run A of each case, and what the second run changes
# ('second_base': the second run's prm includes this file instead of BASE;
# 'prepare': done to A's outputs before the second run).
CASES = {
    "time_step": dict(
        first=section_text("Checkpoint", ["Interval = 5e-6"]),
        second=section_text("Time",
                            ["Automatic time step = false",
                             "Time step = 1e-7"]),
        expected="Time step"),
    "resume": dict(
        first=section_text("Checkpoint", ["Interval = 5e-6"]),
        second=section_text("Checkpoint", ["Resume = true"])
        + section_text("Time", ["End time = 20e-6"])
        + section_text("Loading", ["Pressure = 2.5e6"]),
        expected="Pressure"),
    "mca_time": dict(
        first="",
        second=section_text("Time", ["Time step = 1e-9"]),
        expected="Time step"),
    "mca_resume": dict(
        first=section_text("Checkpoint", ["Interval = 5e-11"]),
        second=section_text("Checkpoint", ["Resume = true"])
        + section_text("Time", ["End time = 2e-10"])
        + "subsection Materials\n" + section_text("Steel", ["Density = 7900"])
        + "end\n",
        expected="Density"),
    "resume_none": dict(
        first="",
        second=RESUME_CONTACT,
        expected="there is no checkpoint"),
    "resume_other_problem": dict(
        first=section_text("Checkpoint", ["Interval = 5e-6"]),
        second_base=os.path.join(SOURCE, "prm", "mca", "wave_pulse.prm"),
        second=section_text("Checkpoint", ["Resume = true"]),
        expected="belongs to a 'contact' run"),
    "resume_corrupt": dict(
        first=section_text("Checkpoint", ["Interval = 5e-6"]),
        prepare=lambda out: overwrite(latest_rank_file(out)),
        second=RESUME_CONTACT,
        expected="damaged"),
    "resume_missing": dict(
        first=section_text("Checkpoint", ["Interval = 5e-6"]),
        prepare=lambda out: os.remove(latest_rank_file(out)),
        second=RESUME_CONTACT,
        expected="incomplete"),
}


def refusal_case(tribodyn, case, base, work):
    out = os.path.join(work, "out")
    spec = CASES[case]
    write_prm(os.path.join(work, "a.prm"), base, out, spec["first"])
    code, _, err = run(tribodyn, "a.prm", work)
    if code != 0:
        sys.exit(f"FAIL: the first run failed ({code}): {err[-1500:]}")
    if not os.path.exists(os.path.join(out, "summary.json")):
        sys.exit("FAIL: the first run wrote no summary.json")
    if "prepare" in spec:
        spec["prepare"](out)
    if "second_base" in spec:
        write_prm(os.path.join(work, "b.prm"), os.path.abspath(spec["second_base"]),
                  out, spec["second"])
    else:
        write_prm(os.path.join(work, "b.prm"), base, out,
                  spec["first"] + spec["second"])
    before = snapshot(work)  # b.prm included
    code, _, err = run(tribodyn, "b.prm", work)
    print(f"second run: exit code {code}; stderr: {err.strip()[-600:]}")
    errors = []
    if code != 2:
        errors.append(f"exit code {code}, expected 2 (a refusal)")
    if spec["expected"] not in err:
        errors.append(f"the message does not name '{spec['expected']}'")
    diff = differences(before, snapshot(work))
    errors += [f"the refusal touched the outputs: {d}" for d in diff]
    return errors


def killed_case(tribodyn, base, work, end_section, long_end, series):
    out = os.path.join(work, "out")
    write_prm(os.path.join(work, "a.prm"), base, out, "")
    code, _, err = run(tribodyn, "a.prm", work)
    if code != 0 or not os.path.exists(os.path.join(out, "summary.json")):
        sys.exit(f"FAIL: the first run failed ({code}): {err[-1500:]}")
    finished = snapshot(out)
    inodes_a = inodes(out)
    write_prm(os.path.join(work, "b.prm"), base, out,
              section_text(end_section, [f"End time = {long_end}"]))
    process = subprocess.Popen([tribodyn, "b.prm"], cwd=work,
                               stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL)
    watched = os.path.join(out, series)
    start = time.time()
    rows = 0
    while time.time() - start < 120 and process.poll() is None:
        try:
            # A's series is moved aside at the claim, one file after the
            # other once previous_run/ exists: the rows are B's only when
            # the series at the top is a file of its own (another inode;
            # on a loaded machine the claim can be caught between the two).
            if (os.path.exists(os.path.join(out, "previous_run"))
                    and os.stat(watched).st_ino != inodes_a[series]):
                rows = len(open(watched).read().splitlines())
                if rows >= 4:
                    break
        except OSError:
            pass
        time.sleep(0.02)
    if process.poll() is not None:
        sys.exit("FAIL: run B ended before it was killed")
    process.send_signal(signal.SIGKILL)
    process.wait()
    print(f"run B killed with {rows} rows in {series}")
    errors = []
    kept = snapshot(os.path.join(out, "previous_run"))
    diff = differences(finished, kept)
    errors += [f"run A not whole in previous_run/: {d}" for d in diff]
    top = [n for n in os.listdir(out) if n != "previous_run"]
    if "summary.json" in top:
        errors.append("a summary.json is left beside the killed run's files")
    parameters = open(os.path.join(out, "parameters.prm")).read()
    if str(long_end) not in parameters:
        errors.append("parameters.prm is not the killed run's")
    lines = open(watched).read().splitlines()
    if len(lines) < 4:
        errors.append(f"{series} does not hold the killed run's rows")
    # Every file at the top was written by B: none of them is one of A's
    # files (same inode), left in place or copied back.
    for name, inode in inodes(out).items():
        if not name.startswith("previous_run") and inode in inodes_a.values():
            errors.append(f"{name} at the top is run A's file")
    return errors


def main():
    tribodyn, case, base, work = sys.argv[1:5]
    base = os.path.abspath(base)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    if case == "killed":
        end_section, long_end, series = sys.argv[5:8]
        errors = killed_case(tribodyn, base, work, end_section, long_end,
                             series)
    else:
        errors = refusal_case(tribodyn, case, base, work)
    for e in errors:
        print("FAIL:", e)
    if errors:
        sys.exit(1)
    print("passed: nothing lost")


if __name__ == "__main__":
    main()
