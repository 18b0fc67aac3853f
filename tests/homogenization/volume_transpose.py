"""A volume and its transpose x <-> y give the same stiffness with its
rows and columns swapped (test homogenization_volume_transpose, issue #51
item 4).

    volume_transpose.py TRIBODYN WORK_DIRECTORY

A 20 x 12 x 6 volume of three phases (epoxy, glass, a soft filler; each
voxel drawn i.i.d. by Python's random with seed 5151) and its transpose
(voxel (i, j, k) -> (j, i, k), a 12 x 20 x 6 volume) are homogenized with
KUBC, SUBC and periodic conditions. Swapping x and y maps the Voigt
components (xx, yy, zz, yz, xz, xy) to (yy, xx, zz, xz, yz, xy): the
permutation P = (1, 0, 2, 4, 3, 5), and the apparent stiffness of the
transpose must be C'[a][b] = C[P a][P b] (and the same for S) for every
condition (preconditioned by AMG): the two problems are the same up to the numbering of the mesh,
so to the CG tolerance (1e-12): max |dC| / |C| <= 1e-10 (measured
<= 9e-14). The non-square box catches an axis mixed up in the
mesh, the voxel indexing or the Voigt order. The KUBC, SUBC and periodic
problems of the original are also solved with the geometric multigrid:
the same C to the CG tolerance (bound 1e-10; measured 7e-14 for KUBC and
SUBC, 1.1e-13 for periodic, whose multigrid carries the periodicity
through its levels).
"""
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volume_tools as v  # noqa: E402

tribodyn, work = sys.argv[1], os.path.abspath(sys.argv[2])
os.makedirs(work, exist_ok=True)
check = v.Checks()

nx, ny, nz, h = 20, 12, 6, 1e-5
rng = random.Random(5151)
ids = {}
for k in range(nz):
    for j in range(ny):
        for i in range(nx):
            x = rng.random()
            ids[i, j, k] = 1 if x < 0.3 else (2 if x < 0.45 else 0)
original = v.write_raw(work, "original", lambda i, j, k: ids[i, j, k],
                       (nx, ny, nz), h)
transposed = v.write_raw(work, "transposed", lambda i, j, k: ids[j, i, k],
                         (ny, nx, nz), h)


def prm(header, preconditioner="AMG"):
    return v.raw_volume_prm(header) + """subsection Materials
  set Names = epoxy, glass, filler
  subsection Epoxy
    set Young modulus = 3e9
    set Poisson ratio = 0.35
    set Density       = 1200
  end
  subsection Glass
    set Young modulus = 70e9
    set Poisson ratio = 0.22
    set Density       = 2500
  end
  subsection Filler
    set Young modulus = 0.5e9
    set Poisson ratio = 0.45
    set Density       = 1000
  end
end
subsection Cell problem
  set Boundary conditions = KUBC, SUBC, periodic
  set Solver tolerance    = 1e-12
  set Preconditioner      = %s
end
""" % preconditioner


a = v.run(tribodyn, os.path.join(work, "original"), prm(original))
b = v.run(tribodyn, os.path.join(work, "transposed"), prm(transposed))
P = [1, 0, 2, 4, 3, 5]
for bc in ("KUBC", "SUBC", "periodic"):
    for key in ("C", "S"):
        A, B = a[bc][key], b[bc][key]
        error = max(abs(B[i][j] - A[P[i]][P[j]])
                    for i in range(6) for j in range(6)) / v.norm(A)
        check(error <= 1e-10, "%s: %s of the transpose = P %s P "
              "(max |d| / |%s| = %.2e <= 1e-10)" % (bc, key, key, key, error))
    # the swap is not trivial: the volume is not symmetric under it
    A = a[bc]["C"]
    asym = max(abs(A[i][j] - A[P[i]][P[j]])
               for i in range(6) for j in range(6)) / v.norm(A)
    check(asym > 1e-4, "%s: C itself changes under the swap (%.2e)"
          % (bc, asym))
# the geometric multigrid solves the same problems
m = v.run(tribodyn, os.path.join(work, "multigrid"),
          prm(original, "multigrid"))
for bc in ("KUBC", "SUBC", "periodic"):
    error = v.norm(v.sub(m[bc]["C"], a[bc]["C"])) / v.norm(a[bc]["C"])
    check(m[bc]["preconditioner"] == "multigrid" and error <= 1e-10,
          "%s: multigrid C = AMG C (|dC| / |C| = %.2e <= 1e-10)"
          % (bc, error))
check(a["huet"]["KUBC_minus_SUBC_holds"]
      and b["huet"]["KUBC_minus_SUBC_holds"],
      "Huet's ordering holds for both")
check.exit()
