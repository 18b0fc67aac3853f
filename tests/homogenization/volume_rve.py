"""The 3D RVE-size study on small volumes (test homogenization_volume_rve,
issue #51 item 2; `set Problem = volume_rve`).

    volume_rve.py TRIBODYN WORK_DIRECTORY

1. Crops of a laminate (layers normal to z, 4 periods of 8 voxels in a
   16 x 16 x 32 box, a glass fraction of 1/4), windows of 8 x 8 x 8,
   8 x 8 x 16 and 16 x 16 x 16 voxels at random positions, periodic
   conditions: every window spans whole periods along z wherever it starts,
   so it is the same periodic laminate (shifted), and its periodic cell
   problem has the exact laminate stiffness (volume_tools.laminate_exact;
   the exact field is piecewise affine, in the Q1 space). Each size's mean
   of k, mu, E_x, E_y, E_z, G_yz, G_xz, G_xy and nu_xy must be the exact
   laminate's within 1e-9 relative (CG tolerance 1e-12; rve.csv keeps ten
   significant digits: measured 1.3e-10), its standard deviation below
   1e-9 of the mean (measured <= 9e-14), and the glass fraction exactly 1/4
   in every window. This checks the crops (a window cut with two axes
   mixed up holds layers across x: shown failing with x and z swapped in
   VoxelVolume::window(), the constants off by up to 4.5 times), the
   constants read from each window's C and the study's statistics.
2. Realisations of random spheres (generator 'spheres', radius 1.5 voxels,
   12 %; windows of 8^3, 12^3 and 16^3 voxels, 8 of each) under KUBC, SUBC
   and periodic conditions, run on 1 rank and on 2 ranks with 'Ranks per
   window = 2' (each window solved by two ranks): the same rve.csv to 1e-8
   relative (the CG tolerance 1e-10; rank independence; measured: equal in
   its ten digits). Huet's ordering on
   the means of every size (it holds window by window): KUBC >= periodic
   >= SUBC for k, mu and the Young and shear moduli (to 1e-9 relative), and
   the KUBC - SUBC gap of k and mu shrinks from size to size (measured
   20.9, 14.6, 10.9 % for k; 64.7, 43.2, 32.3 % for mu, glass in epoxy).
   summary.json names the problem, the voxel size and the fits.
"""
import csv
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volume_tools as v  # noqa: E402

tribodyn, work = sys.argv[1], os.path.abspath(sys.argv[2])
os.makedirs(work, exist_ok=True)
check = v.Checks()
MODULI = ("k", "mu", "E_x", "E_y", "E_z", "G_yz", "G_xz", "G_xy")
CONSTANTS = MODULI + ("nu_xy",)


def study(morphology, sizes, windows, source, bcs, extra=""):
    return ("set Problem = volume_rve\nset Output directory = output\n"
            "subsection Morphology\n%s  set Voxel size = 1e-5\nend\n"
            % morphology
            + v.GLASS_EPOXY_MATERIALS
            + "subsection Cell problem\n  set Boundary conditions = %s\n"
              "  set Solver tolerance = %s\nend\n"
              "subsection RVE study\n  set Window sizes = %s\n"
              "  set Windows per size = %d\n  set Source = %s\n"
              "  set Seed = 11\n  set Plot script = none\n%send\n"
            % (bcs, "1e-12" if bcs == "periodic" else "1e-10", sizes,
               windows, source, extra))


def rows(directory):
    with open(os.path.join(directory, "output", "rve.csv")) as f:
        return list(csv.DictReader(f))


def value(table, size, bc, prop, key="mean"):
    for r in table:
        if (r["size_x_vox"], r["size_y_vox"], r["size_z_vox"]) == size \
                and r["boundary_condition"] == bc and r["property"] == prop:
            return float(r[key])
    raise KeyError((size, bc, prop))


# 1. laminate crops, periodic: every window is the exact laminate
laminate = ("  set Generator = laminate\n  set Voxels in x = 16\n"
            "  set Voxels in y = 16\n  set Voxels in z = 32\n"
            "  set Volume fraction = 0.25\n  set Laminate normal = z\n"
            "  set Laminate periods = 4\n")
v.run(tribodyn, os.path.join(work, "laminate"),
      study(laminate, "8, 8x8x16, 16", 5, "crops", "periodic"))
table = rows(os.path.join(work, "laminate"))
sizes = [("8", "8", "8"), ("8", "8", "16"), ("16", "16", "16")]
check(len(table) == 3 * (2 + 9),
      "laminate: 33 rows (3 sizes x (2 fractions + 9 constants)): %d"
      % len(table))
glass = (70e9, 0.22)
epoxy = (3e9, 0.35)
C_exact = v.laminate_exact([v.isotropic_stiffness(*epoxy),
                            v.isotropic_stiffness(*glass)], [0.75, 0.25], 2)
S_exact = v.inverse(C_exact)
k, mu = v.isotropic_projection(C_exact)
exact = {"k": k, "mu": mu, "E_x": 1 / S_exact[0][0], "E_y": 1 / S_exact[1][1],
         "E_z": 1 / S_exact[2][2], "G_yz": 1 / S_exact[3][3],
         "G_xz": 1 / S_exact[4][4], "G_xy": 1 / S_exact[5][5],
         "nu_xy": -S_exact[0][1] / S_exact[0][0]}
for size in sizes:
    f = value(table, size, "none", "fraction_heterogeneity")
    fs = value(table, size, "none", "fraction_heterogeneity", "std")
    check(abs(f - 0.25) < 1e-14 and fs < 1e-14,
          "laminate %s: glass fraction %.15g +- %.2g (1/4 in every window)"
          % ("x".join(size), f, fs))
    worst, spread = 0.0, 0.0
    for c in CONSTANTS:
        m = value(table, size, "periodic", c)
        worst = max(worst, abs(m / exact[c] - 1))
        spread = max(spread, value(table, size, "periodic", c, "std") / abs(m))
    check(worst <= 1e-9 and spread <= 1e-9,
          "laminate %s, periodic: the 9 constants' means within %.2g of the "
          "exact laminate's, std/mean <= %.2g (bound 1e-9 each)"
          % ("x".join(size), worst, spread))

# 2. spheres, realisations: 1 rank against 2 ranks on each window; Huet
spheres = ("  set Generator = spheres\n  set Voxels in x = 16\n"
           "  set Voxels in y = 16\n  set Voxels in z = 16\n"
           "  set Volume fraction = 0.12\n  set Radius = 1.5\n  set Seed = 5\n")
prm = study(spheres, "8, 12, 16", 8, "realisations", "KUBC, SUBC, periodic")
v.run(tribodyn, os.path.join(work, "spheres_1"), prm)
v.run(tribodyn, os.path.join(work, "spheres_2"),
      prm.replace("  set Seed = 11\n", "  set Seed = 11\n"
                  "  set Ranks per window = 2\n"), ranks=2)
one, two = rows(os.path.join(work, "spheres_1")), \
    rows(os.path.join(work, "spheres_2"))
check(len(one) == 3 * (2 + 3 * 9) and len(two) == len(one),
      "spheres: 87 rows on 1 and 2 ranks (3 sizes x (2 + 3 BCs x 9)): %d, %d"
      % (len(one), len(two)))
worst = 0.0
for a, b in zip(one, two):
    for key in ("mean", "std"):
        x, y = float(a[key]), float(b[key])
        scale = max(abs(float(a["mean"])), 1e-300)
        worst = max(worst, abs(x - y) / scale)
check(worst <= 1e-8, "spheres: 1 rank and 2 ranks per window agree to %.2g "
      "of the means (bound 1e-8)" % worst)
sizes = [(n, n, n) for n in ("8", "12", "16")]
order = True
for size in sizes:
    for c in MODULI:
        K = value(one, size, "KUBC", c)
        P = value(one, size, "periodic", c)
        S = value(one, size, "SUBC", c)
        if not (K >= P * (1 - 1e-9) and P >= S * (1 - 1e-9)):
            order = False
            print("  Huet's ordering broken: %s %s KUBC %g periodic %g SUBC %g"
                  % ("x".join(size), c, K, P, S))
check(order, "spheres: KUBC >= periodic >= SUBC for the 8 moduli at the 3 "
      "sizes (means)")
for c in ("k", "mu"):
    gaps = [value(one, s, "KUBC", c) / value(one, s, "SUBC", c) - 1
            for s in sizes]
    check(gaps[0] > gaps[1] > gaps[2] > 0,
          "spheres: the KUBC - SUBC gap of %s shrinks with the window: %s"
          % (c, ", ".join("%.1f %%" % (100 * g) for g in gaps)))
with open(os.path.join(work, "spheres_2", "output", "summary.json")) as f:
    s = json.load(f)
check(s["problem"] == "volume_rve" and s["voxel_size"] == [1e-5] * 3
      and s["n_window_groups"] == 1 and s["window_sizes_vox"][0] == [8, 8, 8]
      and len(s["fits"]) == 2 + 3 * 9
      and all("rve_volume_m3" in f and "integral_range_vox" in f
              for f in s["fits"]),
      "spheres: summary.json (problem, voxel size, one group of 2 ranks, "
      "sizes, 29 fits with volumes and integral ranges in voxels)")
check.exit()
