"""Shared helpers of the MCA check scripts (tests/mca/*.py): PASS/FAIL lines
and the one output directory of a run. A script imports them (its own
directory is on Python's path), reports each check and ends with finish(),
which exits with 1 when any check failed."""
import os
import sys

_failed = False


def report(good, text):
    """Print a PASS or FAIL line; a FAIL makes finish() exit with 1."""
    global _failed
    _failed = _failed or not good
    print(("PASS  " if good else "FAIL  ") + text)


def finish():
    sys.exit(1 if _failed else 0)


def output_directory(root):
    """The one directory under ROOT holding a summary.json (a run's output);
    FAIL and exit when there is not exactly one."""
    dirs = sorted(folder for folder, _, files in os.walk(root)
                  if "summary.json" in files)
    report(len(dirs) == 1, "one output directory in %s: %s" % (root, dirs))
    if len(dirs) != 1:
        finish()
    return dirs[0]
