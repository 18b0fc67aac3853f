"""The voxel grid and the mesh give the same cell problems (test
homogenization_volume_grids, issue #51 item 5).

    volume_grids.py TRIBODYN WORK_DIRECTORY

'Cell problem/Grid = voxel grid' (nodes, cells, levels and the ranks' slabs
by index arithmetic, source/homogenization/voxel_grid_solver.cc) and
'mesh' (a deal.II triangulation, DoF handler and MatrixFree levels,
cell_multigrid.cc) discretize the same Q1 problem, so their apparent
stiffnesses agree to the CG tolerance. Random glass spheres in epoxy
(contrast 23, as in bench/homogenization/volume_128.prm) in a box of
16 x 12 x 8 voxels (three different sides: an axis mixed up in the index
arithmetic cannot hide),
KUBC, SUBC and periodic at tolerance 1e-10: max |C_grid - C_mesh| /
max |C_mesh| <= 1e-8 for each condition (measured 1e-11 to 1e-15 on cubes
of 16^3 to 64^3: the CG tolerance allows ~1e-10), on 1 rank and on 3
(slabs of 2-3 node planes, ranks without planes on the coarse grids);
every load case's CG count within 2 of the mesh's (the same V-cycle on
the same levels); and 'auto' picks the voxel grid (summary.json 'grid').
The laminate, CalculiX, Mori-Tanaka, z-invariant and transposition tests
check both grids against exact or independent results.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volume_tools as v  # noqa: E402

tribodyn, work = sys.argv[1], os.path.abspath(sys.argv[2])
check = v.Checks()


def prm(grid):
    return """set Problem = volume_homogenization
set Output directory = output
subsection Morphology
  set Generator       = spheres
  set Voxels in x     = 16
  set Voxels in y     = 12
  set Voxels in z     = 8
  set Voxel size      = 1e-5
  set Volume fraction = 0.2
  set Radius          = 3
  set Seed            = 1
end
""" + v.GLASS_EPOXY_MATERIALS + """subsection Cell problem
  set Boundary conditions = KUBC, SUBC, periodic
  set Solver tolerance    = 1e-10
  set Grid                = %s
end
subsection Output
  set Write slices     = false
  set Write morphology = false
end
""".replace("%s", grid)


mesh = v.run(tribodyn, os.path.join(work, "mesh"), prm("mesh"))
runs = {"auto, 1 rank": v.run(tribodyn, os.path.join(work, "auto"),
                              prm("auto")),
        "voxel grid, 3 ranks": v.run(tribodyn, os.path.join(work, "grid3"),
                                     prm("voxel grid"), ranks=3)}
check(mesh["grid"] == "mesh", "'mesh' solved on the mesh")
for name, s in runs.items():
    check(s["grid"] == "voxel grid", "%s solved on the voxel grid" % name)
    for bc in ("KUBC", "SUBC", "periodic"):
        A, B = s[bc]["C"], mesh[bc]["C"]
        scale = max(abs(x) for row in B for x in row)
        diff = max(abs(A[i][j] - B[i][j]) for i in range(6) for j in range(6))
        check(diff <= 1e-8 * scale,
              "%s, %s: max |C_grid - C_mesh| / max |C_mesh| = %.1e <= 1e-8"
              % (name, bc, diff / scale))
        ig, im = s[bc]["cg_iterations"], mesh[bc]["cg_iterations"]
        check(all(abs(a - b) <= 2 for a, b in zip(ig, im)),
              "%s, %s: CG iterations %s within 2 of the mesh's %s"
              % (name, bc, ig, im))
check.exit()
