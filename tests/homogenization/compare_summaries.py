"""The same map as PNG and as TIFF gives identical results (issue #19).

Compares the summary.json of two runs (arguments: the two test
directories): the morphology's phase fractions, and C, c_z and the five
constants of every boundary condition must be equal to the last bit (the
two files hold the same pixels, so the runs do the same arithmetic).
"""
import json
import os
import sys


def load(directory):
    with open(os.path.join(directory, "output", "summary.json")) as f:
        return json.load(f)


a, b = load(sys.argv[1]), load(sys.argv[2])
failures = 0
for bc in ["KUBC", "SUBC", "periodic"]:
    for key in ["C", "c_z", "E_L", "E_T", "G_LT", "nu_LT", "nu_TT", "kappa",
                "mu"]:
        same = a[bc][key] == b[bc][key]
        print(("PASS  " if same else "FAIL  ") + "%s %s: %s vs %s"
              % (bc, key, a[bc][key], b[bc][key]))
        failures += not same
fa = [p["fraction"] for p in a["phases"]]
fb = [p["fraction"] for p in b["phases"]]
print(("PASS  " if fa == fb else "FAIL  ") + "fractions %s vs %s" % (fa, fb))
failures += fa != fb
sys.exit(1 if failures else 0)
