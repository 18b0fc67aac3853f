#!/usr/bin/env python3
"""Fuzz test of the shipped parameter files (issue #10, doc/stability.md).

Each case takes one shipped prm file, replaces ONE number of one 'set'
line (a number inside a list counts) by a perturbation (sign flip, zero,
x1e3, x1e-3, 1e300, -1e300, 1e-300, nan, inf, -inf, text, -1), caps the
simulated time so that cases stay short (contact: End time 2 us and
averaging from 0; mca: End time 2e-11 s) unless the perturbed number is the
end time itself, and runs tribodyn with a timeout. A case passes when:
  - exit 0 and summary.json is complete JSON whose numbers are all finite
    (tribodyn writes a non-finite number as null; null is allowed only for
    the keys that are undefined by design, NULLABLE below); or
  - exit 2 (refused) with a message on stderr naming the perturbed
    parameter (its name, e.g. 'Pressure'), and no summary.json; or
  - exit 3 (the run stopped: unstable, automata leaving the box...) with a
    message, and no summary.json.
Anything else fails: a crash (signal, exit 4 'internal error'), a timeout
without advancing progress lines (a hang), a refusal that does not name
the parameter, a partial summary.json. A timeout whose progress lines were
still advancing is a long run (the perturbation asked for much more work,
e.g. an end time 1000 x longer) and is reported as such, not as a failure.

Only prm files whose capped, unperturbed run succeeds are used (the seed
scale mca scene and the full Table 2 study are skipped: too large).

Usage:
  fuzz.py TRIBODYN [--cases N] [--seed S] [--timeout SECONDS]
          [--work DIR] [--jobs J] [--report FILE]
Exit code 0 when every case passes. The report (CSV) lists every case.
"""
import argparse
import concurrent.futures
import glob
import json
import os
import random
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))
SKIP = {"friction_seed_scale.prm", "table2.prm"}
NUMBER = re.compile(
    r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![\w.])")
PERTURBATIONS = ["flip", "zero", "big", "small", "1e300", "-1e300", "1e-300",
                 "nan", "inf", "-inf", "text", "-1"]


def read_entries(text):
    """(line index, section path, name, value span) of every 'set' line."""
    entries, sections = [], []
    lines = text.split("\n")
    k = 0
    while k < len(lines):
        line = lines[k].split("#")[0]
        stripped = line.strip()
        if stripped.startswith("subsection "):
            sections.append(stripped[11:].strip())
        elif stripped == "end" and sections:
            sections.pop()
        elif stripped.startswith("set ") and "=" in stripped:
            first = k
            while lines[k].rstrip().endswith("\\") and k + 1 < len(lines):
                k += 1
            name = stripped[4:stripped.index("=")].strip()
            entries.append((first, k, "/".join(sections + [name]), name))
        k += 1
    return lines, entries


def perturb(token, kind):
    x = float(token)
    return {"flip": repr(-x) if x != 0 else "-1", "zero": "0",
            "big": repr(x * 1e3) if x != 0 else "1e3",
            "small": repr(x * 1e-3) if x != 0 else "1e-3",
            "text": "abc"}.get(kind, kind)


def caps(problem, path_name):
    """Lines appended to keep the run short (unless the end time itself is
    the perturbed parameter)."""
    if problem in ("contact", "study"):
        if path_name.endswith("Time/End time"):
            return ""
        return ("subsection Time\n  set End time = 2e-6\nend\n"
                "subsection Output\n  set Averaging start time = 0\n"
                "  set Averaging end time = -1\nend\n")
    if problem == "mca":
        if path_name == "Time/End time":
            return ""
        return "subsection Time\n  set End time = 2e-11\nend\n"
    return ""


def problem_of(text):
    m = re.search(r"^\s*set\s+Problem\s*=\s*(\w+)", text, re.M)
    return m.group(1) if m else "homogenization"


def run_case(tribodyn, case, timeout):
    os.makedirs(case["dir"], exist_ok=True)
    prm = os.path.join(case["dir"], "case.prm")
    with open(prm, "w") as f:
        f.write(case["text"])
        f.write(f"\nset Output directory = {case['dir']}/out\n")
        f.write(case["caps"])
    try:
        r = subprocess.run([tribodyn, prm], cwd=ROOT, capture_output=True,
                           text=True, timeout=timeout)
        code, err = r.returncode, r.stderr
    except subprocess.TimeoutExpired as e:
        code = "timeout"
        text = [(x or b"").decode() if isinstance(x, bytes) else (x or "")
                for x in (e.stdout, e.stderr)]
        err = text[1]
        case["progress"] = progress_percentages(text[0])
    summary = os.path.join(case["dir"], "out", "summary.json")
    verdict = judge(code, err, summary, case)
    return code, err, verdict


def progress_percentages(stdout):
    """The step numbers of the progress lines ('contact: step N  t = ...')
    printed before the timeout."""
    values = []
    for line in stdout.splitlines():
        m = re.search(r": step (\d+) ", line)
        if m:
            values.append(float(m.group(1)))
    return values


# Summary keys that are null by design: no contact happened, no layer
# formed, no seed value for a pressure of table 2. Any other null is a NaN
# or inf result.
NULLABLE = {"contact_time", "plastic_strain_layer_center",
            "plastic_strain_layer_thickness", "quasi_fluid_layer_center",
            "quasi_fluid_layer_thickness", "quasi_fluid_layer_thickness_final",
            "seed_mu"}


def _refuse_constant(name):
    raise ValueError("non-finite number " + name)


def non_finite_keys(value, path=""):
    """Keys of VALUE (parsed JSON) holding null outside NULLABLE."""
    if isinstance(value, dict):
        return [k for key, v in value.items()
                for k in non_finite_keys(v, path + "/" + key if path else key)]
    if isinstance(value, list):
        return [k for i, v in enumerate(value)
                for k in non_finite_keys(v, "%s[%d]" % (path, i))]
    if value is None and path.split("/")[-1] not in NULLABLE:
        return [path]
    return []


def judge(code, err, summary, case):
    has_summary = os.path.exists(summary)
    if has_summary:
        try:
            with open(summary) as f:
                parsed = json.load(f, parse_constant=_refuse_constant)
        except ValueError as e:
            return "FAIL partial or non-finite summary.json (%s)" % e
        bad = non_finite_keys(parsed)
        if bad:
            return "FAIL non-finite results in summary.json: " + ", ".join(bad[:5])
    if code == "timeout":
        # Not a hang when the run was still advancing: the perturbation
        # asked for much more work (e.g. an end time 1000 x longer).
        p = case.get("progress", [])
        if len(p) >= 2 and p[-1] > p[0]:
            return (f"pass (long run: progressing, step {p[-1]:.0f} "
                    "at the timeout)")
        return "FAIL timeout (no progress line advancing)"
    if code == 0:
        return "pass (ran)" if has_summary else "FAIL no summary.json"
    if has_summary:
        return "FAIL summary.json left by a failed run"
    if code == 2:
        if case["name"].lower() in err.lower():
            return "pass (refused, names it)"
        return "FAIL refused without naming the parameter"
    if code == 3:
        return "pass (run stopped)" if "tribodyn:" in err else \
            "FAIL exit 3 without message"
    return f"FAIL exit {code}"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("tribodyn")
    parser.add_argument("--cases", type=int, default=200)
    parser.add_argument("--seed", type=int, default=10)
    parser.add_argument("--timeout", type=float, default=60)
    parser.add_argument("--work", default="/tmp/tribodyn-fuzz")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--report", default="")
    parser.add_argument("--prm", nargs="*", default=None,
                        help="prm files (default: the shipped ones)")
    parser.add_argument("--no-baseline", action="store_true",
                        help="use every given prm file without running it "
                             "unperturbed first")
    args = parser.parse_args()
    tribodyn = os.path.abspath(args.tribodyn)
    shutil.rmtree(args.work, ignore_errors=True)

    files = args.prm or sorted(glob.glob(os.path.join(ROOT, "prm", "*",
                                                      "*.prm")))
    files = [f for f in files if os.path.basename(f) not in SKIP]
    bases = []
    for f in files:
        text = open(f).read()
        problem = problem_of(text)
        case = {"dir": os.path.join(args.work, "baseline",
                                    os.path.basename(f)[:-4]),
                "text": text, "caps": caps(problem, ""), "name": ""}
        code = 0
        if not args.no_baseline:
            code, err, _ = run_case(tribodyn, case, args.timeout)
            print(f"baseline {os.path.relpath(f, ROOT)}: exit {code}")
        if code == 0:
            bases.append((f, text, problem))
    rng = random.Random(args.seed)
    cases = []
    for n in range(args.cases):
        f, text, problem = rng.choice(bases)
        lines, entries = read_entries(text)
        numeric = [e for e in entries
                   if NUMBER.search("\n".join(lines[e[0]:e[1] + 1])
                                    .split("=", 1)[1])]
        first, last, path, name = rng.choice(numeric)
        block = "\n".join(lines[first:last + 1])
        head, value = block.split("=", 1)
        tokens = list(NUMBER.finditer(value))
        token = rng.choice(tokens)
        kind = rng.choice(PERTURBATIONS)
        new = perturb(token.group(0), kind)
        value = value[:token.start()] + new + value[token.end():]
        new_lines = lines[:first] + (head + "=" + value).split("\n") + \
            lines[last + 1:]
        cases.append({"dir": os.path.join(args.work, f"case_{n:04d}"),
                      "text": "\n".join(new_lines),
                      "caps": caps(problem, path), "name": name,
                      "path": path, "file": os.path.relpath(f, ROOT),
                      "change": f"{token.group(0)} -> {new}"})
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(
            lambda c: run_case(tribodyn, c, args.timeout), cases))
    failures = 0
    rows = ["case,file,parameter,change,exit,verdict,message"]
    counts = {}
    for n, (case, (code, err, verdict)) in enumerate(zip(cases, results)):
        counts[verdict] = counts.get(verdict, 0) + 1
        message = " ".join(err.split())[:300].replace(",", ";")
        rows.append(f"{n},{case['file']},{case['path']},{case['change']},"
                    f"{code},{verdict},{message}")
        if verdict.startswith("FAIL"):
            failures += 1
            print(f"case {n}: {case['file']} {case['path']}: "
                  f"{case['change']}: exit {code}: {verdict}\n  {message}")
    if args.report:
        with open(args.report, "w") as f:
            f.write("\n".join(rows) + "\n")
    print(f"{len(cases)} cases over {len(bases)} prm files:")
    for verdict, count in sorted(counts.items()):
        print(f"  {count:4d}  {verdict}")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
