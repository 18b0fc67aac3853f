"""Check the outputs of a homogenization run (tests/homogenization).

Checks that summary.json has the documented keys and consistent values:
C symmetric to 1e-8, S = C^-1 to 1e-8, KUBC >= SUBC (Huet: min eigenvalue
of C^K - C^S >= 0), the Voigt/Reuss bounds bracket every apparent
stiffness's E_L, E_T and G_LT, and the CSV and VTU files exist.
"""
import json
import os
import sys

out = os.path.join(sys.argv[1], "output")
with open(os.path.join(out, "summary.json")) as f:
    s = json.load(f)

failures = []


def check(condition, what):
    print(("PASS  " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


for key in ["volume_fraction", "n_dofs", "KUBC", "SUBC", "periodic", "bounds",
            "wall_time_s", "n_mpi_ranks", "tribodyn_version"]:
    check(key in s, "summary.json has key " + key)

for bc in ["KUBC", "SUBC", "periodic"]:
    r = s[bc]
    for key in ["C", "S", "E_L", "E_T", "nu_LT", "nu_TT", "G_LT"]:
        check(key in r, bc + " has key " + key)
    C, S = r["C"], r["S"]
    scale = max(abs(C[i][j]) for i in range(3) for j in range(3))
    asym = max(abs(C[i][j] - C[j][i]) for i in range(3) for j in range(3))
    check(asym <= 1e-8 * scale, bc + " C symmetric (%.2e)" % (asym / scale))
    for i in range(3):
        for j in range(3):
            cs = sum(C[i][k] * S[k][j] for k in range(3))
            check(abs(cs - (i == j)) < 1e-8, bc + " (C S)[%d][%d] = %d" % (i, j, i == j))
    for key in ["E_L", "E_T", "G_LT"]:
        lo, hi = s["bounds"]["reuss"][key], s["bounds"]["voigt"][key]
        check(lo * (1 - 1e-9) <= r[key] <= hi * (1 + 1e-9),
              "%s %s = %.4g GPa within Reuss %.4g and Voigt %.4g" % (bc, key, r[key] / 1e9, lo / 1e9, hi / 1e9))

check(s["kubc_minus_subc_min_eigenvalue"] >= 0, "C^KUBC - C^SUBC is positive semi-definite")
check(abs(s["volume_fraction"] - 0.1) < 0.01, "volume fraction %.4f near 0.1" % s["volume_fraction"])
for name in ["parameters.prm", "effective_properties.csv", "morphology.txt", "morphology.vtu", "fields_KUBC_xx.vtu",
             "fields_KUBC.pvd", "fields_SUBC.pvd", "fields_periodic.pvd"]:
    check(os.path.exists(os.path.join(out, name)), "output file " + name + " exists")
with open(os.path.join(out, "effective_properties.csv")) as f:
    lines = f.read().splitlines()
check(lines[0].startswith("estimate,E_L,E_T,G_LT") and len(lines) == 6,
      "effective_properties.csv has a header and 5 rows")
sys.exit(1 if failures else 0)
