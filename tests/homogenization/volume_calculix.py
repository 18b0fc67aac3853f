"""KUBC on a small voxel volume against CalculiX's static solution on the
same hexahedral mesh (test homogenization_volume_calculix, issue #51 item 4).

    volume_calculix.py TRIBODYN WORK_DIRECTORY [CCX]

A 7 x 5 x 4 volume of three phases (epoxy, glass, a soft filler; each voxel
drawn i.i.d. by Python's random with seed 4051) with voxels of 10 x 15 x 8
um is homogenized by tribodyn (KUBC, one trilinear hexahedron per voxel,
CG to 1e-12). The same mesh goes to CalculiX (Debian's calculix-ccx, the
peer code of this project's static checks): one C3D8 element per voxel
(trilinear, full 2 x 2 x 2 Gauss integration: the element of deal.II's
FE_Q(1) with QGauss(2)), isotropic elastic materials of the same E and nu,
and six linear static steps, each prescribing u = E_k x on every node of
the box's surface, E_k the unit strain of load case k (engineering shears:
E_yz = E_zy = 1/2 for gamma_yz = 1), solved by its direct solver. The volume
average of CalculiX's stresses at the integration points (all elements
have the same volume, and 2 x 2 x 2 Gauss integrates the trilinear field's
stresses exactly) is column k of the apparent stiffness, which must equal
tribodyn's C^KUBC: both solve the same discrete problem.

Tolerance: CalculiX prints stresses with 7 significant digits
(E13.6 in its .dat file), which bounds the agreement of one entry to
~5e-8 |C| (measured 1.8e-9 over the 36 entries, the rounding errors of
the 1 120 points averaging out); tribodyn's CG tolerance adds ~1e-12. Bound: max |C_tribodyn - C_ccx| <= 1e-6 |C|. A quadrature,
a shear convention, an axis or a phase mixed up moves entries by 1e-3 to 1
(an E of one phase changed by 0.1 % moves the largest entry difference to
4.5e-4 |C|: shown failing with the CalculiX model's glass E x 1.001). The
non-cubic voxels and box catch a scaling or an axis swapped.
"""
import os
import random
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volume_tools as v  # noqa: E402

tribodyn, work = sys.argv[1], os.path.abspath(sys.argv[2])
ccx = sys.argv[3] if len(sys.argv) > 3 else "ccx"
# TRIBODYN_CCX_GLASS_FACTOR: the glass E of the CalculiX model only, to
# show the test failing (not used otherwise)
glass_factor = float(os.environ.get("TRIBODYN_CCX_GLASS_FACTOR", "1"))
if shutil.which(ccx) is None:
    raise SystemExit("CalculiX ('%s') is not installed: scripts/test "
                     "installs Debian's calculix-ccx (scripts/common.sh)."
                     % ccx)
os.makedirs(work, exist_ok=True)
check = v.Checks()

n = (7, 5, 4)
h = (1e-5, 1.5e-5, 0.8e-5)
phases = [("epoxy", 3e9, 0.35), ("glass", 70e9, 0.22),
          ("filler", 0.5e9, 0.45)]
rng = random.Random(4051)
ids = {}
for k in range(n[2]):
    for j in range(n[1]):
        for i in range(n[0]):
            x = rng.random()
            ids[i, j, k] = 1 if x < 0.35 else (2 if x < 0.5 else 0)
check(len(set(ids.values())) == 3, "all three phases present")
header = v.write_raw(work, "volume", lambda i, j, k: ids[i, j, k], n, h)

# ---------------------------------------------------------------- tribodyn
s = v.run(tribodyn, os.path.join(work, "tribodyn"), v.raw_volume_prm(header)
          + v.materials_prm([(p[0], p[1], p[2], rho)
                             for p, rho in zip(phases, [1200, 2500, 1000])]) + """
subsection Cell problem
  set Boundary conditions = KUBC
  set Solver tolerance    = 1e-12
end
subsection Output
  set Write slices = false
end
""")
C_tribodyn = s["KUBC"]["C"]

# ---------------------------------------------------------------- CalculiX
nx, ny, nz = n


def node(i, j, k):
    return 1 + i + (nx + 1) * (j + (ny + 1) * k)


lines = ["*HEADING", "tribodyn test homogenization_volume_calculix", "*NODE"]
for k in range(nz + 1):
    for j in range(ny + 1):
        for i in range(nx + 1):
            lines.append("%d, %.15g, %.15g, %.15g"
                         % (node(i, j, k), i * h[0], j * h[1], k * h[2]))
element_sets = {m: [] for m in range(len(phases))}
lines.append("*ELEMENT, TYPE=C3D8, ELSET=EALL")
e = 0
for k in range(nz):
    for j in range(ny):
        for i in range(nx):
            e += 1
            corners = [node(i, j, k), node(i + 1, j, k),
                       node(i + 1, j + 1, k), node(i, j + 1, k),
                       node(i, j, k + 1), node(i + 1, j, k + 1),
                       node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)]
            lines.append("%d, " % e + ", ".join(map(str, corners)))
            element_sets[ids[i, j, k]].append(e)
for m, (name, E, nu) in enumerate(phases):
    lines.append("*ELSET, ELSET=E%s" % name.upper())
    members = element_sets[m]
    lines += [", ".join(map(str, members[a:a + 10]))
              for a in range(0, len(members), 10)]
    lines += ["*MATERIAL, NAME=%s" % name.upper(), "*ELASTIC",
              "%.15g, %.15g" % (E * (glass_factor if name == "glass"
                                     else 1), nu),
              "*SOLID SECTION, ELSET=E%s, MATERIAL=%s"
              % (name.upper(), name.upper())]
surface = [(i, j, k) for k in range(nz + 1) for j in range(ny + 1)
           for i in range(nx + 1)
           if i in (0, nx) or j in (0, ny) or k in (0, nz)]
# load case k (Voigt xx, yy, zz, yz, xz, xy): the unit strain tensor
voigt_pairs = [(0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1)]
for a, b in voigt_pairs:
    strain = [[0.0] * 3 for _ in range(3)]
    value = 1.0 if a == b else 0.5
    strain[a][b] = strain[b][a] = value
    lines += ["*STEP", "*STATIC", "*BOUNDARY, OP=NEW"]
    for i, j, k in surface:
        x = (i * h[0], j * h[1], k * h[2])
        for d in range(3):
            u = sum(strain[d][c] * x[c] for c in range(3))
            lines.append("%d, %d, %d, %.15g" % (node(i, j, k), d + 1, d + 1, u))
    lines += ["*EL PRINT, ELSET=EALL", "S", "*END STEP"]
ccx_dir = os.path.join(work, "calculix")
os.makedirs(ccx_dir, exist_ok=True)
with open(os.path.join(ccx_dir, "volume.inp"), "w") as f:
    f.write("\n".join(lines) + "\n")
out = subprocess.run([ccx, "-i", "volume"], cwd=ccx_dir, capture_output=True,
                     text=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
if out.returncode != 0 or "Job finished" not in out.stdout:
    print(out.stdout[-3000:], out.stderr[-3000:])
    raise SystemExit("CalculiX failed in %s" % ccx_dir)

# The .dat file: per step a block "stresses (elem, integ.pnt.,sxx,syy,szz,
# sxy,sxz,syz) for set EALL and time ...", then one line per integration
# point: element, point, six stresses.
steps, current = [], None
with open(os.path.join(ccx_dir, "volume.dat")) as f:
    for line in f:
        if line.strip().startswith("stresses"):
            current = []
            steps.append(current)
            continue
        fields = line.split()
        if current is not None and len(fields) == 8:
            current.append([float(x) for x in fields[2:]])
n_points = 8 * nx * ny * nz
check(len(steps) == 6 and all(len(p) == n_points for p in steps),
      "CalculiX printed the stresses of 6 steps at %d integration points "
      "each (got %s)" % (n_points, [len(p) for p in steps]))
# CalculiX's order sxx, syy, szz, sxy, sxz, syz -> Voigt xx, yy, zz, yz,
# xz, xy
order = [0, 1, 2, 5, 4, 3]
C_ccx = [[sum(p[order[r]] for p in steps[c]) / n_points for c in range(6)]
         for r in range(6)]

# ---------------------------------------------------------------- compare
scale = v.norm(C_ccx)
error = max(abs(C_tribodyn[r][c] - C_ccx[r][c])
            for r in range(6) for c in range(6)) / scale
print("C^KUBC (GPa), tribodyn / CalculiX:")
for r in range(6):
    print("  " + "  ".join("%9.5f/%9.5f" % (C_tribodyn[r][c] / 1e9,
                                            C_ccx[r][c] / 1e9)
                           for c in range(6)))
check(error <= 1e-6, "C^KUBC of tribodyn = CalculiX's on the same mesh: "
      "max |dC| / |C| = %.2e <= 1e-6" % error)
# the comparison is not trivial: the volume is anisotropic at this size
check(abs(C_ccx[0][0] - C_ccx[1][1]) > 1e-3 * scale,
      "C_11 != C_22 (the box is not symmetric)")
check.exit()
