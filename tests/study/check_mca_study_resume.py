"""A study killed mid-way and started again (issue #47): it reuses its
finished scenes, resumes the interrupted one from its checkpoint on another
number of ranks, runs the rest, and its study.csv equals an uninterrupted
run's.

    check_mca_study_resume.py TRIBODYN STUDY_PRM FINISHED_DIR WORK_DIR

FINISHED_DIR is the uninterrupted study (mca_study_app, 1 rank). Here:
1. the study runs on 1 rank; once its first scene has finished and the
   second has written a checkpoint, it gets SIGTERM: exit code 143, the
   running scene's checkpoint saved;
2. started again with the same file on 2 ranks (two groups of one rank):
   the first scene is reused, the second resumed from its checkpoint, the
   other two run; exit code 0;
3. study.csv equals the uninterrupted study's: the labels exactly, every
   number to 1e-9 relative (the resumed scene continues bit for bit; the
   CSV files carry 17 significant digits);
4. the scenes' parameters.prm rewritten in the names before the renames
   of issue #52 item 3 (as a version up to 6969d3e wrote them: 'Friction
   law = Amontons-Coulomb', 'subsection Dieterich') and without the entry
   'Partition/Mesh cells per rank' (added on 2026-11-30; the scene runs
   leave it at its default), a third start reuses all four scenes and runs
   none;
5. the legs of the interrupted scene (scenes/NAME.legs.csv): two, the
   first 'interrupted', the second 'resume' ... 'finished'.
"""
import csv
import os
import re
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "mca"))
from check_tools import finish, report  # noqa: E402

tribodyn, prm, finished, work = sys.argv[1:5]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
           OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
OUT = "output-mca-tiny-study"
FIRST, SECOND = "steel_seed1_inclusions5", "composite_seed1_inclusions5"

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
scenes = os.path.join(work, OUT, "scenes")

# 1. killed once the second scene has a checkpoint
log = open(os.path.join(work, "first.log"), "w")
process = subprocess.Popen([tribodyn, prm], cwd=work, env=env, stdout=log,
                           stderr=subprocess.STDOUT)
deadline = time.time() + 300
latest = os.path.join(scenes, SECOND, "checkpoint", "latest")
while time.time() < deadline and process.poll() is None:
    if os.path.exists(os.path.join(scenes, FIRST, "summary.json")) \
            and os.path.exists(latest):
        process.send_signal(signal.SIGTERM)
        break
    time.sleep(0.01)
code = process.wait(timeout=300)
log.close()
report(code == 128 + signal.SIGTERM,
       "the study stopped on SIGTERM with exit code %d (expected 143)" % code)
report(not os.path.exists(os.path.join(scenes, SECOND, "summary.json")),
       "the second scene was interrupted (no summary.json)")


def run(ranks, name):
    command = ([tribodyn, prm] if ranks == 1 else
               ["mpirun", "-np", str(ranks), tribodyn, prm])
    result = subprocess.run(command, cwd=work, env=env, capture_output=True,
                            text=True, timeout=600)
    with open(os.path.join(work, name), "w") as f:
        f.write(result.stdout + result.stderr)
    return result


# 2. again, on 2 ranks
second = run(2, "second.log")
report(second.returncode == 0, "started again on 2 ranks: exit code %d"
       % second.returncode)
report("Scene %s: reused" % FIRST in second.stdout,
       "the finished scene %s was reused" % FIRST)
report("Scene %s: resumed from its checkpoint" % SECOND in second.stdout,
       "the interrupted scene %s was resumed" % SECOND)
n_run = second.stdout.count(": run in ")
report(n_run == 2, "the other two scenes were run (%d)" % n_run)


# 3. study.csv as uninterrupted
def rows(directory):
    with open(os.path.join(directory, "study.csv")) as f:
        return list(csv.reader(f))


a, b = rows(os.path.join(finished, OUT)), rows(os.path.join(work, OUT))
worst, same_labels = 0.0, len(a) == len(b)
for ra, rb in zip(a, b):
    same_labels = same_labels and len(ra) == len(rb)
    for x, y in zip(ra, rb):
        try:
            fx, fy = float(x), float(y)
        except ValueError:
            same_labels = same_labels and x == y
            continue
        worst = max(worst, abs(fx - fy) / max(abs(fx), 1e-300))
report(same_labels and worst <= 1e-9,
       "study.csv equals the uninterrupted study's (largest relative "
       "difference %.2g, tolerance 1e-9)" % worst)

# 4. written before the renames, a third start reuses everything
renamed = 0
for scene in sorted(os.listdir(scenes)):
    path = os.path.join(scenes, scene, "parameters.prm")
    if not os.path.isfile(path):
        continue
    text = open(path).read()
    old = re.sub(r"(Friction law\s*=\s*)Coulomb", r"\1Amontons-Coulomb",
                 text).replace("subsection Rate and state friction",
                               "subsection Dieterich")
    # an entry a later version added, at its default
    added = re.compile(r"^\s*set Mesh cells per rank\s*=\s*1000\s*\n",
                       re.MULTILINE)
    old, n_added = added.subn("", old)
    renamed += old != text and n_added == 1
    with open(path, "w") as f:
        f.write(old)
report(renamed == 4, "the four scenes' parameters.prm rewritten in the old "
       "names and without the entry added since (%d)" % renamed)
third = run(1, "third.log")
report(third.returncode == 0 and third.stdout.count(": reused") == 4
       and ": run in " not in third.stdout,
       "a third start reuses the four scenes and runs none")

# 5. the interrupted scene's legs
with open(os.path.join(scenes, SECOND + ".legs.csv")) as f:
    legs = list(csv.DictReader(f))
report([(l["start"], l["end"]) for l in legs]
       == [("fresh", "interrupted"), ("resumed", "finished")],
       "legs of %s: %s" % (SECOND, [(l["start"], l["end"]) for l in legs]))
finish()
