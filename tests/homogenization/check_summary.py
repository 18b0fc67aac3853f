"""Check the outputs of a homogenization run (tests/homogenization).

Checks that summary.json has the documented keys and consistent values:
C symmetric to 1e-8, S = C^-1 to 1e-8, Huet's hierarchy C^KUBC >= C^periodic
>= C^SUBC (eigenvalues of the differences computed here, >= -1e-9 of the
largest stiffness: round-off; the summary's own eigenvalue must agree), the Voigt/Reuss bounds bracket every apparent
stiffness's E_L, E_T and G_LT, and the CSV and VTU files exist.
The Voigt and Reuss bounds are computed here (issue #49: not read from the
code under test): the heterogeneity fraction counted from the pixels of
morphology.txt, the phases' plane-strain stiffnesses from their E and nu in
parameters.prm, the arithmetic means of stiffness (Voigt) and compliance
(Reuss), and E = 1/S_11 of the 3-D normal block with C_33 = C_22 and the
out-of-plane column c_z, as doc/theory/homogenization.md defines them. The
summary's bounds must equal them to 1e-9 (measured ~1e-13).
"""
import json
import os
import math
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "scripts"))
import plot_tools  # noqa: E402  (read_parameters)

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

def inverse(A):
    """Inverse of a 3 x 3 matrix (cofactors)."""
    det = (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1])
           - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0])
           + A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]))
    return [[(A[(j + 1) % 3][(i + 1) % 3] * A[(j + 2) % 3][(i + 2) % 3]
              - A[(j + 1) % 3][(i + 2) % 3] * A[(j + 2) % 3][(i + 1) % 3]) / det
             for j in range(3)] for i in range(3)]


def plane_strain(E, nu):
    """Voigt stiffness (xx, yy, xy) and the column c_z = d sigma_zz / d eps."""
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    return [[lam + 2 * mu, lam, 0], [lam, lam + 2 * mu, 0], [0, 0, mu]], [lam, lam, 0]


def constants(C, c_z):
    N = [[C[0][0], C[0][1], c_z[0]], [C[1][0], C[1][1], c_z[1]], [c_z[0], c_z[1], C[1][1]]]
    S = inverse(N)
    return {"E_L": 1 / S[0][0], "E_T": 1 / S[1][1], "G_LT": C[2][2]}


prm = plot_tools.read_parameters(out)
pixels = [int(v) for line in open(os.path.join(out, "morphology.txt"))
          if not line.startswith("#") for v in line.split()]
f = sum(pixels) / len(pixels)
check(abs(f - s["volume_fraction"]) < 1e-12,
      "volume fraction %.6f = the pixels' %d of %d" % (s["volume_fraction"], sum(pixels), len(pixels)))
phases = [(f, plane_strain(float(prm["Materials/Heterogeneity/Young modulus"]),
                           float(prm["Materials/Heterogeneity/Poisson ratio"]))),
          (1 - f, plane_strain(float(prm["Materials/Matrix/Young modulus"]),
                               float(prm["Materials/Matrix/Poisson ratio"])))]
voigt_C = [[sum(w * C[i][j] for w, (C, _) in phases) for j in range(3)] for i in range(3)]
voigt_cz = [sum(w * cz[i] for w, (_, cz) in phases) for i in range(3)]
reuss_C = inverse([[sum(w * inverse(C)[i][j] for w, (C, _) in phases) for j in range(3)]
                   for i in range(3)])
# uniform stress sigma = C_R <eps>: sigma_zz^k = c_z^k . (S_k sigma)
reuss_cz = [sum(w * sum(cz[m] * sum(inverse(C)[m][n] * reuss_C[n][i] for n in range(3))
                        for m in range(3)) for w, (C, cz) in phases) for i in range(3)]
reference = {"voigt": constants(voigt_C, voigt_cz), "reuss": constants(reuss_C, reuss_cz)}
for bound in reference:
    for key, value in reference[bound].items():
        check(abs(s["bounds"][bound][key] / value - 1) < 1e-9,
              "%s %s = %.6g GPa as computed here (%.6g GPa)"
              % (bound, key, s["bounds"][bound][key] / 1e9, value / 1e9))

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
        lo, hi = reference["reuss"][key], reference["voigt"][key]
        check(lo * (1 - 1e-9) <= r[key] <= hi * (1 + 1e-9),
              "%s %s = %.4g GPa within Reuss %.4g and Voigt %.4g" % (bc, key, r[key] / 1e9, lo / 1e9, hi / 1e9))



def smallest_eigenvalue(A):
    """Smallest eigenvalue of a symmetric 3x3 matrix (trigonometric closed
    form, O. K. Smith, CACM 4 (1961) 168)."""
    q = (A[0][0] + A[1][1] + A[2][2]) / 3
    p1 = A[0][1] ** 2 + A[0][2] ** 2 + A[1][2] ** 2
    p2 = sum((A[i][i] - q) ** 2 for i in range(3)) + 2 * p1
    p = math.sqrt(p2 / 6)
    if p == 0:
        return q
    B = [[(A[i][j] - (q if i == j else 0)) / p for j in range(3)] for i in range(3)]
    det = (B[0][0] * (B[1][1] * B[2][2] - B[1][2] * B[2][1])
           - B[0][1] * (B[1][0] * B[2][2] - B[1][2] * B[2][0])
           + B[0][2] * (B[1][0] * B[2][1] - B[1][1] * B[2][0]))
    phi = math.acos(max(-1.0, min(1.0, det / 2))) / 3
    return q + 2 * p * math.cos(phi + 2 * math.pi / 3)


C = {bc: s[bc]["C"] for bc in ["KUBC", "periodic", "SUBC"]}
scale = max(abs(C[bc][i][j]) for bc in C for i in range(3) for j in range(3))
for hi, lo in [("KUBC", "periodic"), ("periodic", "SUBC"), ("KUBC", "SUBC")]:
    d = [[0.5 * (C[hi][i][j] - C[lo][i][j] + C[hi][j][i] - C[lo][j][i]) for j in range(3)]
         for i in range(3)]
    low = smallest_eigenvalue(d)
    check(low >= -1e-9 * scale, "C^%s - C^%s positive semi-definite: smallest eigenvalue %.4g GPa"
          % (hi, lo, low / 1e9))
    if (hi, lo) == ("KUBC", "SUBC"):
        check(abs(low - s["kubc_minus_subc_min_eigenvalue"]) <= 1e-9 * scale,
              "summary's kubc_minus_subc_min_eigenvalue %.6g = %.6g"
              % (s["kubc_minus_subc_min_eigenvalue"], low))
check(abs(s["volume_fraction"] - 0.1) < 0.01, "volume fraction %.4f near 0.1" % s["volume_fraction"])
for name in ["parameters.prm", "effective_properties.csv", "morphology.txt", "morphology.vtu", "fields_KUBC_xx.vtu",
             "fields_KUBC.pvd", "fields_SUBC.pvd", "fields_periodic.pvd"]:
    check(os.path.exists(os.path.join(out, name)), "output file " + name + " exists")
with open(os.path.join(out, "effective_properties.csv")) as f:
    lines = f.read().splitlines()
check(lines[0].startswith("estimate,E_L,E_T,G_LT") and len(lines) == 6,
      "effective_properties.csv has a header and 5 rows")
sys.exit(1 if failures else 0)
