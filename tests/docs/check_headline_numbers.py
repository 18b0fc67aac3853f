#!/usr/bin/env python3
"""The docs' headline numbers are those the code prints (issue #22).

Runs the fast examples whose figures the README and the user guides quote
(each 1 to 25 s on one rank), then checks that the quoted
text is exactly what this build writes:

- prm/homogenization/default.prm: every row of the README's table of
  effective constants (KUBC, SUBC, periodic, Voigt, Reuss) equals
  effective_properties.csv rounded to the digits the README prints;
- prm/mca/uniaxial_steel.prm: 'E = ... GPa' and 'sigma_y = ... MPa' (three
  decimals) in README.md and doc/user_guide/mca.md;
- prm/mca/two_body_friction.prm and _carbon: the mean friction coefficient
  (six decimals) in doc/user_guide/mca.md;
- prm/contact/homogeneous_matrix.prm and homogenized.prm: mu_global_mean
  (three decimals) and the stick/slip/separation fractions (two) of the
  README's contact table.

A changed result makes the quoted text stale and this test fail: rerun the
example and update the docs. Usage: check_headline_numbers.py TRIBODYN
SOURCE_DIR WORK_DIR
"""
import csv
import json
import os
import re
import shutil
import subprocess
import sys

tribodyn, source, work = sys.argv[1:4]
failures = []


def run(prm):
    """Run SOURCE/prm into WORK/<name>; returns the output directory."""
    name = os.path.splitext(os.path.basename(prm))[0]
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    path = os.path.join(work, name + ".prm")
    with open(path, "w") as f:
        f.write(f"include {os.path.join(source, prm)}\n"
                f"set Output directory = {out}\n"
                f"set Progress interval = 1000\n")
    r = subprocess.run([tribodyn, path], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"FAIL: {prm} exited with {r.returncode}: {r.stderr[-800:]}")
    return out


def doc(name):
    with open(os.path.join(source, name)) as f:
        return f.read()


def expect(doc_name, text, what, printed=None):
    """The doc quotes text, or (a verbatim quote of the run's output) the
    form the run prints, printed."""
    body = doc(doc_name)
    ok = text in body or (printed is not None and printed in body)
    print(("PASS  " if ok else "FAIL  ") + f"{doc_name} quotes '{text}'"
          + (f" or '{printed}'" if printed else "") + f" ({what})")
    if not ok:
        failures.append(doc_name)


os.makedirs(work, exist_ok=True)

# Homogenization: the README's table.
out = run("prm/homogenization/default.prm")
rows = {r["estimate"]: r for r in
        csv.DictReader(open(os.path.join(out, "effective_properties.csv")))}
readme = doc("README.md")
for name, row in rows.items():
    label = {"kubc": "KUBC", "subc": "SUBC"}.get(name.lower(), name)
    match = re.search(r"^%s\s+([-\d.\s]+)$" % re.escape(label), readme,
                      re.M | re.I)
    if not match:
        print(f"FAIL  README.md has no row '{label}' of effective constants")
        failures.append("README.md")
        continue
    quoted = match.group(1).split()
    for key, text in zip(("E_L", "E_T", "G_LT", "nu_LT", "nu_TT"), quoted):
        digits = len(text.split(".")[1]) if "." in text else 0
        value = float(row[key]) / (1e9 if key[0] in "EG" else 1)
        ok = f"{value:.{digits}f}" == text
        print(("PASS  " if ok else "FAIL  ") + f"README.md {label} {key} "
              f"{text} (this build: {value:.{digits + 2}f})")
        if not ok:
            failures.append("README.md")

# MCA uniaxial test.
s = json.load(open(os.path.join(run("prm/mca/uniaxial_steel.prm"),
                                "summary.json")))
for name in ("README.md", "doc/user_guide/mca.md"):
    expect(name, f"E = {s['youngs_modulus'] / 1e9:.3f} GPa", "uniaxial_steel")
    expect(name, f"sigma_y = {s['yield_stress'] / 1e6:.3f} MPa",
           "uniaxial_steel", f"sigma_y = {s['yield_stress'] / 1e6:.6g} MPa")

# MCA friction examples.
for prm in ("two_body_friction", "two_body_friction_carbon"):
    s = json.load(open(os.path.join(run(f"prm/mca/{prm}.prm"),
                                    "summary.json")))
    expect("doc/user_guide/mca.md", f"{s['mean_friction_coefficient']:.6f}",
           prm)

# Contact: the README's table of the homogeneous pins (~25 s each).
for prm, row in (("homogeneous_matrix", "homogeneous, matrix properties"),
                 ("homogenized", "homogeneous, homogenized properties")):
    s = json.load(open(os.path.join(run(f"prm/contact/{prm}.prm"),
                                    "summary.json")))
    expect("README.md", f"| {row} | {s['mu_global_mean']:.3f} | "
           f"{s['stick_fraction']:.2f} / {s['slip_fraction']:.2f} / "
           f"{s['separation_fraction']:.2f} |", prm)

print(f"{len(failures)} stale quote(s)" if failures else "docs match the code")
sys.exit(1 if failures else 0)
