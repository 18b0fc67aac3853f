"""Check the uniaxial compression of steel (prm/mca/uniaxial_steel.prm).

References: the steel's E, nu, sigma_y and hardening modulus H as the
run read them (its parameters.prm: seed 000's Table 1, 206 GPa, 0.28,
800 MPa, and the prm's H = 20 GPa). The stress is that of the interior
automata, the strain that between the loading layers; the block is loaded
dynamically over ~40 wave transits.

The constants are fitted again here from series.csv, as doc/theory/mca.md
describes (E, nu: least squares on the loading branch below 'Elastic fit
fraction' of sigma_y; sigma_y: where that line meets the fit of the last
40 % of the strain; H = E E_t / (E - E_t)); the summary must agree with
this fit within E 1e-3, nu 2e-3, sigma_y 1e-4, H 2e-4 (measured: E 1.9e-4 and
2.1e-4, nu 4.8e-4 and 4.5e-4, sigma_y 1e-5 and 1.1e-5, H 6e-5 and 1.9e-5 on
two builds whose pair arithmetic differs by round-off: the code's window
keeps slightly fewer points) and the fit with the
references within: E 2 %, nu 3 %, sigma_y 2 %, H 5 %. The nominal modulus
(reaction over the nominal section) is lower because of the free surface
layer: within 15 % here (see compare_resolution.py for its convergence).
"""
import csv
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_tools import parameter  # noqa: E402

out = os.path.join(sys.argv[1], "output", "mca", "uniaxial_steel")
with open(os.path.join(out, "summary.json")) as f:
    s = json.load(f)
failures = []


def check(cond, what):
    print(("PASS  " if cond else "FAIL  ") + what)
    if not cond:
        failures.append(what)


def rel(key, ref, tol):
    v = s.get(key)
    ok = v is not None and abs(v - ref) <= tol * abs(ref)
    check(ok, "%s = %s vs %g (tolerance %g relative)" % (key, v, ref, tol))


for key in ["n_automata", "n_steps", "dt", "critical_dt", "wall_time_s",
            "automaton_steps_per_second", "tribodyn_version", "n_mpi_ranks",
            "youngs_modulus", "poisson_ratio", "yield_stress"]:
    check(key in s, "summary.json has " + key)


def line(x, y):
    """Least-squares slope and intercept."""
    mx, my = sum(x) / len(x), sum(y) / len(y)
    b = sum((a - mx) * (c - my) for a, c in zip(x, y)) / sum((a - mx) ** 2 for a in x)
    return b, my - b * mx


E_ref = parameter(out, "Materials/Steel/Young modulus")
nu_ref = parameter(out, "Materials/Steel/Poisson ratio")
sy_ref = parameter(out, "Materials/Steel/Yield stress")
H_ref = parameter(out, "Materials/Steel/Hardening modulus")
with open(os.path.join(out, "series.csv")) as f:
    rows = list(csv.DictReader(f))
eps = [float(r["interior_strain"]) for r in rows]
sig = [float(r["interior_stress"]) for r in rows]
lat = [float(r["lateral_strain"]) for r in rows]
limit = parameter(out, "Analysis/Elastic fit fraction") * sy_ref
first = next(i for i in range(len(sig)) if sig[i] > limit)
elastic = [i for i in range(first) if sig[i] > 0]
E, s0 = line([eps[i] for i in elastic], [sig[i] for i in elastic])
nu = line([eps[i] for i in elastic], [lat[i] for i in elastic])[0]
plastic = [i for i in range(len(eps)) if eps[i] >= 0.6 * max(eps)]
Et, s1 = line([eps[i] for i in plastic], [sig[i] for i in plastic])
sy = E * (s1 - s0) / (E - Et) + s0
H = E * Et / (E - Et)
for key, value, tol in [("youngs_modulus", E, 1e-3), ("poisson_ratio", nu, 2e-3),
                        ("yield_stress", sy, 1e-4), ("hardening_modulus", H, 2e-4)]:
    v = s.get(key)
    check(v is not None and abs(v / value - 1) <= tol,
          "%s = %s, fitted here from series.csv %.6g (tolerance %g)" % (key, v, value, tol))
for name, value, ref, tol in [("E", E, E_ref, 0.02), ("nu", nu, nu_ref, 0.03),
                              ("sigma_y", sy, sy_ref, 0.02), ("H", H, H_ref, 0.05)]:
    check(abs(value - ref) <= tol * abs(ref),
          "fitted %s = %.6g vs the prm's %g (tolerance %g relative)" % (name, value, ref, tol))
rel("youngs_modulus_nominal", E_ref, 0.15)
for name in ["series.csv", "particles.pvd", "particles_0000.pvtu",
             "particles_0000.0.vtu", "parameters.prm"]:
    check(os.path.exists(os.path.join(out, name)), "output file " + name)
with open(os.path.join(out, "series.csv")) as f:
    header = f.readline().strip().split(",")
check(header[:7] == ["time", "kinetic_energy", "elastic_energy", "plastic_work",
                     "friction_work", "n_bonded_pairs", "n_unbonded_contacts"]
      and "top_fz" in header, "series.csv header")
sys.exit(1 if failures else 0)
