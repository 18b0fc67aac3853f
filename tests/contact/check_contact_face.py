"""Check the contact-face outputs of tests/contact/contact_face.prm.

contact_face_lambda_n.csv, _lambda_t.csv and _status.csv: a header 'time'
then the x of the 57 contact nodes (h = 0.5 mm on 28 mm) in increasing
order; one row every 2 samples; the row sums of lambda_N and lambda_T equal
the contact_normal_force and contact_tangential_force columns of
friction.csv at the same times (1e-6 relative: 8 significant digits are
written); the statuses are 0, 1, 2 and their fractions equal
contact_status.csv's; no '.part' file is left. spectrum_normal_force.csv
exists and summary.json has normal_force_dominant_frequency_hz and
regime_contact_face. Before the plane starts (4 us) the pin is pressed on a
plane at rest: its lateral expansion makes edge nodes slip outwards, but by
symmetry the friction forces cancel (sum of lambda_T below 1e-6 of the sum
of lambda_N).
"""
import csv
import json
import os
import sys

out = os.path.join(sys.argv[1], "output")
failures = []


def check(condition, what):
    print(("PASS  " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def read(name):
    with open(os.path.join(out, name)) as f:
        return list(csv.reader(f))


ln, lt, st = (read("contact_face_" + q + ".csv") for q in ["lambda_n", "lambda_t", "status"])
x = [float(v) for v in ln[0][1:]]
check(ln[0][0] == "time" and len(x) == 57, "header: time + 57 node coordinates")
check(all(a < b for a, b in zip(x, x[1:])), "nodes in increasing x")
check(ln[0] == lt[0] == st[0], "the three files share the header")
friction = {round(float(r["time"]) * 1e12): r for r in
            csv.DictReader(open(os.path.join(out, "friction.csv")))}
status = {round(float(r["time"]) * 1e12): r for r in
          csv.DictReader(open(os.path.join(out, "contact_status.csv")))}
check(len(ln) - 1 == (len(friction) + 1) // 2, "one row every 2 samples (%d rows, %d samples)"
      % (len(ln) - 1, len(friction)))
worst = 0.0
for rn, rt, rs in zip(ln[1:], lt[1:], st[1:]):
    key = round(float(rn[0]) * 1e12)
    f = friction[key]
    sn = sum(float(v) for v in rn[1:])
    stt = sum(float(v) for v in rt[1:])
    scale = max(abs(float(f["contact_normal_force"])), 1e-3)
    worst = max(worst, abs(sn - float(f["contact_normal_force"])) / scale,
                abs(stt - float(f["contact_tangential_force"])) / scale)
    s = [int(float(v)) for v in rs[1:]]
    frac = [s.count(k) / len(s) for k in (1, 2, 0)]
    ref = [float(status[key][c]) for c in ("stick_fraction", "slip_fraction",
                                            "separation_fraction")]
    if any(abs(a - b) > 1e-9 for a, b in zip(frac, ref)):
        worst = max(worst, 1.0)
    if float(rn[0]) < 4e-6 and abs(stt) > 1e-6 * max(sn, 1e-3):
        worst = max(worst, 1.0)
check(worst < 1e-6, "row sums = friction.csv forces, status fractions = contact_status.csv, "
      "no net friction before the plane starts (worst %g)" % worst)
check(not any(n.endswith(".part") for n in os.listdir(out)), "no .part file left")
check(os.path.isfile(os.path.join(out, "spectrum_normal_force.csv")),
      "spectrum_normal_force.csv written")
s = json.load(open(os.path.join(out, "summary.json")))
for key in ["normal_force_dominant_frequency_hz", "regime_contact_face", "regime_threshold"]:
    check(key in s, "summary.json has " + key)
if failures:
    sys.exit("%d check(s) failed" % len(failures))
