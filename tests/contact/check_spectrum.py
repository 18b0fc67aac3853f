"""The run's spectrum recomputed from its own series (issue #49 item 4).

check_spectrum.py OUTPUT_DIR

From friction.csv (time, mu_global), independently of the code under test
(FFTW there, a radix-2 transform written here): the samples of the
averaging window (Output/Averaging start time .. end time, the count must be
summary.json's n_samples_averaged), less their mean, times a Hann window,
zero-padded to the first power of two >= 4 m; the amplitude 2 |X_k| / sum(w)
at f_k = k / (n dt_s). Checked against spectrum.csv bin by bin and against
summary.json's dominant_frequency_hz: the largest amplitude at f >= 2 / (m
dt_s) (the trend over the window ignored).

Only the samples on the cadence (every Output/Sample interval steps, dt_s
apart) are in a spectrum: the sample of the run's last step is off the grid
when the step count is not a multiple of the interval (tests/contact/
contact_face.prm: 4000 steps, samples every 20, the last at step 3999).

Tolerances. The frequencies are the same bins when the sample spacing is
(the CSV's times have 10 significant digits: 1e-9 relative). The amplitudes
are computed from mu_global as friction.csv writes it (10 significant
digits), so they agree with the code's to ~1e-9 of the largest amplitude
(measured 1.9e-10 and 2.6e-10 on contact_face.prm); 1e-6 of it is allowed.
With the off-grid last sample taken as on the grid (the code before this
test) the amplitudes differ by 2.8e-2 (mu_global) and 1.9e-2 (normal force)
of the peak: the test fails. The dominant
frequency must be the same bin: within a quarter of the bin width.
"""
import cmath
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "scripts"))
import plot_tools  # noqa: E402  (read_parameters)

out = sys.argv[1]
if os.path.isdir(os.path.join(out, "output")):
    out = os.path.join(out, "output")
with open(os.path.join(out, "summary.json")) as f:
    summary = json.load(f)
failures = []


def check(condition, what):
    print(("PASS  " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def fft(values):
    """Iterative radix-2 Cooley-Tukey (len(values) a power of two)."""
    n = len(values)
    a = list(values)
    j = 0
    for i in range(1, n):
        bit = n >> 1
        while j & bit:
            j ^= bit
            bit >>= 1
        j |= bit
        if i < j:
            a[i], a[j] = a[j], a[i]
    length = 2
    while length <= n:
        w = cmath.exp(-2j * math.pi / length)
        for start in range(0, n, length):
            wk = 1
            for k in range(length // 2):
                u = a[start + k]
                v = a[start + k + length // 2] * wk
                a[start + k] = u + v
                a[start + k + length // 2] = u - v
                wk *= w
        length <<= 1
    return a


AMPLITUDE_TOLERANCE = 1e-6


prm = plot_tools.read_parameters(out)
t0 = float(prm["Output/Averaging start time"])
t1 = float(prm["Output/Averaging end time"])
if t1 < 0:
    t1 = math.inf
with open(os.path.join(out, "friction.csv")) as f:
    rows = [r for r in csv.DictReader(f)]
window = [r for r in rows if t0 <= float(r["time"]) <= t1]
check(len(window) == summary["n_samples_averaged"],
      "%d samples in the averaging window [%g, %g] s, as summary.json's n_samples_averaged (%d)"
      % (len(window), t0, t1, summary["n_samples_averaged"]))
# the samples of the regular cadence (the run's last step, sampled at its
# end, is off that grid unless the step count is a multiple of it)
interval = int(prm["Output/Sample interval"])
dt = summary["dt"]
window = [r for r in window if round(float(r["time"]) / dt) % interval == 0]
m = len(window)
spacing = interval * dt
times = [float(r["time"]) for r in window]
worst_t = max(abs((b - a) - spacing) for a, b in zip(times, times[1:])) / spacing
check(worst_t < 1e-6, "%d samples on the cadence, %g s apart (largest deviation %.1e of it)"
      % (m, spacing, worst_t))
n = 1
while n < 4 * m:
    n <<= 1
hann = [0.5 * (1 - math.cos(2 * math.pi * i / (m - 1))) for i in range(m)]
frequency = [k / (n * spacing) for k in range(n // 2 + 1)]
bin_width = 1 / (n * spacing)
f_min = 2 / (m * spacing)


def check_series(column, spectrum_file, key):
    """The spectrum of friction.csv's @p column against @p spectrum_file and
    summary.json's @p key."""
    if not os.path.exists(os.path.join(out, spectrum_file)):
        return
    series = [float(r[column]) for r in window]
    mean = sum(series) / m
    data = [(series[i] - mean) * hann[i] for i in range(m)] + [0.0] * (n - m)
    transform = fft(data)
    amplitude = [2 * abs(transform[k]) / sum(hann) for k in range(n // 2 + 1)]
    with open(os.path.join(out, spectrum_file)) as f:
        theirs = [(float(r["frequency_hz"]), float(r["amplitude"]))
                  for r in csv.DictReader(f)]
    check(len(theirs) == len(amplitude),
          "%s has the %d bins of n = %d" % (spectrum_file, len(amplitude), n))
    peak = max(amplitude)
    worst_f = max(abs(a[0] - b) / b for a, b in zip(theirs[1:], frequency[1:]))
    worst_a = max(abs(a[1] - b) for a, b in zip(theirs, amplitude)) / peak
    check(worst_f < 1e-6, "%s: the frequencies are the bins k / (n dt_s) "
          "(largest relative difference %.1e)" % (spectrum_file, worst_f))
    check(worst_a < AMPLITUDE_TOLERANCE,
          "%s: the amplitudes of %s recomputed (largest difference %.1e of the peak %.3g)"
          % (spectrum_file, column, worst_a, peak))
    best = max((a, f) for f, a in zip(frequency[1:], amplitude[1:]) if f >= f_min)
    check(abs(best[1] - summary[key]) < 0.25 * bin_width,
          "%s: dominant frequency %.6g Hz = summary.json's %.6g Hz (bin width %.3g Hz)"
          % (column, best[1], summary[key], bin_width))


check_series("mu_global", "spectrum.csv", "dominant_frequency_hz")
check_series("contact_normal_force", "spectrum_normal_force.csv",
             "normal_force_dominant_frequency_hz")
sys.exit(1 if failures else 0)
