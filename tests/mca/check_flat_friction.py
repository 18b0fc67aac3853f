"""Macroscopic friction of two flat elastic blocks against the interface mu
(issue #8, item 6): tests/mca/flat_friction*.prm, derivation in
doc/theory/mca.md Sec. 8.6.

The bodies meet on a (001) plane of the FCC lattice (cube axes along x, y,
z) in registry: every interface automaton of the upper body sits in the
hollow of four lower ones, its four cross-interface pairs inclined at 45
degrees to z. Sliding along y ([100]) carries it straight over the lower
automaton ahead (on-top path, period a = d sqrt 2): it is then in contact
with that one automaton only, whose pair normal makes the angle alpha with
z, sin(alpha) = (a/2 - delta)/d for the relative displacement delta in
[0, a), so alpha runs from +45 (climbing) to -45 degrees (descending) and
the interface rises and falls by d (1 - 1/sqrt 2). Quasi-statically, with
Coulomb slip on that contact (friction angle phi = atan mu), the ratio of
the tangential to the normal force is tan(phi + alpha); averaged over a
period (uniform in delta, hence in time at a constant sliding velocity;
the elastic lag of the bodies averages out over a period, closed integral
of R dR = 0):

  mu_macro = (1/a) int_0^a tan(phi + alpha) d delta
           = (sin(phi)/sqrt 2) [atanh sin(phi + pi/4) - atanh sin(phi - pi/4)]

(0 for mu = 0: the climbs and descents cancel; 1.2465 mu for small mu;
0.3847 for mu = 0.3: a geometric part 0.085 on top of mu), and the mean of
the code's mu = |F_t|/|F_n| (friction.csv) is the mean of |tan(phi + alpha)|
(sqrt 2 - 1 = 0.4142 for mu = 0, 0.5298 for mu = 0.3).

Checked over the whole periods of relative sliding from 0.25 a on (the
ramp is over by then):
1. the period mean of the signed ratio -F_y/F_z of the top loading layer
   (series.csv) equals mu_macro within TOLERANCE;
2. the mean of friction.csv's mu equals the mean of |tan(phi + alpha)|
   within TOLERANCE;
3. the peak-to-peak relative rise of the layers equals d (1 - 1/sqrt 2)
   within RISE_TOLERANCE (the on-top path: the lattice geometry the
   derivation assumes).
TOLERANCE: the derivation is quasi-static with rigid automata;
measured deviations at +-1, +-2 m/s and Courant 0.1, 0.2 are <= 0.002
(mu = 0 and 0.3), 0.007 at +-5 m/s (inertia of the bodies and the viscous
drag of the damped layers change the normal force in time, not the
ratio); an ignored mu (0.3 -> 0), a doubled one (0.3 -> 0.6: 0.85), or the
plain mu without the geometric part (0.30) fail it. Per scene (issue #49:
within 10x of the measured deviation; measured 2026-11-30, the larger of
checks 1 and 2): mu = 0.3 2.5e-3 (0.0014, 0.0003), frictionless 5e-3 (0.0012); the
rate-and-state scenes below 0.01 (0.0026, 0.0025, 0.0050). At 2.5e-3 a
coefficient 2 % off (0.3 -> 0.306: mu_macro 0.3928) fails check 1
(difference -0.0068; shown 2026-11-30). RISE_TOLERANCE = 2 %:
measured 0.7 % below d (1 - 1/sqrt 2), the elastic overlap of the
contacts (a few 1e-3 d at the ~1 GPa pair stresses).

Not the summary's mu_steady: its band test picks a window that is not a
whole number of periods of this periodic signal.

With Friction law = rate and state (flat_friction_dieterich_{1,2,4}.prm, issue
#17 item 2) the contact slides at V_rel / cos(alpha) on the path, its state
is the steady one (D_c << a), and phi(alpha) = atan mu_ss(V_rel / cos(alpha))
under the integral (midpoint rule). Measured deviations -0.0002, +0.0025,
+0.0051 at +-1, +-2, +-4 m/s, within the same TOLERANCE; an Amontons-Coulomb
law at mu0 (mu_macro 0.3847) misses the slowest and fastest by 0.019 and
0.028.

With Friction loading/Sliding delay = 1 ns (flat_friction_delayed.prm:
the pressure alone, then the sliding, as the static coefficient's scenes
are loaded) checks 1-4 hold as they are (measured 2026-12-02: differences
0.0012 and 0.0010, rise 0.7 % below, energy residual 8.7e-6).

4. Energy balance of the run (doc/theory/mca.md Sec. 8.4): kinetic + elastic
   + friction + switching + many-body work + damped energy = work of the
   loads within ENERGY_TOLERANCE of the load work, and the integrator's
   bookkeeping kinetic = pair + load - damped work to 1e-9. Measured
   (2026-11-27, pair-level energy): -0.001 % (mu = 0.3), -0.029 % (Dieterich
   at +-1 m/s, where mu follows the automata's vibrations from step to step;
   +2.3 % before the friction work was taken from the energy the Coulomb
   limit releases). The tolerance is the scene's own (ENERGY_TOLERANCE,
   issue #49: within 10x of its measured residual and below the smallest
   term it must catch; measured 2026-11-29, residual / smallest term, both
   of the load work): mu = 0.3 5e-5 (9.7e-6 / switching 1.4e-4);
   frictionless 4e-4 (9.1e-5 / switching 8.3e-4); Dieterich at 2 and 4 m/s
   5e-5 and 8e-5 (9.9e-6 and 2.3e-5 / switching 1.3e-4 and 1.05e-4). At
   1 m/s the residual (2.9e-4) is as large as the switching work (2.8e-4):
   1e-3 there catches a dropped kinetic (1.2 %) or many-body (3.3 %) term,
   not the switching one. Dropping any term fails the other scenes (shown:
   mu = 0.3 without its switching work, -1.3e-4), and so does the
   bookkeeping error fixed on 2026-11-22 (the kick's dt^2 f^2 / 8m on kinematically
   held components counted as pair instead of load work: 65 % of the load
   work at mu = 0, 18 % at mu = 0.3).
"""
import csv
import json
import math
import os
import sys

from check_tools import (energy_stored, energy_terms, finish,
                         output_directory, parameter, report)

TOLERANCES = {"mca_flat_friction": 2.5e-3,
              "mca_flat_friction_delayed": 2.5e-3,
              "mca_flat_friction_frictionless": 5e-3}
TOLERANCE = TOLERANCES.get(os.path.basename(os.path.normpath(sys.argv[1])),
                           0.01)
RISE_TOLERANCE = 0.02
ENERGY_TOLERANCES = {"mca_flat_friction": 5e-5,
                     "mca_flat_friction_delayed": 5e-5,
                     "mca_flat_friction_frictionless": 4e-4,
                     "mca_flat_friction_dieterich_1": 1e-3,
                     "mca_flat_friction_dieterich_2": 5e-5,
                     "mca_flat_friction_dieterich_4": 8e-5}
ENERGY_TOLERANCE = ENERGY_TOLERANCES.get(
    os.path.basename(os.path.normpath(sys.argv[1])), 3e-3)
START = 0.25  # relative sliding (in periods) at which the averaging starts

out = output_directory(sys.argv[1])


def read_csv(name):
    with open(os.path.join(out, name)) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


law = parameter(out, "Interaction/Friction law")
d = parameter(out, "Geometry/Automaton size")
a = d * math.sqrt(2)

if law == "rate and state":
    # Rate and state (issue #17 item 2): on the on-top path the contact
    # slides at V_rel / cos(alpha) (the relative position turns on a circle
    # of radius d; the layers move at +-V), and with D_c << a its state is
    # the steady one, mu_ss = mu0 + (a - b) ln(V / V0). The means become
    # integrals over a period, by the midpoint rule (N_MID points: the
    # integrand is smooth, the rule's error ~1e-9).
    N_MID = 20000
    dieterich = {k: parameter(out, "Interaction/Rate and state friction/" + k) for k in
                 ("Reference friction coefficient", "Direct effect",
                  "Evolution effect", "Reference slip rate",
                  "Critical slip distance")}
    V_rel = 2 * parameter(out, "Friction loading/Sliding velocity")
    report(dieterich["Critical slip distance"] <= 0.02 * a,
           "D_c <= 0.02 a: the state follows the slip rate (steady state)")

    def mu_pair(alpha):
        return (dieterich["Reference friction coefficient"]
                + (dieterich["Direct effect"] - dieterich["Evolution effect"])
                * math.log(V_rel / math.cos(alpha)
                           / dieterich["Reference slip rate"]))

    ratios = []
    for k in range(N_MID):
        alpha = math.asin((0.5 - (k + 0.5) / N_MID) * a / d)
        ratios.append(math.tan(math.atan(mu_pair(alpha)) + alpha))
    mu_macro = sum(ratios) / N_MID
    mu_magnitude = sum(abs(r) for r in ratios) / N_MID
    mu = mu_pair(0)  # (for the messages: the coefficient at the top)
else:
    mu = parameter(out, "Interaction/Friction coefficient")
    # The derivation: antiderivative of tan(beta) cos(beta - phi), beta =
    # phi + alpha, from which both means follow (the integrand changes sign
    # at 0).
    phi = math.atan(mu)

    def G(beta):
        return (-math.cos(phi) * math.cos(beta)
                + math.sin(phi) * (math.atanh(math.sin(beta))
                                   - math.sin(beta)))

    lo, hi = phi - math.pi / 4, phi + math.pi / 4
    mu_macro = (G(hi) - G(lo)) / math.sqrt(2)
    mu_magnitude = (G(hi) + G(lo) - 2 * G(0)) / math.sqrt(2)
rise = d * (1 - 1 / math.sqrt(2))

s = read_csv("series.csv")
n = len(s["time"])
slide = [(s["top_uy"][k] - s["bottom_uy"][k]) / a for k in range(n)]
periods = int(math.floor(slide[-1] - START))
report(periods >= 1, "relative sliding %.2f periods a, %d whole ones "
       "averaged" % (slide[-1], periods))
if periods < 1:
    sys.exit(1)
window = [k for k in range(n)
          if START <= slide[k] < START + periods and s["top_fz"][k] > 0]
report(len(window) >= 100 * periods,
       "%d samples in the window (>= 100 per period)" % len(window))
ratio = [-s["top_fy"][k] / s["top_fz"][k] for k in window]
signed = sum(ratio) / len(ratio)
report(abs(signed - mu_macro) <= TOLERANCE,
       "%s, mu = %g: period mean of -F_y/F_z %.4f, derived %.4f (mu + "
       "geometric part %.4f), difference %.4f (tolerance %g)"
       % (law, mu, signed, mu_macro, mu_macro - mu, signed - mu_macro,
          TOLERANCE))

f = read_csv("friction.csv")
times = set(s["time"][k] for k in window)
mags = [f["mu"][k] for k in range(len(f["time"])) if f["time"][k] in times]
report(len(mags) == len(window), "friction.csv has the window's samples")
magnitude = sum(mags) / max(len(mags), 1)
report(abs(magnitude - mu_magnitude) <= TOLERANCE,
       "friction.csv mu = |F_t|/|F_n|: mean %.4f, derived %.4f, difference "
       "%.4f (tolerance %g)" % (magnitude, mu_magnitude,
                                magnitude - mu_magnitude, TOLERANCE))

uz = [s["top_uz"][k] - s["bottom_uz"][k] for k in window]
p2p = max(uz) - min(uz)
report(abs(p2p / rise - 1) <= RISE_TOLERANCE,
       "relative rise over a period %.4f d, on-top path d (1 - 1/sqrt 2) = "
       "%.4f d (tolerance %g %%)" % (p2p / d, rise / d, 100 * RISE_TOLERANCE))
with open(os.path.join(out, "summary.json")) as fjson:
    summary = json.load(fjson)
W = summary["load_work"]
identity = summary["kinetic_energy"] - (summary["pair_work"] + W
                                        - summary["damped_work"])
report(W > 0 and abs(identity) <= 1e-9 * W,
       "kinetic = pair + load - damped work: residual %.3g of the load work "
       "(tolerance 1e-9)" % (identity / W))
stored = energy_stored(summary)
print("      " + energy_terms(summary))
report(abs(stored - W) <= ENERGY_TOLERANCE * W,
       "energy balance: residual %.3g of the load work (tolerance %g)"
       % ((stored - W) / W, ENERGY_TOLERANCE))
# 5. The sliding starts Sliding delay after the contact (0: with the
# pressure): before that the layers have not moved along y (exactly: the
# velocity is prescribed to 0), and summary.json's mu_peak is the largest
# smoothed mu of friction.csv from then on (recomputed here; 1e-9: the
# CSV's 10 digits).
t_slide = summary["contact_time"] + parameter(out, "Sliding delay")
held = [abs(slide[k]) for k in range(n) if s["time"][k] < t_slide]
report(len(held) > 0 and max(held) == 0,
       "no relative sliding before the contact + Sliding delay (%.3g ns, "
       "%d samples)" % (t_slide * 1e9, len(held)))
after = [(f["mu_smoothed"][k], f["time"][k]) for k in range(len(f["time"]))
         if f["time"][k] >= t_slide]
peak = max(after)
report(abs(summary["mu_peak"] - peak[0]) <= 1e-9 * peak[0]
       and abs(summary["mu_peak_time"] - peak[1]) <= 1e-9 * peak[1],
       "mu_peak %.6f at %.4g ns = friction.csv's largest smoothed mu after "
       "the start of the sliding (%.6f at %.4g ns)"
       % (summary["mu_peak"], summary["mu_peak_time"] * 1e9, peak[0],
          peak[1] * 1e9))
# the ratio of the mean forces (the dissipation per sliding distance over
# the load) includes the viscous drag of the damped layers (for information)
drag = (-sum(s["top_fy"][k] for k in window)
        / sum(s["top_fz"][k] for k in window))
print("INFO  ratio of the mean forces %.4f (includes the drag of the damped "
      "loading layers, ~V)" % drag)
finish()
