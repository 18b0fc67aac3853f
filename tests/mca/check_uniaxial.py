"""Check the uniaxial compression of steel (prm/mca/uniaxial_steel.prm).

References (seed 000, Table 1 and the prm): E = 206 GPa, nu = 0.28,
sigma_y = 800 MPa, plastic hardening modulus H = 20 GPa. The stress is
that of the interior automata, the strain that between the loading
layers; the block is loaded dynamically over ~40 wave transits.
Tolerances: E 2 %, nu 3 %, sigma_y 2 %, H 5 %. The nominal modulus
(reaction over the nominal section) is lower because of the free surface
layer: within 15 % here (see compare_resolution.py for its convergence).
"""
import json
import os
import sys

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
rel("youngs_modulus", 206e9, 0.02)
rel("poisson_ratio", 0.28, 0.03)
rel("yield_stress", 800e6, 0.02)
rel("hardening_modulus", 20e9, 0.05)
rel("youngs_modulus_nominal", 206e9, 0.15)
for name in ["series.csv", "particles.pvd", "particles_0000.pvtu",
             "particles_0000.0.vtu", "parameters.prm"]:
    check(os.path.exists(os.path.join(out, name)), "output file " + name)
with open(os.path.join(out, "series.csv")) as f:
    header = f.readline().strip().split(",")
check(header[:7] == ["time", "kinetic_energy", "elastic_energy", "plastic_work",
                     "friction_work", "n_bonded_pairs", "n_unbonded_contacts"]
      and "top_fz" in header, "series.csv header")
sys.exit(1 if failures else 0)
