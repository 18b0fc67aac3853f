"""The slices of a 3D cell problem and their PNGs (test
homogenization_volume_slices, 2 ranks, issue #51 item 6):
tests/homogenization/volume/fields.prm (glass spheres in epoxy, 12 x 10 x
8 voxels) with 'Output/Write slices = true' and the default plot script
(scripts/plot_volume).

Checked against what the test reads itself:
- slices.json holds the mid-z, mid-x and mid-y slices (voxel indices 4,
  6, 5) of the first KUBC load case (xx), each with the voxel counts of
  its two axes (z: 12 x 10, x: 10 x 8, y: 12 x 8);
- their material ids are the voxels of morphology.raw on the plane
  (exact), and their von_mises and stress_xx the values of the cells of
  that plane in the VTU of the same load case (fields_KUBC_0.pvtu, its
  pieces written by the two ranks; the same float32 values: 1e-7
  relative), so the pieces of both ranks are in the slice;
- the PNGs, decoded here (volume_tools.read_png): slice_<a>_phases.png
  is one pixel per voxel of the slice (width = voxels along its first
  axis, height along the second, upwards), each pixel the colour of its
  voxel's phase in morphology.raw, one colour per phase in all three PNGs
  and a different one for each phase (the mid-x plane cuts no sphere); slice_z_von_mises.png and slice_z_stress_xx.png are 12
  x 10 pixels, the voxel of the largest value of the slice in viridis'
  last colour (253, 231, 37) and that of the smallest in its first (68,
  1, 84) (within 2 levels of 255: the colour map's rounding);
  volume_slices.png (the figure) is a PNG of at least 400 x 400 pixels.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volume_tools as v  # noqa: E402

out = os.path.join(sys.argv[1], "output")
with open(os.path.join(out, "summary.json")) as f:
    s = json.load(f)
with open(os.path.join(out, "slices.json")) as f:
    slices = json.load(f)
with open(os.path.join(out, "morphology.raw"), "rb") as f:
    voxels = f.read()
check = v.Checks()
n, h = s["n_voxels"], s["voxel_size"]
index = {"x": 0, "y": 1, "z": 2}
check(slices["boundary_condition"] == "KUBC"
      and slices["load_case"] == "xx", "slices of KUBC, load case xx")
check([x["axis"] for x in slices["slices"]] == ["z", "x", "y"],
      "slices normal to z, x and y")
_, cells, _ = v.read_pvtu_cells(out, "fields_KUBC_0.pvtu", h)


def voxel_of(x, a, b):
    """The voxel (i, j, k) at index a along the slice's first axis and b
    along its second."""
    p = [0, 0, 0]
    p[index[x["axis"]]] = x["index"]
    p[index[x["axes"][0]]] = a
    p[index[x["axes"][1]]] = b
    return tuple(p)


viridis_top, viridis_bottom = (253, 231, 37), (68, 1, 84)
colour_of = {}  # phase -> its colour in the PNGs
for x in slices["slices"]:
    axis = x["axis"]
    axes = [index[a] for a in x["axes"]]
    check(x["index"] == n[index[axis]] // 2
          and axes == [d for d in range(3) if d != index[axis]]
          and x["n"] == [n[axes[0]], n[axes[1]]],
          "slice %s = %d of %d, %s x %s voxels" % (
              axis, x["index"], n[index[axis]], x["n"][0], x["n"][1]))
    n0, n1 = x["n"]
    wrong_ids, field_error = 0, 0.0
    for b in range(n1):
        for a in range(n0):
            i, j, k = voxel_of(x, a, b)
            wrong_ids += x["material_id"][a + n0 * b] != voxels[
                (k * n[1] + j) * n[0] + i]
            cell = cells[(i, j, k)]
            for field in ("von_mises", "stress_xx"):
                field_error = max(field_error, abs(
                    x[field][a + n0 * b] - cell[field])
                    / max(abs(c[field]) for c in cells.values()))
    check(wrong_ids == 0, "slice %s: material ids = morphology.raw (%d "
          "voxels differ)" % (axis, wrong_ids))
    check(field_error <= 1e-7, "slice %s: von_mises and stress_xx = the "
          "cells of the plane in fields_KUBC_0.pvtu (relative error %.1e, "
          "tolerance 1e-7)" % (axis, field_error))

    # the phases' PNG: one pixel per voxel, row 0 at the top
    width, height, rows = v.read_png(os.path.join(
        out, "slice_%s_phases.png" % axis))
    check((width, height) == (n0, n1), "slice_%s_phases.png: %d x %d "
          "pixels = the voxels of the slice (%d x %d)"
          % (axis, width, height, n0, n1))
    consistent = True
    for b in range(min(n1, height)):
        for a in range(min(n0, width)):
            i, j, k = voxel_of(x, a, b)
            phase = voxels[(k * n[1] + j) * n[0] + i]
            colour = rows[height - 1 - b][a][:3]
            consistent &= colour_of.setdefault(phase, colour) == colour
    check(consistent, "slice_%s_phases.png: each pixel the colour of its "
          "voxel's phase (the same colour for a phase in every slice)" % axis)
check(len(set(colour_of.values())) == len(colour_of) >= 2,
      "the phases' PNGs: %d phases in %d colours" % (
          len(colour_of), len(set(colour_of.values()))))

z = slices["slices"][0]
n0, n1 = z["n"]
for field in ("von_mises", "stress_xx"):
    width, height, rows = v.read_png(os.path.join(
        out, "slice_z_%s.png" % field))
    check((width, height) == (n0, n1), "slice_z_%s.png: %d x %d pixels"
          % (field, width, height))
    values = z[field]
    for what, at, colour in (
            ("largest", values.index(max(values)), viridis_top),
            ("smallest", values.index(min(values)), viridis_bottom)):
        a, b = at % n0, at // n0
        pixel = rows[height - 1 - b][a][:3] if (width, height) == (n0, n1) \
            else (0, 0, 0)
        check(max(abs(p - c) for p, c in zip(pixel, colour)) <= 2,
              "slice_z_%s.png: the %s value's voxel (%d, %d) in viridis' "
              "%s colour %s (pixel %s)" % (
                  field, what, a, b, "last" if what == "largest" else
                  "first", colour, pixel))
width, height, _ = v.read_png(os.path.join(out, "volume_slices.png"),
                             pixels=False)
check(width >= 400 and height >= 400, "volume_slices.png: %d x %d pixels"
      % (width, height))
check.exit()
