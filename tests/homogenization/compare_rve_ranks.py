"""The RVE study gives the same rve.csv on 1 rank (one group) as on 2 ranks
(two groups, windows round-robin): every window is solved on one rank
either way, so means and standard deviations agree to round-off (1e-12
relative); a window lost or counted twice in the gather would change them.
Arguments: the two test directories."""
import csv
import os
import sys


def load(directory):
    with open(os.path.join(directory, "output", "rve.csv")) as f:
        return list(csv.DictReader(f))


a, b = load(sys.argv[1]), load(sys.argv[2])
failures = 0 if len(a) == len(b) else 1
print(("PASS  " if not failures else "FAIL  ") + "%d vs %d rows" % (len(a), len(b)))
for ra, rb in zip(a, b):
    for key in ["mean", "std"]:
        x, y = float(ra[key]), float(rb[key])
        same = abs(x - y) <= 1e-12 * max(abs(x), abs(y), 1e-300)
        if not same:
            print("FAIL  %s %s %s: %r vs %r" % (ra["property"],
                  ra["boundary_condition"], key, x, y))
            failures += 1
print("PASS  means and stds agree" if failures == 0 else
      "%d differences" % failures)
sys.exit(1 if failures else 0)
