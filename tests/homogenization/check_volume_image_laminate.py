"""A three-phase laminate read from a TIFF stack against its exact
stiffness (tests homogenization_volume_image_laminate and _2ranks, issue
#51 items 2 and 4).

The stack images/stack_laminate.tif (scripts/make_synthetic_images,
laminate_stack(): 16-bit big-endian PackBits pages, Gaussian noise) holds,
inside the crop box (2, 3, 1, 12, 16, 8) of the run's parameters, two
periods of 8 rows of layers normal to y: 2 rows of grey 52000, 3 of 30000,
3 of 8000; outside the box a frame of grey 52000. The references come from
that construction, not from the code under test: Otsu's three classes
(darkest first) are phases 0, 1, 2 at the fractions 3/8, 3/8, 2/8 of a
12 x 16 x 8 volume, and the exact laminate stiffness normal to y follows
from the phases' E and nu in the run's parameters.prm
(volume_tools.check_laminate: periodic C exact to 1e-10 (measured 3.9e-14
on 1 rank, 5.2e-14 on 2; the CG tolerance 1e-12 allows ~1e-12), KUBC >=
exact >= SUBC (to -1e-9 |C|; measured -6e-16, -1.3e-15: round-off), the
exact KUBC and SUBC load cases (1e-10; measured <= 3.9e-13); fewer than 60 CG iterations
per load case: measured 41 for SUBC at this contrast of 77). A reader that ignored the crop,
mixed up rows and pages, misread 16-bit big-endian samples or PackBits, or
segmented otherwise gives other fractions, another normal or no laminate
at all, and fails.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volume_tools as v  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "scripts"))
import plot_tools  # noqa: E402  (read_parameters)

out = os.path.join(sys.argv[1], "output")
with open(os.path.join(out, "summary.json")) as f:
    s = json.load(f)
check = v.Checks()

fractions = [3 / 8, 3 / 8, 2 / 8]
check(s["n_voxels"] == [12, 16, 8],
      "the crop box: 12 x 16 x 8 voxels (got %s)" % s["n_voxels"])
got = [p["fraction"] for p in s["phases"]]
check(len(got) == 3 and all(abs(a - b) < 1e-14
                            for a, b in zip(got, fractions)),
      "phase fractions 3/8, 3/8, 2/8 (got %s)" % got)
check(abs(s["voxel_size"][0] - 2e-6) < 1e-20,
      "voxel size 'Morphology/Voxel size' = 2 um")
prm = plot_tools.read_parameters(out)
given = v.given_materials(prm)
# contrast 230/3: SUBC's multigrid takes ~41 iterations (30 at contrast 23)
v.check_laminate(check, s, given, fractions, 1, max_iterations=60)
check.exit()
