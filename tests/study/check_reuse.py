"""'Study/Reuse finished cases': a study re-analysed from the files of a
finished one gives the same tables.

usage: check_reuse.py TRIBODYN STUDY_PRM FINISHED_OUTPUT WORK_DIR

Copies FINISHED_OUTPUT (the tiny study of study_app_1rank), deletes one
case's directory (that case must run again), and runs the study there with
'Reuse finished cases = true':
1. every other case (and every homogenization run) is reused, not run;
2. table2.csv and cases.csv equal the finished study's: exactly for what
   comes from the runs' summaries (means, fractions), within 1e-6 relative
   for the block-averaged standard errors (recomputed from friction.csv,
   whose samples have 10 significant digits); wall times are not compared;
3. a reused case whose pressure differs from the study's is refused with a
   message naming the parameter and the directory.
"""
import csv
import json
import os
import re
import shutil
import subprocess
import sys

tribodyn, study_prm, finished, work = sys.argv[1:5]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
ok = True


def report(good, text):
    global ok
    ok = ok and good
    print(("PASS  " if good else "FAIL  ") + text)


def make_prm(output):
    text = open(study_prm).read()
    text = re.sub(r"set Output directory\s*=[^\n]*", "set Output directory = " + output, text)
    text = text.replace("subsection Study\n",
                        "subsection Study\n  set Reuse finished cases = true\n", 1)
    path = os.path.join(work, "reuse.prm")
    open(path, "w").write(text)
    return path


shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
copy = os.path.join(work, "output")
shutil.copytree(finished, copy)
for name in ("table2.csv", "table2.md", "cases.csv", "summary.json"):
    os.remove(os.path.join(copy, name))
rerun = "P5MPa_meso_seed2"
shutil.rmtree(os.path.join(copy, "cases", rerun))
homogenization = [os.path.join(root, f) for root, _, files in
                  os.walk(os.path.join(copy, "homogenization")) for f in files
                  if f == "summary.json"]
stamps = {f: os.stat(f).st_mtime_ns for f in homogenization}
prm = make_prm(copy)
run = subprocess.run([tribodyn, prm], cwd=work, env=env, capture_output=True, text=True)
report(run.returncode == 0, "the re-analysis ran (exit %d)" % run.returncode)
if run.returncode != 0:
    print(run.stdout[-3000:], run.stderr[-3000:])
    sys.exit(1)
cases = sorted(os.listdir(os.path.join(finished, "cases")))
reused = re.findall(r"reused: \S*/cases/(\S+)", run.stdout)
report(sorted(reused) == sorted(c for c in cases if c != rerun),
       "the %d other cases were reused, not run (%d reused)" % (len(cases) - 1, len(reused)))
report(rerun not in reused and os.path.exists(os.path.join(copy, "cases", rerun, "summary.json")),
       "the deleted case %s ran again" % rerun)
report(len(stamps) > 0 and all(os.stat(f).st_mtime_ns == t for f, t in stamps.items()),
       "the %d homogenization runs were reused (their summaries untouched)" % len(stamps))

for name in ("table2.csv", "cases.csv"):
    a = list(csv.reader(open(os.path.join(finished, name))))
    b = list(csv.reader(open(os.path.join(copy, name))))
    same = len(a) == len(b) and a[0] == b[0]
    worst = 0.
    if same:
        for ra, rb in zip(a[1:], b[1:]):
            for column, x, y in zip(a[0], ra, rb):
                if column == "wall_time_s":
                    continue
                try:
                    fx, fy = float(x), float(y)
                except ValueError:
                    same = same and x == y
                    continue
                tolerance = 1e-6 if "stderr" in column else 1e-12
                error = abs(fx - fy) / max(abs(fx), 1e-300) if fx != fy else 0.
                worst = max(worst, error / tolerance)
                same = same and error <= tolerance
    report(same, "%s equals the finished study's (largest difference %.2g of its tolerance)"
           % (name, worst))

# A reused case run with another pressure is refused.
summary_file = os.path.join(copy, "cases", "P0.5MPa_matrix", "summary.json")
summary = json.load(open(summary_file))
summary["pressure"] = 1e6
json.dump(summary, open(summary_file, "w"))
bad = subprocess.run([tribodyn, prm], cwd=work, env=env, capture_output=True, text=True)
message = bad.stdout + bad.stderr
report(bad.returncode != 0 and "Reuse finished cases" in message and "P0.5MPa_matrix" in message
       and "pressure" in message,
       "a reused case with another pressure is refused naming the parameter and the case "
       "(exit %d)" % bad.returncode)
sys.exit(0 if ok else 1)
