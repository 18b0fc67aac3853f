"""Includes at two depths, each relative to the file that names it
(tests/core/includes/nested.prm -> level1/pin.prm ->
../../../contact/short_pin.prm): the run reads every level, the later
settings overriding the earlier ones. Checked on the parameters.prm the run
wrote (the input as it was read): End time 6e-6 (nested.prm), Pressure 4e5
(level1/pin.prm), Ramp time 2e-6 and Averaging start time 4e-6
(short_pin.prm; their defaults are 1e-5 and 0), and the run's summary ends
at 6e-6. Before 2026-12-01 the second include was read from the working
directory and the run was refused ('cannot open include file')."""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "scripts"))
import plot_tools  # noqa: E402  (read_parameters)

out = os.path.join(sys.argv[1], "output")
prm = plot_tools.read_parameters(out)
failed = False
for path, value in [("Time/End time", 6e-6), ("Loading/Pressure", 4e5),
                    ("Loading/Ramp time", 2e-6), ("Output/Averaging start time", 4e-6)]:
    good = path in prm and float(prm[path]) == value
    failed = failed or not good
    print(("PASS  " if good else "FAIL  ") + "%s = %s (expected %g)"
          % (path, prm.get(path), value))
with open(os.path.join(out, "summary.json")) as f:
    s = json.load(f)
good = s["end_time"] == 6e-6
failed = failed or not good
print(("PASS  " if good else "FAIL  ") + "the run ends at %g s" % s["end_time"])
sys.exit(1 if failed else 0)
