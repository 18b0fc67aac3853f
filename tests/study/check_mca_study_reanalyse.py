"""A finished study analysed again with other analysis-only parameters
(issue #47): its scenes are re-analysed from their last checkpoints, no step
is run, and the new analysis is what the new parameters give on the same
record.

    check_mca_study_reanalyse.py TRIBODYN STUDY_DIR FINISHED_DIR WORK_DIR

FINISHED_DIR is the study of STUDY_DIR/mca_tiny_study.prm run once
(mca_study_app). Its scenes are copied to WORK_DIR, and the same study is
started there with 'Analysis/Smoothing window = 4e-10; Analysis/Steady
band = 0.3' added to its Settings (the bases: 2e-10 and 0.15). Checked:
1. exit code 0; each of the 4 scenes says it was re-analysed and names the
   two changed entries; none is run or resumed;
2. no step was run: series.csv and layer.csv are byte for byte the
   finished run's (the last row too, which the run's end writes after its
   last checkpoint), friction.csv's recorded columns (all but mu_smoothed)
   too; the scene's legs.csv ends with a leg 'reanalysed ... finished';
3. mu_smoothed is the centred moving average of friction.csv's mu over the
   new window (the samples with |t_j - t_i| <= 2e-10 s), recomputed here
   (2e-9 relative: the CSV keeps 10 significant digits, so each mu and the
   recorded average are rounded by up to 5e-10 relative; measured 5.2e-10),
   and it differs from
   the finished run's (which used 2e-10: the test would notice a scene
   reused with its old analysis);
4. the quasi-steady start is the band test with the new band, recomputed
   here on that mu_smoothed column: the first sample after which it stays
   within 0.3 of its later mean, over at least a fifth of the record;
5. the scene's parameters.prm holds the new values; the study's tables
   satisfy check_mca_study.py's identities (mu_steady the mean from the new
   start, paired differences and their errors recomputed from the series);
6. started a third time, the study reuses all 4 scenes;
7. the finished study copied without its scenes' checkpoint/ directories
   (as data/ keeps scenes) and started with the new analysis: refused with
   exit code 2 before any scene runs, the message naming a scene, the
   changed entry and the missing checkpoint; every scene's files left as
   they were.
"""
import csv
import json
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "mca"))
from check_tools import finish, parameter, report  # noqa: E402

tribodyn, study_dir, finished, work = sys.argv[1:5]
OUT = "output-mca-tiny-study"
WINDOW, BAND = 4e-10, 0.3
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
           OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
shutil.copytree(os.path.join(finished, OUT), os.path.join(work, OUT))
for name in ("mca_small_steel.prm", "mca_small_composite.prm"):
    shutil.copy(os.path.join(study_dir, name), work)
text = open(os.path.join(study_dir, "mca_tiny_study.prm")).read()
old = "set Settings            = Output/Cross section = false"
assert old in text
text = text.replace(old, old + "; Analysis/Smoothing window = %g; "
                    "Analysis/Steady band = %g" % (WINDOW, BAND))
prm = os.path.join(work, "reanalyse.prm")
with open(prm, "w") as f:
    f.write(text)


def run(name, where=work):
    result = subprocess.run([tribodyn, prm], cwd=where, env=env,
                            capture_output=True, text=True, timeout=600)
    with open(os.path.join(where, name), "w") as f:
        f.write(result.stdout + result.stderr)
    return result


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def read(path):
    with open(path, "rb") as f:
        return f.read()


# 1. re-analysed, not run
second = run("second.log")
report(second.returncode == 0, "started with the new analysis: exit code %d"
       % second.returncode)
scenes = sorted(d for d in os.listdir(os.path.join(work, OUT, "scenes"))
                if os.path.isdir(os.path.join(work, OUT, "scenes", d)))
report(len(scenes) == 4, "4 scenes (%s)" % ", ".join(scenes))
for scene in scenes:
    line = [x for x in second.stdout.splitlines()
            if x.startswith("Scene %s:" % scene)]
    report(len(line) == 1 and "re-analysed" in line[0]
           and "'Analysis/Smoothing window'" in line[0]
           and "'Analysis/Steady band'" in line[0],
           "%s: re-analysed, naming both changed entries" % scene)
report(not re.search(r"^Scene \S+: (run in|resumed)", second.stdout,
                     re.MULTILINE),
       "no scene was run or resumed")

for scene in scenes:
    old_dir = os.path.join(finished, OUT, "scenes", scene)
    new_dir = os.path.join(work, OUT, "scenes", scene)
    # 2. the record is the finished run's
    for name in ("series.csv", "layer.csv"):
        report(read(os.path.join(old_dir, name))
               == read(os.path.join(new_dir, name)),
               "%s: %s byte for byte the finished run's" % (scene, name))
    before = rows(os.path.join(old_dir, "friction.csv"))
    after = rows(os.path.join(new_dir, "friction.csv"))
    recorded = [c for c in before[0] if c != "mu_smoothed"]
    report(len(before) == len(after) and all(
        a[c] == b[c] for a, b in zip(before, after) for c in recorded),
        "%s: friction.csv's %s as recorded (%d rows)"
        % (scene, ", ".join(recorded), len(after)))
    legs = rows(os.path.join(work, OUT, "scenes", scene + ".legs.csv"))
    report(legs[-1]["start"] == "reanalysed"
           and legs[-1]["end"] == "finished",
           "%s: legs.csv ends with %s ... %s" % (scene, legs[-1]["start"],
                                                 legs[-1]["end"]))
    # 3. the new window
    t = [float(r["time"]) for r in after]
    mu = [float(r["mu"]) for r in after]
    smoothed = [float(r["mu_smoothed"]) for r in after]
    worst, lo, hi, total = 0.0, 0, 0, 0.0
    for i, ti in enumerate(t):
        while hi < len(t) and t[hi] <= ti + 0.5 * WINDOW * (1 + 1e-12):
            total += mu[hi]
            hi += 1
        while t[lo] < ti - 0.5 * WINDOW * (1 - 1e-12):
            total -= mu[lo]
            lo += 1
        worst = max(worst, abs(smoothed[i] - total / (hi - lo))
                    / max(abs(smoothed[i]), 1e-3))
    report(worst <= 2e-9, "%s: mu_smoothed is the moving average over %g s "
           "(largest relative difference %.2g, tolerance 2e-9)"
           % (scene, WINDOW, worst))
    changed = max(abs(float(a["mu_smoothed"]) - float(b["mu_smoothed"]))
                  for a, b in zip(before, after))
    report(changed > 1e-3, "%s: and not the finished run's (largest change "
           "%.3g)" % (scene, changed))
    # 4. the new band
    n, start = len(t), None
    for i in range(n):
        if t[-1] - t[i] < 0.2 * (t[-1] - t[0]):
            break
        later = smoothed[i:]
        mean = sum(later) / len(later)
        if max(later) - mean <= BAND * abs(mean) \
                and mean - min(later) <= BAND * abs(mean):
            start = t[i]
            break
    with open(os.path.join(new_dir, "summary.json")) as f:
        summary = json.load(f)
    found = summary["steady_state_found"]
    report(start is not None and found
           and abs(summary["steady_start_time"] - start) <= 1e-9 * start,
           "%s: quasi-steady from %.6g s with the band %g (recomputed %s)"
           % (scene, summary["steady_start_time"], BAND,
              "%.6g s" % start if start is not None else "none"))
    # 5. its parameters
    report(abs(parameter(new_dir, "Analysis/Smoothing window") - WINDOW)
           <= 1e-12 * WINDOW
           and abs(parameter(new_dir, "Analysis/Steady band") - BAND) <= 1e-12,
           "%s: parameters.prm holds the new window and band" % scene)

identities = subprocess.run(
    [sys.executable, os.path.join(HERE, "check_mca_study.py"), work],
    capture_output=True, text=True)
print(identities.stdout, end="")
report(identities.returncode == 0,
       "the re-analysed study's tables satisfy check_mca_study.py")

# 6. a third start reuses everything
third = run("third.log")
report(third.returncode == 0
       and third.stdout.count(": reused (a finished run") == 4,
       "started a third time: all 4 scenes reused (exit code %d)"
       % third.returncode)

# 7. without checkpoints: refused, nothing overwritten
bare = work + "_without_checkpoints"
shutil.rmtree(bare, ignore_errors=True)
shutil.copytree(os.path.join(finished, OUT), os.path.join(bare, OUT),
                ignore=shutil.ignore_patterns("checkpoint"))
for name in ("mca_small_steel.prm", "mca_small_composite.prm"):
    shutil.copy(os.path.join(study_dir, name), bare)
before = {os.path.join(d, f): read(os.path.join(d, f))
          for d, _, files in os.walk(os.path.join(bare, OUT, "scenes"))
          for f in files}
refused = run("refused.log", bare)
message = refused.stdout + refused.stderr
report(refused.returncode == 2 and "no checkpoint at its end time" in message
       and "'Analysis/Smoothing window'" in message
       and "checkpoint/" in message
       and not re.search(r"^Scene \S+: ", refused.stdout, re.MULTILINE),
       "copied without checkpoints: refused before any scene starts "
       "(exit code %d: %s)" % (refused.returncode,
                               message.strip().splitlines()[-1][:160]
                               if message.strip() else ""))
after = {os.path.join(d, f): read(os.path.join(d, f))
         for d, _, files in os.walk(os.path.join(bare, OUT, "scenes"))
         for f in files}
report(before == after, "and its %d scene files left as they were"
       % len(before))
finish()
