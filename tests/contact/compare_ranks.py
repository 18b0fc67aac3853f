"""friction.csv of the 1-rank and 2-rank runs of short_pin.prm agree to 1e-9
(relative to each column's largest value)."""
import csv
import os
import sys

base = sys.argv[1]


def read(directory):
    with open(os.path.join(directory, "output", "friction.csv")) as f:
        return list(csv.DictReader(f))


a, b = read(base + "_1rank"), read(base + "_2ranks")
if len(a) != len(b):
    sys.exit("FAIL  different numbers of rows")
worst = 0
for column in ["mu_global", "contact_normal_force", "contact_tangential_force",
               "kinetic_energy", "elastic_energy"]:
    scale = max(abs(float(r[column])) for r in a) or 1
    worst = max(worst, max(abs(float(x[column]) - float(y[column])) / scale
                           for x, y in zip(a, b)))
print(("PASS" if worst < 1e-9 else "FAIL") + "  2 ranks = 1 rank (%.2e)" % worst)
sys.exit(0 if worst < 1e-9 else 1)
