"""A homogeneous transversely isotropic volume returns its own constants
(test homogenization_volume_single_phase_ti, issue #51).

Both phases of a laminate are the same carbon fibre material, transversely
isotropic with axis L = y (E_L = 230 GPa, nu_LT = 0.26, G_LT = 27 GPa in
the prm; E_T = 15 GPa, nu_TT = 0.4 in its plane of isotropy x-z). A uniform
strain (KUBC, periodic) or stress (SUBC) is then the exact solution, so
every condition must return, to the CG tolerance (1e-12; bound 1e-10,
measured 7e-15): E_y = E_L, E_x = E_z = E_T, nu_yx = nu_yz = nu_LT,
nu_xz = nu_zx = nu_TT, G_xy = G_yz = G_LT, G_xz = G_TT = E_T / (2 (1 +
nu_TT)), and the 6x6 compliance written here from these constants (axis y:
S_yy = 1/E_L, S_xy = S_zy = -nu_LT/E_L, S_xx = S_zz = 1/E_T, S_xz =
-nu_TT/E_T, S_44 = S_66 = 1/G_LT, S_55 = 1/G_TT). It checks the 3D
stiffness of transversely isotropic phases (volume_properties.cc) and the
placement of L along y.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volume_tools as v  # noqa: E402

with open(os.path.join(sys.argv[1], "output", "summary.json")) as f:
    s = json.load(f)
check = v.Checks()
E_L, nu_LT, G_LT, E_T, nu_TT = 230e9, 0.26, 27e9, 15e9, 0.4
G_TT = E_T / (2 * (1 + nu_TT))
S = [[0.0] * 6 for _ in range(6)]
S[1][1] = 1 / E_L
S[0][1] = S[1][0] = S[2][1] = S[1][2] = -nu_LT / E_L
S[0][0] = S[2][2] = 1 / E_T
S[0][2] = S[2][0] = -nu_TT / E_T
S[3][3] = S[5][5] = 1 / G_LT
S[4][4] = 1 / G_TT
expected = {"E_y": E_L, "E_x": E_T, "E_z": E_T, "nu_yx": nu_LT,
            "nu_yz": nu_LT, "nu_xz": nu_TT, "nu_zx": nu_TT, "G_xy": G_LT,
            "G_yz": G_LT, "G_xz": G_TT}
for bc in ("KUBC", "SUBC", "periodic"):
    error = v.norm(v.sub(s[bc]["S"], S)) / v.norm(S)
    check(error <= 1e-10, "%s: S = the material's compliance (%.1e)"
          % (bc, error))
    worst = max(abs(s[bc][key] / value - 1) for key, value in expected.items())
    check(worst <= 1e-10, "%s: E, nu, G = the material's (worst %.1e)"
          % (bc, worst))
check.exit()
