"""Check a homogenization run on the three-phase micrograph (issue #19).

With transversely isotropic fibres (homogenization_image_fibres: axis z,
E_L 230 GPa, E_T 15 GPa) the summary must list their constants and give no
Hashin-Shtrikman bounds (null): they need isotropic phases. Hill's
Voigt/Reuss ordering holds for any phases and is checked in both cases.

summary.json must list the three named phases (pores, matrix, fibres) with
fractions summing to 1 (1e-12) and the pores' ersatz Young modulus (1e-6 of
the matrix's); every apparent stiffness must be symmetric (1e-8) and lie
between the Voigt and Reuss estimates in the sense of quadratic forms
(eigenvalues of C_Voigt - C and C - C_Reuss >= -1e-9 |C|); the isotropic
projections kappa, mu of the periodic and KUBC stiffnesses must lie within
the Hashin-Shtrikman bounds (the micrograph is nearly isotropic in the
plane: anisotropy printed, must be below 0.1); morphology.vtu must exist.
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


phases = s["phases"]
check([p["name"] for p in phases] == ["pores", "matrix", "fibres"],
      "phases pores, matrix, fibres")
total = sum(p["fraction"] for p in phases)
check(abs(total - 1) < 1e-12, "phase fractions sum to 1 (%.15f)" % total)
print("fractions: " + ", ".join("%s %.4f" % (p["name"], p["fraction"])
                                for p in phases))
transverse = phases[2].get("transversely_isotropic")
smallest = phases[1]["young_modulus"]  # the matrix: the softest solid
check(phases[0]["pore"] and abs(phases[0]["cell_problem_young_modulus"]
                                - 1e-6 * smallest) < 1e-6 * smallest * 1e-12,
      "pores: ersatz E = 1e-6 x %g GPa" % (smallest / 1e9))
if transverse:
    check(transverse["axis"] == "z" and transverse["E_L"] == 230e9
          and transverse["E_T"] == phases[2]["young_modulus"] == 15e9
          and transverse["G_LT"] == 15e9 and transverse["nu_LT"] == 0.2
          and transverse["nu_TT"] == 0.07,
          "fibres: transversely isotropic, axis z, the given constants")
    check(s["bounds"]["hashin_shtrikman"] is None,
          "no Hashin-Shtrikman bounds with a transversely isotropic phase")



def at_least(A, B, tolerance):
    """A - B >= -tolerance (Loewner order): the symmetric part of
    A - B + tolerance I is positive definite (leading minors > 0)."""
    M = [[0.5 * (A[i][j] - B[i][j] + A[j][i] - B[j][i])
          + (tolerance if i == j else 0) for j in range(3)] for i in range(3)]
    m1 = M[0][0]
    m2 = M[0][0] * M[1][1] - M[0][1] * M[1][0]
    m3 = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1])
          - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0])
          + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]))
    return m1 > 0 and m2 > 0 and m3 > 0


voigt = s["bounds"]["voigt"]["C"]
reuss = s["bounds"]["reuss"]["C"]
hs = s["bounds"]["hashin_shtrikman"]
for bc in ["KUBC", "SUBC", "periodic"]:
    C = s[bc]["C"]
    scale = max(abs(C[i][j]) for i in range(3) for j in range(3))
    check(max(abs(C[i][j] - C[j][i]) for i in range(3) for j in range(3))
          <= 1e-8 * scale, bc + ": C symmetric")
    check(at_least(voigt, C, 1e-9 * scale) and at_least(C, reuss, 1e-9 * scale),
          bc + ": Reuss <= C <= Voigt (quadratic forms)")
    if bc == "SUBC" or transverse:
        continue
    a = s[bc]["anisotropy"]
    check(a < 0.1, bc + ": anisotropy %.4f < 0.1" % a)
    for m in ["kappa", "mu"]:
        v, lo, hi = s[bc][m], hs[m + "_lower"], hs[m + "_upper"]
        check(lo <= v <= hi, "%s: %s = %.4f GPa in HS [%.4f, %.4f]"
              % (bc, m, v / 1e9, lo / 1e9, hi / 1e9))
check(os.path.exists(os.path.join(out, "morphology.vtu")), "morphology.vtu")
sys.exit(1 if failures else 0)
