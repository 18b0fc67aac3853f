#!/usr/bin/env python3
"""The closed bridge's tables (issue #50 item 3) are the data kept in
data/automata_friction_table_closed{,.static}.

    check_friction_table_data.py SOURCE_DIR

- both PROVENANCE files name a commit;
- mu_table.csv is what the kept scenes give: each row's mu and its error
  from the sliding study's scenes.csv (one seed: mu_steady and its
  standard error), the speed-0 row from the static scenes' summary.json
  (mu_peak), exactly (repr of the same doubles);
- the user guide's table of the automata's mu (doc/user_guide/contact.md,
  "The bridge closed") is mu_table.csv to the quoted digits, row by row;
- the pin's table in the user guide and in the README is the kept pin runs
  (pins/LAW_SEED/summary.json, three repeats a law): mu_global_mean and
  mu_contact_mean as mean +- standard error of the repeats (3 decimals), the
  stick/slip/separation fractions' means, the spectrum peak's mean +-
  standard error in kHz (1 decimal), and the range of the tabulated runs'
  share read outside the table (3 decimals, in %).
"""
import csv
import json
import math
import os
import re
import statistics
import sys

source = sys.argv[1]
data = os.path.join(source, "data", "automata_friction_table_closed")
static = data + ".static"
failures = []


def check(condition, what):
    print(("PASS  " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def flat(path):
    return " ".join(open(path).read().split())


guide = flat(os.path.join(source, "doc", "user_guide", "contact.md"))
readme = flat(os.path.join(source, "README.md"))
for d in (data, static):
    provenance = open(os.path.join(d, "PROVENANCE")).read()
    check(re.search(r"^commit: [0-9a-f]{40}", provenance, re.M) is not None,
          os.path.basename(d) + "/PROVENANCE names the commit")

# mu_table.csv against the scenes
with open(os.path.join(data, "mu_table.csv")) as f:
    table = list(csv.DictReader(line for line in f if not line.startswith("#")))
scenes = list(csv.DictReader(open(os.path.join(data, "scenes.csv"))))
statics = list(csv.DictReader(open(os.path.join(static, "scenes.csv"))))
P, V = "Friction loading/Pressure", "Friction loading/Sliding velocity"
for row in table:
    p, v = float(row["pressure"]), float(row["speed"])
    if v == 0:
        (scene,) = [s for s in statics if float(s[P]) == p]
        with open(os.path.join(static, "scenes", scene["scene"], "summary.json")) as f:
            expected = (json.load(f)["mu_peak"], 0.0)
    else:
        (scene,) = [s for s in scenes if float(s[P]) == p and float(s[V]) == v]
        expected = (float(scene["mu_steady"]), float(scene["mu_steady_stderr"]))
    check((float(row["mu"]), float(row["mu_stderr"])) == expected,
          "mu_table.csv at %g Pa, %g m/s = the kept scene's %r" % (p, v, expected))

# the user guide's table of mu(P, V)
pressures = sorted({float(r["pressure"]) for r in table})
speeds = sorted({float(r["speed"]) for r in table})
cell = {(float(r["pressure"]), float(r["speed"])): r for r in table}
for p in pressures:
    parts = ["%d MPa" % round(p / 1e6)]
    for v in speeds:
        r = cell[(p, v)]
        text = "%.3f" % float(r["mu"]) if v == 0 else \
            "%.3f ± %.3f" % (float(r["mu"]), float(r["mu_stderr"]))
        if v > 0 and int(r["n_steady"]) < int(r["n_seeds"]):
            text += " (not steady)"
        parts.append(text)
    line = "| " + " | ".join(parts) + " |"
    check(line in guide, "user guide: " + line)

# the pin's runs
runs = {}
for law in ("tabulated", "regularized", "rate_and_state"):
    runs[law] = []
    for seed in (1, 2, 3):
        with open(os.path.join(data, "pins", "%s_%d" % (law, seed), "summary.json")) as f:
            runs[law].append(json.load(f))


def mean_error(values, digits):
    m = statistics.mean(values)
    e = statistics.stdev(values) / math.sqrt(len(values))
    return "%.*f ± %.*f" % (digits, m, digits, e)


labels = {"tabulated": ("tabulated (automata, the closed table)",
                        "tabulated (automata, closed table)"),
          "regularized": ("regularized, μ = 0.25", "regularized, μ = 0.25"),
          "rate_and_state": ("rate and state (μ0 = 0.25, a = 0.01, b = 0.015, D_c = 1 µm)",
                             "rate and state (μ0 = 0.25, b − a = 0.005)")}
for law, S in runs.items():
    mu = mean_error([s["mu_global_mean"] for s in S], 3)
    contact = mean_error([s["mu_contact_mean"] for s in S], 3)
    fractions = [statistics.mean(s[k] for s in S)
                 for k in ("stick_fraction", "slip_fraction", "separation_fraction")]
    peak = mean_error([s["dominant_frequency_hz"] / 1e3 for s in S], 1) + " kHz"
    digits = 3 if law == "tabulated" else 2
    fr = " / ".join("%.*f" % (digits, x) for x in fractions)
    regimes = {s["regime_contact_face"] for s in S}
    regime = (regimes.pop().replace("-", "–") + " (3)") if len(regimes) == 1 else None
    outside = "—"
    if law == "tabulated":
        shares = sorted(100 * s["tabulated_clamped_fraction"] for s in S)
        outside = "**%.3f–%.3f %%**" % (shares[0], shares[-1])
    line = "| %s | %s | %s | %s | %s | %s | %s |" % (labels[law][0], mu, contact, fr,
                                                     regime, peak, outside)
    check(line in guide, "user guide: " + line)
    line = "| %s | %s | %s | %s | %s |" % (labels[law][1], mu, contact, fr, peak)
    check(line in readme, "README: " + line)

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
