"""Pulse time of flight returns c_p (prm/mca/wave_pulse.prm and the
longer pulse of wave_pulse_long.prm). The lattice is dispersive: the peak
of a pulse of length l travels at the group velocity, slower than c_p by
~(pi h / l)^2 / 2 (h = a/2 the layer spacing). Tolerances: 2 % for the
example's pulse (l ~ 22 layers), 0.8 % for the pulse twice as long, and
the error must shrink by at least a factor 1.5 from the first to the
second (measured: 1.24 % -> 0.69 %; the pulse also broadens on its way, so
the peak delay is not purely second order in h / l)."""
import json
import os
import sys

build = os.path.dirname(sys.argv[1])
errors = []
ok = True
for test, folder, tol in [("mca_wave_pulse", "output/mca/wave_pulse", 0.02),
                          ("mca_wave_pulse_long", "output-mca-wave-pulse-long", 0.008)]:
    with open(os.path.join(build, test, folder, "summary.json")) as f:
        s = json.load(f)
    e = abs(s["wave_speed"] - s["p_wave_speed_reference"]) / s["p_wave_speed_reference"]
    errors.append(e)
    good = e <= tol
    ok = ok and good
    print(("PASS  " if good else "FAIL  ") + "%s: c = %.2f m/s vs c_p = %.2f m/s, error %.4f (tolerance %g)"
          % (test, s["wave_speed"], s["p_wave_speed_reference"], e, tol))
good = errors[1] * 1.5 <= errors[0]
ok = ok and good
print(("PASS  " if good else "FAIL  ") + "error shrinks: %.4f -> %.4f" % tuple(errors))
sys.exit(0 if ok else 1)
