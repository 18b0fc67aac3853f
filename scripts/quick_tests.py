#!/usr/bin/env python3
"""The quick tests of `scripts/test --quick`, as one regex alternation.

Reads `ctest --show-only=json-v1` on stdin and tests/slow_tests.txt (argv[1]);
prints the names of the tests that are not slow and whose fixtures (the
outputs of other tests they read: tests/CMakeLists.txt tribodyn_test_reads)
are set up by quick tests only, recursively, joined by '|'. (ctest -E with the
slow names would run the checks without their slow producers: it adds
fixture set-ups only to tests selected by name.)
"""
import json
import sys

with open(sys.argv[1]) as f:
    slow = {line.strip() for line in f
            if line.strip() and not line.startswith("#")}
tests = json.load(sys.stdin)["tests"]


def fixtures(test, kind):
    for p in test.get("properties", []):
        if p["name"] == kind:
            return p["value"]
    return []


setup_by = {}
for t in tests:
    for fixture in fixtures(t, "FIXTURES_SETUP"):
        setup_by.setdefault(fixture, []).append(t["name"])
required = {t["name"]: fixtures(t, "FIXTURES_REQUIRED") for t in tests}


def quick(name, seen=()):
    if name in slow or name in seen:
        return name not in slow
    return all(quick(p, seen + (name,))
               for fixture in required.get(name, [])
               for p in setup_by.get(fixture, []))


print("|".join(t["name"] for t in tests if quick(t["name"])))
