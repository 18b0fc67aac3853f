"""The voxel size of a TIFF stack from its resolution tags (test
homogenization_volume_stack_resolution, issue #51 items 2 and 6).

    volume_stack_resolution.py TRIBODYN WORK_DIRECTORY

A two-phase stack of 6 x 5 pixels and 4 pages (grey 50 and 200, Otsu's
split) is written here with scripts/make_synthetic_images'
tiff_stack_bytes and different resolution tags, and homogenized (KUBC,
'Morphology/Voxel size' = 7e-6, the spacing of the pages). Checked, the
sizes being those written into the file (XResolution and YResolution are
exact rationals, so to 1e-12):
- tags of 2500 pixels per cm in x and 2000 in y (ResolutionUnit cm),
  'Image stack/Pixel size' = 0: summary.json's voxel_size = (4e-6, 5e-6,
  7e-6) m, the box 24 x 25 x 28 um;
- 6350 pixels per inch (ResolutionUnit inch): (4e-6, 4e-6, 7e-6);
- 'Pixel size = 4e-6' with tags of 2500 pixels per cm (agreeing): (4e-6,
  4e-6, 7e-6);
- refused (exit code 2, the message naming 'Morphology/Image
  stack/Pixel size' or 'Morphology/Image stack/File', the stack's path,
  the cause and the fix): a stack without tags and 'Pixel size = 0'; tags
  with ResolutionUnit none (no length: as in 2D); 'Pixel size = 3e-6'
  against tags of 4 um; a stack whose second page has other tags than its
  first.
"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volume_tools as v  # noqa: E402

tribodyn, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
os.makedirs(work, exist_ok=True)
check = v.Checks()
images = v.synthetic_images()
SHORT, RATIONAL = 3, 5
pages = [(6, 5, [[200 if (i + r + k) % 3 == 0 else 50 for i in range(6)]
                 for r in range(5)]) for k in range(4)]


def stack(name, pixels_per_cm=None, tags=None, per_page=None):
    """Write the stack NAME.tif; per_page: tags of each page instead."""
    path = os.path.join(work, name + ".tif")
    if per_page is None:
        data = images.tiff_stack_bytes(pages, pixels_per_cm=pixels_per_cm,
                                       tags=tags)
    else:
        # tiff_stack_bytes gives every page the same tags: two stacks of
        # the same layout (the rationals take 8 bytes whatever their
        # value), page 0 from the first and the later pages from the
        # second
        first = images.tiff_stack_bytes(pages[:1], pixels_per_cm=per_page[0])
        both = images.tiff_stack_bytes(pages, pixels_per_cm=per_page[0])
        other = images.tiff_stack_bytes(pages, pixels_per_cm=per_page[1])
        assert len(both) == len(other) and len(first) < len(both)
        data = both[:len(first)] + other[len(first):]
    with open(path, "wb") as f:
        f.write(data)
    return path


def prm(path, pixel_size):
    return """set Problem = volume_homogenization
set Output directory = output
subsection Morphology
  set Generator  = image stack
  set Voxel size = 7e-6
  subsection Image stack
    set File         = %s
    set Pixel size   = %r
    set Segmentation = Otsu
  end
end
%s
subsection Cell problem
  set Boundary conditions = KUBC
end
subsection Output
  set Write slices = false
end
""" % (path, pixel_size, v.GLASS_EPOXY_MATERIALS)


def run(name, path, pixel_size):
    directory = os.path.join(work, name)
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, "run.prm"), "w") as f:
        f.write(prm(path, pixel_size))
    return subprocess.run([tribodyn, "run.prm"], cwd=directory,
                          capture_output=True, text=True), directory


for name, path, pixel_size, expected in (
        ("cm", stack("cm", tags={282: (RATIONAL, [(2500, 1)]),
                                 283: (RATIONAL, [(2000, 1)]),
                                 296: (SHORT, [3])}), 0, (4e-6, 5e-6)),
        ("inch", stack("inch", pixels_per_cm=6350,
                       tags={296: (SHORT, [2])}), 0, (4e-6, 4e-6)),
        ("given", stack("given", pixels_per_cm=2500), 4e-6, (4e-6, 4e-6))):
    result, directory = run(name, path, pixel_size)
    print(result.stdout)
    check(result.returncode == 0, "%s: the run succeeds (exit code %d%s)"
          % (name, result.returncode, result.stderr and ": " + result.stderr))
    if result.returncode != 0:
        continue
    with open(os.path.join(directory, "output", "summary.json")) as f:
        h = json.load(f)["voxel_size"]
    want = list(expected) + [7e-6]
    error = max(abs(a / b - 1) for a, b in zip(h, want))
    check(error <= 1e-12, "%s: voxel size %s = %s from the tags and 'Voxel "
          "size' (relative error %.1e, tolerance 1e-12)"
          % (name, h, want, error))

pixel = "Parameter 'Morphology/Image stack/Pixel size': "
for name, path, pixel_size, expected in (
        ("untagged", stack("untagged"), 0,
         [pixel + "the image stack '%s' has no resolution tags",
          "so the size of its voxels in x and y is unknown. Give the size "
          "of a pixel in m"]),
        ("unit_none", stack("unit_none", pixels_per_cm=2500,
                            tags={296: (SHORT, [1])}), 0,
         [pixel + "the image stack '%s' has no resolution tags"]),
        ("conflict", stack("conflict", pixels_per_cm=2500), 3e-6,
         [pixel + "3e-06 m disagrees with the resolution tags of the image "
          "stack '%s', pixels of 4e-06 x 4e-06 m",
          "Set 'Pixel size = 0' to take the tags' size"]),
        ("pages", stack("pages", per_page=(2500, 2000)), 0,
         ["The image file '%s' (parameter 'Morphology/Image stack/File') is "
          "not a stack of equal pages: page 1 (from 0) has pixels of 5e-06 x "
          "5e-06 m in its resolution tags but page 0 pixels of 4e-06 x "
          "4e-06 m", "Write the same XResolution"])):
    result, _ = run(name, path, pixel_size)
    missing = [e for e in expected if (e % path if "%s" in e else e)
               not in result.stderr]
    check(result.returncode == 2 and not missing,
          "%s: refused with exit code 2 (%d) and the message naming the "
          "parameter, the stack, the cause and the fix%s"
          % (name, result.returncode,
             "" if not missing else "; missing %r in %r"
             % (missing, result.stderr)))
check.exit()
