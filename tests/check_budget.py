#!/usr/bin/env python3
"""Every test has a timeout, and tests/slow_tests.txt names only tests that
exist (issue #49 item 7).

Usage: check_budget.py CTEST BUILD_DIR SLOW_TESTS.txt

Reads ctest's own description of the suite (`ctest --show-only=json-v1`):
a test without a TIMEOUT property would run for ctest's default of 1500 s
before CI notices it hangs; a name in the slow list that no test has any
more means the list is stale (and the quick suite may have grown).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "scripts"))
import plot_tools  # noqa: E402  (ctest_tests: leaves the build's LastTest.log alone)


def main():
    ctest, build_dir, slow_file = sys.argv[1:4]
    tests = plot_tools.ctest_tests(build_dir, ctest)
    names = set()
    without_timeout = []
    for test in tests:
        names.add(test["name"])
        properties = {p["name"]: p["value"]
                      for p in test.get("properties", [])}
        if not properties.get("TIMEOUT"):
            without_timeout.append(test["name"])
    with open(slow_file) as f:
        slow = [line.strip() for line in f
                if line.strip() and not line.startswith("#")]
    unknown = [name for name in slow if name not in names]
    failures = 0
    if without_timeout:
        print("tests without a TIMEOUT: " + ", ".join(without_timeout))
        failures += 1
    if unknown:
        print(f"{slow_file} names tests that do not exist: "
              + ", ".join(unknown))
        failures += 1
    print(f"{len(names)} tests, all with a timeout; {len(slow)} slow, "
          f"{len(names) - len(slow)} quick" if failures == 0 else
          f"{failures} check(s) failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
