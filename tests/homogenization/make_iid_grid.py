"""Write an i.i.d. Bernoulli(p) pixel map as a tribodyn grid file.

    make_iid_grid.py FILE NX NY P SEED

Each pixel is 1 (heterogeneity) with probability P, independently (Python's
Mersenne Twister seeded with SEED, so the file is the same on every
machine). Run at configure time by tests/homogenization/CMakeLists.txt for
the end-to-end i.i.d. check of the RVE study (rve_iid.prm.in).
"""
import random
import sys

path, nx, ny, p, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), \
    float(sys.argv[4]), int(sys.argv[5])
rng = random.Random(seed)
with open(path, "w") as f:
    f.write("# i.i.d. Bernoulli(%g) map, %d x %d pixels, seed %d\n"
            % (p, nx, ny, seed))
    for _ in range(ny):
        f.write(" ".join("1" if rng.random() < p else "0" for _ in range(nx))
                + "\n")
