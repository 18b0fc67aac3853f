"""Pores in a voxel volume (test homogenization_volume_pores, issue #51).

Spherical pores (E = 0: the ersatz material of 'Pore stiffness ratio' =
1e-6 of the epoxy's E, nu = 0) placed periodically cut the faces. Checked:
- the warning names the number of pore voxels on the faces, counted here
  from morphology.raw (exact);
- SUBC puts the traction Sigma n on those voxels, so its apparent moduli
  fall to the ersatz's order: every SUBC E below 1e-3 of the epoxy's;
- KUBC and periodic stay those of a porous solid: E between 0.5 and 1
  times the epoxy's (10 % of pores; measured 0.83-0.85), KUBC >= periodic
  (Huet, eigenvalues computed here, to -1e-8 |C|).
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volume_tools as v  # noqa: E402

out = os.path.join(sys.argv[1], "output")
with open(os.path.join(out, "summary.json")) as f:
    s = json.load(f)
with open(os.path.join(sys.argv[1], "stdout.txt")) as f:
    stdout = f.read()
check = v.Checks()

n = s["n_voxels"]
with open(os.path.join(out, "morphology.raw"), "rb") as f:
    voxels = f.read()
on_faces = sum(1 for k in range(n[2]) for j in range(n[1])
               for i in range(n[0])
               if (i in (0, n[0] - 1) or j in (0, n[1] - 1)
                   or k in (0, n[2] - 1))
               and voxels[(k * n[1] + j) * n[0] + i] == 1)
warned = re.search(r"Warning: (\d+) pore voxels touch the boundary", stdout)
check(warned is not None and int(warned.group(1)) == on_faces,
      "the warning counts the %d pore voxels on the faces (printed: %s)"
      % (on_faces, warned.group(1) if warned else "none"))
E = 3e9
for key in ("E_x", "E_y", "E_z"):
    check(s["SUBC"][key] < 1e-3 * E, "SUBC %s = %.3g Pa < 1e-3 E_epoxy"
          % (key, s["SUBC"][key]))
    for bc in ("KUBC", "periodic"):
        check(0.5 * E < s[bc][key] < E, "%s %s = %.3f GPa in (0.5, 1) E_epoxy"
              % (bc, key, s[bc][key] / 1e9))
e = v.min_eigenvalue(v.sub(s["KUBC"]["C"], s["periodic"]["C"]))
check(e >= -1e-8 * v.norm(s["KUBC"]["C"]),
      "C^KUBC - C^periodic >= 0 (%.3g Pa)" % e)
check.exit()
