"""A 3D laminate against its exact stiffness (test
homogenization_volume_laminate, issue #51 item 4).

Layers normal to z through the whole box, on voxel faces: the exact field
is piecewise affine (uniform traction sigma.e_z and uniform in-layer
strain), hence in the Q1 space, and it is periodic, so the periodic cell
problem must give the exact laminate stiffness, derived here
(volume_tools.laminate_exact) from the phases' E and nu in the run's
parameters.prm, up to the CG tolerance (1e-12): |C^per - C_exact| /
|C_exact| <= 1e-10 (measured 1.3e-14; the CG tolerance allows ~1e-12).
KUBC and SUBC are not exact for a laminate (the affine displacement,
resp. the uniform traction, on the faces cut by the layers is not the
laminate's field), but they bracket it (Huet): C^KUBC - C_exact and
C_exact - C^SUBC positive semi-definite (to -1e-9 |C|). Some of their load cases are exact: under the in-plane shear
gamma_xy the uniform strain is the solution (KUBC: C_66 = <mu>, column 6
diagonal), under the out-of-plane shears sigma_yz, sigma_xz the uniform
stress is (SUBC: S_44 = S_55 = <1/mu>); tolerance 1e-10 as above
(measured <= 1e-13). The right-hand side of the exact KUBC load case is
zero up to round-off, so CG may stop at 0 iterations there.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volume_tools as v  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "scripts"))
import plot_tools  # noqa: E402  (read_parameters)

with open(os.path.join(sys.argv[1], "output", "summary.json")) as f:
    s = json.load(f)
check = v.Checks()

phases = s["phases"]
fractions = [p["fraction"] for p in phases]
# the generator's layers: 2 of every 8 voxels along z
check(abs(fractions[1] - 0.25) < 1e-14,
      "glass fraction 2/8 = 0.25 (got %r)" % fractions[1])
fractions = [0.75, 0.25]
prm = plot_tools.read_parameters(os.path.join(sys.argv[1], "output"))
given = [(float(prm["Materials/%s/Young modulus" % name]),
          float(prm["Materials/%s/Poisson ratio" % name]))
         for name in ("Matrix", "Heterogeneity")]
C_phase = [v.isotropic_stiffness(E, nu) for E, nu in given]
exact = v.laminate_exact(C_phase, fractions, 2)
scale = v.norm(exact)

per = s["periodic"]["C"]
error = v.norm(v.sub(per, exact)) / scale
check(error <= 1e-10, "periodic C = exact laminate C: |dC|/|C| = %.2e <= 1e-10"
      % error)
S_exact = v.inverse(exact)
error_S = v.norm(v.sub(s["periodic"]["S"], S_exact)) / v.norm(S_exact)
check(error_S <= 1e-10, "periodic S = exact laminate S: %.2e <= 1e-10"
      % error_S)
E_z = 1 / S_exact[2][2]
check(abs(s["periodic"]["E_z"] - E_z) <= 1e-10 * E_z,
      "periodic E_z = %.6g GPa (exact %.6g)" % (s["periodic"]["E_z"] / 1e9,
                                                E_z / 1e9))

kubc, subc = s["KUBC"]["C"], s["SUBC"]["C"]
lower = v.min_eigenvalue(v.sub(kubc, exact)) / scale
upper = v.min_eigenvalue(v.sub(exact, subc)) / scale
check(lower >= -1e-9, "C^KUBC - C_exact >= 0 (min eigenvalue / |C| = %.2e)"
      % lower)
check(upper >= -1e-9, "C_exact - C^SUBC >= 0 (min eigenvalue / |C| = %.2e)"
      % upper)
mu = [E / (2 * (1 + nu)) for E, nu in given]
mu_voigt = sum(f * m for f, m in zip(fractions, mu))
inv_mu_reuss = sum(f / m for f, m in zip(fractions, mu))
check(abs(kubc[5][5] - mu_voigt) <= 1e-10 * mu_voigt,
      "KUBC C_66 = <mu> = %.6g GPa (got %.6g)" % (mu_voigt / 1e9,
                                                  kubc[5][5] / 1e9))
off = max(abs(kubc[i][5]) for i in range(5)) / scale
check(off <= 1e-10, "KUBC column 6 diagonal (%.1e)" % off)
S_subc = s["SUBC"]["S"]
for i, name in ((3, "S_44"), (4, "S_55")):
    check(abs(S_subc[i][i] - inv_mu_reuss) <= 1e-10 * inv_mu_reuss,
          "SUBC %s = <1/mu> (relative error %.1e)"
          % (name, abs(S_subc[i][i] / inv_mu_reuss - 1)))
check(s["huet"]["KUBC_minus_SUBC_holds"] is True,
      "summary.json reports Huet's ordering KUBC >= SUBC")
check(all(0 <= n < 30 for bc in ("KUBC", "SUBC", "periodic")
          for n in s[bc]["cg_iterations"]),
      "CG iterations: %s" % {bc: s[bc]["cg_iterations"]
                             for bc in ("KUBC", "SUBC", "periodic")})
check.exit()
