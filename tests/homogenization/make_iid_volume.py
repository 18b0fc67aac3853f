"""Write an i.i.d. Bernoulli(p) voxel volume as a tribodyn raw volume.

    make_iid_volume.py HEADER NX NY NZ P SEED

Each voxel is 1 (heterogeneity) with probability P, independently (Python's
Mersenne Twister seeded with SEED, so the volume is the same on every
machine); written as HEADER (size, voxel size 1e-5 m, type uint8) and the
raw file beside it (one byte per voxel, x fastest). Run at configure time by
tests/homogenization/CMakeLists.txt for the end-to-end i.i.d. check of the
3D RVE study (rve_prm/volume_rve_iid.prm.in).
"""
import os
import random
import sys

header, nx, ny, nz, p, seed = sys.argv[1], int(sys.argv[2]), \
    int(sys.argv[3]), int(sys.argv[4]), float(sys.argv[5]), int(sys.argv[6])
rng = random.Random(seed)
raw = os.path.splitext(header)[0] + ".raw"
with open(raw, "wb") as f:
    f.write(bytes(1 if rng.random() < p else 0 for _ in range(nx * ny * nz)))
with open(header, "w") as f:
    f.write("# i.i.d. Bernoulli(%g) volume, seed %d\nsize = %d %d %d\n"
            "voxel size = 1e-5\ntype = uint8\nfile = %s\n"
            % (p, seed, nx, ny, nz, os.path.basename(raw)))
