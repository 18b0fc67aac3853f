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

The references are computed here from the phases' constants and fractions
(not read from the summary): each phase's plane-strain stiffness is the
in-plane block (xx, yy, xy) of its 3D stiffness, the inverse of its 3D
compliance (isotropic, or transversely isotropic about z); Voigt = sum
c_i C_i, Reuss = (sum c_i C_i^-1)^-1, and the 2D Hashin-Shtrikman bounds of
the in-plane bulk kappa_i = lambda_i + mu_i and shear mu_i moduli
(Hashin 1965; Torquato, Random Heterogeneous Materials, eq. 21.31):
  kappa_+- = (sum c_i / (kappa_i + mu_+-))^-1 - mu_+-,
  mu_+- = (sum c_i / (mu_i + zeta_+-))^-1 - zeta_+-,
  zeta = kappa mu / (kappa + 2 mu) at the largest (+) or smallest (-) kappa
  and mu. The summary's bounds must equal these to 1e-12 relative (the
  same formulas in another order of operations; measured 2.8e-16).
"""
import json
import os
import sys

from volume_tools import inverse  # the small linear algebra of 2D and 3D

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



def phase_stiffness(phase):
    """Plane-strain stiffness (xx, yy, xy; engineering shear) of a phase:
    the in-plane block of the inverse of its 3D compliance."""
    t = phase.get("transversely_isotropic")
    if t:
        E_T, nu_TT, E_L, nu_LT, G_LT = (t["E_T"], t["nu_TT"], t["E_L"],
                                        t["nu_LT"], t["G_LT"])
    else:
        E_T = E_L = phase["cell_problem_young_modulus"]
        nu_TT = nu_LT = phase["poisson_ratio"]
        G_LT = E_T / (2 * (1 + nu_TT))
    S = [[0.0] * 6 for _ in range(6)]  # xx yy zz yz zx xy, axis z
    S[0][0] = S[1][1] = 1 / E_T
    S[0][1] = S[1][0] = -nu_TT / E_T
    S[0][2] = S[2][0] = S[1][2] = S[2][1] = -nu_LT / E_L
    S[2][2] = 1 / E_L
    S[3][3] = S[4][4] = 1 / G_LT
    S[5][5] = 2 * (1 + nu_TT) / E_T
    C3 = inverse(S)
    block = [0, 1, 5]
    return [[C3[i][j] for j in block] for i in block]


def relative(a, b):
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


fractions = [p["fraction"] for p in phases]
stiffnesses = [phase_stiffness(p) for p in phases]
voigt = [[sum(c * C[i][j] for c, C in zip(fractions, stiffnesses))
          for j in range(3)] for i in range(3)]
reuss = inverse([[sum(c * inverse(C)[i][j]
                      for c, C in zip(fractions, stiffnesses))
                  for j in range(3)] for i in range(3)])
for name, mine in [("voigt", voigt), ("reuss", reuss)]:
    theirs = s["bounds"][name]["C"]
    worst = max(relative(mine[i][j], theirs[i][j])
                for i in range(3) for j in range(3) if mine[i][j] != 0)
    check(worst < 1e-12, "%s C = the one computed here (%.1e)" % (name, worst))
if not transverse:
    kappa = [C[0][1] + C[2][2] for C in stiffnesses]  # lambda + mu
    mu = [C[2][2] for C in stiffnesses]
    hs_mine = {}
    for side, pick in [("upper", max), ("lower", min)]:
        k, m = pick(kappa), pick(mu)
        zeta = k * m / (k + 2 * m)
        hs_mine["kappa_" + side] = 1 / sum(
            c / (ki + m) for c, ki in zip(fractions, kappa)) - m
        hs_mine["mu_" + side] = 1 / sum(
            c / (mi + zeta) for c, mi in zip(fractions, mu)) - zeta
    for key, value in hs_mine.items():
        check(relative(value, s["bounds"]["hashin_shtrikman"][key]) < 1e-12,
              "Hashin-Shtrikman %s %.4f GPa = the summary's %.4f GPa"
              % (key, value / 1e9,
                 s["bounds"]["hashin_shtrikman"][key] / 1e9))


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


hs = hs_mine if not transverse else None
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
