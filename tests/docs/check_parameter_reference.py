#!/usr/bin/env python3
"""The parameter reference in doc/parameters/ is what this build prints
(issue #52 item 3's acceptance: a test fails when it is stale).

    check_parameter_reference.py TRIBODYN SOURCE_DIR

For every problem `tribodyn --help` lists, `tribodyn --print-parameters
PROBLEM` must equal doc/parameters/PROBLEM.prm byte for byte, and no file
of doc/parameters/ may belong to a problem the build does not have. A
parameter declared, renamed or re-documented without regenerating the
reference fails here, with the diff and the fix (scripts/make_parameter_docs).
"""
import difflib
import os
import re
import subprocess
import sys

tribodyn, source = sys.argv[1:3]
reference = os.path.join(source, "doc", "parameters")
failures = []


def check(condition, what):
    print(("PASS  " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


help_text = subprocess.run([tribodyn, "--help"], check=True,
                           capture_output=True, text=True).stdout
problems = re.findall(r"^  ([a-z_]+): ", help_text.split("Problems:")[1],
                      re.M)
check(len(problems) >= 7, "tribodyn --help lists its problems: %s" % problems)
for problem in problems:
    printed = subprocess.run([tribodyn, "--print-parameters", problem],
                             check=True, capture_output=True,
                             text=True).stdout
    path = os.path.join(reference, problem + ".prm")
    kept = open(path).read() if os.path.exists(path) else ""
    same = printed == kept
    if not same:
        diff = difflib.unified_diff(kept.splitlines(), printed.splitlines(),
                                    "doc/parameters/%s.prm" % problem,
                                    "tribodyn --print-parameters %s" % problem,
                                    lineterm="", n=1)
        print("\n".join(list(diff)[:40]))
    check(same, "doc/parameters/%s.prm is what this build prints" % problem)
extra = sorted(f for f in os.listdir(reference)
               if f.endswith(".prm") and f[:-4] not in problems)
check(not extra, "no reference for a problem the build lacks: %s" % extra)
if failures:
    print("The parameter reference is stale: run scripts/make_parameter_docs "
          "and commit doc/parameters/.")
sys.exit(1 if failures else 0)
