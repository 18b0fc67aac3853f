"""A 3D laminate against its exact stiffness (test
homogenization_volume_laminate, issue #51 item 4).

Layers normal to z through the whole box, on voxel faces: the exact field
is piecewise affine (uniform traction sigma.e_z and uniform in-layer
strain), hence in the Q1 space, and it is periodic, so the periodic cell
problem must give the exact laminate stiffness, derived here
(volume_tools.laminate_exact, through volume_tools.check_laminate) from the
phases' E and nu in the run's parameters.prm, up to the CG tolerance
(1e-12): |C^per - C_exact| / |C_exact| <= 1e-10 (measured 1.3e-14; the CG
tolerance allows ~1e-12).
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
prm = plot_tools.read_parameters(os.path.join(sys.argv[1], "output"))
given = [(float(prm["Materials/%s/Young modulus" % name]),
          float(prm["Materials/%s/Poisson ratio" % name]))
         for name in ("Matrix", "Heterogeneity")]
v.check_laminate(check, s, given, [0.75, 0.25], 2)
check.exit()
