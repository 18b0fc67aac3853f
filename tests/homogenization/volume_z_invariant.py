"""A z-invariant volume against the 2D plane-strain homogenization of its
cross-section (test homogenization_volume_z_invariant, issue #51 item 4).

    volume_z_invariant.py TRIBODYN WORK_DIRECTORY

A 2D map of 12 x 10 pixels (three random discs of glass in epoxy, Python's
random with seed 51) is written as a grid file and, extruded over 4 voxels
along z, as a raw volume; both are homogenized with periodic conditions.
The 3D periodic problem is invariant under a shift by one voxel along z and
under the mirror z -> -z, so its solution under an in-plane load is the
extruded 2D field with w_z = 0; Q1 on the extruded hexahedra with 2x2x2
Gauss points integrates it as Q1 on the quadrilaterals with 2x2 points
does. Hence, to the CG tolerance (1e-12 in both runs):
  C3[i][j] = C2[i][j] for i, j in (xx, yy, xy),
  C3[zz][j] = c_z[j] (the plane-strain sigma_zz row),
  C3[yz][j] = C3[xz][j] = 0,
relative to |C| <= 1e-10 (measured 6e-15). The KUBC and
SUBC problems are not z-invariant (their conditions on the faces z = 0, L
hold the ends), and their difference from 2D is printed, not checked.
"""
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volume_tools as v  # noqa: E402

tribodyn, work = sys.argv[1], os.path.abspath(sys.argv[2])
os.makedirs(work, exist_ok=True)
check = v.Checks()

nx, ny, nz, h = 12, 10, 4, 1e-5
rng = random.Random(51)
discs = [(rng.uniform(0, nx), rng.uniform(0, ny), rng.uniform(1.5, 2.5))
         for _ in range(3)]


def pixel(i, j):
    """Glass (1) when the pixel's centre lies in a disc (periodic)."""
    for cx, cy, r in discs:
        dx = abs(i + 0.5 - cx)
        dy = abs(j + 0.5 - cy)
        dx, dy = min(dx, nx - dx), min(dy, ny - dy)
        if dx * dx + dy * dy <= r * r:
            return 1
    return 0


grid = os.path.join(work, "section.txt")
with open(grid, "w") as f:
    for j in reversed(range(ny)):  # top row first
        f.write(" ".join(str(pixel(i, j)) for i in range(nx)) + "\n")
header = v.write_raw(work, "extruded", lambda i, j, k: pixel(i, j),
                     (nx, ny, nz), h)
fraction = sum(pixel(i, j) for i in range(nx) for j in range(ny)) / (nx * ny)
print("glass fraction %.4f" % fraction)

materials = v.GLASS_EPOXY_MATERIALS
s2 = v.run(tribodyn, os.path.join(work, "2d"), """set Problem = homogenization
set Output directory = output
subsection Morphology
  set Generator = grid file
  set Grid file = %s
  set Width     = %r
  set Height    = %r
end
%s
subsection Cell problem
  set Boundary conditions = periodic, KUBC, SUBC
  set Solver tolerance    = 1e-12
end
subsection Output
  set Write fields     = false
  set Write morphology = false
end
""" % (grid, nx * h, ny * h, materials))
s3 = v.run(tribodyn, os.path.join(work, "3d"), v.raw_volume_prm(header) + """\
%s
subsection Cell problem
  set Boundary conditions = periodic, KUBC, SUBC
  set Solver tolerance    = 1e-12
end
""" % materials)

plane = [0, 1, 5]  # xx, yy, xy of the 3D Voigt order
for bc in ("periodic", "KUBC", "SUBC"):
    C3 = s3[bc]["C"]
    C2, cz = s2[bc]["C"], s2[bc]["c_z"]
    scale = v.norm(C3)
    in_plane = max(abs(C3[plane[i]][plane[j]] - C2[i][j])
                   for i in range(3) for j in range(3)) / scale
    zz = max(abs(C3[2][plane[j]] - cz[j]) for j in range(3)) / scale
    shear = max(abs(C3[i][plane[j]]) for i in (3, 4) for j in range(3)) / scale
    if bc == "periodic":
        check(in_plane <= 1e-10,
              "periodic: 3D in-plane block = 2D plane-strain C "
              "(max |dC| / |C| = %.2e <= 1e-10)" % in_plane)
        check(zz <= 1e-10, "periodic: 3D sigma_zz row = 2D c_z (%.2e)" % zz)
        check(shear <= 1e-10,
              "periodic: no out-of-plane shear stress (%.2e)" % shear)
    else:
        print("info  %s: 3D in-plane block - 2D plane strain: %.2e of |C| "
              "(the faces z = 0, L are held: not expected to agree)"
              % (bc, in_plane))
check.exit()
