"""The VTU fields of a 3D cell problem (tests homogenization_volume_fields
on 1 rank and homogenization_volume_fields_2ranks, issue #51 item 6):
tests/homogenization/volume/fields.prm, glass spheres in epoxy in 12 x 10
x 8 voxels, 'Output/Write fields = true', KUBC, SUBC and periodic.

Read back here (scripts/plot_tools.read_vtu on every piece of every .pvtu)
and checked against what the test computes itself, not against the code
under test:
- fields_<BC>.pvd lists the six load cases, timestep k ->
  fields_<BC>_<k>.pvtu, and each .pvtu one piece per MPI rank
  (summary.json's n_mpi_ranks), each piece a file of its own;
- the cells of each load case are the voxels, each exactly once (cells =
  12 x 10 x 8 = 960, the cell centres on the voxel centres), and their
  material_id is that of the voxel in morphology.raw (exact);
- the averages over the cells (equal volumes) of the stress and strain
  fields against the apparent properties in summary.json: for KUBC and
  periodic, the mean stress of load case k is column k of C and the mean
  strain the unit strain e_k; for SUBC the mean strain is column k of S
  and the mean stress the unit stress e_k. The fields are written as
  float32 (relative round-off 6e-8 per value): tolerance 1e-6 of |C|
  (|S|) and of the unit load (measured below 1e-7);
- KUBC: the displacement on the boundary equals E_k x (the fluctuation
  is zero there), to 1e-6 of max |E_k x| (float32; measured ~1e-8);
  periodic: u(x + L_d e_d) - u(x) = E_k L_d e_d between the points of
  opposite faces (the fluctuation is periodic), to 1e-6 of max |u|;
- von_mises equals sqrt(((sxx - syy)^2 + (syy - szz)^2 + (szz - sxx)^2)
  / 2 + 3 (syz^2 + sxz^2 + sxy^2)) of the written components (1e-6 of
  its maximum; float32).
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volume_tools as v  # noqa: E402

out = os.path.join(sys.argv[1], "output")
with open(os.path.join(out, "summary.json")) as f:
    s = json.load(f)
check = v.Checks()
n, h = s["n_voxels"], s["voxel_size"]
L = [n[d] * h[d] for d in range(3)]
with open(os.path.join(out, "morphology.raw"), "rb") as f:
    voxels = f.read()
ranks = s["n_mpi_ranks"]
voigt = ["xx", "yy", "zz", "yz", "xz", "xy"]
stress = ["stress_" + c for c in voigt]
strain = ["strain_" + c for c in voigt[:3]] + ["strain_gamma_" + c
                                              for c in voigt[3:]]


def affine(k, x):
    """E_k x for the unit Voigt strain e_k (engineering shears)."""
    E = [[0.0] * 3 for _ in range(3)]
    if k < 3:
        E[k][k] = 1.0
    else:
        a, b = [d for d in range(3) if d != k - 3]
        E[a][b] = E[b][a] = 0.5
    return [sum(E[i][j] * x[j] for j in range(3)) for i in range(3)]


for bc in ("KUBC", "SUBC", "periodic"):
    listed = v.read_pvd(out, "fields_%s.pvd" % bc)
    check(listed == [(k, "fields_%s_%d.pvtu" % (bc, k)) for k in range(6)],
          "fields_%s.pvd lists fields_%s_0.pvtu to fields_%s_5.pvtu as "
          "timesteps 0 to 5" % (bc, bc, bc))
    M = s[bc]["S" if bc == "SUBC" else "C"]
    scale = v.norm(M)
    mean_error, load_error, u_error, vm_error = 0.0, 0.0, 0.0, 0.0
    for k, name in listed:
        pieces, cells, duplicates = v.read_pvtu_cells(out, name, h)
        check(len(pieces) == ranks and all(
            os.path.isfile(os.path.join(out, p)) for p in pieces),
            "%s: %d piece(s), one per rank, each a file" % (name, ranks))
        expected = {(i, j, kk) for i in range(n[0]) for j in range(n[1])
                    for kk in range(n[2])}
        check(duplicates == 0 and set(cells) == expected,
              "%s: %d cells, each voxel once (of %d)"
              % (name, len(cells), len(expected)))
        wrong = sum(cells[c]["material_id"] != voxels[
            (c[2] * n[1] + c[1]) * n[0] + c[0]] for c in cells)
        check(wrong == 0, "%s: material_id = morphology.raw (%d cells "
              "differ)" % (name, wrong))
        count = len(cells)
        mean_s = [sum(c[f] for c in cells.values()) / count for f in stress]
        mean_e = [sum(c[f] for c in cells.values()) / count for f in strain]
        averaged, loaded = (mean_e, mean_s) if bc == "SUBC" else \
            (mean_s, mean_e)
        mean_error = max(mean_error, max(abs(averaged[a] - M[a][k])
                                         for a in range(6)) / scale)
        load_error = max(load_error, max(abs(loaded[a] - (a == k))
                                         for a in range(6)))
        # the von Mises stress of the written components
        top = max(c["von_mises"] for c in cells.values())
        for c in cells.values():
            sxx, syy, szz, syz, sxz, sxy = (c[f] for f in stress)
            vm = math.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2
                                  + (szz - sxx) ** 2)
                           + 3 * (syz ** 2 + sxz ** 2 + sxy ** 2))
            vm_error = max(vm_error, abs(vm - c["von_mises"]) / top)
        # the displacement on the boundary
        points = {}
        for c in cells.values():
            for x, u in zip(c["points"], c["displacement"]):
                points[tuple(round(x[d] / h[d]) for d in range(3))] = (x, u)
        if bc == "KUBC":
            size = max(math.sqrt(sum(e * e for e in affine(k, x)))
                       for x, _ in points.values())
            for p, (x, u) in points.items():
                if any(p[d] in (0, n[d]) for d in range(3)):
                    u_error = max(u_error, max(
                        abs(a - b) for a, b in zip(u, affine(k, x))) / size)
        elif bc == "periodic":
            size = max(math.sqrt(sum(e * e for e in u))
                       for _, u in points.values())
            for p, (x, u) in points.items():
                for d in range(3):
                    if p[d] == 0:
                        q = list(p)
                        q[d] = n[d]
                        jump = affine(k, [L[d] if e == d else 0.0
                                          for e in range(3)])
                        u_far = points[tuple(q)][1]
                        u_error = max(u_error, max(
                            abs(u_far[i] - u[i] - jump[i])
                            for i in range(3)) / size)
    what = "S" if bc == "SUBC" else "C"
    check(mean_error <= 1e-6,
          "%s: the cells' mean %s of load case k = column k of the summary's "
          "%s (max relative error %.2e, tolerance 1e-6)"
          % (bc, "strain" if bc == "SUBC" else "stress", what, mean_error))
    check(load_error <= 1e-6,
          "%s: the cells' mean %s of load case k = the unit %s e_k (max "
          "error %.2e, tolerance 1e-6)"
          % (bc, "stress" if bc == "SUBC" else "strain",
             "stress" if bc == "SUBC" else "strain", load_error))
    if bc == "KUBC":
        check(u_error <= 1e-6, "KUBC: displacement on the boundary = E_k x "
              "(relative error %.2e, tolerance 1e-6)" % u_error)
    if bc == "periodic":
        check(u_error <= 1e-6, "periodic: u(x + L_d e_d) - u(x) = E_k L_d "
              "e_d on opposite faces (relative error %.2e, tolerance 1e-6)"
              % u_error)
    check(vm_error <= 1e-6, "%s: von_mises of the written stress components "
          "(relative error %.2e, tolerance 1e-6)" % (bc, vm_error))
check.exit()
